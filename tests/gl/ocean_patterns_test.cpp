// GL tier: the FFT wave patterns (render/OceanPatterns), transformed by the GPU's compute shaders
// and by the CPU path (ocean::PatternSynthesis, FFTW in single precision, uploaded), each
// against the same sea synthesised in double with FFTW from the same spectra (Dupuy & Bruneton
// 2012 §2).
#include <gtest/gtest.h>
#include <fftw3.h>

#include <chrono>
#include <ctime>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <numbers>
#include <vector>

#include "geo/Camera.hpp"
#include "gl/Context.hpp"
#include "ocean/WavePatterns.hpp"
#include "render/OceanPatterns.hpp"
#include "support/GlFixtures.hpp"

using namespace og;

namespace {
constexpr double kPi = std::numbers::pi;

// One real field of one pattern at time t: sum_k F(k) h(k, t) e^{ik.x}, F the field's
// multiplier of h(k, t) (e.g. i kx for the x slope), synthesised with FFTW in double.
std::vector<double> synthesize(const ocean::WavePatterns& w, int set, int pattern, double timeS,
                               std::complex<double> (*multiplier)(double kx, double ky)) {
  const int n = w.params.fftSize;
  const auto& h0 = w.h0[static_cast<std::size_t>(set)][static_cast<std::size_t>(pattern)];
  const double dk = 2.0 * kPi / w.params.sizesM[static_cast<std::size_t>(pattern)];
  const double tau = std::fmod(timeS, ocean::kWaveRepeatPeriodS) / ocean::kWaveRepeatPeriodS;
  std::vector<std::complex<double>> spectrum(static_cast<std::size_t>(n) * n), field(spectrum.size());
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::size_t at = static_cast<std::size_t>(y) * n + x;
      const std::size_t mirror = static_cast<std::size_t>((n - y) % n) * n + (n - x) % n;
      const int mx = x < n / 2 ? x : x - n, my = y < n / 2 ? y : y - n;
      const double kx = mx * dk, ky = my * dk;
      const double cycles = std::fmod(ocean::patternFrequencyStep(std::hypot(kx, ky)) * tau, 1.0);
      const std::complex<double> e = std::polar(1.0, 2.0 * kPi * cycles);
      const std::complex<double> h = std::complex<double>(h0[at]) * std::conj(e) +
                                     std::conj(std::complex<double>(h0[mirror])) * e;
      spectrum[at] = (mx == 0 && my == 0) ? 0.0 : multiplier(kx, ky) * h;
    }
  fftw_plan plan = fftw_plan_dft_2d(n, n, reinterpret_cast<fftw_complex*>(spectrum.data()),
                                    reinterpret_cast<fftw_complex*>(field.data()), FFTW_BACKWARD,
                                    FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  std::vector<double> out(field.size());
  for (std::size_t i = 0; i < field.size(); ++i) out[i] = field[i].real();
  return out;
}

std::vector<float> readLayer(GLuint texture, int layer, int n, int channels) {
  std::vector<float> v(static_cast<std::size_t>(n) * n * channels);
  glGetTextureSubImage(texture, 0, 0, 0, layer, n, n, 1, channels == 4 ? GL_RGBA : GL_RG, GL_FLOAT,
                       static_cast<GLsizei>(v.size() * sizeof(float)), v.data());
  return v;
}

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

// 64² patterns for a 12 m/s reference wind: small enough to synthesise on the CPU.
ocean::WavePatternParams smallPatternParams() {
  ocean::WavePatternParams p;
  p.fftSize = 64;
  p.referenceWindMs = 12.0;
  return p;
}

}  // namespace

using Multiplier = std::complex<double> (*)(double kx, double ky);
const Multiplier kHeight = [](double, double) { return std::complex<double>(1.0, 0.0); };
const Multiplier kSlopeX = [](double kx, double) { return std::complex<double>(0.0, kx); };
const Multiplier kSlopeY = [](double, double ky) { return std::complex<double>(0.0, ky); };
const Multiplier kDispX = [](double kx, double ky) { return std::complex<double>(0.0, -kx / std::hypot(kx, ky)); };
// dDx/dx + dDy/dy = (kx² + ky²)/|k| h: the Jacobian's linear term.
const Multiplier kTrace = [](double kx, double ky) { return std::complex<double>(std::hypot(kx, ky), 0.0); };

// Largest difference between a GPU channel and the CPU field, relative to the field's rms.
double relativeError(const std::vector<float>& gpu, int channels, int channel, const std::vector<double>& cpu) {
  double worst = 0.0;
  for (std::size_t i = 0; i < cpu.size(); ++i)
    worst = std::max(worst, std::abs(static_cast<double>(gpu[i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(channel)]) - cpu[i]));
  return worst / std::max(rms(cpu), 1e-12);
}

