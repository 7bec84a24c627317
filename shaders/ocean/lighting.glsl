// Light arriving at the sea and its reflection: Algorithm 5.1 of Bruneton et al. 2010. Shared by
// the projected grid (below 20 km) and the globe's sea (above), so the two agree exactly when
// the grid's waves have faded out.
//
// Inputs are in ECEF axes; the lighting is evaluated in the point's own local frame (x east,
// y north, z up along `upE`), where the Sun-zenith-indexed sky maps are defined (§6): each point
// uses the layer of its local Sun zenith, rotated to its local Sun azimuth. Radiance is in units
// of the Sun's irradiance at the top of the atmosphere; aerial perspective is the caller's.
//
// The sky comes from shaders/atmosphere/skymap.glsl (skyMapRadianceStereo, skyIrradiance,
// sunIrradiance); define OCEAN_SIMPLE_SKY before including this file to use a small analytic
// sky instead (tests of the ocean alone).

#include "common/constants.glsl"

#ifdef OCEAN_SIMPLE_SKY
uniform vec3 uSkyZenith;   // radiance at the zenith
uniform vec3 uSkyHorizon;  // radiance at the horizon
vec3 skyMapRadianceStereo(vec2 u, float sunZenith, float sunAzimuth, vec2 dUdx, vec2 dUdy) {
  float q = dot(u, u);
  float z = (1.0 - q) / (1.0 + q);  // inverse stereographic: cos(zenith angle)
  return mix(uSkyHorizon, uSkyZenith, sqrt(clamp(z, 0.0, 1.0))) * clamp(cos(sunZenith) * 4.0, 0.0, 1.0);
}
vec3 skyIrradiance(float sunZenith) { return vec3(0.1, 0.13, 0.18) * clamp(cos(sunZenith) * 2.0, 0.0, 1.0); }
vec3 sunIrradiance(float sunZenith) { return vec3(1.0) * step(0.0, cos(sunZenith)); }
#else
#include "atmosphere/skymap.glsl"
#endif

uniform vec3 uSeaColor;  // upwelling radiance per unit irradiance (sr^-1)
#include "terrain/shallow.glsl"  // shallow water: the sea floor seen through the water
const float SUN_SIGMA2_MIN = 2e-5;  // slope variance of the Sun's disc (radius 0.27°)

// Unit local frame at a point with vertical upE: columns east, north, up (ECEF axes).
mat3 localFrame(vec3 upE) {
  vec3 east = cross(vec3(0.0, 0.0, 1.0), upE);
  east = dot(east, east) > 1e-12 ? normalize(east) : vec3(0.0, 1.0, 0.0);  // at the poles
  return mat3(east, cross(upE, east), upE);
}

// The view, the Sun and the surface in the point's local frame, and the light arriving there.
struct SeaPoint {
  vec3 v, n, l, tx, ty;  // to the eye, normal, to the Sun, tangents along/across the wind
  float sunZenith, sunAzimuth;
  vec3 eSun, eSky;       // Sun and sky irradiance at sea level for this Sun zenith
};

// Fraction of the Sun's disc seen from the sea point being shaded (the terrain's shadows:
// terrain/shadow.glsl); the grid's shaders set it before shading, elsewhere the Sun is open.
float gSeaSunVisibility = 1.0;

SeaPoint seaPoint(vec3 vE, vec3 nE, vec3 windE, vec3 upE, vec3 sunE) {
  mat3 toLocal = transpose(localFrame(upE));
  SeaPoint p;
  p.v = toLocal * vE;
  p.n = toLocal * nE;
  p.l = toLocal * sunE;
  vec3 w = toLocal * windE;
  p.tx = normalize(w - dot(w, p.n) * p.n + vec3(1e-6, 0.0, 0.0));
  p.ty = cross(p.n, p.tx);
  p.sunZenith = acos(clamp(p.l.z, -1.0, 1.0));
  p.sunAzimuth = atan2Safe(p.l.y, p.l.x);
  p.eSun = sunIrradiance(p.sunZenith) * gSeaSunVisibility;
  p.eSky = skyIrradiance(p.sunZenith);
  return p;
}

// The Sun through the Ross BRDF, variance clamped so a flat sea still shows the Sun's disc
// (Eq. 6).
vec3 seaSunGlint(SeaPoint p, vec2 sigma2) {
  return p.eSun * rossSun(p.v, p.l, p.n, p.tx, p.ty, max(sigma2, vec2(SUN_SIGMA2_MIN)));
}

