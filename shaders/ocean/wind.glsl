// Locally varying wind (data layers): the 10 m wind over the globe, so the sea's waves, roughness,
// glint and whitecaps follow the local wind (ocean/patterns.glsl scales and turns the waves).
//   uWind: the layer stack rasterised to a global lat/lon texture (RG = eastward, northward
//   m/s; columns from -180°, rows from -90°, cell centres), repeating in longitude.
#include "common/constants.glsl"
layout(binding = 1) uniform sampler2D uWind;
uniform int uLocalWind;          // 1: read the wind from uWind; 0: the constant uniforms below
uniform vec2 uConstantWind;      // (speed m/s, azimuth rad clockwise from north) when uLocalWind = 0

// Local wind (speed m/s, azimuth radians clockwise from north, the direction it blows towards)
// at geodetic (latitude, longitude) in radians.
vec2 localWind(vec2 latLon) {
  if (uLocalWind == 0) return uConstantWind;
  vec2 uv = vec2(latLon.y / (2.0 * PI) + 0.5, latLon.x / PI + 0.5);
  vec2 w = texture(uWind, uv).rg;
  return vec2(length(w), atan2Safe(w.x, w.y));
}
