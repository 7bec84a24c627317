#include "render/OceanPatterns.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <span>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/Log.hpp"
#include "gl/Context.hpp"
#include "gl/DriverProfile.hpp"
#include "gl/Shader.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {
namespace {
constexpr int kLayers = ocean::kPatternSets * ocean::kPatternCount;

gl::Texture makeArray(GLenum format, int size, int layers, int levels) {
  return gl::createSquareArray(format, size, layers, levels, GL_REPEAT);  // the patterns tile
}

int log2Of(int n) {
  int l = 0;
  while ((1 << l) < n) ++l;
  return l;
}

// The per-wind tables as a uniform block, laid out as shaders/ocean/patterns.glsl reads them
// (row by row, a vec4 per wind speed: std140 packs a vec4 array tightly). A block rather than
// a texture: llvmpipe's indexed block reads cost a pixel less than texel fetches (~10 % of the
// open sea's shading, docs/performance.md "Ninth session").
gl::Buffer makeTableBuffer(const ocean::PatternTables& t) {
  static_assert(ocean::PatternTables::kSpeeds == 51, "shaders/ocean/patterns.glsl's PATTERN_TABLE_COLUMNS");
  constexpr int kColumns = ocean::PatternTables::kSpeeds, kRows = 2 * ocean::kPatternCount + 1;
  std::vector<float> texels(static_cast<std::size_t>(4 * kColumns * kRows), 0.0f);
  auto at = [&](int c, int r) { return &texels[static_cast<std::size_t>(4 * (r * kColumns + c))]; };
  for (int c = 0; c < kColumns; ++c) {
    for (int i = 0; i < ocean::kPatternCount; ++i) {
      const ocean::PatternTableEntry& e = t.pattern[static_cast<std::size_t>(c)][static_cast<std::size_t>(i)];
      float* v = at(c, i);
      v[0] = static_cast<float>(e.heightScale);
      v[1] = static_cast<float>(e.slopeScale);
      v[2] = static_cast<float>(e.slope.up);
      v[3] = static_cast<float>(e.slope.cross);
      at(c, ocean::kPatternCount + 1 + i)[0] = static_cast<float>(e.jacobianVariance);
    }
    float* v = at(c, ocean::kPatternCount);
    v[0] = static_cast<float>(t.tail[static_cast<std::size_t>(c)].up);
    v[1] = static_cast<float>(t.tail[static_cast<std::size_t>(c)].cross);
    v[2] = static_cast<float>(t.jacobianVariance[static_cast<std::size_t>(c)]);
  }
  gl::Buffer buffer = gl::createBuffer();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(texels.size() * sizeof(float)), texels.data(), 0);
  return buffer;
}

// Bit p set: pattern p is displaced horizontally (three FFT slots instead of two).
int displacedMask(const ocean::WavePatternParams& p) {
  int mask = 0;
  for (int i = 0; i < ocean::kPatternCount; ++i)
    if (ocean::patternDisplaced(p, i)) mask |= 1 << i;
  return mask;
}

int fftLayersPerSet(const ocean::WavePatternParams& p) { return (ocean::fftSlots(p, ocean::kPatternCount) + 1) / 2; }

std::vector<std::string> fftDefines(const ocean::WavePatternParams& p) {
  return {"PATTERN_COUNT " + std::to_string(ocean::kPatternCount),
          "PATTERN_DISPLACED " + std::to_string(displacedMask(p)),
          "FFT_LAYERS_PER_SET " + std::to_string(fftLayersPerSet(p)),
          "FFT_SIZE " + std::to_string(p.fftSize), "FFT_LOG2 " + std::to_string(log2Of(p.fftSize))};
}

