// The elevation layer (relief and bathymetry, metres) as a lat/lon texture: shared by the globe
// pass (land/sea, land colours) and the ocean passes (no sea over land). Where the GSHHG land
// mask is bound (terrain/landmask.glsl) it decides the coast; the layer only gives heights.
#include "terrain/landmask.glsl"
layout(binding = OG_UNIT_ELEVATION) uniform sampler2D uElevation;  // metres, keepDepth; rows south to north
uniform vec4 uElevationMap;  // (lon0, lat0, dLon, dLat) in radians, cell centres
uniform vec2 uElevationSize; // (columns, rows)
uniform int uElevationWraps; // 1 when the columns cover 360 degrees

// The layer's (height m, keepDepth) at (latitude, longitude) in radians; outside a regional
// layer: (-1, 0), sea.
vec2 elevationLayerAt(vec2 latLon) {
  vec2 cell = vec2((latLon.y - uElevationMap.x) / uElevationMap.z,
                   (latLon.x - uElevationMap.y) / uElevationMap.w);
  if (uElevationWraps == 1) cell.x = mod(cell.x, uElevationSize.x);
  vec2 uv = (cell + 0.5) / uElevationSize;
  if (uElevationWraps == 0 && (uv.x < 0.0 || uv.x > 1.0)) return vec2(-1.0, 0.0);
  return texture(uElevation, uv).rg;  // m; LatLonGrid::keepDepth
}

// Elevation at (latitude, longitude) in radians as a footprint of `footprintRad` (radians of
// arc on the ground) sees the coast (terrain/landmask.glsl); outside a regional layer: -1 (sea).
float elevationAt(vec2 latLon, float footprintRad) {
  vec2 heightKeep = elevationLayerAt(latLon);
  return constrainByLandMask(heightKeep.x, heightKeep.y, latLon, footprintRad);
}
// At the 2′ level's coast, for readers that blur over kilometres anyway and run often (the
// water's depth along a pixel's ray, the shore's waves): the coast itself is decided with a
// footprint. Without the fine level's code, which llvmpipe would run masked.
float elevationAt(vec2 latLon) {
  vec2 heightKeep = elevationLayerAt(latLon);
  return constrainByCoarseLandMask(heightKeep.x, heightKeep.y, latLon);
}
