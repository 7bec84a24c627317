#version 450 core
#if defined(GLOBE_CLASSIFY_EXPORT) && defined(OG_STENCIL_EXPORT)  // (OG_STENCIL_EXPORT: gl::Program)
#extension GL_ARB_shader_stencil_export : require
#endif
// The globe as the WGS84 ellipsoid, ray-cast per pixel in the eye-relative frame, seen through
// the precomputed atmosphere (Bruneton & Neyret 2008; shaders/atmosphere/): the sky behind the
// globe from any altitude (with the Sun's disc), aerial perspective on the surface, and the
// surface lit by the attenuated Sun plus the sky's irradiance. Land and sea from the elevation
// layer with stand-in materials (the ocean and terrain passes replace them). Conventions shared
// with those passes: radiance in units of the Sun's irradiance (a white Lambertian plate facing
// the unattenuated Sun has radiance 1/pi), alpha = globe coverage, reversed-Z depth =
// near / view distance (0 for the sky).
//
// Atmosphere geometry. The tables are for a spherical shell of radius R = bottomRadius. Every
// shaded point is looked up at r = R + its exact altitude above the ellipsoid: the camera at
// R + uCamAltitude (from the CPU, in double), points on the globe at R. View rays use a sphere
// of radius R under the camera, oriented by the geodetic normal there (uCamUp):
//  * a ray that hits the ellipsoid at distance t keeps t: its zenith cosine is replaced by the
//    one for which a ray of length t joins the camera's altitude to altitude 0 in the sphere,
//    mu' = -(h (2R + h) + t^2) / (2 r t) (t clamped to the sphere's horizon distance). The
//    aerial perspective thus spans exactly the camera-to-surface path, and the horizon (where
//    the globe's coverage ends) stays where the ellipsoid puts it;
//  * a ray that misses the ellipsoid keeps its zenith cosine, raised to just above the
//    sphere's horizon where the sphere would still hit (the two horizons differ by well under
//    a pixel at any altitude for Earth's flattening).
#include "common/constants.glsl"
#include "geo/ellipsoid.glsl"
#include "atmosphere/model.glsl"
#include "atmosphere/skymap.glsl"
#include "common/types.glsl"
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"
#include "ocean/wind.glsl"
#include "ocean/patterns.glsl"
#include "render/elevation.glsl"
#include "render/aerial.glsl"
#include "terrain/imagery.glsl"
#include "terrain/material.glsl"

// The globe is drawn in parts (GlobeRenderer::classifyGlobe, shadeGlobe). llvmpipe runs a
// shader's code after a `discard` too, masked, so a part cannot leave early by discarding;
// what it does skip is a fragment failing the depth or stencil test before the shader runs.
// So three cheap classifying draws (GLOBE_PART_CLASSIFY, arithmetic only) first count into the
// stencil buffer what each pixel needs: 0 nothing (pure space), 1 the sky only (no ray hits
// the ellipsoid), 2 both (an edge: the limb, the horizon), 3 the surface only (all four rays
// hit). Then one draw per part, stencil-tested before the shader (early fragment tests), each
// compiled with only its part's code. Below 20 km, where no pixel sees pure space and the
// depth test leaves out what the terrain and the grid cover, the first step is skipped and the
// counts are one lower. Above, the terrain is drawn between the classifying draws and the
// parts, and zeroes the count where it draws. Where the driver lets a fragment shader write the
// stencil value (GL_ARB_shader_stencil_export; llvmpipe does), one classifying draw
// (GLOBE_CLASSIFY_EXPORT) writes the count the steps would have reached: the rays are traced
// once instead of three times. Above 20 km three more classes, nested: the four samples all on
// land or all on the sea by the same test the surface part makes (count 4: the land, shaded
// once without the sea's code), all on the sea (count 5: the sea, without the land's code; the
// surface part ran both, masked, for every pixel), and within it the open deep sea
// (render/OpenSeaMap: the four samples within a coarse map's clearance of land and shallow
// floors), to a part without the water column either (count 6). Count 3 is left to the
// coasts, their land samples and their sea samples each shaded once. Above 20 km, where the
// land mask decides the coast, the CPU first classes blocks of 8 x 8 pixels from their
// corners and the mask's pyramid
// (render/GlobeBlocks): blocks wholly land, sea or open sea get their count and depth from a
// draw that only intersects the pixel-centre ray (GLOBE_PART_BLOCK_FILL), the sky's blocks
// the classifying draw without the land's and the sea's tests, and the classifying draws
// proper cover only the rest (coasts, the limb, grazing views): render/blocks.vert.
#define GLOBE_PART_SKY 1
#define GLOBE_PART_EDGE 2
#define GLOBE_PART_SURFACE 3
#define GLOBE_PART_CLASSIFY 4
#define GLOBE_PART_OPEN_SEA 5
#define GLOBE_PART_SEA 6
#define GLOBE_PART_LAND 7
#define GLOBE_PART_SKY_LOW 8  // the sky below the grid's ceiling at a lower resolution (below)
#define GLOBE_PART_BLOCK_FILL 9  // blocks of pixels classed on the CPU: their depth (below)
#ifndef GLOBE_PART
#define GLOBE_PART GLOBE_PART_EDGE  // all the shading code
#endif
#ifdef GLOBE_COMPUTE
// The general part over a list of pixels (render/globe_pixels.glsl): a work group of 64, each
// invocation a pixel, whose centre and outputs stand in for the fragment's.
layout(local_size_x = OG_GLOBE_PIXELS_GROUP) in;
#include "render/globe_pixels.glsl"
layout(binding = 0, rgba32f) uniform writeonly image2D uRadianceImage;  // the HDR target
vec2 vNdc;
vec4 fragRadiance, fragAux;
#else
in vec2 vNdc;
#include "render/outputs.glsl"
#endif
#if GLOBE_PART != GLOBE_PART_CLASSIFY && GLOBE_PART != GLOBE_PART_BLOCK_FILL && !defined(GLOBE_COMPUTE)
// Below 20 km the globe is drawn last, behind the terrain and the grid (GlobeRenderer): only
// the pixels they left empty (sky, far land, the grid's horizon gaps) pass the depth test.
// Each part's pixels pass the stencil test (see above). Both tests run before this shader;
// the depth was written by the classifying draws.
layout(early_fragment_tests) in;
#endif
#ifdef GLOBE_SKY_LOW
layout(binding = OG_UNIT_SKY_LOW) uniform sampler2D uSkyLow;  // GLOBE_PART_SKY_LOW's texels
uniform vec2 uSkyLowScale;  // 1 / (their count x uSkyLowFactor): fragment -> texture coordinates
#endif