/// Whether every channel of every layer agrees: largest |gpu - cpu| at most `bound` times that
/// channel's rms over the layer plus `absolute` (the outputs' rounding near zero).
bool layersAgree(const std::vector<float>& gpu, std::span<const float> cpu, std::size_t texels, double bound,
                 double absolute) {
  for (std::size_t layer = 0; layer < static_cast<std::size_t>(kLayers); ++layer)
    for (std::size_t c = 0; c < 4; ++c) {
      double sum = 0.0, worst = 0.0;
      for (std::size_t i = 0; i < texels; ++i) {
        const std::size_t at = 4 * (layer * texels + i) + c;
        const double want = cpu[at];
        sum += want * want;
        worst = std::max(worst, std::abs(static_cast<double>(gpu[at]) - want));
      }
      if (worst > bound * std::sqrt(sum / static_cast<double>(texels)) + absolute) return false;
    }
  return true;
}

}  // namespace

// The GPU's transforms: the compute programs, the spectra (h0(k), conj(h0(-k)) per texel,
// RGBA32F; each mode's frequency step, R32UI) and the FFT's ping-pong buffers.
struct OceanPatterns::GpuFft {
  explicit GpuFft(const ocean::WavePatterns& w);
  void uploadSpectra(const ocean::WavePatterns& w);
  void setLayerUniforms(const ocean::WavePatternParams& p, const gl::Program& program) const;

  gl::Program spectrum;
  gl::Program line;  ///< whole-line FFT in shared memory
  gl::Program finish;
  gl::Program mips;  ///< ocean/pattern_mips.comp: one mip level of both textures
  gl::Texture h0;
  gl::Texture steps;
  gl::Texture fields[2];
  int fftLayers = 0;  ///< layers of the FFT buffers (1 or 2 per pattern layer)
};

OceanPatterns::GpuFft::GpuFft(const ocean::WavePatterns& w)
    : spectrum({{GL_COMPUTE_SHADER, "ocean/fft_spectrum.comp"}}, fftDefines(w.params)),
      line({{GL_COMPUTE_SHADER, "ocean/fft_line.comp"}}, fftDefines(w.params)),
      finish({{GL_COMPUTE_SHADER, "ocean/fft_finish.comp"}}, fftDefines(w.params)),
      mips({{GL_COMPUTE_SHADER, "ocean/pattern_mips.comp"}}),
      fftLayers(ocean::kPatternSets * fftLayersPerSet(w.params)) {
  uploadSpectra(w);
  for (gl::Texture& f : fields) f = makeArray(GL_RGBA32F, w.params.fftSize, fftLayers, 1);
  for (const gl::Program* p : {&spectrum, &line, &finish}) setLayerUniforms(w.params, *p);
}

OceanPatterns::OceanPatterns(std::shared_ptr<const ocean::WavePatterns> patterns, double requestedWindMs,
                             std::optional<Fft> fft)
    : patterns_(std::move(patterns)), tables_(ocean::makePatternTables(*patterns_)) {
  firstPattern_ = ocean::firstPatternWithWaves(*patterns_, tables_);
  requestedWindMs_ = requestedWindMs;
  const int n = patterns_->params.fftSize;
  const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  const bool profileChooses = !fft.has_value();
  if (!fft) fft = gl::driverProfile().cpuWaveFft ? Fft::Cpu : Fft::Gpu;
  if (*fft == Fft::Cpu) {
    cpu_ = std::make_unique<ocean::PatternSynthesis>(*patterns_);
  } else {
    gpu_ = std::make_unique<GpuFft>(*patterns_);
    // Spectra (16 B/texel) + steps (4) + FFT buffers (2 x 16 per FFT layer).
    gpuBytes_ = texels * kLayers * 20 + texels * static_cast<std::size_t>(gpu_->fftLayers) * 32;
  }
  const int levels = log2Of(n) + 1;
  displacement_ = makeArray(GL_RGBA16F, n, kLayers, levels);
  slopes_ = makeArray(GL_RGBA32F, n, kLayers, levels);  // squares of slopes ~1e-5: below half floats
  table_ = makeTableBuffer(tables_);
  const std::size_t outputBytes = texels * kLayers * 24 * 4 / 3;  // the mip-mapped outputs
  gpuBytes_ += outputBytes;
  gl::checkErrors("OceanPatterns setup");
  if (profileChooses && gpu_ != nullptr && !gpuFftTrusted()) {
    gpu_.reset();
    cpu_ = std::make_unique<ocean::PatternSynthesis>(*patterns_);
    gpuBytes_ = outputBytes;
    computed_ = 0;
  }
}

