// The water volume's smooth terms per vertex of the projected grid (ocean/grid.vert), read by
// ocean/water_volume.glsl: they vary over kilometres, a grid cell spans a few pixels, and
// llvmpipe pays for every lookup per pixel (docs/performance.md). The sea floor's depth under
// the vertex (each pixel's search along its refracted ray starts there instead of marching
// from the surface), and the Sun's and the sky's irradiance at sea level (the atmosphere's
// tables, two lookups a pixel otherwise).
// Needs (included first): render/elevation.glsl, geo/ellipsoid.glsl; without OCEAN_SIMPLE_SKY
// uSunDirEcef.
#ifndef OCEAN_NO_WATER_VOLUME
GRID_OUT float vFloorDepthM;  // m below mean sea level, negative over land (the fine coast)
GRID_OUT float vFloorFine;    // 1 where the land mask's fine level moves the floor (water_volume.glsl)
#ifndef OCEAN_SIMPLE_SKY
#include "atmosphere/skymap.glsl"
GRID_OUT vec3 vWaterSunE;     // the Sun's irradiance at the vertex's Sun zenith (skymap.glsl's units)
GRID_OUT vec3 vWaterSkyE;     // the sky's, on a horizontal surface
#endif

void prepareWaterVolumeVertex(vec2 latLon, vec3 up) {
  // The floor at the mask's finest level, whatever the cell's size (grown cells span
  // kilometres): the search per pixel refines from here at the pixel's own footprint.
  vec2 heightKeep = elevationLayerAt(latLon);  // one lookup for both levels
  float heightM = constrainByLandMask(heightKeep.x, heightKeep.y, latLon, 0.0);
  vFloorDepthM = uElevationSize.x > 0.0 ? -heightM : 1e4;
  vFloorFine = abs(heightM - constrainByCoarseLandMask(heightKeep.x, heightKeep.y, latLon)) > 0.01 ? 1.0 : 0.0;
#ifndef OCEAN_SIMPLE_SKY
  float sunZenith = acos(clamp(dot(uSunDirEcef, up), -1.0, 1.0));
  vWaterSunE = sunIrradiance(sunZenith);
  vWaterSkyE = skyIrradiance(sunZenith);
#endif
}
#else
void prepareWaterVolumeVertex(vec2 latLon, vec3 up) {}
#endif

// The sea's classes (render/OceanRenderer's split, ocean/sea_classify.frag): whether land may lie
// within reach of the vertex (every triangle touching it is inside that radius), so that only
// triangles with a flagged vertex need the per-pixel coast test (ocean/coast.glsl). With the
// GSHHG mask the coast is its land fraction's 0.5 contour (terrain/landmask.glsl: the layer
// cannot make land where the fraction is below 0.5), and the fraction's quadratic B-spline
// changes by at most sqrt(2) per mask cell (its derivative is a linear spline of the cells'
// differences, each in [-1, 1]); without it, the layer's own height with its steepest slope
// (uLayerMaxSlope, m/m, from the CPU: render/WaterVolume's layerMaxSlope).
#ifdef OCEAN_SEA_CLASSIFY
uniform float uLayerMaxSlope;
uniform float uWaveReachM;  // how far the waves move a point of the grid, m (their amplitude bound)
// How far from land the terrain's shadows can fall on the sea or on the floor seen through it
// (render/OceanRenderer::shadowReachM), in two parts: the casters' height (m, with its margin),
// which each vertex divides by the tangent of its own Sun elevation (uSunDirEcef: a caster
// shades a sea point only from between it and the Sun, and farther where the Sun stands lower),
// and the rest (m: the floor's lookups, the maps' soft edge); negative: the frame's shadows are
// not routed (every class keeps them).
uniform float uShadowCasterHeightM;
uniform float uShadowBesideCastersM;
GRID_OUT float vNearLand;    // > 0 in triangles that may hold land (1 at a flagged vertex)
GRID_OUT float vNearShadow;  // > 0 in triangles that the terrain's shadows may reach

// The undisplaced point of grid vertex `i` (camera-relative, m): grid.vert's cast of its ray
// onto the ellipsoid, rays above the horizon lowered onto it.
vec3 seaClassGridPoint(ivec2 i) {
  vec2 ndc = gridNdc(clamp(i, ivec2(0), uGridSize - 1));
  vec3 dir = cameraRay(ndc);
  float t = intersectEllipsoid(dir);
  if (t < 0.0) {
    vec3 up = transpose(uEcefToOcean)[2];
    float dip = acos(clamp(WGS84_A / (WGS84_A + uEyeHeight), 0.0, 1.0)) + 1e-5;
    vec3 horizontal = normalize(dir - dot(dir, up) * up);
    dir = normalize(horizontal * cos(dip) - up * sin(dip));
    t = intersectEllipsoid(dir);
    if (t < 0.0) t = sqrt(uEyeHeight * (2.0 * WGS84_A + uEyeHeight));
  }
  return t * dir;
}

// How far from the undisplaced point `rel` of grid vertex `i` (column, row) any pixel of the
// triangles around it can lie:
// the farthest of its 8 neighbours' points (the triangles are their convex hulls) plus what the
// waves move the vertices by, m.
float seaClassReachM(vec3 rel, ivec2 i) {
  float most = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) most = max(most, distance(rel, seaClassGridPoint(i + ivec2(dx, dy))));
  return most + 2.0 * uWaveReachM;
}

// The vertex's grid row, for ocean/sea_classify.frag to record the rows of each class's pixels
// (the provoking vertex's: a triangle row r spans vertex rows r and r + 1).
GRID_FLAT_OUT int vGridRow;

