#include "ocean/WavePatterns.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/Error.hpp"

namespace og::ocean {
namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kLargestPatternM = 4983.0;

// SplitMix64 finaliser: a fully specified hash, so spectra are identical on every platform
// and standard library (std distributions are not).
std::uint64_t mix(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
double unitInterval(std::uint64_t bits) { return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53; }

// Two independent standard normal numbers for mode (mx, my) of a pattern (Box-Muller), from a
// hash of everything that names the mode: independent of the order modes are visited in.
std::complex<double> gaussianPair(std::uint64_t seed, int set, int pattern, int mx, int my) {
  std::uint64_t h = mix(seed);
  h = mix(h ^ static_cast<std::uint64_t>(set * kPatternCount + pattern));
  h = mix(h ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(mx)) << 32 |
               static_cast<std::uint32_t>(my)));
  const double u1 = unitInterval(h), u2 = unitInterval(mix(h));
  const double r = std::sqrt(-2.0 * std::log(u1));
  return {r * std::cos(2.0 * kPi * u2), r * std::sin(2.0 * kPi * u2)};
}

void checkParams(const WavePatternParams& p) {
  if (!std::isfinite(p.referenceWindMs) || p.referenceWindMs < 0.0 || p.referenceWindMs > 50.0)
    throw InputError("wave patterns: reference wind must be within [0, 50] m/s");
  if (p.fftSize < 16 || p.fftSize > 1024 || (p.fftSize & (p.fftSize - 1)) != 0)
    throw InputError("wave patterns: FFT size must be a power of two in [16, 1024]");
  for (int i = 0; i < kPatternCount; ++i) {
    if (!(p.sizesM[i] > 0.0) || !std::isfinite(p.sizesM[i]) ||
        (i > 0 && !(p.sizesM[i] < p.sizesM[i - 1])))
      throw InputError("wave patterns: tile sizes must be finite, positive and decreasing");
    if (!(p.choppiness[i] >= 0.0 && p.choppiness[i] <= 2.0))
      throw InputError("wave patterns: choppiness must be within [0, 2]");
  }
}

// Second moments of the pattern's fields over its modes (P = time-averaged mode power).
struct Moments {
  double h = 0, up = 0, cross = 0;  // height; slopes along/across the set's wind
  double trace = 0;                 // dDx/dx + dDy/dy ~ |k| h (no lambda)
};

void accumulate(Moments& m, double power, double kx, double ky, double windAngle) {
  const double ku = kx * std::cos(windAngle) + ky * std::sin(windAngle);
  const double kc = -kx * std::sin(windAngle) + ky * std::cos(windAngle);
  m.h += power;
  m.up += power * ku * ku;
  m.cross += power * kc * kc;
  m.trace += power * (kx * kx + ky * ky);
}

PatternStats statsOf(const Moments& m, double lambda) {
  PatternStats s;
  s.heightVarianceM2 = m.h;
  s.slope = {m.up, m.cross};
  s.jacobianVariance = lambda * lambda * m.trace;
  return s;
}

// The band's height variance and slope variance (local wind frame) at a wind, integrated in
// log k over the radial band with the spectrum's own spreading.
struct BandIntegral {
  double height = 0.0;
  SlopeVariance slope;
};
BandIntegral bandIntegral(double k0, double k1, double u10) {
  BandIntegral b;
  if (!(k1 > k0) || k0 <= 0.0) return b;
  // Midpoint rule in log k (S k dk and B d ln k are smooth there); 48 steps per decade.
  const int steps = std::max(16, static_cast<int>(48.0 * std::log10(k1 / k0)));
  const double a = std::log(k0), h = (std::log(k1) - a) / steps;
  for (int i = 0; i < steps; ++i) {
    const double k = std::exp(a + (i + 0.5) * h);
    const double curvature = curvatureSpectrum(k, u10) * h;  // k² S dk
    const double d = spreading(k, u10);
    b.height += curvature / (k * k);
    b.slope.up += curvature * (0.5 + 0.25 * d);
    b.slope.cross += curvature * (0.5 - 0.25 * d);
  }
  return b;
}
}  // namespace

std::array<double, kPatternCount> defaultPatternSizes(int fftSize) {
  const double finest = kShortestPatternWaveM * fftSize / kTexelsPerShortestWave;
  const double ratio = std::pow(kLargestPatternM / finest, 1.0 / (kPatternCount - 1));
  std::array<double, kPatternCount> sizes{};
  for (int i = 0; i < kPatternCount; ++i) sizes[i] = kLargestPatternM / std::pow(ratio, i);
  return sizes;
}

