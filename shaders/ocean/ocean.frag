#version 450 core
// Sea-surface shading of the projected grid: the footprint's mean normal and unresolved slope
// variance from the FFT wave patterns (ocean/patterns.glsl; Bruneton 2010 Eqs. 3-4 as
// mip-mapped moments), the back-facing fix, whitecaps from the Jacobian's statistics in the
// footprint (Dupuy & Bruneton 2012), then Algorithm 5.1 (ocean/lighting.glsl), with the
// globe's aerial perspective on top.
// OCEAN_DEFERRED: a full-screen pass per sea class reading the grid's values from the surface
// buffer (ocean/sea_surface.glsl, render/OceanRenderer::drawDeferred), once per pixel; the
// coast test was the surface pass's. Otherwise the grid's own fragments, with their varyings;
// OCEAN_RADIANCE_TERMS: the radiance from the vertices' quadratic in the pixel's mean slope and
// covariance (ocean/radiance_terms.glsl), where the cells are large.
#ifdef OCEAN_DEFERRED
#define SEA_IN
#define PATTERN_BANDS_PER_PIXEL  // ocean/patterns.glsl
#else
#define SEA_IN in
#endif
#include "common/types.glsl"
#include "geo/ellipsoid.glsl"
#include "ocean/wind.glsl"
#include "ocean/patterns.glsl"
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"
#include "ocean/radiance_terms.glsl"
#include "render/elevation.glsl"
#include "ocean/coast.glsl"
#include "terrain/shadow.glsl"
#include "ocean/water_volume.glsl"  // the sea floor seen through the water (seed 001)

SEA_IN vec2 vOceanXY;
SEA_IN vec3 vRelative;
SEA_IN vec2 vPatternMean;  // the patterns the grid's vertices looked up (ocean/grid.vert)
SEA_IN vec3 vPatternCov;
SEA_IN vec2 vPatternJacobian;
SEA_IN float vPatternShare[PATTERN_COUNT];
#ifndef PATTERN_BANDS_PER_PIXEL  // (the deferred sea and the radiance terms look the tables up)
in vec2 vPatternBand[PATTERN_COUNT];  // patternBands at the vertex's wind
in vec3 vPatternAveragedFrom[PATTERN_COUNT + 1];
#endif
#ifdef OCEAN_RADIANCE_TERMS
// The sea's radiance in the cell, the aerial perspective folded in (ocean/grid_vertex.glsl's
// prepareRadianceTerms, from ocean/grid_cached.vert).
in vec4 vRadianceTerms[SEA_RADIANCE_VEC4S];
#endif
#if !defined(OCEAN_SIMPLE_SKY) && !defined(OCEAN_RADIANCE_TERMS)
SEA_IN vec3 vTransmittance;  // aerial perspective, per vertex (ocean/grid.vert)
SEA_IN vec3 vInscatter;
#endif
#ifdef OCEAN_COMPUTE
// A deferred class's pass as a compute shader (OCEANGLOBE_SEA=compute: render/OceanRenderer::
// drawDeferred): work groups of 8 x 8 pixels over the frame, an invocation a pixel, shading
// those of the class (the stencil's value, or the surface buffer's where the driver cannot
// export stencil values) into the HDR target's image. Where the water volume needs the slopes'
// change to the next pixel (a fragment's dFdx, dFdy), the group's pixels exchange their slopes
// in shared memory, every pixel of a group with one of the class computing its own as a
// fragment quad's helpers do. For GPUs whose compute units outnumber their pixel shaders'
// (docs/performance.md, "Thirty-second session").
#ifndef OCEAN_DEFERRED
#error "the compute pass shades the deferred sea"
#endif
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform writeonly image2D uRadianceImage;
#if !defined(SEA_CLASS_IN_SURFACE) && !defined(SEA_VISIBILITY)
layout(binding = OG_UNIT_SEA_STENCIL) uniform usampler2D uSeaStencil;  // the classes
#endif
uniform int uSeaClass;  // the class shaded (1..5)
vec4 fragRadiance, fragAux;
ivec2 gSeaPixel = ivec2(0);
bool gSeaOfClass = false;  // this invocation's pixel is the class's (else it only lends its slopes)
shared vec2 sSeaSlope[64];
shared uint sSeaAnyOfClass;
#define SEA_PIXEL gSeaPixel
#else
#define SEA_PIXEL ivec2(gl_FragCoord.xy)
#endif
#include "ocean/sea_surface.glsl"
#ifdef OCEAN_COMPUTE
// The pixel's class: 0 where no sea was drawn.
uint seaClassAt(ivec2 pixel) {
#if defined(SEA_VISIBILITY)  // (one class: the frame's sea has none)
  return seaVisibilityAt(pixel) != 0u ? 1u : 0u;
#elif defined(SEA_CLASS_IN_SURFACE)
  return texelFetch(uSeaSurface, ivec3(pixel, 0), 0).y & SEA_CLASS_BITS;
#else
  return texelFetch(uSeaStencil, pixel, 0).r;
#endif
}
// The change of `slope` to the next pixel in x and in y, within the pixel's 2 x 2 quad (as
// llvmpipe's dFdx, dFdy: the quad's row and column differences). Reached by every invocation
// of the group; zero without the water volume, their only reader.
void groupSlopeDerivatives(vec2 slope, out vec2 dx, out vec2 dy) {
#ifdef OCEAN_NO_WATER_VOLUME
  dx = vec2(0.0);
  dy = vec2(0.0);
#else
  uvec2 l = gl_LocalInvocationID.xy, q = l & ~1u;
  sSeaSlope[8u * l.y + l.x] = slope;
  memoryBarrierShared();
  barrier();
  dx = sSeaSlope[8u * l.y + q.x + 1u] - sSeaSlope[8u * l.y + q.x];
  dy = sSeaSlope[8u * (q.y + 1u) + l.x] - sSeaSlope[8u * q.y + l.x];
#endif
}
#else
#include "render/outputs.glsl"
#endif

