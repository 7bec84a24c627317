#include "ocean/PatternSynthesis.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <thread>

namespace og::ocean {
namespace {
constexpr double kTwoPi = 6.283185307179586;
constexpr int kLayers = kPatternSets * kPatternCount;
}  // namespace

struct PatternSynthesis::Mode {
  std::size_t texel;     ///< y n + x
  float kx, ky, kLength;  ///< wave vector, rad/m
  std::complex<float> h0, h0MinusConj;  ///< h0(k), conj(h0(-k))
  std::uint32_t steps;   ///< omega / (2 pi / kWaveRepeatPeriodS)
};

struct PatternSynthesis::Plan {
  fftwf_complex* buffer = nullptr;  ///< [set][slot]: n² complex each
  fftwf_plan plan = nullptr;        ///< one n x n inverse transform, in place
  ~Plan() {
    if (plan != nullptr) fftwf_destroy_plan(plan);
    fftwf_free(buffer);
  }
};

PatternSynthesis::PatternSynthesis(const WavePatterns& patterns)
    : patterns_(patterns), n_(patterns.params.fftSize), plan_(std::make_unique<Plan>()) {
  const WavePatternParams& p = patterns_.params;
  slotsPerSet_ = fftSlots(p, kPatternCount);
  const int n = n_;
  const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  // Only the modes in a pattern's band are nonzero (a fifth of the tile): the spectra at a
  // time are made from those alone.
  for (int layer = 0; layer < kLayers; ++layer) {
    const auto set = static_cast<std::size_t>(layer / kPatternCount);
    const auto pattern = static_cast<std::size_t>(layer % kPatternCount);
    const auto& h0 = patterns_.h0[set][pattern];
    const double dk = kTwoPi / p.sizesM[pattern];
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(n) + static_cast<std::size_t>(x);
        const std::size_t mirror = static_cast<std::size_t>((n - y) % n) * static_cast<std::size_t>(n) +
                                   static_cast<std::size_t>((n - x) % n);
        if (h0[at] == std::complex<float>() && h0[mirror] == std::complex<float>()) continue;
        const int mx = x < n / 2 ? x : x - n, my = y < n / 2 ? y : y - n;
        const double kx = mx * dk, ky = my * dk, k = std::hypot(kx, ky);
        modes_[static_cast<std::size_t>(layer)].push_back(
            {at, static_cast<float>(kx), static_cast<float>(ky), static_cast<float>(std::max(k, 1e-9)), h0[at],
             std::conj(h0[mirror]), patternFrequencyStep(k)});
      }
  }
  plan_->buffer = fftwf_alloc_complex(texels * static_cast<std::size_t>(kPatternSets * slotsPerSet_));
  plan_->plan = fftwf_plan_dft_2d(n, n, plan_->buffer, plan_->buffer, FFTW_BACKWARD, FFTW_ESTIMATE);
  for (int lod = 0; (n >> lod) >= 1; ++lod) {
    const auto side = static_cast<std::size_t>(n >> lod);
    displacement_.emplace_back(side * side * 4 * kLayers, 0.0f);
    slopes_.emplace_back(side * side * 4 * kLayers, 0.0f);
  }
}

PatternSynthesis::~PatternSynthesis() = default;

void PatternSynthesis::compute(double timeS, int patternCount) {
  patternCount = std::clamp(patternCount, 1, kPatternCount);
  const double tau = waveRepeatFraction(timeS);
  const auto texels = static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
  const int slots = fftSlots(patterns_.params, patternCount);
  // The sets are independent: one on a second thread (FFTW's execute is thread-safe).
  auto run = [&](int set) {
    fillSpectra(set, patternCount, tau);
    fftwf_complex* first = plan_->buffer + static_cast<std::size_t>(set * slotsPerSet_) * texels;
    for (int s = 0; s < slots; ++s) {
      fftwf_complex* slot = first + static_cast<std::size_t>(s) * texels;
      fftwf_execute_dft(plan_->plan, slot, slot);
    }
    finish(set, patternCount);
    reduceMips(set, patternCount);
  };
  static_assert(kPatternSets == 2, "one set on each of two threads");
  std::thread other(run, 1);
  run(0);
  other.join();
}

