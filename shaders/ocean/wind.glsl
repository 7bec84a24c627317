// Locally varying wind (data layers): the 10 m wind over the globe and the per-wind tables of
// the wave model, so the sea's roughness, glint and wave heights follow the local wind.
//   uWind: the layer stack rasterised to a global lat/lon texture (RG = eastward, northward
//   m/s; columns from -180°, rows from -90°, cell centres), repeating in longitude.
//   uOceanTable: column s = wind speed s * uOceanTableStep m/s; row 0 = total slope variance
//   (up, cross) at that wind; row 1 + i = amplitude of wave i (m) at that wind.
#include "common/constants.glsl"
layout(binding = 1) uniform sampler2D uWind;
layout(binding = 10) uniform sampler2D uOceanTable;
uniform int uLocalWind;          // 1: read the wind from uWind; 0: the constant uniforms below
uniform float uOceanTableStep;   // m/s per column
uniform vec2 uConstantWind;      // (speed m/s, azimuth rad clockwise from north) when uLocalWind = 0

// Local wind (speed m/s, azimuth radians clockwise from north, the direction it blows towards)
// at geodetic (latitude, longitude) in radians.
vec2 localWind(vec2 latLon) {
  if (uLocalWind == 0) return uConstantWind;
  vec2 uv = vec2(latLon.y / (2.0 * 3.14159265358979) + 0.5, latLon.x / 3.14159265358979 + 0.5);
  vec2 w = texture(uWind, uv).rg;
  return vec2(length(w), atan2Safe(w.x, w.y));
}

// Continuous column coordinate of a wind speed in uOceanTable.
float oceanTableColumn(float speed) {
  float last = float(textureSize(uOceanTable, 0).x - 1);
  return clamp(speed / uOceanTableStep, 0.0, last);
}

// Total slope variance (up, cross) of the sea at a wind speed (linear between table columns).
vec2 windSlopeVariance(float speed) {
  float c = oceanTableColumn(speed);
  int c0 = int(floor(c));
  int c1 = min(c0 + 1, textureSize(uOceanTable, 0).x - 1);
  return mix(texelFetch(uOceanTable, ivec2(c0, 0), 0).rg, texelFetch(uOceanTable, ivec2(c1, 0), 0).rg,
             c - float(c0));
}

// Amplitude of wave i at a wind speed, m.
float waveAmplitudeAt(int i, float speed) {
  float c = oceanTableColumn(speed);
  int c0 = int(floor(c));
  int c1 = min(c0 + 1, textureSize(uOceanTable, 0).x - 1);
  return mix(texelFetch(uOceanTable, ivec2(c0, i + 1), 0).r, texelFetch(uOceanTable, ivec2(c1, i + 1), 0).r,
             c - float(c0));
}