#include "geo/camera_ray.glsl"
uniform vec2 uPixelNdc;    // size of one pixel in NDC
uniform float uNear;       // near plane, m
uniform float uGlobeDepthPushM;  // the classifying draws' depth over land: GlobeRenderer::kGlobeDepthPushM
uniform vec3 uSunDir;      // unit, ECEF axes

// Below 20 km (GLOBE_BEHIND) the projected-grid pass draws the sea: the globe leaves its sea
// samples to it (and shades the grid's horizon gaps); above, it shades the sea itself. A
// constant, not a uniform: llvmpipe runs both sides of every `if`, so each variant compiles
// only the sea shading it uses.
#ifdef GLOBE_BEHIND
const bool SEA_BY_GRID = true;
#else
const bool SEA_BY_GRID = false;
#endif

// A pixel's footprint on the ground at distance t along dir (geodetic normal n there), radians
// of arc, widened at grazing incidence: what the imagery and the land mask's coast resolve.
float groundFootprintRad(vec3 dir, float t, vec3 n) {
  return coastFootprintRad(t, uPixelNdc.y * uTanHalfFov.y, dot(n, -dir));
}

const bool PART_HAS_SKY = GLOBE_PART != GLOBE_PART_SURFACE;
const bool PART_HAS_SURFACE = GLOBE_PART != GLOBE_PART_SKY;
// The sky's part holds the pixels none of whose four rays hits the ellipsoid (the classifying
// draws found so): it need not intersect them again.
const bool PART_ALL_MISS = GLOBE_PART == GLOBE_PART_SKY;

vec3 landAlbedo(float elevation, float latitude) {
  // Stand-in ramp until imagery/material layers exist: lowland green, upland brown, snow.
  vec3 lowland = vec3(0.09, 0.14, 0.05);
  vec3 upland = vec3(0.22, 0.17, 0.11);
  vec3 snow = vec3(0.80, 0.82, 0.86);
  vec3 c = mix(lowland, upland, smoothstep(200.0, 1800.0, elevation));
  float snowLine = terrainSnowLineM(degrees(latitude));  // the terrain's (terrain/material.glsl)
  return mix(c, snow, smoothstep(snowLine - 300.0, snowLine + 300.0, elevation));
}

// Land's albedo: the imagery (terrain/imagery.glsl), the ramp where it shows water (its coarse
// pixels blur the sea onto the shore) or when imagery is off. footprintRad: the sample's
// footprint on the ground, radians of arc.
vec3 landColour(vec2 latLon, float elevation, float footprintRad) {
  vec3 ramp = landAlbedo(elevation, latLon.x);
  if (uImageryEnabled == 0) return ramp;
  vec3 a = imageryAlbedo(latLon, footprintRad);
  return mix(a, ramp, imageryWaterness(a));
}

// Land: Lambertian, lit by the attenuated Sun (irradiance sunIrr on a surface facing it) and
// the sky (irradiance skyIrr on the horizontal surface).
vec3 shadeLand(vec3 albedo, float muS, vec3 sunIrr, vec3 skyIrr) {
  return albedo / PI * (sunIrr * max(muS, 0.0) + skyIrr);
}

// Sea seen from afar (above 20 km, and wherever the grid is not drawn): the ellipsoid with the
// Ross BRDF over the whole slope distribution of the local wind (Bruneton 2010 §6) and the
// whitecap coverage of the local wind's Jacobian statistics (Dupuy 2012), the same lighting
// code as the projected grid (ocean/lighting.glsl), so the switch between the two is invisible.
float gSeaFoam = 0.0;  // whitecap coverage of the last shadeSea (the auxiliary output)
vec2 gSeaSigma2 = vec2(0.0);  // and its slope variances along and across the wind
vec3 shadeSea(vec3 v, vec3 n, float footprintRad) {
  vec2 w = localWind(latLonOfNormal(n));  // speed, azimuth (PATTERN_CONSTANT_WIND: uniforms)
  gSeaSigma2 = seaSlopeVarianceTotal(w.x);
  vec3 wind = windDirectionEcef(windAzimuthSinCos(w), n);
  float foam = whitecapCoverage(vec2(1.0, seaJacobianVarianceTotal(w.x)));
  gSeaFoam = foam;
#if GLOBE_PART == GLOBE_PART_OPEN_SEA
  gWater = WaterVolume(true, uSeaColor);  // deeper than the water's reach: prepareWaterColumn's
#else
  prepareWaterColumn(v, n, uSunDir, 1.0, footprintRad);  // the floor through the water (terrain/shallow.glsl)
#endif
  return seaRadianceWithFoam(v, n, wind, gSeaSigma2, n, uSunDir, foam);
}

