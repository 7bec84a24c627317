#pragma once
// The set of trochoid waves the ocean shaders sum (Bruneton et al. 2010, §4): wavelengths in
// geometric progression, amplitudes from the spectrum, directions spread about the wind.
#include <cstdint>
#include <vector>

#include "ocean/Spectrum.hpp"

namespace og::ocean {

struct WaveSetParams {
  double windSpeedMs = 7.0;        ///< 10 m wind, [0, 50] m/s
  double windDirectionDeg = 90.0;  ///< direction the wind blows towards, clockwise from north
  int count = 60;                  ///< number of waves, [1, 256]
  double lambdaMinM = 0.02;        ///< shortest wavelength, m
  /// Longest wavelength, m; <= 0 picks 2.5 x the spectral peak wavelength, within [5, 1000] m.
  double lambdaMaxM = 0.0;
  std::uint64_t seed = 1;          ///< directions and phases are reproducible from it
};

/// One trochoid: t = [k/|k| h sin(omega t - k.x + phase); h cos(omega t - k.x + phase)] (Eq. 1).
struct Wave {
  double wavelengthM = 0.0;
  double kEast = 0.0;         ///< wave vector, rad/m, local east component
  double kNorth = 0.0;        ///< local north component
  double amplitudeM = 0.0;    ///< h
  double omegaRadS = 0.0;     ///< angular frequency
  double phaseRad = 0.0;      ///< initial phase
  double directionDeg = 0.0;  ///< propagation direction, clockwise from north
  [[nodiscard]] double k() const { return 2.0 * 3.14159265358979323846 / wavelengthM; }
};

struct WaveSet {
  WaveSetParams params;
  std::vector<Wave> waves;       ///< longest first; wavelengths in geometric progression
  double wavelengthRatio = 1.0;  ///< lambda[i+1] / lambda[i] (< 1)
  SlopeVariance resolved;        ///< Eq. 4 with w_r = 1 summed over the waves (wind frame)
  SlopeVariance unresolvedTail;  ///< spectrum beyond the shortest wave (and below the longest)
  SlopeVariance total;           ///< resolved + tail: the slope variance of the whole sea
  double heightVarianceM2 = 0.0; ///< sum of h²/2
};

/// Builds the wave set for a wind. Deterministic for a given params (seed included).
/// Throws og::InputError for out-of-range parameters.
WaveSet makeWaveSet(const WaveSetParams& params);

/// Amplitude (m) wave `i` of `set` would have under a local wind of `windSpeedMs`: the same
/// spectral band and steepness cap as makeWaveSet, at another wind. Used to scale each wave's
/// amplitude point by point where the wind varies (the paper's §6 remark, made real).
double waveAmplitudeAt(const WaveSet& set, std::size_t i, double windSpeedMs);

/// Per-wind tables for the shaders, for wind speeds 0, step, 2 step ... (count entries):
/// the total slope variance (up, cross) and every wave's amplitude at that wind.
struct WindTables {
  double speedStepMs = 1.0;
  std::vector<SlopeVariance> total;              ///< [speed]
  std::vector<std::vector<double>> amplitudeM;   ///< [speed][wave]
};
WindTables makeWindTables(const WaveSet& set, int count = 41, double speedStepMs = 1.0);

/// Slope variance of one trochoid along unit direction (dx, dy), Eq. 4 of Bruneton 2010 with
/// weight w: (k.d)²/|k|² (1 - sqrt(1 - |k|² w² h²)).
double trochoidSlopeVariance(const Wave& wave, double dx, double dy, double weight = 1.0);

}  // namespace og::ocean