uniform mat3 uEcefToOcean;
uniform vec3 uSunDirEcef;

vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance);  // aerial perspective (the pass)

void shadeSeaPixel() {
#ifdef OCEAN_DEFERRED
  float footprint;
  vec2 floorSlope;
  readSeaSurface(footprint, floorSlope);
#endif
  mat3 oceanToEcef = transpose(uEcefToOcean);
  float dist = length(vRelative);
  vec3 dir = vRelative / dist;
  vec3 v = -dir;
  // Pixel footprint from the screen-space derivatives of the undisplaced position (taken
  // before any discard, while the whole quad is alive).
#ifndef OCEAN_DEFERRED
  float footprint = max(length(dFdx(vOceanXY)), length(dFdy(vOceanXY)));
#ifndef OCEAN_NO_WATER_VOLUME
  vec2 floorSlope = floorDepthSlope(vOceanXY, vFloorDepthM);  // the floor's plane in the triangle
#endif
#endif
#ifdef OCEAN_VALIDATION_REFERENCE
  // Validation reference: the rasterised triangle's plane, the geometry the sample already has.
  vec3 nGeometry = normalize(cross(dFdx(vRelative), dFdy(vRelative)));
  if (dot(nGeometry, v) < 0.0) nGeometry = -nGeometry;
#endif
  vec3 up = ellipsoidNormal(dir, dist);
  vec2 latLon = latLonOfNormal(up);
  gSeaSunVisibility = sunVisibility(vRelative, up);  // mountains shade the sea at their feet
  vec2 wind = localWind(latLon);  // speed, azimuth
  SeaSurface sea = oceanSurface(vOceanXY, max(footprint, 1e-4), wind,
                                PatternSums(vPatternMean, vPatternCov, vPatternJacobian, vPatternShare),
#ifdef PATTERN_BANDS_PER_PIXEL
                                PatternBands(vec2[PATTERN_COUNT](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0)),
                                             vec3[PATTERN_COUNT + 1](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0),
                                                                     vec3(0.0), vec3(0.0))));  // unread
#else
                                PatternBands(vPatternBand, vPatternAveragedFrom));
#endif
  // The resolved slopes' change to the next pixel, taken while the pixel's quad is whole
  // (before the coast test's discard: derivatives of discarded neighbours are undefined on GPUs).
#ifdef OCEAN_COMPUTE
  vec2 dSlopeDx, dSlopeDy;
  groupSlopeDerivatives(sea.meanSlope, dSlopeDx, dSlopeDy);
  if (!gSeaOfClass) return;
#else
  vec2 dSlopeDx = dFdx(sea.meanSlope), dSlopeDy = dFdy(sea.meanSlope);
#endif
  KEEP_SEA_SAMPLES(vRelative)  // no sea over land (ocean/coast.glsl)
#ifdef OCEAN_VALIDATION_CONSTANT_BRDF
  sea.covariance = vec3(patternTable(PATTERN_COUNT, wind.x).xy, 0.0);  // the paper's constant BRDF
#endif
  vec3 n = seaTiltedNormal(sea.meanSlope, oceanToEcef, up);
