// Screen-space projected grid (Bruneton 2010 §4.2, after Hinsinger et al.): a regular grid of
// vertices every few pixels, each cast onto the WGS84 ellipsoid (not a plane) along its pixel's
// ray and displaced by the FFT wave patterns filtered by the cell's size (ocean/patterns.glsl).
// Vertices whose rays miss the sea are pulled down onto the horizon so no triangle spans the
// sky. Positions stay camera- or frame-relative.
// gridVertex computes one vertex's outputs: in the grid's vertex shader (ocean/grid.vert,
// GRID_OUT = out), or in the compute pass that computes them all before the deferred sea's
// surface pass (ocean/grid_vertices.comp, GRID_OUT empty: plain globals it stores;
// ocean/grid_vertex_buffer.glsl).
#include "common/types.glsl"
#include "geo/ellipsoid.glsl"
#include "ocean/wind.glsl"
#include "ocean/patterns.glsl"
#include "ocean/coast.glsl"  // waves shrink over shoaling water (the shore)
// The sea's radiance per vertex (OCEAN_RADIANCE_TERMS; included outside it: files are included
// once, before the preprocessor runs, and later files include the sky maps inside their own).
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"
#include "ocean/radiance_terms.glsl"

uniform ivec2 uGridSize;      // vertices per row, rows
uniform vec4 uGridMarginNdc;  // overshoot (left, right, bottom, top) so displaced edges stay covered
#include "geo/camera_ray.glsl"
uniform mat4 uViewProjection; // camera-relative ECEF -> clip (reversed-Z)
uniform mat3 uEcefToOcean;    // rows: ocean frame east, north, up in ECEF
uniform float uEyeHeight;     // eye height above the ellipsoid, m
uniform float uCellAngle;     // angular size of a grid cell, radians

uniform float uCellPixels;    // grid cell size, pixels
// The rows: below the screen, where only waves tall enough to rise into view matter, cells
// kGridCoarseFactor times taller (render/OceanRenderer::draw); from just below the screen's
// bottom up, cells of uCellPixels.
uniform vec4 uGridRowsNdc;    // (bottom row, coarse rows' step, first fine row, fine rows' step), NDC
uniform int uGridCoarseRows;  // coarse rows (0: every row fine)

// The NDC position of grid vertex i (the grid overshoots the screen by uGridMarginNdc).
vec2 gridNdc(ivec2 i) {
  float x = mix(-1.0 - uGridMarginNdc.x, 1.0 + uGridMarginNdc.y, float(i.x) / float(uGridSize.x - 1));
  float y = i.y <= uGridCoarseRows ? uGridRowsNdc.x + float(i.y) * uGridRowsNdc.y
                                   : uGridRowsNdc.z + float(i.y - uGridCoarseRows) * uGridRowsNdc.w;
  return vec2(x, y);
}

GRID_OUT vec2 vOceanXY;            // undisplaced position in the ocean frame, m
GRID_OUT vec3 vRelative;           // displaced position relative to the eye, ECEF axes, m
// The patterns the vertices look up for the pixels (oceanVertexPatterns, ocean/patterns.glsl).
GRID_OUT vec2 vPatternMean;
GRID_OUT vec3 vPatternCov;
GRID_OUT vec2 vPatternJacobian;
GRID_OUT float vPatternShare[PATTERN_COUNT];
#ifndef PATTERN_BANDS_PER_PIXEL  // (else the pixels look the tables up themselves)
GRID_OUT vec2 vPatternBand[PATTERN_COUNT];              // patternBands at the vertex's wind
GRID_OUT vec3 vPatternAveragedFrom[PATTERN_COUNT + 1];
#endif

uniform vec3 uSunDirEcef;  // unit, ECEF axes
#ifndef OCEAN_SIMPLE_SKY
// Aerial perspective per vertex: smooth over a cell of a few pixels, and the costliest part
// of the sea's shading when evaluated per pixel (docs/performance.md).
#include "render/aerial.glsl"
GRID_OUT vec3 vTransmittance;      // of the eye-to-vertex path
GRID_OUT vec3 vInscatter;          // light scattered towards the eye along it (units of the Sun's irradiance)
#endif
#include "ocean/water_volume_vertex.glsl"  // the water volume's smooth terms per vertex