// The verdict of matchesCpu, asked once per driver, shader tree (OCEANGLOBE_SHADER_DIR) and
// program variant in a process (GL runs on one thread: the map needs no lock).
bool OceanPatterns::gpuFftTrusted() {
  static std::map<std::string, bool> verdicts;
  const std::string& renderer = gl::currentContextInfo().renderer;
  std::string key = renderer + "|" + gl::shaderSourceDir();
  for (const std::string& d : fftDefines(patterns_->params)) key += "|" + d;
  const auto known = verdicts.find(key);
  if (known != verdicts.end()) return known->second;
  const bool trusted = matchesCpu();
  if (!trusted)
    log::warn("the wave patterns' FFT on the GPU does not match the CPU's on this driver (" + renderer +
              "): the CPU transforms them instead");
  verdicts.emplace(key, trusted);
  return trusted;
}

OceanPatterns::~OceanPatterns() = default;

// h0(k) and conj(h0(-k)) per texel (RGBA32F), and each mode's frequency step (R32UI).
void OceanPatterns::GpuFft::uploadSpectra(const ocean::WavePatterns& w) {
  const int n = w.params.fftSize;
  const auto texelsPerLayer = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  std::vector<float> spectra(4 * texelsPerLayer * kLayers);
  std::vector<std::uint32_t> frequencySteps(texelsPerLayer * kLayers);
  for (int layer = 0; layer < kLayers; ++layer) {
    const auto set = static_cast<std::size_t>(layer / ocean::kPatternCount);
    const auto pattern = static_cast<std::size_t>(layer % ocean::kPatternCount);
    const auto& modes = w.h0[set][pattern];
    const double dk = 2.0 * 3.14159265358979323846 / w.params.sizesM[pattern];
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::size_t at = static_cast<std::size_t>(y) * n + x;
        const std::size_t mirror = static_cast<std::size_t>((n - y) % n) * n + (n - x) % n;
        const std::size_t texel = static_cast<std::size_t>(layer) * texelsPerLayer + at;
        float* t = &spectra[4 * texel];
        t[0] = modes[at].real();
        t[1] = modes[at].imag();
        t[2] = modes[mirror].real();  // conj(h0(-k))
        t[3] = -modes[mirror].imag();
        const int mx = x < n / 2 ? x : x - n, my = y < n / 2 ? y : y - n;
        frequencySteps[texel] = ocean::patternFrequencyStep(dk * std::hypot(mx, my));
      }
  }
  h0 = makeArray(GL_RGBA32F, n, kLayers, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage3D(h0.id(), 0, 0, 0, 0, n, n, kLayers, GL_RGBA, GL_FLOAT, spectra.data());
  steps = makeArray(GL_R32UI, n, kLayers, 1);
  glTextureSubImage3D(steps.id(), 0, 0, 0, 0, n, n, kLayers, GL_RED_INTEGER, GL_UNSIGNED_INT, frequencySteps.data());
}

void OceanPatterns::GpuFft::setLayerUniforms(const ocean::WavePatternParams& p, const gl::Program& program) const {
  std::vector<float> chop, sizes;
  for (int i = 0; i < ocean::kPatternCount; ++i) {
    chop.push_back(static_cast<float>(p.choppiness[static_cast<std::size_t>(i)]));
    sizes.push_back(static_cast<float>(p.sizesM[static_cast<std::size_t>(i)]));
  }
  for (const auto& [name, values] : {std::pair{"uChoppiness", &chop}, std::pair{"uPatternSizeM", &sizes}}) {
    const GLint at = program.location(name);
    if (at >= 0) glProgramUniform1fv(program.id(), at, ocean::kPatternCount, values->data());
  }
}

