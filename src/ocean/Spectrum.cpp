#include "ocean/Spectrum.hpp"

#include <algorithm>
#include <cmath>

#include "core/GlslShim.hpp"

namespace og::ocean {
namespace glsl {
using namespace og::glsl;
#include "ocean/spectrum.glsl"
}  // namespace glsl

double curvatureSpectrum(double k, double u10) { return glsl::spectrumCurvature(k, u10); }
double elevationSpectrum(double k, double u10) { return glsl::spectrumElevation(k, u10); }
double spreading(double k, double u10) { return glsl::spectrumSpreading(k, u10); }
double peakWavenumber(double u10) { return glsl::spectrumPeakK(u10); }

double angularFrequency(double k) {
  // omega² = g k (1 + (k/km)²): gravity waves with the capillary correction.
  const double r = k / glsl::SPECTRUM_KM;
  return std::sqrt(kGravity * k * (1.0 + r * r));
}

SlopeVariance spectrumSlopeVariance(double kMin, double kMax, double u10) {
  SlopeVariance v;
  if (!(kMax > kMin) || kMin <= 0.0) return v;
  // Midpoint rule in log k: k² S dk = B(k) d(ln k), smooth in ln k.
  const int steps = 4000;
  const double a = std::log(kMin), b = std::log(kMax), h = (b - a) / steps;
  for (int i = 0; i < steps; ++i) {
    const double k = std::exp(a + (i + 0.5) * h);
    const double bk = curvatureSpectrum(k, u10) * h;
    const double d = spreading(k, u10);
    v.up += bk * (0.5 + 0.25 * d);
    v.cross += bk * (0.5 - 0.25 * d);
  }
  return v;
}

SlopeVariance coxMunkCleanSurface(double windSpeed) {
  return {3.16e-3 * windSpeed, 0.003 + 1.92e-3 * windSpeed};
}

}  // namespace og::ocean