// Whether a regional layer's border is within `reachM` of (latitude, longitude): the -1 m
// outside it is sea, but the slope bound does not hold across the border.
bool seaClassNearLayerBorder(vec2 latLon, float reachM) {
  if (uElevationWraps == 1) return false;
  vec2 cell = vec2((latLon.y - uElevationMap.x) / uElevationMap.z, (latLon.x - uElevationMap.y) / uElevationMap.w);
  vec2 margin = reachM / (WGS84_A * vec2(uElevationMap.z * max(cos(latLon.x), 1e-3), uElevationMap.w));
  return any(lessThan(cell, margin - 0.5)) || any(greaterThan(cell, uElevationSize - 0.5 - margin));
}

#include "render/open_sea_map.glsl"
// How far from (latitude, longitude) the land mask has no land (its fine cells included), m:
// the map's land clearance, radians to metres on the ellipsoid's tightest curvature
// (b² / a = 6335 km) less a margin.
float landClearanceM(vec2 latLon) { return 6.3e6 * openSeaMapAt(latLon).g; }

// Whether land may lie within `reachM` of (latitude, longitude) (1) or not (0).
float seaClassLandWithin(vec2 latLon, float reachM) {
  if (uElevationSize.x <= 0.0) return 0.0;  // no layer: sea everywhere (seaAt)
  if (landMaskOn()) {
    if (reachM < landClearanceM(latLon)) return 0.0;  // no land that near (one fetch, 7.5′ cells)
    float cellM = WGS84_A * PI / float(textureSize(uLandMask, 0).y);
    float perCell = reachM / (cellM * max(cos(latLon.x), 1e-3));
    return landFraction(latLon) + 1.4143 * perCell >= 0.5 ? 1.0 : 0.0;
  }
  bool nearLand = elevationAt(latLon) + uLayerMaxSlope * reachM >= 0.0;
  return nearLand || seaClassNearLayerBorder(latLon, reachM) ? 1.0 : 0.0;
}

// The flags of classes 2 and 4 (the terrain's shadows may reach) where shadows are routed, and
// of class 5 (land near: every feature) where the coast test is routed
// (ocean/sea_classify.frag), for grid vertex `i` (column, row) at `rel`.
void prepareSeaClassVertex(vec2 latLon, vec3 rel, ivec2 i) {
  float reachM = seaClassReachM(rel, i);
  vNearLand = seaClassLandWithin(latLon, reachM);
  // Every caster whose shadow may fall on the triangles lies in the disc around the point half
  // the casters' reach towards the Sun (its azimuth and elevation at the point: from 20 km up
  // the sea reaches hundreds of km, where both differ from the eye's), of radius the rest of the
  // reach (the segment towards the Sun, widened by the floor's and the triangles' reach): a
  // quarter of the disc round the point that holds them all, so sea whose land near lies away
  // from the Sun is open sea. With the Sun near the zenith, the disc round the point; with it
  // within ~1.6° of the horizon there, every point with land in reach at all keeps the shadows.
  vec2 sinCosLat = vec2(sin(latLon.x), cos(latLon.x)), sinCosLon = vec2(sin(latLon.y), cos(latLon.y));
  vec3 east = vec3(-sinCosLon.x, sinCosLon.y, 0.0);
  vec3 north = vec3(-sinCosLat.x * sinCosLon.y, -sinCosLat.x * sinCosLon.x, sinCosLat.y);
  vec3 up = vec3(sinCosLat.y * sinCosLon.y, sinCosLat.y * sinCosLon.x, sinCosLat.x);
  float elevation = asin(clamp(dot(uSunDirEcef, up), -1.0, 1.0)) - 0.01;  // as shadowReachM's
  bool low = elevation < 0.0175;
  float towards = low ? 0.0 : uShadowCasterHeightM / tan(elevation);
  float besideM = uShadowBesideCastersM + (low ? 1e7 : 0.0);
  vec2 sunEastNorth = vec2(dot(uSunDirEcef, east), dot(uSunDirEcef, north));
  float horizontal = length(sunEastNorth);
  float halfTowards = horizontal > 1e-3 ? 0.5 * towards : 0.0;
  vec2 d = halfTowards * sunEastNorth / max(horizontal, 1e-3) / WGS84_A;  // radians east, north
  float lon = latLon.y + d.x / max(sinCosLat.y, 1e-3);
  vec2 centre = vec2(clamp(latLon.x + d.y, -0.5 * PI, 0.5 * PI), lon - 2.0 * PI * floor((lon + PI) / (2.0 * PI)));
  vNearShadow = uShadowBesideCastersM < 0.0 ? 0.0 : seaClassLandWithin(centre, reachM + besideM + towards - halfTowards);
  vGridRow = i.y;
}
#else
// Whether a regional layer's border is within `reachM` of (latitude, longitude): the -1 m
// outside it is sea, but the slope bound does not hold across the border.
bool seaClassNearLayerBorder(vec2 latLon, float reachM) {
  if (uElevationWraps == 1) return false;
  vec2 cell = vec2((latLon.y - uElevationMap.x) / uElevationMap.z, (latLon.x - uElevationMap.y) / uElevationMap.w);
  vec2 margin = reachM / (WGS84_A * vec2(uElevationMap.z * max(cos(latLon.x), 1e-3), uElevationMap.w));
  return any(lessThan(cell, margin - 0.5)) || any(greaterThan(cell, uElevationSize - 0.5 - margin));
}

void prepareSeaClassVertex(vec2 latLon, vec3 rel, ivec2 i) {}
#endif
