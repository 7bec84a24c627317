// Shared numeric constants: named once in C++ (src/gl/ShaderContract.hpp from src/geo/Wgs84.hpp)
// and injected into every shader as #defines (C++ twins define them from the same names).
#include "common/types.glsl"
const Number PI = OG_PI;
const Number WGS84_A = OG_WGS84_A;  // semi-major axis, m
const Number WGS84_B = OG_WGS84_B;  // semi-minor axis, m

// atan(y, x) is undefined at (0, 0) in GLSL (llvmpipe returns NaN): directions straight up,
// points exactly at a pole and calm winds all land there. Any angle will do at that point.
Number atan2Safe(Number y, Number x) { return (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x); }

// The azimuth of a unit direction `d` in a local frame (x east, y north, z up) as (cos, sin),
// counter-clockwise from +x: what the sky maps' lookup turns by (atmosphere/skymap.glsl's
// skyMapRadianceStereo), without atan2Safe's angle and its cos and sin per pixel. (1, 0) straight
// up or down, where atan2Safe gives 0.
vec2 sunAzimuthCosSin(vec3 d) {
  Number r2 = d.x * d.x + d.y * d.y;
  return r2 > 1e-24 ? vec2(d.x, d.y) / sqrt(r2) : vec2(1.0, 0.0);
}