// Light refracted from below the surface, L_sea (1 - F) (§5.3), F the Fresnel factor used for
// the reflected sky.
vec3 seaRefracted(SeaPoint p, vec3 upE, float fresnel) {
  return shallowSeaColor(uSeaColor, seaFloorDepthM(upE)) * (p.eSun * max(p.l.z, 0.0) + p.eSky) *
         (1.0 - fresnel);
}

// The clear sea at a shading point (Algorithm 5.1): sigma2 the unresolved slope variances
// along/across the wind, upE the ellipsoid normal (ECEF axes).
vec3 seaRadianceAt(SeaPoint p, vec2 sigma2, vec3 upE) {
  // Sky: filtered reflection (Eqs. 9-10): the gradient lookup integrates the sky map over the
  // unresolved slopes' footprint, U(zeta) the stereographic coordinate of a facet's mirror ray.
  float sigmaV = sqrt(azimuthVariance(p.v, p.tx, p.ty, sigma2));
  float fbar = effectiveFresnel(dot(p.v, p.n), sigmaV);
  const float eps = 1e-3;
  vec2 u0 = stereographic(reflectedBySlope(p.v, p.n, p.tx, p.ty, vec2(0.0)));
  vec2 ux = stereographic(reflectedBySlope(p.v, p.n, p.tx, p.ty, vec2(eps, 0.0)));
  vec2 uy = stereographic(reflectedBySlope(p.v, p.n, p.tx, p.ty, vec2(0.0, eps)));
  vec2 sigma = sqrt(sigma2);
  vec3 sky = fbar * skyMapRadianceStereo(u0, p.sunZenith, p.sunAzimuth,
                                         2.0 * sigma.x * (ux - u0) / eps, 2.0 * sigma.y * (uy - u0) / eps);
  return seaSunGlint(p, sigma2) + sky + seaRefracted(p, upE, fbar);
}

// vE: to the eye; nE: mean (resolved) normal; windE: the wind's direction (any vector with a
// horizontal component along it); sigma2: unresolved slope variances along/across the wind;
// upE: the ellipsoid normal at the point; sunE: towards the Sun. All unit, ECEF axes.
vec3 seaRadiance(vec3 vE, vec3 nE, vec3 windE, vec2 sigma2, vec3 upE, vec3 sunE) {
  return seaRadianceAt(seaPoint(vE, nE, windE, upE, sunE), sigma2, upE);
}

// Whitecap foam (Dupuy & Bruneton 2012 Eq. 2): a Lambertian surface of reflectance 0.4
// (Koepke 1984) over the fraction `coverage` of the footprint, the clear sea over the rest:
// R = W R_foam + (1 - W) R_sea.
const float FOAM_REFLECTANCE = 0.4;
vec3 seaRadianceWithFoam(vec3 vE, vec3 nE, vec3 windE, vec2 sigma2, vec3 upE, vec3 sunE,
                         float coverage) {
  SeaPoint p = seaPoint(vE, nE, windE, upE, sunE);
  vec3 clear = seaRadianceAt(p, sigma2, upE);
  vec3 foam = FOAM_REFLECTANCE / PI * (p.eSun * max(p.l.z, 0.0) + p.eSky);
  return mix(clear, foam, coverage);
}

#ifdef OCEAN_VALIDATION_REFERENCE
// The brute-force reference of the validation (paper §7.2, docs/validation.md): each sample is a
// perfect mirror with its exact facet normal n (every wave), the pixel's average coming from
// supersampling, not from a slope distribution. Sky: a point lookup in the mirror direction with
// the exact per-facet Fresnel F(v.n) (no F̄ fit, Eq. 10). The Sun: the Ross lobe of sigma2, the
// spectrum's tail below the shortest wave, which no wave carries; it also lets a few dozen
// samples per pixel find the Sun's 0.27° disc.
vec3 seaRadianceMirror(vec3 vE, vec3 nE, vec3 windE, vec2 sigma2, vec3 upE, vec3 sunE) {
  SeaPoint p = seaPoint(vE, nE, windE, upE, sunE);
  float f = fresnelSchlick(dot(p.v, p.n));
  vec3 sky = f * skyMapRadianceStereo(stereographic(reflect(-p.v, p.n)), p.sunZenith, p.sunAzimuth,
                                      vec2(0.0), vec2(0.0));
  return seaSunGlint(p, sigma2) + sky + seaRefracted(p, upE, f);
}
#endif
