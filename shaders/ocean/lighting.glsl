// Light arriving at the sea and its reflection (Algorithm 5.1, Bruneton 2010). Everything in
// the ocean frame (x east, y north, z up); radiance in units of the Sun's irradiance.
//
// The sky is read from a stereographic sky map with textureGrad, the lookup footprint set by
// the unresolved slopes (§5.2): U(zeta) maps a facet slope to the sky map coordinate of its
// mirror direction, and the gradients 2 sigma dU/dzeta make the GPU's mip selection integrate
// the sky over the slope distribution.

uniform vec3 uSunDirOcean;     // unit, towards the Sun
uniform vec3 uSunIrradiance;   // Sun irradiance at sea level, after the atmosphere
uniform vec3 uSkyIrradiance;   // sky irradiance on a horizontal sea
uniform vec3 uSeaColor;        // upwelling radiance per unit irradiance (sr^-1)
const float SUN_SIGMA2_MIN = 2e-5;  // slope variance of the Sun's disc (radius 0.27°)

vec3 oceanSkyMap(vec2 u, vec2 dudx, vec2 dudy);  // provided by the pass (sky maps)

vec3 oceanRadiance(vec3 v, vec3 n, vec3 tx, vec3 ty, vec2 sigma2, vec3 relOcean) {
  vec3 l = uSunDirOcean;
  // Sun: Ross BRDF, variance clamped so a flat sea still shows the Sun's disc.
  vec3 sun = uSunIrradiance * rossSun(v, l, n, tx, ty, max(sigma2, vec2(SUN_SIGMA2_MIN)));
  // Sky: filtered reflection (Eqs. 9-10).
  float sigmaV = sqrt(azimuthVariance(v, tx, ty, sigma2));
  float fbar = effectiveFresnel(dot(v, n), sigmaV);
  const float eps = 1e-3;
  vec2 u0 = stereographic(reflectedBySlope(v, n, tx, ty, vec2(0.0)));
  vec2 ux = stereographic(reflectedBySlope(v, n, tx, ty, vec2(eps, 0.0)));
  vec2 uy = stereographic(reflectedBySlope(v, n, tx, ty, vec2(0.0, eps)));
  vec2 sigma = sqrt(sigma2);
  vec3 sky = fbar * oceanSkyMap(u0, 2.0 * sigma.x * (ux - u0) / eps, 2.0 * sigma.y * (uy - u0) / eps);
  // Refracted light from below: L_sea (1 - F̄) (§5.3).
  vec3 sea = uSeaColor * (uSunIrradiance * max(l.z, 0.0) + uSkyIrradiance) * (1.0 - fbar);
  return sun + sky + sea;
}