double WavePatterns::setWindAngleRad(int set) { return set * 0.25 * kPi; }

double directionalSpectrum(double k, double phiRad, double u10) {
  if (!(k > 0.0)) return 0.0;
  const double spread = (1.0 + spreading(k, u10) * std::cos(2.0 * phiRad)) * (1.0 + std::cos(phiRad));
  return elevationSpectrum(k, u10) / k * spread / (2.0 * kPi);
}

bool patternDisplaced(const WavePatternParams& p, int pattern) {
  return p.choppiness[static_cast<std::size_t>(pattern)] >= kDisplacedChoppiness;
}

int fftSlots(const WavePatternParams& p, int patternCount) {
  int slots = 0;
  for (int i = 0; i < patternCount; ++i) slots += patternDisplaced(p, i) ? 3 : 2;
  return slots;
}

double waveRepeatFraction(double timeS) {
  return std::fmod(std::fmod(timeS, kWaveRepeatPeriodS) + kWaveRepeatPeriodS, kWaveRepeatPeriodS) / kWaveRepeatPeriodS;
}

std::uint32_t patternFrequencyStep(double k) {
  const double step = 2.0 * kPi / kWaveRepeatPeriodS;
  return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(angularFrequency(k) / step)));
}

WavePatterns makeWavePatterns(const WavePatternParams& params) {
  WavePatterns w;
  w.params = params;
  if (w.params.sizesM[0] == 0.0) w.params.sizesM = defaultPatternSizes(params.fftSize);
  checkParams(w.params);
  const WavePatternParams& p = w.params;
  const double u = std::max(p.referenceWindMs, 1.0);
  w.params.referenceWindMs = u;
  const int n = p.fftSize;
  w.kEdge[0] = 0.0;
  for (int i = 0; i < kPatternCount; ++i)
    w.kEdge[i + 1] = 2.0 * kPi * n / (kTexelsPerShortestWave * p.sizesM[i]);
  for (int set = 0; set < kPatternSets; ++set) {
    const double windAngle = WavePatterns::setWindAngleRad(set);
    for (int i = 0; i < kPatternCount; ++i) {
      const double dk = 2.0 * kPi / p.sizesM[i];
      std::vector<std::complex<float>>& h0 = w.h0[set][i];
      h0.assign(static_cast<std::size_t>(n) * n, {0.0f, 0.0f});
      Moments m;
      for (int iy = 0; iy < n; ++iy)
        for (int ix = 0; ix < n; ++ix) {
          const int mx = ix < n / 2 ? ix : ix - n, my = iy < n / 2 ? iy : iy - n;
          const double kx = mx * dk, ky = my * dk, k = std::hypot(kx, ky);
          if (k < w.kEdge[i] || k >= w.kEdge[i + 1] || k == 0.0) continue;
          const double phi = std::atan2(ky, kx) - windAngle;
          // E|h0|² = S dk² / 2: each mode and its conjugate partner carry the band's variance.
          const double amplitude = std::sqrt(0.5 * directionalSpectrum(k, phi, u) * dk * dk);
          const std::complex<double> g = gaussianPair(p.seed, set, i, mx, my) * (amplitude / std::sqrt(2.0));
          h0[static_cast<std::size_t>(iy) * n + ix] = std::complex<float>(g);
          accumulate(m, 2.0 * std::norm(g), kx, ky, windAngle);
        }
      w.stats[set][i] = statsOf(m, p.choppiness[i]);
    }
  }
  return w;
}

namespace {
// How much a band's amplitudes grow from the reference wind to another: sqrt of the ratio of
// their variances. A band (nearly) empty at the reference wind — the longest patterns under a
// 1–3 m/s reference, ~1e-187 m² — stays empty: its texels underflow to 0 in float, and the
// ratio would overflow float (inf × 0 = NaN where the GPU interpolates between two winds).
double bandScale(double variance, double referenceVariance) {
  constexpr double kEmpty = 1e-24;  // m², or (rad)² for slopes: far below anything visible
  constexpr double kMaxScale = 1e4;
  if (!(referenceVariance > kEmpty)) return 0.0;
  return std::min(std::sqrt(variance / referenceVariance), kMaxScale);
}
}  // namespace