// Tessendorf 2001 Eq. 43, h(k, t) = h0(k) e^{-i w t} + conj(h0(-k)) e^{i w t}, and the fields'
// spectra packed two real fields to a complex slot (A + iB transforms to a + ib for real a, b):
// (h + i dh/dx), (dh/dy + i t), and for displaced patterns (Dx + i Dy), D = -i k/|k| h.
void PatternSynthesis::fillSpectra(int set, int patternCount, double tau) {
  const auto texels = static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
  auto* first = reinterpret_cast<std::complex<float>*>(plan_->buffer) + static_cast<std::size_t>(set * slotsPerSet_) * texels;
  std::fill(first, first + static_cast<std::size_t>(fftSlots(patterns_.params, patternCount)) * texels, std::complex<float>());
  const std::complex<float> i1(0.0f, 1.0f);
  for (int pattern = 0; pattern < patternCount; ++pattern) {
    std::complex<float>* slot = first + static_cast<std::size_t>(fftSlots(patterns_.params, pattern)) * texels;
    const bool chop = patternDisplaced(patterns_.params, pattern);
    for (const Mode& m : modes_[static_cast<std::size_t>(set * kPatternCount + pattern)]) {
      double cycles = std::fmod(static_cast<double>(m.steps) * tau, 1.0);
      const auto phase = static_cast<float>(kTwoPi * cycles);
      const std::complex<float> e(std::cos(phase), std::sin(phase));
      const std::complex<float> h = m.h0 * std::conj(e) + m.h0MinusConj * e;
      const std::complex<float> ih = i1 * h;
      slot[m.texel] = h + i1 * (m.kx * ih);
      slot[texels + m.texel] = m.ky * ih + i1 * (m.kLength * h);
      if (chop) slot[2 * texels + m.texel] = (-m.kx / m.kLength) * ih + i1 * ((-m.ky / m.kLength) * ih);
    }
  }
}

// The transformed slots into level 0 of the two textures (fft_finish.comp's layout).
void PatternSynthesis::finish(int set, int patternCount) {
  const auto texels = static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
  const auto* first = reinterpret_cast<const std::complex<float>*>(plan_->buffer) + static_cast<std::size_t>(set * slotsPerSet_) * texels;
  const double windAngle = WavePatterns::setWindAngleRad(set);
  const auto ax = static_cast<float>(std::cos(windAngle)), ay = static_cast<float>(std::sin(windAngle));
  for (int pattern = 0; pattern < patternCount; ++pattern) {
    const std::complex<float>* slot = first + static_cast<std::size_t>(fftSlots(patterns_.params, pattern)) * texels;
    const auto lambda = static_cast<float>(patterns_.params.choppiness[static_cast<std::size_t>(pattern)]);
    const bool chop = patternDisplaced(patterns_.params, pattern);
    const std::size_t layer = static_cast<std::size_t>(set * kPatternCount + pattern) * texels * 4;
    float* disp = displacement_[0].data() + layer;
    float* slopes = slopes_[0].data() + layer;
    for (std::size_t t = 0; t < texels; ++t) {
      const std::complex<float> a = slot[t], b = slot[texels + t];
      const std::complex<float> d = chop ? lambda * slot[2 * texels + t] : std::complex<float>();
      const float sx = a.imag(), sy = b.real();
      const float su = sx * ax + sy * ay, sc = -sx * ay + sy * ax;
      disp[4 * t] = d.real();
      disp[4 * t + 1] = d.imag();
      disp[4 * t + 2] = a.real();
      disp[4 * t + 3] = 0.0f;
      slopes[4 * t] = su;
      slopes[4 * t + 1] = sc;
      slopes[4 * t + 2] = su * su + sc * sc;
      slopes[4 * t + 3] = lambda * b.imag();
    }
  }
}

// Each level the mean of the 2 x 2 texels under it (pattern_mips.comp), down to 1 x 1.
void PatternSynthesis::reduceMips(int set, int patternCount) {
  for (std::vector<std::vector<float>>* chain : {&displacement_, &slopes_})
    for (std::size_t lod = 1; lod < chain->size(); ++lod) {
      const auto side = static_cast<std::size_t>(n_ >> lod), above = 2 * side;
      for (int pattern = 0; pattern < patternCount; ++pattern) {
        const auto layer = static_cast<std::size_t>(set * kPatternCount + pattern);
        const float* src = (*chain)[lod - 1].data() + layer * above * above * 4;
        float* dst = (*chain)[lod].data() + layer * side * side * 4;
        for (std::size_t y = 0; y < side; ++y)
          for (std::size_t x = 0; x < side; ++x)
            for (std::size_t c = 0; c < 4; ++c) {
              const std::size_t at = (2 * y * above + 2 * x) * 4 + c;
              dst[(y * side + x) * 4 + c] = 0.25f * (src[at] + src[at + 4] + src[at + above * 4] + src[at + above * 4 + 4]);
            }
      }
    }
}

std::span<const float> PatternSynthesis::displacement(int lod, int firstLayer, int count) const {
  const auto side = static_cast<std::size_t>(n_ >> lod);
  const std::vector<float>& level = displacement_[static_cast<std::size_t>(lod)];
  return {level.data() + static_cast<std::size_t>(firstLayer) * side * side * 4, static_cast<std::size_t>(count) * side * side * 4};
}

std::span<const float> PatternSynthesis::slopes(int lod, int firstLayer, int count) const {
  const auto side = static_cast<std::size_t>(n_ >> lod);
  const std::vector<float>& level = slopes_[static_cast<std::size_t>(lod)];
  return {level.data() + static_cast<std::size_t>(firstLayer) * side * side * 4, static_cast<std::size_t>(count) * side * side * 4};
}

}  // namespace og::ocean
