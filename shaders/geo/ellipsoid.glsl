// Ray / WGS84 ellipsoid intersection from the eye, in the eye-relative frame (ECEF axes).
// GLSL twin of og::geo::intersectEllipsoid (src/geo/Camera.cpp). Positions are scaled by
// (1/a, 1/a, 1/b) so the ellipsoid is the unit sphere and the eye sits at uEyeScaled (|.| ~ 1);
// along the ray p(s) = uEyeScaled + s d with d = dir * (1, 1, a/b) and t = a s metres.
// C = |uEyeScaled|² - 1 is tiny near the surface and comes from the CPU in double precision,
// so the near root C / (-B + sqrt(B² - AC)) stays accurate 0.1 m above the sea.
#include "common/constants.glsl"

uniform vec3 uEyeScaled;  // eye ECEF / (a, a, b)
uniform float uEyeC;      // |uEyeScaled|² - 1, computed in double

const vec3 ELLIPSOID_DIR_SCALE = vec3(1.0, 1.0, WGS84_A / WGS84_B);

// Distance in metres along the unit ray `dir` to the ellipsoid, or -1 when it misses.
float intersectEllipsoid(vec3 dir) {
  vec3 d = dir * ELLIPSOID_DIR_SCALE;  // scaled space, in units of a
  float A = dot(d, d);
  float B = dot(uEyeScaled, d);
  float disc = B * B - A * uEyeC;
  if (disc < 0.0 || B >= 0.0) return -1.0;
  return WGS84_A * uEyeC / (-B + sqrt(disc));  // stable near root
}

// Geodetic surface normal (ECEF axes) at the point `t` metres along `dir`.
vec3 ellipsoidNormal(vec3 dir, float t) {
  vec3 p = uEyeScaled + (t / WGS84_A) * dir * ELLIPSOID_DIR_SCALE;  // on the unit sphere
  return normalize(vec3(p.xy, p.z * (WGS84_A / WGS84_B)));
}

// Geodetic latitude and longitude (radians) of a geodetic normal. The latitude by atan, not
// asin: Mesa's asin (llvmpipe) is a polynomial off by up to ~2e-4 rad, a latitude 1.3 km south at
// 36° N, which put the land mask's 15″ coast (460 m) a few cells away from the terrain's
// (whose latitudes come from the CPU); atan is good to ~1e-6 rad there.
vec2 latLonOfNormal(vec3 n) { return vec2(atan(n.z, length(n.xy)), atan2Safe(n.y, n.x)); }
