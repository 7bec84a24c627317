#version 450 core
// Sea-surface shading of the projected grid: per-pixel normal from the waves resolved at the
// pixel's footprint (Eq. 3, with the back-facing fix), the rest of the slope variance in the
// BRDF (Eq. 4, w_r = 1 - w_n), then Algorithm 5.1 (ocean/lighting.glsl), with the globe's
// aerial perspective on top.
#include "common/types.glsl"
#include "geo/ellipsoid.glsl"
#include "ocean/wind.glsl"
#include "ocean/waves.glsl"
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"
#include "render/elevation.glsl"

in vec2 vOceanXY;
in vec3 vRelative;
out vec4 fragRadiance;

uniform mat3 uEcefToOcean;
uniform vec3 uSunDirEcef;

vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance);  // aerial perspective (the pass)

void main() {
  mat3 oceanToEcef = transpose(uEcefToOcean);
  float dist = length(vRelative);
  vec3 dir = vRelative / dist;
  vec3 v = -dir;
  // Pixel footprint from the screen-space derivatives of the undisplaced position (taken
  // before any discard, while the whole quad is alive).
  float footprint = max(length(dFdx(vOceanXY)), length(dFdy(vOceanXY)));
  vec3 frameUp = oceanToEcef[2];
  vec3 up = ellipsoidNormal(dir, dist);
  vec2 latLon = latLonOfNormal(up);
  // No sea over land: the elevation layer decides where the coast is.
  if (uElevationSize.x > 0.0 && elevationAt(latLon) > 0.0) discard;
  vec2 wind = localWind(latLon);  // speed, azimuth
  OceanNormal on = oceanNormal(vOceanXY, max(footprint, 1e-4), wind.x);
  // Waves live in the frame's tangent plane; tilt their normal onto the ellipsoid's curvature
  // so that with the waves faded out the normal is exactly the ellipsoid's (as in orbit).
  vec3 nFrame = oceanToEcef * on.normal;
  vec3 n = normalize(nFrame + (up - frameUp) * dot(nFrame, frameUp));
  // Back-facing normals seen at grazing angles: reflect about the view plane (§5.1).
  float nv = dot(n, v);
  if (nv < 0.0) n = normalize(n - 2.0 * nv * v);
  // Unresolved slope variance: the local wind's total minus what the normals already show.
  // (The resolved part is split along/across the reference wind the waves were built for.)
  vec2 sigma2 = max(windSlopeVariance(wind.x) - on.resolvedVariance, vec2(2e-5));
  mat3 local = localFrame(up);
  vec3 windDir = sin(wind.y) * local[0] + cos(wind.y) * local[1];
  vec3 radiance = seaRadiance(v, n, windDir, sigma2, up, uSunDirEcef);
  fragRadiance = vec4(oceanSurfaceRadiance(vRelative, radiance), 1.0);
}

#ifdef OCEAN_SIMPLE_SKY
vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance) { return radiance; }
#else
#include "render/aerial.glsl"
vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance) {
  float t = length(relative);
  return withAerialPerspective(radiance, relative / t, t, uSunDirEcef);
}
#endif
