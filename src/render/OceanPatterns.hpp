#pragma once
// The FFT wave patterns on the GPU (Dupuy & Bruneton 2012): the initial spectra of
// ocean::WavePatterns uploaded once, and every frame an inverse FFT per pattern and direction
// set (compute shaders shaders/ocean/fft_*.comp) into three mip-mapped texture arrays the sea
// shaders sample (shaders/ocean/patterns.glsl); where the driver renders on the CPU, the same
// transforms by FFTW (ocean::PatternSynthesis) uploaded instead (gl::DriverProfile::cpuWaveFft):
//   displacement (OG_UNIT_PATTERN_DISPLACEMENT): (lambda Dx, lambda Dy, h, 0), m, tile axes
//   slopes       (OG_UNIT_PATTERN_SLOPES): (s_u, s_c, s_u² + s_c², j): slopes along/across the
//                set's wind, their second moment, the whitecaps' Jacobian term
// layer = set * 4 + pattern. Plus the per-wind tables (the uniform block OG_BLOCK_PATTERN_TABLE, ocean::PatternTables).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geo/Camera.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "ocean/OceanFrame.hpp"
#include "ocean/PatternSynthesis.hpp"
#include "ocean/WavePatterns.hpp"

namespace og::render {

class OceanPatterns {
 public:
  /// Where the transforms run: the GPU's compute shaders, or FFTW on the CPU (uploaded).
  enum class Fft { Gpu, Cpu };
  /// Needs a current GL 4.5 context. Uploads the spectra (GPU) and the per-wind tables.
  /// `requestedWindMs`: the reference wind the caller asked for (before clamping), for reuse.
  /// `fft`: none takes the driver profile's choice (gl::DriverProfile::cpuWaveFft), the CPU's
  /// where the GPU's fails gpuFftMatchesCpu (checked once per driver and shader tree, logged).
  explicit OceanPatterns(std::shared_ptr<const ocean::WavePatterns> patterns, double requestedWindMs = -1.0,
                         std::optional<Fft> fft = std::nullopt);
  ~OceanPatterns();
  [[nodiscard]] Fft fft() const { return cpu_ != nullptr ? Fft::Cpu : Fft::Gpu; }
  [[nodiscard]] double requestedWindMs() const { return requestedWindMs_; }

  [[nodiscard]] const ocean::WavePatterns& patterns() const { return *patterns_; }
  [[nodiscard]] const ocean::PatternTables& tables() const { return tables_; }

  /// Makes the textures show the sea at simulation time `timeS` (seconds, any value): runs the
  /// FFTs unless the textures already hold that time. Only the first `patternCount` patterns
  /// (largest first, 1..kPatternCount) are transformed; the others keep an earlier time and
  /// must not be sampled (resolvedPatternCount says which a frame can need).
  void update(double timeS, int patternCount = ocean::kPatternCount);

  /// Patterns (a prefix of the list, largest first) that a pixel of footprint `finestFootprintM`
  /// (m, the smallest on the screen) or larger can resolve: pattern i is averaged out wholly
  /// (patterns.glsl: level of detail >= log2(fftSize)) where the footprint is at least its
  /// tile's size. With a margin of half a level of detail; at least 1.
  [[nodiscard]] static int resolvedPatternCount(const ocean::WavePatternParams& params, double finestFootprintM);

  /// Smallest pixel footprint (m) of the sea on a `heightPx`-row image of `view`, as the sea
  /// shader measures it (the larger of the undisplaced position's steps between neighbouring
  /// pixels), from rays over a 17 x 17 grid of the screen; infinity when no ray meets the sea.
  [[nodiscard]] static double finestSeaFootprintM(const geo::CameraView& view, int heightPx);

  /// Binds the textures to their units (12, 13 and the table on 10).
  void bind() const;

