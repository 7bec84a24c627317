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
//
// Written in the twins' subset (common/types.glsl): src/ocean/Lighting.cpp compiles this file as
// C++ in double precision with the analytic sky (ocean::lighting, its tests).

#include "common/constants.glsl"
// Outside the #ifdef: files are included once, before the preprocessor runs.
#include "atmosphere/skymap_common.glsl"

#ifdef OCEAN_SIMPLE_SKY
uniform vec3 uSkyZenith;   // radiance at the zenith
uniform vec3 uSkyHorizon;  // radiance at the horizon
vec3 skyIrradiance(Number sunZenith) { return vec3(0.1, 0.13, 0.18) * clamp(cos(sunZenith) * 2.0, 0.0, 1.0); }
vec3 skyMapRadianceStereo(vec2 u, Number sunZenith, vec2 sunAzimuthCS, vec2 dUdx, vec2 dUdy) {
  Number q = dot(u, u);
  Number z = (1.0 - q) / (1.0 + q);  // inverse stereographic: cos(zenith angle)
  vec3 sky = mix(uSkyHorizon, uSkyZenith, sqrt(clamp(z, 0.0, 1.0))) * clamp(cos(sunZenith) * 4.0, 0.0, 1.0);
  // Below the horizon as the maps (skymap_common.glsl), the step filtered over the footprint
  // (the maps' textureGrad does that): the share beyond the band of a Gaussian footprint whose
  // axes dUdx, dUdy are 2 sigma, sigma_r its spread across the horizon (Phi as a linear ramp of
  // the same slope at 0).
  vec2 radial = u / max(sqrt(q), 1e-6);
  Number sigmaR = 0.5 * length(vec2(dot(dUdx, radial), dot(dUdy, radial)));
  Number below = clamp(0.5 + (sqrt(q) - sqrt(SKYMAP_HORIZON_BAND)) / max(2.5 * sigmaR, 1e-4), 0.0, 1.0);
  return mix(sky, skyMapBelowHorizon(skyIrradiance(sunZenith)), below);
}
vec3 sunIrradiance(Number sunZenith) { return vec3(1.0) * step(0.0, cos(sunZenith)); }
#else
#include "atmosphere/skymap.glsl"
#endif

uniform vec3 uSeaColor;  // upwelling radiance per unit irradiance (sr^-1)
#ifndef OG_GLSL_SHIM
#include "terrain/shallow.glsl"  // shallow water: the sea floor seen through the water
#else
// The C++ twin (src/ocean/Lighting.cpp) lights the open sea: shallow.glsl's behaviour without an
// elevation layer or a prepared water column (the water's own twin is ocean/WaterOptics).
Number seaFloorDepthM(vec3) { return 1e4; }
vec3 shallowSeaColor(vec3 deepColor, Number) { return deepColor; }
#endif
// The Sun's apparent angular radius, rad (0.267°, atmosphere::Parameters::sunAngularRadiusRad):
// its disc is convolved into the glint (sunDiscSlopeCovariance, ocean/brdf.glsl), so a glassy
// sea shows the disc, not a lobe of an arbitrary variance floor.
const Number SUN_ANGULAR_RADIUS_RAD = 0.004675;
// Smallest slope variance handed to the BRDF's divisions (a mirror, for the sky's lookups).
const Number SEA_SIGMA2_MIN = 1e-9;

// Unit local frame at a point with vertical upE: columns east, north, up (ECEF axes).
mat3 localFrame(vec3 upE) {
  vec3 east = cross(vec3(0.0, 0.0, 1.0), upE);
  east = dot(east, east) > 1e-12 ? normalize(east) : vec3(0.0, 1.0, 0.0);  // at the poles
  return mat3(east, cross(upE, east), upE);
}

// The horizontal unit vector (ECEF axes) towards the azimuth whose (sin, cos) is
// `azimuthSinCos` (clockwise from north) at a point of vertical upE: a wind's direction.
vec3 windDirectionEcef(vec2 azimuthSinCos, vec3 upE) {
  mat3 local = localFrame(upE);
  return azimuthSinCos.x * local[0] + azimuthSinCos.y * local[1];
}

// The view, the Sun and the surface in the point's local frame, and the light arriving there.
struct SeaPoint {
  vec3 v, n, l, tx, ty;  // to the eye, normal, to the Sun, tangents along/across the wind
  Number sunZenith;
  vec2 sunAzimuthCS;     // (cos, sin) of the Sun's azimuth (common/constants.glsl)
  vec3 eSun, eSky;       // Sun and sky irradiance at sea level for this Sun zenith
};

#ifdef OCEAN_LIGHTING_TERMS
// Weights of the terms (Sun, sky, refracted, whitecaps): 1 each, but `validate` renders them
// one at a time (paper §7.2 compares them separately).
uniform vec4 uLightingTerms;
#else
const vec4 uLightingTerms = vec4(1.0);
#endif

// Fraction of the Sun's disc seen from the sea point being shaded (the terrain's shadows:
// terrain/shadow.glsl); the grid's shaders set it before shading, elsewhere the Sun is open.
Number gSeaSunVisibility = 1.0;