// Each test runs with both transforms (the driver profile picks one per driver).
class OceanPatternsFft : public ::testing::TestWithParam<render::OceanPatterns::Fft> {};
INSTANTIATE_TEST_SUITE_P(Transforms, OceanPatternsFft,
                         ::testing::Values(render::OceanPatterns::Fft::Gpu, render::OceanPatterns::Fft::Cpu),
                         [](const auto& test) { return test.param == render::OceanPatterns::Fft::Gpu ? "Gpu" : "Cpu"; });

TEST_P(OceanPatternsFft, PatternsMatchDoubleSynthesis) {
  auto ctx = gl::createHeadlessContext();
  const ocean::WavePatternParams p = smallPatternParams();
  auto w = std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p));
  render::OceanPatterns gpu(w, -1.0, GetParam());
  ASSERT_EQ(gpu.fft(), GetParam());
  // A large time exercises the exact phase path (t mod period on the CPU, integer steps on the GPU).
  for (const double t : {0.0, 37.25, 3.0e6 + 0.125}) {
    gpu.update(t);
    glFinish();
    for (int set = 0; set < ocean::kPatternSets; ++set)
      for (int pattern = 0; pattern < ocean::kPatternCount; ++pattern) {
        SCOPED_TRACE("set " + std::to_string(set) + " pattern " + std::to_string(pattern) + " t " + std::to_string(t));
        const int layer = set * ocean::kPatternCount + pattern;
        const int n = p.fftSize;
        const std::vector<float> disp = readLayer(gpu.displacementTexture(), layer, n, 4);
        const std::vector<float> slopes = readLayer(gpu.slopesTexture(), layer, n, 4);
        // Half floats keep ~11 bits: a few 1e-3 of the rms at the field's extremes.
        EXPECT_LT(relativeError(disp, 4, 2, synthesize(*w, set, pattern, t, kHeight)), 4e-3);
        const double angle = ocean::WavePatterns::setWindAngleRad(set);
        const std::vector<double> sx = synthesize(*w, set, pattern, t, kSlopeX);
        const std::vector<double> sy = synthesize(*w, set, pattern, t, kSlopeY);
        std::vector<double> along(sx.size());
        for (std::size_t i = 0; i < sx.size(); ++i) along[i] = sx[i] * std::cos(angle) + sy[i] * std::sin(angle);
        EXPECT_LT(relativeError(slopes, 4, 0, along), 4e-3);
        // The second moment |s|² (rotation-invariant): its mean, the slope variance the BRDF
        // gets (the longest pattern's squares are ~1e-5, half floats' subnormals, so texel by
        // texel only the mean is exact enough to compare).
        double gpuSquare = 0.0, cpuSquare = 0.0;
        for (std::size_t i = 0; i < sx.size(); ++i) {
          cpuSquare += sx[i] * sx[i] + sy[i] * sy[i];
          gpuSquare += static_cast<double>(slopes[4 * i + 2]);
        }
        EXPECT_NEAR(gpuSquare / cpuSquare, 1.0, 0.02);
        const double lambda = p.choppiness[static_cast<std::size_t>(pattern)];
        if (lambda == 0.0) continue;
        std::vector<double> j = synthesize(*w, set, pattern, t, kTrace);
        for (double& v : j) v *= lambda;
        EXPECT_LT(relativeError(slopes, 4, 3, j), 4e-3);
        if (lambda < ocean::kDisplacedChoppiness) continue;
        std::vector<double> dx = synthesize(*w, set, pattern, t, kDispX);
        for (double& v : dx) v *= lambda;
        EXPECT_LT(relativeError(disp, 4, 0, dx), 4e-3);
      }
  }
}