  /// Sets shaders/ocean/patterns.glsl's uniforms on `program`: the tiles, the field's offset and
  /// rotation in `frame` (none: the orbit's sea, which uses the per-wind tables only) and the
  /// amplitude of the resolved waves, [0, 1].
  void setUniforms(const gl::Program& program, const ocean::OceanFrame* frame, double amplitude) const;

  /// Sets the PATTERN_CONSTANT_WIND uniforms (ocean/patterns.glsl, ocean/wind.glsl) on
  /// `program` for one wind over the whole sea, `speedMs` (m/s, >= 0) blowing towards
  /// `towardsRad` (clockwise from north), the field turned by `fieldRotationRad` from the
  /// ocean frame: its patternBands from the tables as the shader reads them, the whole sea's
  /// slope and Jacobian variances (seaSlopeVarianceTotal, seaJacobianVarianceTotal: the
  /// globe's sea), the wind as wind.glsl's localWind would find it, and its one bin of the
  /// patterns (the nearest).
  void setConstantWind(const gl::Program& program, double speedMs, double towardsRad, double fieldRotationRad) const;

  /// patterns.glsl's fieldWindAngle and windBins in double, for a wind blowing towards
  /// `towardsRad` (clockwise from north) over a field turned by `fieldRotationRad` from the
  /// ocean frame: its angle in the field's axes (radians, [0, 2 pi)) and its place among the
  /// patterns' 8 direction bins of 45° ([0, 8): bin floor(bin), a fraction past it).
  struct FieldWind {
    double angleRad = 0.0, bin = 0.0;
  };
  [[nodiscard]] static FieldWind fieldWind(double towardsRad, double fieldRotationRad);

  /// The defines programs including shaders/ocean/patterns.glsl need.
  [[nodiscard]] static std::vector<std::string> shaderDefines();

  /// Largest displacement the waves reach at the reference wind (about 4 standard deviations
  /// of the height, chop included), m: how far the grid must overshoot the screen.
  [[nodiscard]] double amplitudeBoundM() const;

  /// The textures (for read-back in tests).
  [[nodiscard]] GLuint displacementTexture() const { return displacement_.id(); }
  [[nodiscard]] GLuint slopesTexture() const { return slopes_.id(); }

  /// GPU memory of the textures, bytes.
  [[nodiscard]] std::size_t gpuBytes() const { return gpuBytes_; }

  /// Whether the GPU's transforms of `patterns` at t = 0 (every pattern, mip level 0) match the
  /// CPU's within 2 % of each channel's rms (plus the outputs' rounding). A driver whose compiler
  /// gets the compute shaders wrong (NVIDIA 580.159 did: docs/performance.md, "Tenth session")
  /// fails it. Needs a current context; costs the GPU programs, one transform on each side and
  /// a read-back. The constructor asks it of itself where the driver profile picks the GPU.
  [[nodiscard]] static bool gpuFftMatchesCpu(const std::shared_ptr<const ocean::WavePatterns>& patterns);

 private:
  struct GpuFft;  ///< the compute programs, the spectra and the FFT's buffers
  void runGpuFft(double timeS, int patternCount);
  void generateMipmaps(int patternCount);
  void uploadCpuFft(int patternCount);
  bool gpuFftTrusted();
  bool matchesCpu();

  std::shared_ptr<const ocean::WavePatterns> patterns_;
  ocean::PatternTables tables_;
  int firstPattern_ = 0;  ///< ocean::firstPatternWithWaves: the shaders' loops start there
  std::unique_ptr<GpuFft> gpu_;                   ///< Fft::Gpu
  std::unique_ptr<ocean::PatternSynthesis> cpu_;  ///< Fft::Cpu
  gl::Texture displacement_;
  gl::Texture slopes_;
  gl::Buffer table_;  ///< the per-wind tables, a std140 uniform block (makeTableBuffer)
  double requestedWindMs_ = -1.0;
  double timeS_ = 0.0;
  int computed_ = 0;          ///< patterns the textures hold at timeS_ (0: none)
  std::size_t gpuBytes_ = 0;
};

}  // namespace og::render