#ifdef OCEAN_RADIANCE_TERMS
// The sea's radiance at the vertex as a quadratic in a pixel's mean slope and covariance
// (ocean/radiance_terms.glsl), for the pixels of large cells, with the aerial perspective
// folded in: each term times the transmittance, the light scattered in added to the constant
// (and to the foam's radiance) so that the pixel's mix of the two needs neither.
GRID_OUT vec4 vRadianceTerms[SEA_RADIANCE_VEC4S];
void prepareRadianceTerms(vec2 xy, float pixelFootprintM, vec2 wind, PatternSums coarse, PatternBands bands) {
  SeaSurface sea = oceanSurface(xy, pixelFootprintM, wind, coarse, bands);  // a pixel's sea here
  // Expanded about the cell's mean slope (the vertices' patterns: the pixels' own average out
  // over a cell) and the covariance a pixel has here, in steps of the pixels' spread: the
  // slope variance the pixels resolve (what their BRDF does not hold), at least half the
  // BRDF's standard deviation (a vertex whose pixel keeps more than the sea's average would
  // take a tangent its neighbours' pixels extrapolate far: bright specks).
  vec2 cellSlope = frameVector(uPatternAmplitude * coarse.mean);
  vec2 total = seaSlopeVarianceTotal(wind.x);
  float kept = sea.covariance.x + sea.covariance.y;
  float spread = max(sqrt(max(0.5 * (total.x + total.y - kept), 0.125 * kept)), 1e-4);
  float dist = length(vRelative);
  vec3 v = -vRelative / dist;
  vec3 up = ellipsoidNormal(-v, dist);
  SeaPlace place = seaPlace(v, transpose(uEcefToOcean), windDirectionEcef(windAzimuthSinCos(wind), up), up, uSunDirEcef);
  SeaRadianceTerms t = seaRadianceTerms(place, cellSlope, sea.covariance, spread);
  vec3 foam = foamRadiance(place.p);
#ifndef OCEAN_SIMPLE_SKY
  foldAerialPerspective(t, foam, vTransmittance, vInscatter);
#endif
  packSeaRadianceTerms(t, foam, vRadianceTerms);
}
#endif
// Grid vertex `vertexId` (row after row); returns its clip-space position.
vec4 gridVertex(int vertexId) {
  int ix = vertexId % uGridSize.x;
  int iy = vertexId / uGridSize.x;
  vec2 ndc = gridNdc(ivec2(ix, iy));
  vec3 dir = cameraRay(ndc);
  float t = intersectEllipsoid(dir);
  if (t < 0.0) {
    // Above the horizon: lower the ray in its vertical plane until it grazes the sea.
    vec3 up = transpose(uEcefToOcean)[2];
    float r = WGS84_A;  // the dip angle hardly depends on which radius is used
    float dip = acos(clamp(r / (r + uEyeHeight), 0.0, 1.0)) + 1e-5;
    vec3 horizontal = normalize(dir - dot(dir, up) * up);
    dir = normalize(horizontal * cos(dip) - up * sin(dip));
    t = intersectEllipsoid(dir);
    if (t < 0.0) t = sqrt(uEyeHeight * (2.0 * r + uEyeHeight));
  }
  vec3 rel = t * dir;
  vec3 local = uEcefToOcean * rel + vec3(0.0, 0.0, uEyeHeight);
  // Projected size of a cell: along the view it is stretched by 1/cos(incidence).
  vec3 n = uEcefToOcean * ellipsoidNormal(dir, t);
  float cosIncidence = max(abs(dot(uEcefToOcean * dir, n)), 0.02);
  float pixelCell = t * uCellAngle / cosIncidence;  // a cell of uCellPixels
  float cell = iy < uGridCoarseRows ? pixelCell * (uGridRowsNdc.y / uGridRowsNdc.w) : pixelCell;
  vec2 latLon = latLonOfNormal(ellipsoidNormal(dir, t));
  vec2 wind = localWind(latLon);
  vec3 d = oceanDisplacement(local.xy, cell, wind) * shoreWaveFactor(latLon, seaStateWaveHeightM(wind.x), cell / WGS84_A);
  prepareWaterVolumeVertex(latLon, ellipsoidNormal(dir, t));
  prepareSeaClassVertex(latLon, rel, ivec2(ix, iy));  // the classes' draw only (OCEAN_SEA_CLASSIFY)
  // Displacement along the frame's axes; near the camera (where waves are resolved at all)
  // they coincide with the local tangent frame.
  vRelative = rel + transpose(uEcefToOcean) * d;
  vOceanXY = local.xy;
  PatternSums coarse = oceanVertexPatterns(local.xy, pixelCell / uCellPixels, wind);
  vPatternMean = coarse.mean;
  vPatternCov = coarse.cov;
  vPatternJacobian = coarse.jac;
  vPatternShare = coarse.share;
  PatternBands bands = patternBands(wind.x);
#ifndef PATTERN_BANDS_PER_PIXEL
  vPatternBand = bands.band;
  vPatternAveragedFrom = bands.averagedFrom;
#endif
#ifndef OCEAN_SIMPLE_SKY
  float dist = length(vRelative);
  aerialPerspective(vRelative / dist, dist, uSunDirEcef, vTransmittance, vInscatter);
#endif
#ifdef OCEAN_RADIANCE_TERMS
  prepareRadianceTerms(local.xy, pixelCell / uCellPixels, wind, coarse, bands);
  // Large cells of sub-pixel waves (render/OceanRenderer::layOutGridOnBlocks): the vertex on
  // its grid point, the cells' edges between the rasteriser's pixel blocks; the displaced
  // point (vRelative) shades.
  vec4 clip = uViewProjection * vec4(rel, 1.0);
  return vec4(ndc * clip.w, clip.zw);
#else
  return uViewProjection * vec4(vRelative, 1.0);
#endif
}