// A frame that resolves only the largest patterns transforms only those (the "ocean waves"
// pass at altitude): they, and their mip-maps, are exact at the new time; the rest keep the
// time they were last transformed at until a frame needs them again.
TEST_P(OceanPatternsFft, PrefixUpdateTransformsOnlyTheLargestPatterns) {
  auto ctx = gl::createHeadlessContext();
  const ocean::WavePatternParams p = smallPatternParams();
  auto w = std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p));
  render::OceanPatterns gpu(w, -1.0, GetParam());
  const int n = p.fftSize;
  auto heightError = [&](int set, int pattern, double t) {
    const std::vector<float> disp = readLayer(gpu.displacementTexture(), set * ocean::kPatternCount + pattern, n, 4);
    return relativeError(disp, 4, 2, synthesize(*w, set, pattern, t, kHeight));
  };
  // Level 1 of the mip chain is the 2x2 mean of level 0: a prefix whose mip-maps were not
  // regenerated would still show the previous time there.
  auto mipError = [&](int layer) {
    const std::vector<float> fine = readLayer(gpu.displacementTexture(), layer, n, 4);
    std::vector<float> coarse(static_cast<std::size_t>(n / 2) * (n / 2) * 4);
    glGetTextureSubImage(gpu.displacementTexture(), 1, 0, 0, layer, n / 2, n / 2, 1, GL_RGBA, GL_FLOAT,
                         static_cast<GLsizei>(coarse.size() * sizeof(float)), coarse.data());
    std::vector<double> mean(coarse.size() / 4);
    for (int y = 0; y < n / 2; ++y)
      for (int x = 0; x < n / 2; ++x) {
        double sum = 0.0;
        for (int k = 0; k < 4; ++k)
          sum += static_cast<double>(fine[4 * static_cast<std::size_t>((2 * y + k / 2) * n + 2 * x + k % 2) + 2]);
        mean[static_cast<std::size_t>(y * (n / 2) + x)] = 0.25 * sum;
      }
    return relativeError(coarse, 4, 2, mean);
  };
  gpu.update(0.0);
  gpu.update(37.25, 3);
  glFinish();
  for (int set = 0; set < ocean::kPatternSets; ++set) {
    for (int pattern = 0; pattern < 3; ++pattern) {
      SCOPED_TRACE("set " + std::to_string(set) + " pattern " + std::to_string(pattern));
      EXPECT_LT(heightError(set, pattern, 37.25), 4e-3);
      EXPECT_LT(mipError(set * ocean::kPatternCount + pattern), 4e-3);
    }
    for (int pattern = 3; pattern < ocean::kPatternCount; ++pattern) EXPECT_LT(heightError(set, pattern, 0.0), 4e-3);
  }
  gpu.update(37.25, 4);  // the same time, one pattern more: transformed again
  gpu.update(37.25);
  glFinish();
  for (int set = 0; set < ocean::kPatternSets; ++set)
    for (int pattern = 0; pattern < ocean::kPatternCount; ++pattern) EXPECT_LT(heightError(set, pattern, 37.25), 4e-3);
}

// Which patterns a view needs: straight down from 1000 m onto the sea, 1000 rows over 60°, a
// pixel spans 2 tan(30°) = 1.155 m (a flat sea under a rectilinear camera: the same over the
// whole image; the Earth's curve widens it off the centre). Patterns of 4983, 530, 56.5 and 6.0
// m tiles are resolved there, the 0.64 m one is not (even with the half level of margin).
TEST(OceanPatterns, ResolvedPatternsFollowTheFinestFootprint) {
  geo::CameraPose pose;
  pose.position = {20.0, -40.0, 1000.0};
  pose.pitchDeg = -90.0;
  pose.verticalFovDeg = 60.0;
  const geo::CameraView view = geo::makeCameraView(pose, 1000, 1000);
  const double finest = render::OceanPatterns::finestSeaFootprintM(view, 1000);
  EXPECT_NEAR(finest, 2.0 * std::tan(kPi / 6.0), 0.01);
  ocean::WavePatternParams p;
  p.sizesM = ocean::defaultPatternSizes(p.fftSize);
  EXPECT_EQ(render::OceanPatterns::resolvedPatternCount(p, finest), 4);
  EXPECT_EQ(render::OceanPatterns::resolvedPatternCount(p, 0.01), ocean::kPatternCount);
  EXPECT_EQ(render::OceanPatterns::resolvedPatternCount(p, 1e4), 1);
  pose.pitchDeg = 10.0;  // looking above the horizon from 1000 m: the top half is sky
  const geo::CameraView up = geo::makeCameraView(pose, 1000, 1000);
  EXPECT_GT(render::OceanPatterns::finestSeaFootprintM(up, 1000), finest);
  pose.pitchDeg = 60.0;  // only sky
  EXPECT_TRUE(std::isinf(render::OceanPatterns::finestSeaFootprintM(geo::makeCameraView(pose, 1000, 1000), 1000)));
}

TEST_P(OceanPatternsFft, FftCostAtProductionSize) {
  auto ctx = gl::createHeadlessContext();
  for (int n : {64, 128}) {
    ocean::WavePatternParams p;
    p.fftSize = n;
    auto w = std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p));
    render::OceanPatterns gpu(w, -1.0, GetParam());
    gpu.update(0.0);
    glFinish();
    for (const int patterns : {ocean::kPatternCount, 3}) {
      timespec c0{}, c1{};
      clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = 1; i <= 5; ++i) gpu.update(i / 30.0 + patterns, patterns);
      glFinish();
      clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / 5;
      const double cpu = (static_cast<double>(c1.tv_sec - c0.tv_sec) * 1e3 + static_cast<double>(c1.tv_nsec - c0.tv_nsec) * 1e-6) / 5;
      std::printf("FFT patterns %d, %d of them (%s): %.1f ms per update (process CPU %.1f ms)\n", n, patterns,
                  GetParam() == render::OceanPatterns::Fft::Gpu ? "GPU's compute shaders" : "CPU, FFTW", ms, cpu);
    }
  }
}