// Light leaving the globe's surface at distance t along dir, towards the viewer; `sea` says
// which of the two the point is (the caller has tested it).
vec3 surfaceRadiance(vec3 dir, float t, bool sea) {
  gSeaFoam = 0.0;
  vec3 n = ellipsoidNormal(dir, t);
  vec2 latLon = latLonOfNormal(n);
  float footprint = groundFootprintRad(dir, t, n);
  float elevation = elevationAt(latLon, footprint);
  float muSP = dot(n, uSunDir);
  vec3 skyIrr;
  vec3 sunIrr = sunAndSkyIrradiance(uAtmosphere, uAtmTransmittance, uAtmIrradiance,
                                    uAtmosphere.bottomRadius, muSP, skyIrr);
  if (sea && !SEA_BY_GRID) return shadeSea(-dir, n, footprint);
  return shadeLand(landColour(latLon, elevation, footprint), muSP, sunIrr, skyIrr) +
         nightLightsRadiance(latLon, footprint, muSP);
}

// The `coverage` samples on the globe (of a pixel's four: their summed directions hitDir and
// distances hitT, m), whose surface radiance sums to `surface`, through the aerial perspective
// of their mean path (see the header); the sum of what reaches the eye from them.
vec3 throughAerialPerspective(vec3 surface, vec3 hitDir, float hitT, float coverage) {
  vec3 dir = normalize(hitDir);
  vec3 transmittance, inscatter;
  aerialToSeaLevel(hitT / coverage, dot(dir, uSunDir), uSunDir, transmittance, inscatter);  // render/aerial.glsl
  return surface * transmittance + inscatter * coverage;
}

// surfaceRadiance on the mean of some of a pixel's rays that hit the globe (their summed
// directions sumDir; meanT, m, their mean distance, the fallback should rounding make the mean
// ray miss).
vec3 surfaceAtMeanRay(vec3 sumDir, float meanT, bool sea) {
  vec3 dir = normalize(sumDir);
  float t = intersectEllipsoid(dir);
  return surfaceRadiance(dir, t >= 0.0 ? t : meanT, sea);
}

// A pixel's four rays: 4 rotated-grid samples, for an anti-aliased limb, horizon and coastline;
// ts < 0 where a ray misses the ellipsoid. Arithmetic only (the classifying draws use it).
struct PixelRays {
  vec3 dirs[4];
  float ts[4];
  int nHit;  // rays that hit the ellipsoid
};
// Which of a pixel's four samples lie on the sea (samples that miss the globe: false), the
// coast as the pixel's footprint resolves it: the same test as surfaceRadiance's elevationAt
// (render/elevation.glsl) with the sample's footprint, the land mask's fine blocks fetched
// once for the four (terrain/landmask.glsl's landFraction4).
// GLOBE_MASK_COAST (GlobeRenderer: the land mask decides this renderer's coast): the fraction
// alone, without the layer's heights. constrainByLandFraction's height is at most 0 on the sea
// side (f < 0.5) and above 0 on the land side but at f = 0.5 exactly over a height at or below
// 0, which this calls land, as terrain.frag's coast test does.
bvec4 samplesSea(PixelRays rays) {
  vec2 latLon[4];
  vec4 height = vec4(0.0), keep = vec4(0.0);
  float footprint = 0.0;
  for (int i = 0; i < 4; ++i) {
    float t = max(rays.ts[i], 0.0);
    vec3 n = ellipsoidNormal(rays.dirs[i], t);
    latLon[i] = latLonOfNormal(n);
#ifndef GLOBE_MASK_COAST
    vec2 heightKeep = elevationLayerAt(latLon[i]);
    height[i] = heightKeep.x;
    keep[i] = heightKeep.y;
#endif
    footprint += 0.25 * groundFootprintRad(rays.dirs[i], t, n);
  }
  vec4 f = landFraction4(latLon[0], latLon[1], latLon[2], latLon[3], footprint);
  bvec4 sea;
  for (int i = 0; i < 4; ++i)
#ifdef GLOBE_MASK_COAST
    sea[i] = rays.ts[i] >= 0.0 && f[i] < 0.5;
#else
    sea[i] = rays.ts[i] >= 0.0 &&
             (landMaskOn() ? constrainByLandFraction(height[i], keep[i], f[i]) : height[i]) <= 0.0;
#endif
  return sea;
}

PixelRays traceRays() {
  const vec2 offsets[4] = vec2[4](vec2(-0.125, -0.375), vec2(0.375, -0.125),
                                  vec2(0.125, 0.375), vec2(-0.375, 0.125));
  PixelRays rays;
  rays.nHit = 0;
  for (int i = 0; i < 4; ++i) {
    vec2 ndc = vNdc + offsets[i] * uPixelNdc;
    rays.dirs[i] = cameraRay(ndc);
    rays.ts[i] = PART_ALL_MISS ? -1.0 : intersectEllipsoid(rays.dirs[i]);
    rays.nHit += rays.ts[i] >= 0.0 ? 1 : 0;
  }
  return rays;
}

