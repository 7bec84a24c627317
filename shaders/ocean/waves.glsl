// The wave set of Bruneton et al. 2010 (seed 000, §4): a sum of trochoids in the local ocean
// frame (x east, y north, z up, metres), filtered by the projected size of a grid cell
// (geometry) or of a pixel (normals): waves too short for the footprint fade out and move into
// the BRDF's slope variance. Waves are sorted longest first with wavelengths in geometric
// progression, so the waves with non-zero weight are a prefix whose length follows from the
// footprint: loops never visit waves with zero weight (cost falls as the camera rises).

struct OceanWave {
  vec4 kPhase;  // (k_east, k_north) rad/m, amplitude h (m), phase at x = 0 (rad)
  vec4 extra;   // wavelength (m), |k|, (k.tx)²/|k|², (k.ty)²/|k|² (wind-frame direction split)
};
layout(std430, binding = 0) readonly buffer OceanWaves { OceanWave uWaves[]; };
uniform int uWaveCount;
uniform float uWaveLambdaMax;   // wavelength of uWaves[0], m
uniform float uWaveLogRatio;    // log(lambda[i+1] / lambda[i]) < 0
uniform float uWaveAmplitude;   // global amplitude scale (1 = the spectrum; fades waves out)

const float OCEAN_NMIN = 1.0;   // filter: weight 0 below N_min footprints per wavelength
const float OCEAN_NMAX = 2.5;   // weight 1 above N_max

// w(a, b, x) = 3x̄² - 2x̄³ with x̄ = clamp((x - a)/(b - a), 0, 1) (§4.1).
// Validation variants (`oceanglobe validate`, docs/validation.md; default: neither defined):
// OCEAN_VALIDATION_REFERENCE takes every wave into the normal whatever the footprint (the
// brute-force reference supersamples instead of filtering; see oceanNormal);
// OCEAN_VALIDATION_CONSTANT resolves no wave at all (flat sea, the whole slope variance in the
// BRDF: the "BRDF only" model).
float oceanFilterWeight(float lambdaOverFootprint) {
  float x = clamp((lambdaOverFootprint - OCEAN_NMIN) / (OCEAN_NMAX - OCEAN_NMIN), 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// Number of leading waves with lambda > N_min * footprint.
int oceanWaveCountFor(float footprint) {
#ifdef OCEAN_VALIDATION_CONSTANT
  return 0;
#endif
  float f = max(footprint * OCEAN_NMIN, 1e-6);
  float n = floor(log(f / uWaveLambdaMax) / uWaveLogRatio) + 1.0;
  return int(clamp(n, 0.0, float(uWaveCount)));
}

// Amplitude of wave i where the local wind speed is `speed` (m/s): the wave set's own amplitude
// under a uniform wind, else the table's, which scales each wave by the local spectrum.
float oceanWaveAmplitude(int i, float speed) {
  return uLocalWind == 1 ? waveAmplitudeAt(i, speed) : uWaves[i].kPhase.z;
}

// Displacement of the sea surface at xy (Eq. 2): sum of w_p,i t_i with the trochoid
// t_i = [k̂ h sin(theta); h cos(theta)], theta = phase - k.x.
vec3 oceanDisplacement(vec2 xy, float cellFootprint, float windSpeed) {
  vec3 d = vec3(0.0);
  int n = oceanWaveCountFor(cellFootprint);
  for (int i = 0; i < n; ++i) {
    OceanWave w = uWaves[i];
    float weight = oceanFilterWeight(w.extra.x / cellFootprint) * uWaveAmplitude;
    float theta = w.kPhase.w - dot(w.kPhase.xy, xy);
    float h = oceanWaveAmplitude(i, windSpeed) * weight;
    d += vec3(w.kPhase.xy / w.extra.y * (h * sin(theta)), h * cos(theta));
  }
  return d;
}

// Normal of the displaced surface from dp/dx x dp/dy with w_n weights (Eq. 3), plus the
// slope variance those resolved waves carry, in the wind frame (Eq. 4 with w = w_n).
struct OceanNormal {
  vec3 normal;
  vec2 resolvedVariance;
};
OceanNormal oceanNormal(vec2 xy, float pixelFootprint, float windSpeed) {
  vec3 dpdx = vec3(1.0, 0.0, 0.0);
  vec3 dpdy = vec3(0.0, 1.0, 0.0);
  vec2 resolved = vec2(0.0);
#ifdef OCEAN_VALIDATION_REFERENCE
  int n = uWaveCount;  // reference: all waves, weights 1 (its geometry stays filtered by its fine grid)
#else
  int n = oceanWaveCountFor(pixelFootprint);
#endif
  for (int i = 0; i < n; ++i) {
    OceanWave w = uWaves[i];
#ifdef OCEAN_VALIDATION_REFERENCE
    float weight = uWaveAmplitude;
#else
    float weight = oceanFilterWeight(w.extra.x / pixelFootprint) * uWaveAmplitude;
#endif
    float theta = w.kPhase.w - dot(w.kPhase.xy, xy);
    float h = oceanWaveAmplitude(i, windSpeed) * weight;
    vec2 khat = w.kPhase.xy / w.extra.y;
    float c = cos(theta), s = sin(theta);
    // d theta / dx = -k_x: derivatives of [k̂ h sin; h cos].
    dpdx += vec3(-khat * (h * c * w.kPhase.x), h * s * w.kPhase.x);
    dpdy += vec3(-khat * (h * c * w.kPhase.y), h * s * w.kPhase.y);
    float kh = min(w.extra.y * h, 0.999);
    resolved += w.extra.zw * (1.0 - sqrt(1.0 - kh * kh));
  }
  OceanNormal r;
  r.normal = normalize(cross(dpdx, dpdy));
  r.resolvedVariance = resolved;
  return r;
}