// Sets p's normal n and its tangents along and across the wind w (both in p's local frame).
void setSeaNormal(INOUT(SeaPoint) p, vec3 n, vec3 w) {
  p.n = n;
  p.tx = normalize(w - dot(w, n) * n + vec3(1e-6, 0.0, 0.0));
  p.ty = cross(p.n, p.tx);
}

SeaPoint seaPoint(vec3 vE, vec3 nE, vec3 windE, vec3 upE, vec3 sunE) {
  mat3 toLocal = transpose(localFrame(upE));
  SeaPoint p;
  p.v = toLocal * vE;
  p.l = toLocal * sunE;
  setSeaNormal(p, toLocal * nE, toLocal * windE);
  p.sunZenith = acos(clamp(p.l.z, -1.0, 1.0));
  p.sunAzimuthCS = sunAzimuthCosSin(p.l);
  p.eSun = sunIrradiance(p.sunZenith) * gSeaSunVisibility;
  p.eSky = skyIrradiance(p.sunZenith);
  return p;
}

// Turns p's tangents (tx, ty) onto the principal axes of the slope covariance cov = (xx, yy, xy)
// given in them, and returns the variances along the new axes (ocean/brdf.glsl).
vec2 alignToSlopeAxes(INOUT(SeaPoint) p, vec3 cov) {
  SlopeFrame f = slopePrincipalAxes(cov);
  vec3 tx = f.axis.x * p.tx + f.axis.y * p.ty;
  p.tx = tx;
  p.ty = cross(p.n, tx);
  return max(f.sigma2, vec2(SEA_SIGMA2_MIN));
}

// The Sun through the Ross BRDF (Eq. 6) of the facets' slope covariance cov (xx, yy, xy in p's
// tx, ty) convolved with the Sun's disc: a flat sea shows the disc's reflection.
vec3 seaSunGlint(SeaPoint p, vec3 cov) {
  cov += sunDiscSlopeCovariance(p.v, p.l, p.tx, p.ty, SUN_ANGULAR_RADIUS_RAD);
  vec2 sigma2 = alignToSlopeAxes(p, cov);
  return p.eSun * rossSun(p.v, p.l, p.n, p.tx, p.ty, sigma2);
}

// Light refracted from below the surface, L_sea (1 - F) (§5.3), F the Fresnel factor used for
// the reflected sky.
vec3 seaRefracted(SeaPoint p, vec3 upE, Number fresnel) {
  return shallowSeaColor(uSeaColor, seaFloorDepthM(upE)) * (p.eSun * max(p.l.z, 0.0) + p.eSky) *
         (1.0 - fresnel);
}

// vE: to the eye; nE: mean (resolved) normal; windE: the wind's direction (any vector with a
// horizontal component along it); cov: unresolved slope covariance (xx, yy, xy) in the frame
// along/across the wind (its principal axes need not be the wind's: the resolved waves taken
// out of it are those of the local wind bins, Bruneton 2010 Eq. 4 with the full matrix);
// upE: the ellipsoid normal at the point; sunE: towards the Sun. All unit, ECEF axes.
vec3 seaRadianceAt(SeaPoint p, vec3 cov, vec3 upE) {
  vec3 glint = seaSunGlint(p, cov);
  vec2 sigma2 = alignToSlopeAxes(p, cov);
  // Sky: filtered reflection (Eqs. 9-10): the gradient lookup integrates the sky map over the
  // unresolved slopes' footprint, U(zeta) the stereographic coordinate of a facet's mirror ray.
  Number sigmaV = sqrt(azimuthVariance(p.v, p.tx, p.ty, sigma2));
  Number fbar = effectiveFresnel(dot(p.v, p.n), sigmaV);
  // The footprint in the view's azimuth (a towards the eye's side, b across) of the visible
  // slopes: along a the moments of visibleSlopeMoments (brdf.glsl), across b the Gaussian's.
  vec2 a = vec2(dot(p.v, p.tx), dot(p.v, p.ty));
  Number sinV = length(a);
  a = sinV > 1e-6 ? a / sinV : vec2(1.0, 0.0);
  vec2 b = vec2(-a.y, a.x);
  Number sigmaB = sqrt(dot(b * b, sigma2));
  vec2 visible = visibleSlopeMoments(max(dot(p.v, p.n), 0.0) / max(sinV * sigmaV, 1e-6));
  vec2 zeta0 = visible.x * sigmaV * a;  // mean < 0: the visible facets lean towards the eye
  const Number eps = 1e-3;
  vec2 u0 = stereographic(reflectedBySlope(p.v, p.n, p.tx, p.ty, zeta0));
  vec2 ua = stereographic(reflectedBySlope(p.v, p.n, p.tx, p.ty, zeta0 + eps * a));
  vec2 ub = stereographic(reflectedBySlope(p.v, p.n, p.tx, p.ty, zeta0 + eps * b));
  vec3 sky = fbar * skyMapRadianceStereo(u0, p.sunZenith, p.sunAzimuthCS,
                                         2.0 * sigmaV * sqrt(visible.y) * (ua - u0) / eps,
                                         2.0 * sigmaB * (ub - u0) / eps);
  return uLightingTerms.x * glint + uLightingTerms.y * sky + uLightingTerms.z * seaRefracted(p, upE, fbar);
}
vec3 seaRadiance(vec3 vE, vec3 nE, vec3 windE, vec3 cov, vec3 upE, vec3 sunE) {
  return seaRadianceAt(seaPoint(vE, nE, windE, upE, sunE), cov, upE);
}
// sigma2: variances along/across the wind, no cross term.
vec3 seaRadiance(vec3 vE, vec3 nE, vec3 windE, vec2 sigma2, vec3 upE, vec3 sunE) {
  return seaRadiance(vE, nE, windE, vec3(sigma2, 0.0), upE, sunE);
}

