// Layout of the sky maps and the sea-level irradiance table, shared by their precomputation
// (atmosphere/precompute.comp) and their lookup (atmosphere/skymap.glsl). Mirrored in
// src/render/Atmosphere.hpp.

// The maps cover the stereographic square u in [-EXTENT, EXTENT]^2 (the horizon is the unit
// circle); texels beyond the horizon hold the horizon's radiance in their azimuth.
const float SKYMAP_EXTENT = 1.1;
// Layer k of L holds the Sun at zenith angle k / (L - 1) * SKYMAP_MAX_ZENITH (radians, 105°).
const float SKYMAP_MAX_ZENITH = 1.8325957;

float skyMapLayerZenith(int layer, int layers) {
  return float(layer) / float(layers - 1) * SKYMAP_MAX_ZENITH;
}
// Entry k of N of the irradiance table holds the Sun at zenith angle k / (N - 1) * pi.
float skyIrradianceZenith(int entry, int entries) {
  return float(entry) / float(entries - 1) * 3.14159265358979;
}

// Unit direction (local frame, z up) of texture coordinates uv in [0, 1]^2 of a sky map.
vec3 skyMapDirection(vec2 uv) {
  vec2 u = (uv * 2.0 - 1.0) * SKYMAP_EXTENT;
  float s = dot(u, u);
  vec3 dir = vec3(2.0 * u, 1.0 - s) / (1.0 + s);
  if (dir.z < 0.0) dir = vec3(normalize(u), 0.0);
  return dir;
}