// The patterns' mip chains (ocean/pattern_mips.comp, one dispatch a level for both textures):
// every level of every layer transformed, in the displacement and the slopes' moments, is the
// mean of the 2 x 2 texels under it in the level above, down to 1 x 1; after an update of the
// three largest patterns only, their levels follow the new time and the others keep theirs.
TEST_P(OceanPatternsFft, MipLevelsAreTheMeansOfTheLevelAbove) {
  auto ctx = gl::createHeadlessContext();
  const ocean::WavePatternParams p = smallPatternParams();
  auto w = std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p));
  render::OceanPatterns gpu(w, -1.0, GetParam());
  const auto level = [&](GLuint texture, int lod, int layer) {
    const int size = std::max(1, p.fftSize >> lod);
    std::vector<float> texels(static_cast<std::size_t>(size) * size * 4);
    glGetTextureSubImage(texture, lod, 0, 0, layer, size, size, 1, GL_RGBA, GL_FLOAT,
                         static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
    return texels;
  };
  // Largest |level - mean of the 2 x 2 above| over a layer's chain, relative to the layer's
  // largest value (half floats: the displacement rounds at 2^-11 of it).
  const auto chainError = [&](GLuint texture, int layer) {
    double worst = 0.0, scale = 1e-30;
    std::vector<float> above = level(texture, 0, layer);
    for (float v : above) scale = std::max(scale, std::abs(static_cast<double>(v)));
    for (int lod = 1; (p.fftSize >> (lod - 1)) > 1; ++lod) {
      const int n = p.fftSize >> lod;
      const std::vector<float> here = level(texture, lod, layer);
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          for (int c = 0; c < 4; ++c) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k)
              sum += static_cast<double>(above[static_cast<std::size_t>(((2 * y + k / 2) * 2 * n + 2 * x + k % 2) * 4 + c)]);
            worst = std::max(worst, std::abs(static_cast<double>(here[static_cast<std::size_t>((y * n + x) * 4 + c)]) - 0.25 * sum));
          }
      above = here;
    }
    return worst / scale;
  };
  gpu.update(0.0);
  gpu.update(12.5, 3);
  glFinish();
  for (int layer = 0; layer < ocean::kPatternSets * ocean::kPatternCount; ++layer) {
    SCOPED_TRACE("layer " + std::to_string(layer));
    EXPECT_LT(chainError(gpu.displacementTexture(), layer), 2e-3);
    EXPECT_LT(chainError(gpu.slopesTexture(), layer), 1e-5);
  }
}

// A driver whose compiler gets the FFT's compute shaders wrong (NVIDIA 580.159 lost the x
// slopes: docs/performance.md, "Tenth session") must not draw a wrong sea: the patterns check
// the GPU's transforms against the CPU's once and fall back to the CPU's. The driver's mistake
// is played here by a shader tree whose first slot drops dh/dx, as that driver did.
TEST(OceanPatternsCheck, GpuTransformsThatDisagreeWithTheCpusAreNotUsed) {
  namespace fs = std::filesystem;
  const fs::path broken = fs::path(OG_TEST_OUT_DIR) / "shaders_fft_without_x_slopes";
  fs::remove_all(broken);
  fs::create_directories(broken.parent_path());
  fs::copy(fs::path(OG_SOURCE_DIR) / "shaders", broken, fs::copy_options::recursive);
  const fs::path spectrum = broken / "ocean" / "fft_spectrum.comp";
  std::ifstream in(spectrum);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const std::string slot = "slots[slot++] = (1.0 - k.x) * h;";
  const auto at = text.find(slot);
  ASSERT_NE(at, std::string::npos) << "fft_spectrum.comp no longer writes its first slot as " << slot;
  text.replace(at, slot.size(), "slots[slot++] = h;");
  std::ofstream(spectrum) << text;

  const test::ScopedEnv gpuProfile("OCEANGLOBE_FFT", "gpu");  // the profile of a GPU driver
  auto ctx = gl::createHeadlessContext();
  auto w = std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(smallPatternParams()));
  EXPECT_TRUE(render::OceanPatterns::gpuFftMatchesCpu(w));
  EXPECT_EQ(render::OceanPatterns(w).fft(), render::OceanPatterns::Fft::Gpu);
  const test::ScopedEnv brokenShaders("OCEANGLOBE_SHADER_DIR", broken.c_str());
  EXPECT_FALSE(render::OceanPatterns::gpuFftMatchesCpu(w));
  EXPECT_EQ(render::OceanPatterns(w).fft(), render::OceanPatterns::Fft::Cpu);
}