// Whitecap foam (Dupuy & Bruneton 2012 Eq. 2): a Lambertian surface of reflectance 0.4
// (Koepke 1984) over the fraction `coverage` of the footprint, the clear sea over the rest:
// R = W R_foam + (1 - W) R_sea.
const Number FOAM_REFLECTANCE = 0.4;
// The foam's radiance at p (the light it gets does not depend on the normal).
vec3 foamRadiance(SeaPoint p) { return FOAM_REFLECTANCE / PI * (p.eSun * max(p.l.z, 0.0) + p.eSky); }
// The clear sea's and the foam's radiance mixed by the foam's `coverage` of the footprint.
vec3 mixFoam(vec3 clear, vec3 foam, Number coverage) {
  OG_EXPECT_RANGE(coverage, 0.0, 1.0);  // a share of the footprint (asserts in debug C++ only)
  return mix(clear, foam, coverage * uLightingTerms.w);
}
vec3 seaRadianceWithFoam(vec3 vE, vec3 nE, vec3 windE, vec3 cov, vec3 upE, vec3 sunE,
                         Number coverage) {
  SeaPoint p = seaPoint(vE, nE, windE, upE, sunE);  // once for the sea and the foam
  return mixFoam(seaRadianceAt(p, cov, upE), foamRadiance(p), coverage);
}
vec3 seaRadianceWithFoam(vec3 vE, vec3 nE, vec3 windE, vec2 sigma2, vec3 upE, vec3 sunE,
                         Number coverage) {
  return seaRadianceWithFoam(vE, nE, windE, vec3(sigma2, 0.0), upE, sunE, coverage);
}

#ifdef OCEAN_VALIDATION_REFERENCE
// The brute-force reference of the validation (paper §7.2, docs/validation.md): each sample is a
// perfect mirror with its exact facet normal n (every wave), the pixel's average coming from
// supersampling, not from a slope distribution. Sky: a point lookup in the mirror direction with
// the exact per-facet Fresnel F(v.n) (no F̄ fit, Eq. 10). The Sun: a true disc, no tail lobe.
// A mirror sample would find the 0.27° disc only with the paper's hundreds of samples per pixel,
// so each sample stands for its patch of mirror surface, over which the facet slope varies
// linearly (its screen derivatives), and the disc's reflection is integrated over the patch in
// closed form, the patch's slopes and the disc taken as Gaussians of their second moments: the
// Ross lobe of the patch's covariance plus the disc's (seaSunGlint). Same expectation as point
// samples of the disc, far less noise.

// Covariance (along, across the wind, cross) of the slopes over a sample's patch: a slope
// varying linearly by dSlopeDx, dSlopeDy (frame axes x east, y north) across the sample spreads
// like a box, variance d²/12 per direction. windAzimuth: radians clockwise from north.
vec3 referencePatchCovariance(vec2 dSlopeDx, vec2 dSlopeDy, Number windAzimuth) {
  vec2 along = vec2(sin(windAzimuth), cos(windAzimuth)), across = vec2(-along.y, along.x);
  vec2 gx = vec2(dot(dSlopeDx, along), dot(dSlopeDx, across));
  vec2 gy = vec2(dot(dSlopeDy, along), dot(dSlopeDy, across));
  return vec3(gx.x * gx.x + gy.x * gy.x, gx.y * gx.y + gy.y * gy.y, gx.x * gx.y + gy.x * gy.y) / 12.0;
}

vec3 seaRadianceMirror(vec3 vE, vec3 nE, vec3 windE, vec3 patchCov, vec3 upE, vec3 sunE) {
  SeaPoint p = seaPoint(vE, nE, windE, upE, sunE);
  Number f = fresnelSchlick(dot(p.v, p.n));
  vec3 sky = f * skyMapRadianceStereo(stereographic(reflect(-p.v, p.n)), p.sunZenith, p.sunAzimuthCS,
                                      vec2(0.0), vec2(0.0));
  return uLightingTerms.x * seaSunGlint(p, patchCov) + uLightingTerms.y * sky +
         uLightingTerms.z * seaRefracted(p, upE, f);
}
#endif
