// GL tier: the FFT wave patterns computed on the GPU (render/OceanPatterns) against the same
// sea synthesised on the CPU with FFTW from the same spectra (Dupuy & Bruneton 2012 §2).
#include <gtest/gtest.h>
#include <fftw3.h>

#include <chrono>
#include <ctime>
#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "gl/Context.hpp"
#include "ocean/WavePatterns.hpp"
#include "render/OceanPatterns.hpp"

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

TEST(OceanPatterns, GpuFftMatchesCpuSynthesis) {
  auto ctx = gl::createHeadlessContext();
  ocean::WavePatternParams p;
  p.fftSize = 64;
  p.referenceWindMs = 12.0;
  auto w = std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p));
  render::OceanPatterns gpu(w);
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

TEST(OceanPatterns, FftCostAtProductionSize) {
  auto ctx = gl::createHeadlessContext();
  for (int n : {64, 128}) {
    ocean::WavePatternParams p;
    p.fftSize = n;
    auto w = std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p));
    render::OceanPatterns gpu(w);
    gpu.update(0.0);
    glFinish();
    timespec c0{}, c1{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 1; i <= 5; ++i) gpu.update(i / 30.0);
    glFinish();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / 5;
    const double cpu = (static_cast<double>(c1.tv_sec - c0.tv_sec) * 1e3 + static_cast<double>(c1.tv_nsec - c0.tv_nsec) * 1e-6) / 5;
    std::printf("FFT patterns %d: %.1f ms per update (process CPU %.1f ms)\n", n, ms, cpu);
  }
}