PatternTables makePatternTables(const WavePatterns& w) {
  PatternTables t{};
  const double uRef = w.params.referenceWindMs;
  std::array<BandIntegral, kPatternCount> ref;
  for (int i = 0; i < kPatternCount; ++i) ref[i] = bandIntegral(std::max(w.kEdge[i], 1e-4), w.kEdge[i + 1], uRef);
  const double kFirst = 2.0 * kPi / w.params.sizesM[0];
  for (int s = 0; s < PatternTables::kSpeeds; ++s) {
    const double u = std::max(static_cast<double>(s), 0.1);
    double jVar = 0.0;
    for (int i = 0; i < kPatternCount; ++i) {
      const BandIntegral b = bandIntegral(std::max(w.kEdge[i], 1e-4), w.kEdge[i + 1], u);
      PatternTableEntry& e = t.pattern[s][i];
      e.heightScale = bandScale(b.height, ref[i].height);
      e.slopeScale = bandScale(b.slope.total(), ref[i].slope.total());
      e.slope = b.slope;
      // The Jacobian's (linear) term scales like the slopes.
      double variance = 0.0;
      for (int set = 0; set < kPatternSets; ++set) variance += w.stats[set][i].jacobianVariance / kPatternSets;
      e.jacobianVariance = e.slopeScale * e.slopeScale * variance;
      jVar += e.jacobianVariance;
    }
    t.jacobianVariance[s] = jVar;
    const SlopeVariance shortTail = bandIntegral(w.kEdge[kPatternCount], kSpectrumKMax, u).slope;
    const SlopeVariance longTail = bandIntegral(1e-4, kFirst, u).slope;
    t.tail[s] = {shortTail.up + longTail.up, shortTail.cross + longTail.cross};
  }
  return t;
}

int firstPatternWithWaves(const WavePatterns& w, const PatternTables& t) {
  // The realisation's variances per pattern (the larger of the two sets).
  std::array<double, kPatternCount> height{}, slope{};
  for (std::size_t i = 0; i < kPatternCount; ++i)
    for (const auto& set : w.stats) {
      height[i] = std::max(height[i], set[i].heightVarianceM2);
      slope[i] = std::max(slope[i], set[i].slope.total());
    }
  const int lastSpeed = std::clamp(static_cast<int>(std::ceil(w.params.referenceWindMs)), 0, PatternTables::kSpeeds - 1);
  // Whether pattern i holds at least kEmptyPatternShare of one of the sums at any speed.
  auto holdsWaves = [&](std::size_t i) {
    for (int s = 0; s <= lastSpeed; ++s) {
      const auto& row = t.pattern[static_cast<std::size_t>(s)];
      double heightSum = 0.0, slopeSum = 0.0;
      for (std::size_t j = 0; j < kPatternCount; ++j) {
        heightSum += row[j].heightScale * row[j].heightScale * height[j];
        slopeSum += row[j].slopeScale * row[j].slopeScale * slope[j];
      }
      if (row[i].heightScale * row[i].heightScale * height[i] > kEmptyPatternShare * heightSum ||
          row[i].slopeScale * row[i].slopeScale * slope[i] > kEmptyPatternShare * slopeSum ||
          row[i].slope.total() > kEmptyPatternShare * t.totalSlopeVariance(s).total())
        return true;
    }
    return false;
  };
  int first = 0;
  while (first < kPatternCount - 1 && !holdsWaves(static_cast<std::size_t>(first))) ++first;
  return first;
}

SlopeVariance PatternTables::totalSlopeVariance(int speed) const {
  const auto s = static_cast<std::size_t>(speed);
  SlopeVariance v = tail.at(s);
  for (const PatternTableEntry& e : pattern.at(s)) {
    v.up += e.slope.up;
    v.cross += e.slope.cross;
  }
  return v;
}

double whitecapCoverage(double jacobianMean, double jacobianVariance) {
  if (!(jacobianVariance > 0.0)) return jacobianMean < kWhitecapThreshold ? 1.0 : 0.0;
  return 0.5 * std::erfc((jacobianMean - kWhitecapThreshold) / std::sqrt(2.0 * jacobianVariance));
}

double whitecapCoverageForWind(double u10, const WavePatternParams& base) {
  WavePatternParams p = base;
  p.referenceWindMs = std::clamp(u10, 0.0, 50.0);
  const WavePatterns w = makeWavePatterns(p);
  double variance = 0.0;
  for (int i = 0; i < kPatternCount; ++i)
    for (int set = 0; set < kPatternSets; ++set) variance += w.stats[set][i].jacobianVariance / kPatternSets;
  return whitecapCoverage(1.0, variance);
}

double monahanWhitecapCoverage(double u10) { return 3.84e-6 * std::pow(std::max(u10, 0.0), 3.41); }

}  // namespace og::ocean