// The sky seen by the rays that miss: their mean direction's zenith cosine at the camera,
// raised to just above the sphere's horizon (see the header), and whether it leaves the
// atmosphere unseen (rays from space that miss it see only the Sun's disc).
struct SkyView {
  vec3 dir;
  float mu;
  bool space;
  float sunDisc;  // rays in the Sun's disc
};
SkyView skyOf(PixelRays rays) {
  float cosSun = cos(uAtmosphere.sunAngularRadius);
  vec3 sum = vec3(0.0);
  SkyView sky;
  sky.sunDisc = 0.0;
  for (int i = 0; i < 4; ++i) {
    bool miss = rays.ts[i] < 0.0;
    sum += miss ? rays.dirs[i] : vec3(0.0);
    sky.sunDisc += miss && dot(rays.dirs[i], uSunDir) > cosSun ? 1.0 : 0.0;
  }
  float R = uAtmosphere.bottomRadius;
  float r = R + uCamAltitude;
  float rho2 = uCamAltitude * (2.0 * R + uCamAltitude);
  float top = uAtmosphere.topRadius;
  sky.dir = normalize(sum);
  sky.mu = max(dot(sky.dir, uCamUp), -sqrt(rho2) / r + 1e-5);
  sky.space = r > top && (sky.mu >= 0.0 || r * r * (sky.mu * sky.mu - 1.0) + top * top < 0.0);
  return sky;
}

#if GLOBE_PART == GLOBE_PART_CLASSIFY
#include "render/open_sea_map.glsl"
uniform int uOpenSeaOn;  // 0: no pixel is classed open sea (GlobeRenderer::setOpenSeaPart)
uniform int uLandAtFarPlane;  // 1: the land's class keeps the far plane's depth (GLOBE_LAND_SEA)

// How many of a pixel's four samples hit the globe on the sea (-1 unless all four hit): the
// surface part's own test of each sample (below), so the land and sea parts shade exactly the
// pixels it would shade as all land or all sea.
int samplesOnSea(PixelRays rays) {
  int n = 0;
  bvec4 sea = samplesSea(rays);
  for (int i = 0; i < 4; ++i) n += sea[i] ? 1 : 0;
  return rays.nHit == 4 ? n : -1;
}

// Whether all four of a pixel's samples lie in the open deep sea: within the clearance radius
// (render/OpenSeaMap) of the 7.5′ cell under the pixel-centre ray's hit (geodetic normal
// nCentre at latLon, radians). The radius holds for every point of the cell, so the samples'
// largest angle from nCentre is compared with it, with a 10 % margin (the shading point, the
// samples' mean ray, lies among them; float rounding), as chords: the angle from a float dot
// product near 1 is lost in its rounding at the smallest radii (one free cell, ~2e-3 cos φ rad).
bool inOpenSea(PixelRays rays, vec3 nCentre, vec2 latLon) {
  float clearance = openSeaMapAt(latLon).r;
  float maxChord = 0.0;
  for (int i = 0; i < 4; ++i) maxChord = max(maxChord, distance(ellipsoidNormal(rays.dirs[i], rays.ts[i]), nCentre));
  return uOpenSeaOn != 0 && rays.nHit == 4 && maxChord < 2.0 * sin(0.45 * clearance);
}

