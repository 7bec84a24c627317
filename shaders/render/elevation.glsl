// The elevation layer (relief and bathymetry, metres) as a lat/lon texture: shared by the globe
// pass (land/sea, land colours) and the ocean passes (no sea over land). Where the GSHHG land
// mask is bound (terrain/landmask.glsl) it decides the coast; the layer only gives heights.
#include "terrain/landmask.glsl"
layout(binding = OG_UNIT_ELEVATION) uniform sampler2D uElevation;  // metres, keepDepth; rows south to north
uniform vec4 uElevationMap;  // (lon0, lat0, dLon, dLat) in radians, cell centres
uniform vec2 uElevationSize; // (columns, rows)
uniform int uElevationWraps; // 1 when the columns cover 360 degrees

// Elevation at (latitude, longitude) in radians; outside a regional layer: -1 (sea).
float elevationAt(vec2 latLon) {
  vec2 cell = vec2((latLon.y - uElevationMap.x) / uElevationMap.z,
                   (latLon.x - uElevationMap.y) / uElevationMap.w);
  if (uElevationWraps == 1) cell.x = mod(cell.x, uElevationSize.x);
  vec2 uv = (cell + 0.5) / uElevationSize;
  if (uElevationWraps == 0 && (uv.x < 0.0 || uv.x > 1.0)) return -1.0;
  vec2 heightKeep = texture(uElevation, uv).rg;  // m; LatLonGrid::keepDepth
  return constrainByLandMask(heightKeep.x, heightKeep.y, latLon);
}
