#pragma once
// The FFT wave patterns at a time on the CPU, with FFTW (Dupuy & Bruneton 2012 §2; Tessendorf
// 2001): the same fields, packing and mip chains as the GPU's compute passes
// (shaders/ocean/fft_spectrum.comp, fft_line.comp, fft_finish.comp, pattern_mips.comp), for
// render/OceanPatterns to upload where the GL driver renders on the CPU: llvmpipe runs the
// compute shaders' barriers as coroutines, and FFTW does the same transforms in a fraction of
// the time on the same cores (docs/performance.md, "Eighth session").
//
// Per layer (set * kPatternCount + pattern), mip-mapped down to 1 x 1, RGBA floats:
//   displacement: (lambda Dx, lambda Dy, h, 0), m, the tile's axes
//   slopes:       (s_u, s_c, s_u² + s_c², j): slopes along/across the set's wind, their second
//                 moment, j = lambda (dDx/dx + dDy/dy), the Jacobian's linear term
#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "ocean/WavePatterns.hpp"

namespace og::ocean {

class PatternSynthesis {
 public:
  /// Plans the transforms (FFTW, single precision) for `patterns`, which must outlive this.
  explicit PatternSynthesis(const WavePatterns& patterns);
  ~PatternSynthesis();
  PatternSynthesis(const PatternSynthesis&) = delete;
  PatternSynthesis& operator=(const PatternSynthesis&) = delete;

  /// The first `patternCount` patterns (largest first, 1..kPatternCount) of both sets at time
  /// `timeS` (s, any value: taken modulo kWaveRepeatPeriodS in double, as the GPU's exact phase
  /// path), all their mip levels. The other layers keep what they held.
  void compute(double timeS, int patternCount);

  /// Mip levels of a pattern tile: log2(fftSize) + 1.
  [[nodiscard]] int levels() const { return static_cast<int>(displacement_.size()); }
  /// Level `lod` of layers [firstLayer, firstLayer + count): (fftSize >> lod)² RGBA texels per
  /// layer, rows along x, layer after layer (as glTextureSubImage3D takes them).
  [[nodiscard]] std::span<const float> displacement(int lod, int firstLayer, int count) const;
  [[nodiscard]] std::span<const float> slopes(int lod, int firstLayer, int count) const;

 private:
  struct Mode;  // a nonzero Fourier mode of one pattern: where, k, h0, conj(h0(-k)), frequency
  struct Plan;  // FFTW's
  void fillSpectra(int set, int patternCount, double tau);
  void finish(int set, int patternCount);
  void reduceMips(int set, int patternCount);

  const WavePatterns& patterns_;
  int n_ = 0;
  int slotsPerSet_ = 0;  ///< complex fields per set: 2 per pattern, 3 for displaced ones
  std::array<std::vector<Mode>, kPatternSets * kPatternCount> modes_;
  std::unique_ptr<Plan> plan_;
  std::vector<std::vector<float>> displacement_, slopes_;  ///< [lod]: layers x texels x 4
};

}  // namespace og::ocean
