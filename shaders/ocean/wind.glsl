// Locally varying wind (data layers): the 10 m wind over the globe, so the sea's waves, roughness,
// glint and whitecaps follow the local wind (ocean/patterns.glsl scales and turns the waves).
//   uWind: the layer stack rasterised to a global lat/lon texture (RG = eastward, northward
//   m/s; columns from -180°, rows from -90°, cell centres), repeating in longitude.
#include "common/constants.glsl"
//   It is the only wind the shaders see: without data layers it is one cell holding the
//   constant wind (render/WindTextures.hpp).
layout(binding = OG_UNIT_WIND) uniform sampler2D uWind;

// localWind: the local wind (speed m/s, azimuth radians clockwise from north, the direction it
// blows towards) at geodetic (latitude, longitude) in radians; windAzimuthSinCos: (sin, cos) of
// the azimuth of a wind localWind gave (with PATTERN_CONSTANT_WIND the constant one's, whatever
// is passed).
#ifdef PATTERN_CONSTANT_WIND
// One constant wind (render/OceanRenderer's programs for it): the texture's one cell as the CPU
// computed it (OceanPatterns::setConstantWind), without a lookup, a length, an atan and the
// azimuth's sine and cosine per point.
uniform vec4 uWindConst;  // (speed m/s, azimuth rad, its sine, its cosine)
vec2 localWind(vec2 latLon) { return uWindConst.xy; }
vec2 windAzimuthSinCos(vec2 wind) { return uWindConst.zw; }
#else
vec2 windAzimuthSinCos(vec2 wind) { return vec2(sin(wind.y), cos(wind.y)); }
vec2 localWind(vec2 latLon) {
  vec2 uv = vec2(latLon.y / (2.0 * PI) + 0.5, latLon.x / PI + 0.5);
  vec2 w = texture(uWind, uv).rg;
  return vec2(length(w), atan2Safe(w.x, w.y));
}
#endif
