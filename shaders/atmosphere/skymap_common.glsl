// Layout of the sky maps and the sea-level irradiance table, shared by their precomputation
// (atmosphere/precompute.comp) and their lookup (atmosphere/skymap.glsl). Mirrored in
// src/render/Atmosphere.hpp. In the twins' subset (common/types.glsl): ocean/lighting.glsl's C++
// twin compiles it.
#include "common/types.glsl"

// The maps cover the stereographic square u in [-EXTENT, EXTENT]^2 (the horizon is the unit
// circle). Below the horizon, as in the sky-map shader of Bruneton's ocean lighting demo (2010)
// and Proland 4.0's ocean: a thin band |u|² <= SKYMAP_HORIZON_BAND holds the horizon's radiance
// (so that bilinear filtering does not pull the horizon's value inwards), and beyond it the
// texels hold the light reflected by waves from below the horizon, approximated by "average
// Fresnel x average sky radiance" = SEA_MEAN_FRESNEL * E_sky / pi (skyMapBelowHorizon). Rough
// seas at grazing angles reflect facets that see the sea, not the horizon's bright sky.
const Number SKYMAP_EXTENT = 1.1;
const Number SKYMAP_HORIZON_BAND = 1.02;  // |u|² of the band's outer edge
// The radial sums' reach in |u| (atmosphere/skymap_radial.comp): past the horizon's band by more
// than half a texel of the coarsest level read (skymap.glsl: 32 texels along it, 0.4 in u), so
// the sums stand still at the table's edge and clamping there loses nothing.
const Number SKY_RADIAL_MAX_RHO = 1.6;
const Number SEA_MEAN_FRESNEL = 0.17;     // Bruneton's demo / Proland: avgFresnel
// Layer k of L holds the Sun at zenith angle k / (L - 1) * SKYMAP_MAX_ZENITH (radians, 105°;
// render::Atmosphere::kSkyMapMaxZenithRad on the CPU, which blends the frame layer).
const Number SKYMAP_MAX_ZENITH = 1.8325957;

Number skyMapLayerZenith(int layer, int layers) {
  return Number(layer) / Number(layers - 1) * SKYMAP_MAX_ZENITH;
}
// Entry k of N of the irradiance table holds the Sun at zenith angle k / (N - 1) * pi.
Number skyIrradianceZenith(int entry, int entries) {
  return Number(entry) / Number(entries - 1) * 3.14159265358979;
}

// Radiance stored below the horizon: SEA_MEAN_FRESNEL * E_sky / pi, E_sky the sky's irradiance of
// a horizontal surface at sea level (same units as the maps' radiance).
vec3 skyMapBelowHorizon(vec3 skyIrradianceHorizontal) {
  return SEA_MEAN_FRESNEL / 3.14159265358979 * skyIrradianceHorizontal;
}
// Whether texture coordinates uv in [0, 1]^2 of a sky map lie beyond the horizon band.
bool skyMapIsBelowHorizon(vec2 uv) {
  vec2 u = (uv * 2.0 - 1.0) * SKYMAP_EXTENT;
  return dot(u, u) > SKYMAP_HORIZON_BAND;
}

// Unit direction (local frame, z up) of texture coordinates uv in [0, 1]^2 of a sky map (on the
// horizon, in its azimuth, for the horizon band and beyond).
vec3 skyMapDirection(vec2 uv) {
  vec2 u = (uv * 2.0 - 1.0) * SKYMAP_EXTENT;
  Number s = dot(u, u);
  vec3 dir = vec3(2.0 * u, 1.0 - s) / (1.0 + s);
  if (dir.z < 0.0) dir = vec3(normalize(u), 0.0);
  return dir;
}
