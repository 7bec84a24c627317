#version 450 core
// Sea-surface shading of the projected grid, exactly Algorithm 5.1 of Bruneton et al. 2010:
// per-pixel normal from the waves resolved at the pixel's footprint, the rest of the slope
// variance in the Ross BRDF (Sun), the filtered sky reflection through the effective Fresnel,
// and the refracted light L_sea (1 - F̄).
#include "common/types.glsl"
#include "geo/ellipsoid.glsl"
#include "ocean/waves.glsl"
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"
#include "ocean/sky_simple.glsl"

in vec2 vOceanXY;
in vec3 vRelative;
out vec4 fragRadiance;

uniform mat3 uEcefToOcean;
uniform vec3 uWindTx;         // unit tangent along the wind, ocean frame
uniform vec2 uTotalVariance;  // (sigma_up², sigma_cross²) of the whole sea at this wind

void main() {
  vec3 relOcean = uEcefToOcean * vRelative;
  float dist = length(vRelative);
  vec3 v = -relOcean / dist;  // to the eye, ocean frame
  // Pixel footprint from the screen-space derivatives of the undisplaced position.
  float footprint = max(length(dFdx(vOceanXY)), length(dFdy(vOceanXY)));
  OceanNormal on = oceanNormal(vOceanXY, max(footprint, 1e-4));
  vec3 n = on.normal;
  // Back-facing normals seen from grazing angles: reflect about the view plane (§5.1).
  float nv = dot(n, v);
  if (nv < 0.0) n = normalize(n - 2.0 * nv * v);
  vec3 tx = normalize(uWindTx - dot(uWindTx, n) * n);
  vec3 ty = cross(n, tx);
  // Unresolved slope variance: total minus what the normals already show (Eq. 4, w_r = 1 - w_n).
  vec2 sigma2 = max(uTotalVariance - on.resolvedVariance, vec2(2e-5));
  vec3 radiance = oceanRadiance(v, n, tx, ty, sigma2, relOcean);
  fragRadiance = vec4(radiance, 1.0);
}
