// Where the sea is: the elevation layer decides (at or below 0 m). Both sea shaders test each
// of the pixel's samples (interpolateAtSample, no per-sample shading) and keep only the sea's
// in gl_SampleMask, so under multisampling the shoreline's land side is anti-aliased too.
#include "geo/ellipsoid.glsl"
#include "render/elevation.glsl"

// Whether the point at camera-relative `relative` (on or near the ellipsoid) is over the sea,
// its coast as a footprint of `footprintRad` (radians of arc) resolves it: the same coast as
// the terrain's per-pixel test and the globe's.
bool seaAt(vec3 relative, float footprintRad) {
  if (uElevationSize.x <= 0.0) return true;
  float d = length(relative);
  return elevationAt(latLonOfNormal(ellipsoidNormal(relative / d, d)), footprintRad) <= 0.0;
}

// No sea over land, sample by sample: keeps the pixel's sea samples in gl_SampleMask and drops
// the fragment when it has none. A macro because interpolateAtSample takes the shader's input
// variable itself (`RELATIVE`, the camera-relative position), not a copy.
// With no land in view (uCoastTest = 0: every terrain tile deep under the sea) the loop runs
// no trip; the projected grid's program compiles the test out instead (SEA_NO_COAST_TEST, a
// variant of render/OceanRenderer): llvmpipe runs a loop's first trip, masked, even when no
// pixel enters it.
#ifdef SEA_NO_COAST_TEST
#define KEEP_SEA_SAMPLES(RELATIVE) {}
#else
uniform int uCoastTest;
#define KEEP_SEA_SAMPLES(RELATIVE)                                     \
  {                                                                    \
    int seaSamples = uCoastTest == 1 ? 0 : (1 << gl_NumSamples) - 1;   \
    vec3 viewDir = normalize(RELATIVE);                                \
    float footprintRad = coastFootprintRad(length(RELATIVE), max(length(dFdx(viewDir)), length(dFdy(viewDir))), \
        -dot(ellipsoidNormal(viewDir, length(RELATIVE)), viewDir));    \
    for (int i = 0; i < gl_NumSamples * uCoastTest; ++i)               \
      if (seaAt(interpolateAtSample(RELATIVE, i), footprintRad)) seaSamples |= 1 << i; \
    if (seaSamples == 0) discard;                                      \
    gl_SampleMask[0] = seaSamples;                                     \
  }
#endif

// The shore: a wave breaks once its height reaches ~0.78 of the water's depth (McCowan 1894's
// breaker index), so over shoaling water the waves' displacement is scaled down to what that
// depth holds, reaching 0 at the shoreline: the sea surface meets the land at sea level and
// waves never cross onto it. `waveHeightM`: the sea's significant wave height there;
// `footprintRad`: the grid cell's size (radians of arc), which coast it resolves.
const float BREAKER_INDEX = 0.78;
float shoreWaveFactor(vec2 latLon, float waveHeightM, float footprintRad) {
  if (uElevationSize.x <= 0.0) return 1.0;
  float depthM = max(-elevationAt(latLon, footprintRad), 0.0);
  return clamp(BREAKER_INDEX * depthM / max(waveHeightM, 1e-3), 0.0, 1.0);
}

// Significant wave height of a fully developed sea under a 10 m wind of `speedMs`, m
// (Pierson & Moskowitz 1964: H_s = 0.21 U_19.5² / g, U_19.5 ~ 1.075 U_10).
float seaStateWaveHeightM(float speedMs) { return 0.0247 * speedMs * speedMs; }
