#pragma once
// The wind-wave spectrum (Elfouhaily et al. 1997) and the slope statistics it implies.
// The functions are those of shaders/ocean/spectrum.glsl, compiled as C++ in double.

namespace og::ocean {

inline constexpr double kGravity = 9.81;  ///< m/s²

/// Omnidirectional curvature spectrum B(k) (dimensionless) at wavenumber k (rad/m) for a 10 m
/// wind of u10 m/s.
double curvatureSpectrum(double k, double u10);
/// Elevation spectrum S(k) = B(k)/k³, m³: the height variance per unit wavenumber.
double elevationSpectrum(double k, double u10);
/// Spreading Delta(k) in [-1, 1] of D(k, phi) = (1 + Delta cos 2 phi) / (2 pi).
double spreading(double k, double u10);
/// Spectral peak wavenumber, rad/m.
double peakWavenumber(double u10);
/// Deep-water gravity-capillary angular frequency omega(k), rad/s.
double angularFrequency(double k);

/// Slope variances along (up) and across (cross) the wind, dimensionless.
struct SlopeVariance {
  double up = 0.0;
  double cross = 0.0;
  [[nodiscard]] double total() const { return up + cross; }
};

/// Slope variance of the spectrum between wavenumbers kMin and kMax (rad/m), integrated in
/// log k: up = ∫ k² S (1/2 + Delta/4) dk, cross = ∫ k² S (1/2 - Delta/4) dk.
SlopeVariance spectrumSlopeVariance(double kMin, double kMax, double u10);

/// Cox & Munk (1954) clean-surface regressions (their Eq. 3, U at 12.5 m in m/s; we apply it
/// to U10, within the regressions' scatter): up = 3.16e-3 U, cross = 0.003 + 1.92e-3 U.
SlopeVariance coxMunkCleanSurface(double windSpeed);

/// Upper limit of the integration: beyond it the capillary spectrum is negligible (rad/m).
inline constexpr double kSpectrumKMax = 1.0e4;

}  // namespace og::ocean