void OceanPatterns::update(double timeS, int patternCount) {
  patternCount = std::clamp(patternCount, 1, ocean::kPatternCount);
  if (computed_ >= patternCount && timeS == timeS_) return;
  if (cpu_ != nullptr) {
    cpu_->compute(timeS, patternCount);
    uploadCpuFft(patternCount);
  } else {
    runGpuFft(timeS, patternCount);
  }
  timeS_ = timeS;
  computed_ = patternCount;
}

int OceanPatterns::resolvedPatternCount(const ocean::WavePatternParams& params, double finestFootprintM) {
  // Half a level of detail of margin: the CPU's rays against the grid's interpolated positions.
  const double footprint = finestFootprintM * std::sqrt(0.5);
  int count = 1;
  while (count < ocean::kPatternCount && params.sizesM[static_cast<std::size_t>(count)] > footprint) ++count;
  return count;
}

double OceanPatterns::finestSeaFootprintM(const geo::CameraView& view, int heightPx) {
  constexpr int kSteps = 16;
  const double pixel = 2.0 / std::max(heightPx, 1);  // one pixel in NDC (both axes: square pixels)
  const glm::dvec3 up = view.enu.up;
  // The sea point of a ray, in the tangent plane under the eye (as vOceanXY, ocean/grid.vert).
  auto hit = [&](double x, double y, glm::dvec3& p) {
    const glm::dvec3 dir = view.rayDirection(x, y);
    const std::optional<double> t = geo::intersectEllipsoid(view.positionEcef, dir);
    if (!t) return false;
    p = *t * dir;
    p -= glm::dot(p, up) * up;
    return true;
  };
  double finest = std::numeric_limits<double>::infinity();
  for (int j = 0; j <= kSteps; ++j)
    for (int i = 0; i <= kSteps; ++i) {
      const double x = -1.0 + 2.0 * i / kSteps, y = -1.0 + 2.0 * j / kSteps;
      const double dx = i < kSteps ? pixel / view.aspect : -pixel / view.aspect, dy = j < kSteps ? pixel : -pixel;
      glm::dvec3 p, px, py;
      if (!hit(x, y, p) || !hit(x + dx, y, px) || !hit(x, y + dy, py)) continue;
      finest = std::min(finest, std::max(glm::length(px - p), glm::length(py - p)));
    }
  return finest;
}