#ifdef OCEAN_VALIDATION_REFERENCE
  // Sub-triangle facets are sampled uniformly over the triangle, but a facet's share of the
  // pixel is its area projected towards the eye: weight (v.n) / ((v.n_g)(n.n_g)), whose mean
  // over the slopes is 1; facets facing away are hidden (weight 0). Masking by neighbouring
  // facets is not modelled (docs/validation.md).
  float sampleWeight = max(dot(n, v), 0.0) /
                       (max(dot(v, nGeometry), 1e-3) * max(dot(n, nGeometry), 1e-3));
#endif
  n = seaNormalFacing(n, v);  // back-facing normals seen at grazing angles (§5.1)
  vec3 windDir = windDirectionEcef(windAzimuthSinCos(wind), up);
#ifdef OCEAN_VALIDATION_REFERENCE
  // Validation reference: a mirror per sample, the Sun's disc integrated over the sample's patch.
  vec3 patchCov = referencePatchCovariance(dSlopeDx, dSlopeDy, wind.y);
  vec3 radiance = seaRadianceMirror(v, n, windDir, patchCov, up, uSunDirEcef);
  // Weighted sample: premultiplied radiance, weight in alpha (never 0, alpha also marks sea).
  fragRadiance = vec4(oceanSurfaceRadiance(vRelative, radiance) * sampleWeight, max(sampleWeight, 1e-6));
  fragAux = vec4(0.0);
  return;
#else
  float foam = whitecapCoverage(sea.jacobian);
#ifdef OCEAN_RADIANCE_TERMS
  // The vertices' quadratic in the pixel's mean slope and covariance, the aerial perspective
  // folded in (ocean/radiance_terms.glsl).
  vec3 clear = seaRadianceOfTerms(unpackSeaRadianceTerms(vRadianceTerms), sea.meanSlope, sea.covariance);
  fragRadiance = vec4(mixFoam(clear, unpackFoamRadiance(vRadianceTerms), foam), 1.0);
  fragAux = vec4(foam, 0.0, 0.0, 0.0);
  return;
#endif
#ifndef OCEAN_NO_WATER_VOLUME  // compiled out when no sea floor in view is within reach
  // How the pixel's slopes spread: the mean slope's change to the next pixel (deferred:
  // between neighbouring pixels' own values, which at the sea's edges may belong to no sea
  // pixel: capped) and the unresolved slopes' standard deviation within it.
  vec2 slopeSpread = vec2(min(max(length(dSlopeDx), length(dSlopeDy)), 0.5),
                          sqrt(sea.variance.x + sea.variance.y));
  prepareWaterVolume(vRelative, v, n, up, latLon, vOceanXY, uEcefToOcean, max(footprint, 1e-4), wind, uSunDirEcef,
                     floorSlope, slopeSpread);
#endif
  vec3 radiance = seaRadianceWithFoam(v, n, windDir, sea.covariance, up, uSunDirEcef, foam);
  fragRadiance = vec4(oceanSurfaceRadiance(vRelative, radiance), 1.0);
  fragAux = vec4(foam, 0.0, 0.0, 0.0);
#endif
}

#ifdef OCEAN_COMPUTE
void main() {
  ivec2 size = imageSize(uRadianceImage), at = ivec2(gl_GlobalInvocationID.xy);
  gSeaPixel = min(at, size - 1);
  gSeaOfClass = all(lessThan(at, size)) && seaClassAt(gSeaPixel) == uint(uSeaClass);
#ifdef OCEAN_NO_WATER_VOLUME
  if (!gSeaOfClass) return;  // no neighbour needs its slopes
#else
  // A group without a pixel of the class returns as one (the derivatives' barrier).
  if (gl_LocalInvocationIndex == 0u) sSeaAnyOfClass = 0u;
  memoryBarrierShared();
  barrier();
  if (gSeaOfClass) sSeaAnyOfClass = 1u;
  memoryBarrierShared();
  barrier();
  if (sSeaAnyOfClass == 0u) return;
#endif
  shadeSeaPixel();
  if (gSeaOfClass) imageStore(uRadianceImage, gSeaPixel, fragRadiance);
}
#elif defined(OUTPUT_DISPLAY)
// The sea's one pass writes the display itself wherever it draws (render/OceanRenderer::
// setDisplayTarget): render/tonemap.frag's curve, the sRGB store encoding it. (Outputs are
// readable.)
#include "common/color.glsl"
uniform float uExposure;
void main() {
  shadeSeaPixel();
  fragRadiance = vec4(toneMap(fragRadiance.rgb, uExposure), 1.0);
}
#else
void main() { shadeSeaPixel(); }
#endif

#if defined(OCEAN_SIMPLE_SKY) || defined(OCEAN_RADIANCE_TERMS)  // (the terms carry it)
vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance) { return radiance; }
#else
vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance) { return radiance * vTransmittance + vInscatter; }
#endif
