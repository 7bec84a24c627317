// Wind-wave spectrum of Elfouhaily et al. 1997, "A unified directional spectrum for long and
// short wind-driven waves" (JGR 102(C7)), used for the wave set's amplitudes, the per-point
// amplitude scaling by local wind, and the unresolved slope variance.
//
// Shared by GLSL and C++: src/ocean/Spectrum.cpp includes this file with Number = double and
// the GLSL built-ins mapped onto <cmath>, so the CPU tests exercise the very code the shaders
// run. Keep to the common subset: Number, exp, sqrt, log, tanh, pow, max, min, abs.
//
// Units: wavenumber k in rad/m, wind speed U10 (10 m above the sea) in m/s.

const Number SPECTRUM_G = 9.81;         // gravity, m/s²
const Number SPECTRUM_KM = 370.0;       // k of the gravity-capillary phase-speed minimum, rad/m
const Number SPECTRUM_CM = 0.23;        // phase speed at SPECTRUM_KM, m/s
const Number SPECTRUM_OMEGA = 0.84;     // inverse wave age of a fully developed sea

// Phase speed c(k) including capillarity (Eq. 4 context: c² = g/k (1 + (k/km)²)).
Number spectrumPhaseSpeed(Number k) {
  return sqrt(SPECTRUM_G / k * (1.0 + (k / SPECTRUM_KM) * (k / SPECTRUM_KM)));
}

// Friction velocity u* from U10 with the drag coefficient of Wu (1982), Cd = (0.8 + 0.065 U)1e-3.
Number spectrumFrictionVelocity(Number u10) {
  return sqrt((0.8 + 0.065 * u10) * 1e-3) * u10;
}

// Spectral peak wavenumber, k_p = g (Omega / U10)² (Eq. 3).
Number spectrumPeakK(Number u10) {
  Number u = max(u10, 0.1);
  return SPECTRUM_G * (SPECTRUM_OMEGA / u) * (SPECTRUM_OMEGA / u);
}

// Omnidirectional curvature spectrum B(k) = B_l + B_h (Eqs. 32-43); elevation S(k) = B / k³.
Number spectrumCurvature(Number k, Number u10) {
  Number u = max(u10, 0.1);
  Number kp = spectrumPeakK(u);
  Number c = spectrumPhaseSpeed(k);
  Number cp = spectrumPhaseSpeed(kp);
  Number ustar = spectrumFrictionVelocity(u);
  // Long waves: Pierson-Moskowitz shape with JONSWAP peak enhancement (Eqs. 32-36).
  Number lpm = exp(-1.25 * (kp / k) * (kp / k));
  Number gamma = 1.7;  // Omega = 0.84 < 1 (Eq. 3)
  Number sigma = 0.08 * (1.0 + 4.0 / (SPECTRUM_OMEGA * SPECTRUM_OMEGA * SPECTRUM_OMEGA));
  Number s = sqrt(k / kp) - 1.0;
  Number jp = pow(gamma, exp(-(s * s) / (2.0 * sigma * sigma)));
  Number alphaP = 6e-3 * sqrt(SPECTRUM_OMEGA);
  Number fp = lpm * jp * exp(-SPECTRUM_OMEGA / sqrt(10.0) * s);
  Number bl = 0.5 * alphaP * (cp / c) * fp;
  // Short waves (Eqs. 40-44): gravity-capillary range set by the friction velocity.
  Number alphaM = ustar < SPECTRUM_CM ? 0.01 * (1.0 + log(ustar / SPECTRUM_CM))
                                      : 0.01 * (1.0 + 3.0 * log(ustar / SPECTRUM_CM));
  Number q = k / SPECTRUM_KM - 1.0;
  Number fm = lpm * jp * exp(-0.25 * q * q);
  Number bh = 0.5 * max(alphaM, 0.0) * (SPECTRUM_CM / c) * fm;
  return bl + bh;
}

// Elevation spectrum S(k) in m³ (variance per unit k): S = B / k³.
Number spectrumElevation(Number k, Number u10) {
  return spectrumCurvature(k, u10) / (k * k * k);
}

// Angular spreading Delta(k) of D(k, phi) = (1 + Delta cos 2phi) / (2 pi) (Eqs. 57-59), phi
// from the wind direction; it makes slopes larger along the wind than across it.
Number spectrumSpreading(Number k, Number u10) {
  Number u = max(u10, 0.1);
  Number c = spectrumPhaseSpeed(k);
  Number cp = spectrumPhaseSpeed(spectrumPeakK(u));
  Number ustar = spectrumFrictionVelocity(u);
  Number a0 = log(2.0) / 4.0;
  Number ap = 4.0;
  Number am = 0.13 * ustar / SPECTRUM_CM;
  return tanh(a0 + ap * pow(c / cp, 2.5) + am * pow(SPECTRUM_CM / c, 2.5));
}
