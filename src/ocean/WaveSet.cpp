#include "ocean/WaveSet.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/Error.hpp"

namespace og::ocean {
namespace {
constexpr double kPi = std::numbers::pi;

// SplitMix64: a tiny, fully specified generator, so wave sets are identical on every
// platform and standard library (std distributions are not).
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

// Inverse CDF of the spreading D(phi) = (1 + Delta cos 2phi) / pi on [-pi/2, pi/2]
// (waves travel downwind): CDF(phi) = (phi + pi/2 + Delta/2 sin 2phi) / pi, by bisection.
double sampleDirection(double u, double delta) {
  double lo = -0.5 * kPi, hi = 0.5 * kPi;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double cdf = (mid + 0.5 * kPi + 0.5 * delta * std::sin(2.0 * mid)) / kPi;
    (cdf < u ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Height variance of the spectrum between k0 and k1: integral of S(k) dk in log k.
double bandVariance(double k0, double k1, double u10) {
  const int steps = 64;
  const double a = std::log(k0), h = (std::log(k1) - a) / steps;
  double v = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double k = std::exp(a + (i + 0.5) * h);
    v += elevationSpectrum(k, u10) * k * h;
  }
  return v;
}
}  // namespace

double waveAmplitudeAt(const WaveSet& set, std::size_t i, double windSpeedMs) {
  const double u = std::clamp(windSpeedMs, 0.1, 50.0);
  const double k = set.waves.at(i).k();
  const std::size_t n = set.waves.size();
  const double halfBand = n > 1 ? std::sqrt(set.wavelengthRatio) : 0.5;
  const double h = std::sqrt(2.0 * bandVariance(k * halfBand, k / halfBand, u));
  return std::min(h, 0.44 / k);
}

WindTables makeWindTables(const WaveSet& set, int count, double speedStepMs) {
  WindTables t;
  t.speedStepMs = speedStepMs;
  for (int s = 0; s < count; ++s) {
    const double u = s * speedStepMs;
    WaveSetParams p = set.params;
    p.windSpeedMs = std::clamp(u, 0.0, 50.0);
    p.lambdaMaxM = set.params.lambdaMaxM;  // the same waves, another wind
    t.total.push_back(makeWaveSet(p).total);
    std::vector<double> amps;
    for (std::size_t i = 0; i < set.waves.size(); ++i) amps.push_back(waveAmplitudeAt(set, i, u));
    t.amplitudeM.push_back(std::move(amps));
  }
  return t;
}

double trochoidSlopeVariance(const Wave& w, double dx, double dy, double weight) {
  const double k2 = w.kEast * w.kEast + w.kNorth * w.kNorth;
  const double kd = w.kEast * dx + w.kNorth * dy;
  const double kh2 = std::min(k2 * weight * weight * w.amplitudeM * w.amplitudeM, 1.0);
  return kd * kd / k2 * (1.0 - std::sqrt(1.0 - kh2));
}

WaveSet makeWaveSet(const WaveSetParams& p) {
  if (!std::isfinite(p.windSpeedMs) || p.windSpeedMs < 0.0 || p.windSpeedMs > 50.0)
    throw InputError("wind speed must be within [0, 50] m/s");
  if (!std::isfinite(p.windDirectionDeg)) throw InputError("wind direction must be finite");
  if (p.count < 1 || p.count > 256) throw InputError("wave count must be within [1, 256]");
  const double u = std::max(p.windSpeedMs, 0.1);
  const double lambdaPeak = 2.0 * kPi / peakWavenumber(u);
  const double lambdaMax = p.lambdaMaxM > 0.0 ? p.lambdaMaxM : std::clamp(2.5 * lambdaPeak, 5.0, 1000.0);
  if (!(p.lambdaMinM > 0.0) || !(lambdaMax > p.lambdaMinM))
    throw InputError("wavelength range must satisfy 0 < lambda_min < lambda_max");

  WaveSet set;
  set.params = p;
  set.params.lambdaMaxM = lambdaMax;
  const int n = p.count;
  set.wavelengthRatio = n > 1 ? std::pow(p.lambdaMinM / lambdaMax, 1.0 / (n - 1)) : 1.0;
  const double halfBand = std::sqrt(set.wavelengthRatio);  // band edges in wavelength
  const double windRad = p.windDirectionDeg * kPi / 180.0;

  SplitMix64 rng{p.seed};
  const double stratum = rng.uniform();
  double kFirst = 0.0, kLast = 0.0;
  for (int i = 0; i < n; ++i) {
    Wave w;
    w.wavelengthM = lambdaMax * std::pow(set.wavelengthRatio, i);
    const double k = 2.0 * kPi / w.wavelengthM;
    // The wave stands for the spectral band between the neighbouring geometric midpoints.
    const double k0 = k * (n > 1 ? halfBand : 0.5), k1 = k / (n > 1 ? halfBand : 0.5);
    if (i == 0) kFirst = k0;
    kLast = k1;
    w.amplitudeM = std::sqrt(2.0 * bandVariance(k0, k1, u));
    // Trochoids loop when k h >= 1; real seas break well before (Stokes limit k h ~ 0.44).
    w.amplitudeM = std::min(w.amplitudeM, 0.44 / k);
    // Directions: stratified (golden-ratio sequence) through the spreading's inverse CDF, so a
    // few dozen waves already follow the up/crosswind statistics.
    const double uDir = std::fmod(stratum + (i + 0.5) * 0.6180339887498949, 1.0);
    const double phi = sampleDirection(uDir, spreading(k, u));
    const double dir = windRad + phi;  // clockwise from north
    w.directionDeg = std::fmod(dir * 180.0 / kPi + 720.0, 360.0);
    w.kEast = k * std::sin(dir);
    w.kNorth = k * std::cos(dir);
    w.omegaRadS = angularFrequency(k);
    w.phaseRad = 2.0 * kPi * rng.uniform();
    set.heightVarianceM2 += 0.5 * w.amplitudeM * w.amplitudeM;
    // Eq. 4 (w_r = 1) in the wind frame: up = along the wind, cross = across it.
    set.resolved.up += trochoidSlopeVariance(w, std::sin(windRad), std::cos(windRad));
    set.resolved.cross += trochoidSlopeVariance(w, std::cos(windRad), -std::sin(windRad));
    set.waves.push_back(w);
  }
  const SlopeVariance shortTail = spectrumSlopeVariance(kLast, kSpectrumKMax, u);
  const SlopeVariance longTail = spectrumSlopeVariance(1e-4, kFirst, u);
  set.unresolvedTail = {shortTail.up + longTail.up, shortTail.cross + longTail.cross};
  set.total = {set.resolved.up + set.unresolvedTail.up, set.resolved.cross + set.unresolvedTail.cross};
  return set;
}

}  // namespace og::ocean