void OceanPatterns::runGpuFft(double timeS, int patternCount) {
  const ocean::WavePatterns& w = *patterns_;
  const int n = w.params.fftSize;
  // tau = (t mod period) / period, split into a 12-bit integer part and the rest (exact).
  const double tau = ocean::waveRepeatFraction(timeS);
  const double coarse = std::floor(tau * 4096.0);
  glProgramUniform1ui(gpu_->spectrum.id(), gpu_->spectrum.location("uTimeSteps"), static_cast<GLuint>(coarse));
  gpu_->spectrum.set("uTimeFine", static_cast<float>(tau - coarse / 4096.0));
  gpu_->spectrum.set("uPatternCount", patternCount);
  gpu_->finish.set("uPatternCount", patternCount);
  // The FFT layers the first patternCount patterns fill (slots in pattern order, two a layer).
  const int lineLayers = std::min((ocean::fftSlots(w.params, patternCount) + 1) / 2, fftLayersPerSet(w.params));
  glBindImageTexture(0, gpu_->h0.id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(1, gpu_->steps.id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
  glBindImageTexture(2, gpu_->fields[0].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gpu_->spectrum.use();
  glDispatchCompute(static_cast<GLuint>(n / 8), static_cast<GLuint>(n / 8), ocean::kPatternSets);

  // Rows, then columns: one work group per line of every FFT layer (fft_line.comp).
  int source = 0;
  gpu_->line.use();
  for (int vertical = 0; vertical < 2; ++vertical) {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    gpu_->line.set("uVertical", vertical);
    glBindImageTexture(0, gpu_->fields[source].id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, gpu_->fields[1 - source].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(static_cast<GLuint>(n), static_cast<GLuint>(lineLayers), ocean::kPatternSets);
    source = 1 - source;
  }

  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, gpu_->fields[source].id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(1, displacement_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(2, slopes_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gpu_->finish.use();
  glDispatchCompute(static_cast<GLuint>(n / 8), static_cast<GLuint>(n / 8), ocean::kPatternSets);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  generateMipmaps(patternCount);
  for (GLuint unit = 0; unit < 4; ++unit) glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  gl::checkErrors("OceanPatterns::update");
}

// Mip-maps of the patterns transformed this time (each set's first patternCount layers), one
// compute dispatch a level for both textures (ocean/pattern_mips.comp): glGenerateMipmap blits
// every layer and level on llvmpipe (14-30 ms a frame) and has no layer range.
void OceanPatterns::generateMipmaps(int patternCount) {
  const int levels = log2Of(patterns_->params.fftSize) + 1;
  gpu_->mips.set("uPatternCount", patternCount);
  gpu_->mips.set("uLayersPerSet", ocean::kPatternCount);
  gpu_->mips.use();
  for (int level = 1; level < levels; ++level) {
    glBindImageTexture(0, displacement_.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA16F);
    glBindImageTexture(1, displacement_.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(2, slopes_.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(3, slopes_.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const auto groups = static_cast<GLuint>(std::max(1, ((patterns_->params.fftSize >> level) + 7) / 8));
    glDispatchCompute(groups, groups, static_cast<GLuint>(patternCount * ocean::kPatternSets));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

// The CPU's transforms of the first patternCount patterns of each set, every mip level.
void OceanPatterns::uploadCpuFft(int patternCount) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int lod = 0; lod < cpu_->levels(); ++lod) {
    const int side = patterns_->params.fftSize >> lod;
    for (int set = 0; set < ocean::kPatternSets; ++set) {
      const int first = set * ocean::kPatternCount;
      for (const auto& [texture, texels] : {std::pair{displacement_.id(), cpu_->displacement(lod, first, patternCount)},
                                            std::pair{slopes_.id(), cpu_->slopes(lod, first, patternCount)}})
        glTextureSubImage3D(texture, lod, 0, 0, first, side, side, patternCount, GL_RGBA, GL_FLOAT, texels.data());
    }
  }
  gl::checkErrors("OceanPatterns::uploadCpuFft");
}

std::vector<std::string> OceanPatterns::shaderDefines() {
  return {"PATTERN_COUNT " + std::to_string(ocean::kPatternCount)};
}

double OceanPatterns::amplitudeBoundM() const {
  double variance = 0.0;
  for (int i = 0; i < ocean::kPatternCount; ++i)
    variance += patterns_->stats[0][static_cast<std::size_t>(i)].heightVarianceM2;
  return 4.0 * std::sqrt(variance) * 1.5;  // heights and, as large, the choppy displacement
}

void OceanPatterns::setUniforms(const gl::Program& program, const ocean::OceanFrame* frame,
                                double amplitude) const {
  const ocean::WavePatternParams& p = patterns_->params;
  std::vector<float> sizes, chop, offsets;
  for (int i = 0; i < ocean::kPatternCount; ++i) {
    const double size = p.sizesM[static_cast<std::size_t>(i)];
    sizes.push_back(static_cast<float>(size));
    chop.push_back(static_cast<float>(p.choppiness[static_cast<std::size_t>(i)]));
    const glm::dvec2 o = frame != nullptr ? frame->fieldOffsetModulo(size) : glm::dvec2(0.0);
    offsets.push_back(static_cast<float>(o.x));
    offsets.push_back(static_cast<float>(o.y));
  }
  auto setArray = [&](const char* name, int count, const float* v, bool pairs) {
    const GLint at = program.location(name);
    if (at < 0) return;
    if (pairs) glProgramUniform2fv(program.id(), at, count, v);
    else glProgramUniform1fv(program.id(), at, count, v);
  };
  setArray("uPatternSizeM", ocean::kPatternCount, sizes.data(), false);
  setArray("uPatternChoppiness", ocean::kPatternCount, chop.data(), false);
  setArray("uPatternOffsetM", ocean::kPatternCount, offsets.data(), true);
  const double rotation = frame != nullptr ? frame->fieldRotationRad() : 0.0;
  program.set("uFieldRotation", glm::vec2(static_cast<float>(std::cos(rotation)), static_cast<float>(std::sin(rotation))));
  program.set("uPatternAmplitude", static_cast<float>(amplitude));
  program.set("uWhitecapThreshold", static_cast<float>(ocean::kWhitecapThreshold));
  program.set("uPatternFftSize", static_cast<float>(p.fftSize));
  program.set("uPatternTopLod", static_cast<float>(log2Of(p.fftSize)));
  program.set("uPatternFirst", firstPattern_);
}

namespace {

// The wind's and its bin's uniforms of PATTERN_CONSTANT_WIND: what wind.glsl's localWind reads
// from the one-cell texture (render/WindTextures: the vector's float components; a calm has
// azimuth 0, as atan2Safe gives it), and patterns.glsl's windBins(fieldWindAngle(azimuth)) with
// one bin, in double.
void setConstantWindBin(const gl::Program& program, double speedMs, double towardsRad, double fieldRotationRad) {
  const double pi = std::numbers::pi;
  const double u = static_cast<float>(speedMs * std::sin(towardsRad)), v = static_cast<float>(speedMs * std::cos(towardsRad));
  const double azimuth = u != 0.0 || v != 0.0 ? std::atan2(u, v) : 0.0;
  program.set("uWindConst", glm::vec4(static_cast<float>(std::hypot(u, v)), static_cast<float>(azimuth),
                                      static_cast<float>(std::sin(azimuth)), static_cast<float>(std::cos(azimuth))));
  const auto [thetaField, b] = OceanPatterns::fieldWind(azimuth, fieldRotationRad);
  const int bin = static_cast<int>(std::floor(b + 0.5)) & 7;
  const double binAngle = bin * 0.25 * pi;
  program.set("uWindBinConst", bin);
  program.set("uWindBinTurnsConst",
              glm::vec4(static_cast<float>(std::cos(binAngle)), static_cast<float>(std::sin(binAngle)),
                        static_cast<float>(std::cos(binAngle - thetaField)), static_cast<float>(std::sin(binAngle - thetaField))));
  program.set("uWindFieldTurnConst", glm::vec2(static_cast<float>(std::cos(thetaField)), static_cast<float>(std::sin(thetaField))));
}

}  // namespace

OceanPatterns::FieldWind OceanPatterns::fieldWind(double towardsRad, double fieldRotationRad) {
  const double pi = std::numbers::pi;
  double b = (0.5 * pi - towardsRad - std::remainder(fieldRotationRad, 2.0 * pi)) / (0.25 * pi);
  b -= 8.0 * std::floor(b / 8.0);
  return {b * 0.25 * pi, b};
}

void OceanPatterns::setConstantWind(const gl::Program& program, double speedMs, double towardsRad,
                                    double fieldRotationRad) const {
  // patterns.glsl's patternTable: the two speed columns around the wind, mixed.
  const double c = std::clamp(speedMs, 0.0, static_cast<double>(ocean::PatternTables::kSpeeds - 1));
  const int c0 = std::min(static_cast<int>(c), ocean::PatternTables::kSpeeds - 2);
  const double f = c - c0;
  auto mix = [f](double a, double b) { return a + (b - a) * f; };
  const auto& row0 = tables_.pattern[static_cast<std::size_t>(c0)];
  const auto& row1 = tables_.pattern[static_cast<std::size_t>(c0 + 1)];
  // patternBands: each band's (slope scale, share along the wind), and the averaged-out
  // statistics from pattern i on (the tail's slopes first).
  std::array<float, 2 * ocean::kPatternCount> bands{};
  std::array<float, 3 * (ocean::kPatternCount + 1)> averaged{};
  const auto tail0 = tables_.tail[static_cast<std::size_t>(c0)], tail1 = tables_.tail[static_cast<std::size_t>(c0 + 1)];
  glm::dvec3 sum(mix(tail0.up, tail1.up), mix(tail0.cross, tail1.cross), 0.0);
  auto store = [&averaged](int i, const glm::dvec3& v) {
    for (int k = 0; k < 3; ++k) averaged[static_cast<std::size_t>(3 * i + k)] = static_cast<float>(v[k]);
  };
  store(ocean::kPatternCount, sum);
  for (int i = ocean::kPatternCount - 1; i >= 0; --i) {
    const ocean::PatternTableEntry& a = row0[static_cast<std::size_t>(i)];
    const ocean::PatternTableEntry& b = row1[static_cast<std::size_t>(i)];
    const double up = mix(a.slope.up, b.slope.up), cross = mix(a.slope.cross, b.slope.cross);
    bands[static_cast<std::size_t>(2 * i)] = static_cast<float>(mix(a.slopeScale, b.slopeScale));
    bands[static_cast<std::size_t>(2 * i + 1)] = static_cast<float>(up / std::max(up + cross, 1e-12));
    sum += glm::dvec3(up, cross, mix(a.jacobianVariance, b.jacobianVariance));
    store(i, sum);
  }
  // patterns.glsl's seaSlopeVarianceTotal (the tail and every band) and seaJacobianVarianceTotal.
  program.set("uSeaTotalsConst", glm::vec3(static_cast<float>(sum.x), static_cast<float>(sum.y),
                                           static_cast<float>(mix(tables_.jacobianVariance[static_cast<std::size_t>(c0)],
                                                                  tables_.jacobianVariance[static_cast<std::size_t>(c0 + 1)]))));
  if (const GLint at = program.location("uPatternBandConst"); at >= 0)
    glProgramUniform2fv(program.id(), at, ocean::kPatternCount, bands.data());
  if (const GLint at = program.location("uPatternAveragedFromConst"); at >= 0)
    glProgramUniform3fv(program.id(), at, ocean::kPatternCount + 1, averaged.data());
  setConstantWindBin(program, speedMs, towardsRad, fieldRotationRad);
}

void OceanPatterns::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, gl::kBlockPatternTable, table_.id());
  glBindTextureUnit(gl::kUnitPatternDisplacement, displacement_.id());
  glBindTextureUnit(gl::kUnitPatternSlopes, slopes_.id());
}

bool OceanPatterns::gpuFftMatchesCpu(const std::shared_ptr<const ocean::WavePatterns>& patterns) {
  OceanPatterns gpu(patterns, -1.0, Fft::Gpu);
  return gpu.matchesCpu();
}

// This object's GPU transforms at t = 0 against FFTW's, read back at level 0.
bool OceanPatterns::matchesCpu() {
  update(0.0);
  ocean::PatternSynthesis cpu(*patterns_);
  cpu.compute(0.0, ocean::kPatternCount);
  const int n = patterns_->params.fftSize;
  const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  std::vector<float> displacement(4 * texels * kLayers), slopes(displacement.size());
  const auto bytes = static_cast<GLsizei>(displacement.size() * sizeof(float));
  glGetTextureSubImage(displacement_.id(), 0, 0, 0, 0, n, n, kLayers, GL_RGBA, GL_FLOAT, bytes, displacement.data());
  glGetTextureSubImage(slopes_.id(), 0, 0, 0, 0, n, n, kLayers, GL_RGBA, GL_FLOAT, bytes, slopes.data());
  glUseProgram(0);
  gl::checkErrors("OceanPatterns::matchesCpu");
  // Half floats round to 2^-11 of a value, and to 6e-8 below 6e-5 (their subnormals).
  return layersAgree(displacement, cpu.displacement(0, 0, kLayers), texels, 0.02, 1e-7) &&
         layersAgree(slopes, cpu.slopes(0, 0, kLayers), texels, 0.02, 1e-9);
}

}  // namespace og::render