// The classifying draws (GlobeRenderer::classifyGlobe): each keeps the pixels that pass its step,
// the stencil counting them: step 0 anything to shade (not pure space), 1 a ray on the globe,
// 2 all four on it, and above 20 km 3 all four on land or all on the sea, 4 all four on the
// sea, 5 all four in the open deep sea. Step 0 also writes the depth above 20 km.
// GLOBE_CLASSIFY_EXPORT: all the steps in one draw, writing the count. Steps 3-4 and 5 are
// left out where their parts are off.
#if !defined(GLOBE_BEHIND) && (GLOBE_CLASSIFY_STEP == 0 || GLOBE_CLASSIFY_STEP == 5 || defined(GLOBE_CLASSIFY_EXPORT))
#define GLOBE_CLASSIFY_CENTRE
#endif
void main() {
  PixelRays rays = traceRays();
#ifdef GLOBE_CLASSIFY_CENTRE
  // The pixel-centre ray: its hit decides the open sea and gives the depth.
  vec3 centreDir = cameraRay(vNdc);
  float centreT = rays.nHit > 0 ? intersectEllipsoid(centreDir) : -1.0;
  vec3 centreNormal = ellipsoidNormal(centreDir, max(centreT, 0.0));
  vec2 centreLatLon = latLonOfNormal(centreNormal);
  // Not at grazing incidence (the limb's last pixels), where the shading is ill-conditioned
  // enough that the two parts' compiled code rounds differently.
  bool openSea = centreT >= 0.0 && dot(centreNormal, -centreDir) > 0.2 &&
                 inOpenSea(rays, centreNormal, centreLatLon);
#endif
#ifdef GLOBE_CLASSIFY_EXPORT
#ifdef GLOBE_BEHIND
  int count = 0;  // below 20 km no pixel sees pure space: step 0 is skipped
#else
  SkyView sky = skyOf(rays);
  int count = rays.nHit == 0 && sky.space && sky.sunDisc == 0.0 ? 0 : 1;
#ifdef GLOBE_LAND_SEA  // the land's and the sea's steps (GlobeRenderer::landSeaSplitPays)
  int onSea = samplesOnSea(rays);
  count += onSea == 0 || onSea == 4 ? 1 : 0;
  count += onSea == 4 ? 1 : 0;
  count += openSea && onSea == 4 ? 1 : 0;  // the open sea is within the sea
#else
  count += openSea ? 1 : 0;
#endif
#endif
  count += (rays.nHit > 0 ? 1 : 0) + (rays.nHit == 4 ? 1 : 0);
  if (count == 0) discard;
  gl_FragStencilRefARB = count;
#elif GLOBE_CLASSIFY_STEP == 0
  SkyView sky = skyOf(rays);
  if (rays.nHit == 0 && sky.space && sky.sunDisc == 0.0) discard;
#elif GLOBE_CLASSIFY_STEP == 1
  if (rays.nHit == 0) discard;
#elif GLOBE_CLASSIFY_STEP == 2
  if (rays.nHit < 4) discard;
#elif GLOBE_CLASSIFY_STEP == 3
  int onSea = samplesOnSea(rays);
  if (onSea != 0 && onSea != 4) discard;
#elif GLOBE_CLASSIFY_STEP == 4
  if (samplesOnSea(rays) != 4) discard;
#else
  if (!openSea) discard;
#endif
  fragRadiance = vec4(0.0);  // colour writes are masked off
  fragAux = vec4(0.0);
#if !defined(GLOBE_BEHIND) && (GLOBE_CLASSIFY_STEP == 0 || defined(GLOBE_CLASSIFY_EXPORT))
  // Depth of the surface on the pixel-centre ray where it hits the globe, as the terrain and
  // the grid rasterise theirs, so land at or above sea level always passes in front of this
  // fallback (the nearest sample would stand up to half a pixel's footprint closer: from 30
  // km, hundreds of metres at a grazing angle, hiding low coasts). The nearest sample
  // otherwise; the far plane (0) for the sky.
  float depthZ = 1e30;
  for (int i = 0; i < 4; ++i)
    depthZ = rays.ts[i] >= 0.0 ? min(depthZ, rays.ts[i] * dot(rays.dirs[i], uForward)) : depthZ;
  if (centreT >= 0.0) {
    depthZ = centreT * dot(centreDir, uForward);
    // Over land the terrain draws the ground and this flat fallback must never stand in front
    // of a tile: the coarsest tiles' chords sag up to ~0.5 km below the ellipsoid; pushed
    // uGlobeDepthPushM back (GlobeRenderer::viewDistance takes it back out). Over the sea the
    // depth stays exact, hiding the land the terrain would draw as whole pixels where the
    // globe's samples see sea (islets under a pixel). Land as the 2′ mask's coast has it: the
    // pixel's own footprint and the fine level cost a fifth of the globe pass on llvmpipe
    // (run masked wherever any pixel needs them); the 15″ islets and bays it leaves out are
    // drawn by the globe's samples instead of the terrain. Where the footprint spans several
    // 2′ cells, the pyramid's fraction (landFractionCoarse, at the centre ray's footprint; the
    // samples take their mean's, within a hair of it).
#ifdef GLOBE_MASK_COAST  // (land at the mask's fraction alone, as samplesSea)
    if (landFractionCoarse(centreLatLon, groundFootprintRad(centreDir, centreT, centreNormal)) >= 0.5)
      depthZ += uGlobeDepthPushM;
#else
    if (elevationAt(centreLatLon) > 0.0) depthZ += uGlobeDepthPushM;
#endif
  }
  gl_FragDepth = rays.nHit > 0 ? clamp(uNear / depthZ, 0.0, 1.0) : 0.0;
#if defined(GLOBE_CLASSIFY_EXPORT) && defined(GLOBE_LAND_SEA)
  // The land's class keeps the far plane: its part comes after the terrain's tiles with water,
  // only where none drew (GlobeRenderer::frameLandLast_), and every tile passes in front of it.
  if (onSea == 0 && uLandAtFarPlane != 0) gl_FragDepth = 0.0;
#endif
#endif
}
#elif GLOBE_PART == GLOBE_PART_BLOCK_FILL
// Blocks of pixels classed as a whole on the CPU (render/GlobeBlocks, drawn over them by
// GlobeRenderer::classifyGlobe): every sample of their pixels lies on the land or on the sea,
// which the stencil's reference value records. This writes the depth of the pixel-centre ray
// (which hits: the blocks' corners did), pushed back over land as the per-pixel draw does
// (there by the 2′ mask at the centre; a block the 15″ cells decide by its own class).
uniform int uBlockLand;  // 1: the blocks are land
void main() {
  vec3 centreDir = cameraRay(vNdc);
  float centreT = max(intersectEllipsoid(centreDir), 0.0);
  float depthZ = centreT * dot(centreDir, uForward);
  if (uBlockLand != 0) depthZ += uGlobeDepthPushM;
  gl_FragDepth = clamp(uNear / depthZ, 0.0, 1.0);
  fragRadiance = vec4(0.0);  // colour writes are masked off
  fragAux = vec4(0.0);
}
#elif GLOBE_PART == GLOBE_PART_SKY_LOW
// The sky below the grid's ceiling, one texel per uSkyLowFactor² pixels (GlobeRenderer::drawSkyLow):
// seen from under 20 km it varies over degrees, not pixels (the Sun's disc is added per pixel
// by the sky part), and the precomputed atmosphere's lookups were ~40 % of the globe pass on
// llvmpipe. Texel (i, j) holds the sky on the ray of the full frame's pixel coordinate
// ((i, j) + 0.5) uSkyLowFactor, the pixel-centre ray's zenith cosine raised to just above the
// horizon as skyOf raises it (below the horizon: the horizon's sky, so the lookup stays smooth
// across it). No depth or stencil: every texel.
uniform float uSkyLowFactor;
uniform vec2 uFrameSize;  // the full frame, pixels
void main() {
  vec2 ndc = gl_FragCoord.xy * uSkyLowFactor / uFrameSize * 2.0 - 1.0;
  vec3 dir = cameraRay(ndc);
  float R = uAtmosphere.bottomRadius;
  float r = R + uCamAltitude;
  float mu = max(dot(dir, uCamUp), -sqrt(uCamAltitude * (2.0 * R + uCamAltitude)) / r + 1e-5);
  vec3 transmittance;
  fragRadiance = vec4(skyRadiance(uAtmosphere, uAtmTransmittance, uAtmScattering, uAtmSingleMie, r, mu,
                                  dot(uSunDir, uCamUp), dot(dir, uSunDir), transmittance), 1.0);
  fragAux = vec4(0.0);
}
#elif GLOBE_PART == GLOBE_PART_LAND || GLOBE_PART == GLOBE_PART_SEA || GLOBE_PART == GLOBE_PART_OPEN_SEA
// The land, the sea and the open deep sea (classified above): four samples all on land or all
// on the sea, shaded once at their mean ray as the surface part shades such a pixel, by
// surfaceRadiance with a constant for which they are, so that only the land's or the sea's
// code is compiled in (and no per-sample coast test); the open deep sea's part also without
// the water column (deeper than the water's reach there: shadeSea).
int gClassRaysHit = 4;  // shadeClassPixel's rays that hit the ellipsoid (the lattice's)
void shadeClassPixel() {
  PixelRays rays = traceRays();
  gClassRaysHit = rays.nHit;
  vec3 hitDir = vec3(0.0);
  float hitT = 0.0;
  for (int i = 0; i < 4; ++i) {
    hitDir += rays.dirs[i];
    hitT += rays.ts[i];
  }
  vec3 surface = 4.0 * surfaceAtMeanRay(hitDir, 0.25 * hitT, GLOBE_PART != GLOBE_PART_LAND);
  float foam = 4.0 * gSeaFoam;  // 0 on land
  fragRadiance = vec4(throughAerialPerspective(surface, hitDir, hitT, 4.0) * 0.25, 1.0);
  fragAux = vec4(foam * 0.25, 0.0, 0.0, 0.0);
}
#ifdef GLOBE_LATTICE
// The sea's or the open sea's part at the points of a lattice every SEA_LATTICE_PX pixels
// (render/SeaLattice: listed by the CPU around its sea and open-sea blocks), each shaded as a
// pixel centred there: the radiance into the lattice's texel, the whitecaps in alpha, or -1
// where the lattice cannot stand for the pixels around the point (render/sea_lattice.comp then
// leaves its blocks per pixel):
//  * a ray of the point misses the ellipsoid (a partial block's point past the frame's edge
//    off the limb), or the radiance is not finite;
//  * the glint's lobe is too narrow: the slopes' standard deviation across the wind under
//    SEA_LATTICE_MIN_LOBE_PX half-turns of the reflection a pixel, the Gaussian of the glint
//    then under that many pixels wide and the lattice's linear interpolation of it off by over
//    ~1/200 of its peak (a calm sea; the Sun's disc, which widens it, left out). A pixel turns
//    the reflection by the view's turn plus twice the normal's (the ground's arc a pixel,
//    widened at grazing incidence: ~8 times the view's near the limb from 400 km);
//  * the sea's part, where the elevation layer's cells are narrower than two spacings on the
//    ground (a fine bathymetry from high up): the floor within the water's reach and its depth
//    not linear over the spacing (its second difference over half the spacing on either side
//    above SEA_LATTICE_MAX_FLOOR_BEND_M), a shoal the check between the points could miss.
const float SEA_LATTICE_PX = 4.0;
const float SEA_LATTICE_MIN_LOBE_PX = 20.0;
const float SEA_LATTICE_MAX_FLOOR_BEND_M = 0.5;
// The ground's arc a pixel (rad) at distance t along dir (normal n there), widened at grazing
// incidence down to the CPU's sea blocks' least cosine (render/GlobeBlocks' kMinCosIncidence):
// groundFootprintRad's widening stops at 0.2.
float latticeArcRad(vec3 dir, float t, vec3 n) {
  return t * uPixelNdc.y * uTanHalfFov.y / (WGS84_A * max(dot(n, -dir), 0.1));
}
// The floor's depth where the ray `dir` meets the ellipsoid at t (normal n there; m, deep where
// it misses: t < 0), its coast as the shading's (prepareWaterColumn: the land mask's lift at
// the pixel's footprint); and along the frame's ray through `ndc`.
float latticeFloorDepthM(vec3 dir, float t, vec3 n) {
  float land, keepDepth;
  return t < 0.0 ? 1e4 : seaFloorDepthM(n, groundFootprintRad(dir, t, n), land, keepDepth);
}
float latticeFloorDepthM(vec2 ndc) {
  vec3 dir = cameraRay(ndc);
  float t = intersectEllipsoid(dir);
  return latticeFloorDepthM(dir, t, ellipsoidNormal(dir, max(t, 0.0)));
}
bool floorBendsWithinReach(vec2 ndc, vec3 dir, float t, vec3 n) {
#if GLOBE_PART == GLOBE_PART_SEA
  // A layer whose cells span two spacings or more on the ground bends no narrower than that:
  // the check between the points sees it (the embedded 5′ layer from up to ~1000 km at 720p).
  float cellRad = min(uElevationMap.w, uElevationMap.z * max(length(n.xy), 1e-3));
  if (uElevationSize.x <= 0.0 || cellRad >= 2.0 * SEA_LATTICE_PX * latticeArcRad(dir, t, n)) return false;
  vec2 halfStep = 0.5 * SEA_LATTICE_PX * uPixelNdc;
  float d = latticeFloorDepthM(dir, t, n);
  float dx0 = latticeFloorDepthM(ndc - vec2(halfStep.x, 0.0)), dx1 = latticeFloorDepthM(ndc + vec2(halfStep.x, 0.0));
  float dy0 = latticeFloorDepthM(ndc - vec2(0.0, halfStep.y)), dy1 = latticeFloorDepthM(ndc + vec2(0.0, halfStep.y));
  float reach = waterMaxPathM(uWaterAttenuation, WATER_EPSILON);
  bool within = min(d, min(min(dx0, dx1), min(dy0, dy1))) < reach;
  return within && max(abs(dx0 + dx1 - 2.0 * d), abs(dy0 + dy1 - 2.0 * d)) > SEA_LATTICE_MAX_FLOOR_BEND_M;
#else
  return false;  // (the open sea's floor is beyond reach)
#endif
}
void main() {
  uint i = (gl_WorkGroupID.y * GLOBE_PIXELS_ROW + gl_WorkGroupID.x) * GLOBE_PIXELS_GROUP + gl_LocalInvocationID.x;
  if (i >= uCount) return;
  ivec2 point = ivec2(uPixels[i] & 0xffffu, uPixels[i] >> 16);
  vNdc = vec2(point) * (SEA_LATTICE_PX * uPixelNdc) - 1.0;
  shadeClassPixel();
  vec3 dir = cameraRay(vNdc);
  float t = intersectEllipsoid(dir);
  vec3 n = ellipsoidNormal(dir, max(t, 0.0));
  float turnRad = uPixelNdc.y * uTanHalfFov.y + 2.0 * latticeArcRad(dir, max(t, 0.0), n);
  bool wide = sqrt(min(gSeaSigma2.x, gSeaSigma2.y)) >= SEA_LATTICE_MIN_LOBE_PX * 0.5 * turnRad;
  bool finite = !any(isnan(fragRadiance.rgb)) && !any(isinf(fragRadiance.rgb));
  bool usable = gClassRaysHit == 4 && t >= 0.0 && finite && wide && !floorBendsWithinReach(vNdc, dir, t, n);
  imageStore(uRadianceImage, point, usable ? vec4(fragRadiance.rgb, fragAux.r) : vec4(0.0, 0.0, 0.0, -1.0));
}
#else
void main() { shadeClassPixel(); }
#endif
#elif GLOBE_PART == GLOBE_PART_SKY && defined(GLOBE_SKY_LOW)
// The sky below the ceiling (no ray of the pixel on the globe): the lower-resolution pass's sky;
// only pixels near the Sun's disc trace their four rays, for its coverage and the transmittance
// towards it (a loop of a trip there: a GPU skips it elsewhere; llvmpipe runs its body once,
// masked, whatever the condition, so the loop is compiled in only for a second draw over the
// Sun's box, GLOBE_SKY_SUN_DISC: GlobeRenderer::drawSunDisc). What the general part below
// computes for such pixels, without its per-sample bookkeeping (loops over the samples), which
// cost llvmpipe a sixth of the globe pass at 1280x720.
void main() {
  vec3 radiance = 4.0 * textureLod(uSkyLow, gl_FragCoord.xy * uSkyLowScale, 0.0).rgb;
#ifdef GLOBE_SKY_SUN_DISC  // drawn again over the Sun's box only (GlobeRenderer::drawSunDisc)
  vec3 centreDir = cameraRay(vNdc);
  // A pixel spans at most this angle (its diagonal at the centre of the frame), rad
  // (render::sunDiscScissor's cone).
  float pixelRad = length(uPixelNdc * uTanHalfFov);
  float cosNear = cos(uAtmosphere.sunAngularRadius + pixelRad);
  for (int k = 0; k < (dot(centreDir, uSunDir) > cosNear ? 1 : 0); ++k) {
    SkyView sky = skyOf(traceRays());
    float r = uAtmosphere.bottomRadius + uCamAltitude;
    vec3 transmittance = transmittanceToTop(uAtmosphere, uAtmTransmittance, r, sky.mu);
    radiance += sky.sunDisc * transmittance * sunDiscRadiance(uAtmosphere);
  }
#endif
  fragRadiance = vec4(radiance * 0.25, 0.0);
  fragAux = vec4(0.0);
}
#else
void shadePixel() {
  // The surface is shaded once for the samples on land and once for those on the sea (below);
  // the atmosphere, smooth across a pixel, once per pixel for the samples on the globe (at
  // their mean distance) and once for those in the sky. Loops run only as many times as
  // needed: llvmpipe skips a loop's trips after the first for a whole vector of pixels (the
  // first it runs, masked) but evaluates both sides of an if.
  PixelRays rays = traceRays();
  bvec4 seaSamples = PART_HAS_SURFACE ? samplesSea(rays) : bvec4(false);
  vec3 hitDir = vec3(0.0);
  float hitT = 0.0;
  int nHit = 0, nSea = 0;
  // The samples on the globe apart on land and on the sea: their summed directions and distances.
  vec3 landDir = vec3(0.0), seaDir = vec3(0.0);
  float landT = 0.0, seaT = 0.0;
  int nLand = 0;
  float seaHoles = 0.0;
  vec3 seaHoleDir = vec3(0.0);
  float seaHoleT = 0.0;
  for (int i = 0; i < 4; ++i) {
    bool sea = PART_HAS_SURFACE && seaSamples[i];
    // Below 20 km the grid pass draws the sea: leave sea samples to it (no colour).
    if (sea && SEA_BY_GRID) {
      seaHoles += 1.0;
      seaHoleDir = rays.dirs[i];
      seaHoleT = rays.ts[i];
      continue;
    }
    nSea += sea ? 1 : 0;
    if (rays.ts[i] >= 0.0) {
      ++nHit;
      hitDir += rays.dirs[i];
      hitT += rays.ts[i];
      landDir += sea ? vec3(0.0) : rays.dirs[i];
      landT += sea ? 0.0 : rays.ts[i];
      seaDir += sea ? rays.dirs[i] : vec3(0.0);
      seaT += sea ? rays.ts[i] : 0.0;
      nLand += sea ? 0 : 1;
    }
  }
  float R = uAtmosphere.bottomRadius;
  float h = uCamAltitude;
  float r = R + h;
  float rho2 = h * (2.0 * R + h);
  vec3 surface = vec3(0.0);
  float foam = 0.0;  // whitecap coverage summed over the samples
  // The surface varies little across a pixel but where it changes from land to sea: the
  // samples on land are shaded once at their mean ray, those on the sea once at theirs (the
  // rays that hit a convex body from outside form a convex cone, so a mean of hits hits),
  // each weighted by its count. At most one trip of each loop: llvmpipe runs both sides of an
  // if, so shading every sample with the land's and the sea's code cost a coast pixel 4x both.
  for (int k = 0; k < (PART_HAS_SURFACE && nLand > 0 ? 1 : 0); ++k)
    surface += float(nLand) * surfaceAtMeanRay(landDir, landT / float(nLand), false);
  for (int k = 0; k < (PART_HAS_SURFACE && nSea > 0 ? 1 : 0); ++k) {
    surface += float(nSea) * surfaceAtMeanRay(seaDir, seaT / float(nSea), true);
    foam += float(nSea) * gSeaFoam;
  }

  float coverage = float(nHit);
  float muS = dot(uSunDir, uCamUp);
  float skyCount = 4.0 - float(rays.nHit);
  vec3 radiance = vec3(0.0);
  // Two loops of 0 or 1 trips: the globe's samples through the aerial perspective of their mean
  // path, the sky's through the sky to the boundary (llvmpipe runs each loop's first trip,
  // masked, even where no pixel enters it: the parts' programs leave out what they lack).
  for (int k = 0; k < (PART_HAS_SURFACE && nHit > 0 ? 1 : 0); ++k)
    radiance += throughAerialPerspective(surface, hitDir, hitT, coverage);
  if (PART_HAS_SKY) {
    SkyView sky = skyOf(rays);
    if (skyCount > 0.0 && sky.space) radiance += sky.sunDisc * sunDiscRadiance(uAtmosphere);
    for (int k = 0; k < (skyCount > 0.0 && !sky.space ? 1 : 0); ++k) {
      vec3 transmittance;  // (the low-resolution sky's part is the main above)
      vec3 inscatter = skyRadiance(uAtmosphere, uAtmTransmittance, uAtmScattering, uAtmSingleMie,
                                   r, sky.mu, muS, dot(sky.dir, uSunDir), transmittance);
      radiance += inscatter * skyCount + sky.sunDisc * transmittance * sunDiscRadiance(uAtmosphere);
    }
  }
  // Sea holes: the grid pass paints over them; where it leaves a gap (between its horizon
  // vertices, where the chord falls short of the curved horizon) this far-field sea shows,
  // which is what the grid converges to there anyway. Shaded once per pixel, no depth.
  if (SEA_BY_GRID && PART_HAS_SURFACE && seaHoles > 0.0) {
    vec3 holeN = ellipsoidNormal(seaHoleDir, seaHoleT);
    radiance += seaHoles * withAerialPerspective(shadeSea(-seaHoleDir, holeN, groundFootprintRad(seaHoleDir, seaHoleT, holeN)),
                                                 seaHoleDir, seaHoleT, uSunDir);
    foam += seaHoles * gSeaFoam;
  }
  fragRadiance = vec4(radiance * 0.25, (coverage + seaHoles) * 0.25);
  fragAux = vec4(foam * 0.25, 0.0, 0.0, 0.0);
}
#ifdef GLOBE_COMPUTE
void main() {
  uint i = (gl_WorkGroupID.y * GLOBE_PIXELS_ROW + gl_WorkGroupID.x) * GLOBE_PIXELS_GROUP + gl_LocalInvocationID.x;
  if (i >= uCount) return;
  ivec2 pixel = ivec2(uPixels[i] & 0xffffu, uPixels[i] >> 16);
  vNdc = (vec2(pixel) + 0.5) * uPixelNdc - 1.0;
  shadePixel();
  imageStore(uRadianceImage, pixel, fragRadiance);
}
#else
void main() { shadePixel(); }
#endif
#endif
