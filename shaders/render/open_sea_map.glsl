// render/OpenSeaMap on the GPU (OpenSeaTexture): per 7.5′ cell (columns from 180° W eastwards,
// rows from 90° S northwards), .r the great-circle radius (rad) around any point of it holding
// only open deep sea (render/globe.frag's open-sea part), .g the same around land alone, the
// land mask's fine cells included (ocean/water_volume_vertex.glsl's sea classes); 0: none.
layout(binding = OG_UNIT_OPEN_SEA) uniform sampler2D uOpenSea;

// The map's texel under (latitude, longitude), radians.
vec2 openSeaMapAt(vec2 latLon) {
  const float perDeg = float(OG_OPEN_SEA_CELLS_PER_DEG);
  vec2 cell = floor(degrees(vec2(latLon.y + PI, latLon.x + 0.5 * PI)) * perDeg);
  return texelFetch(uOpenSea, ivec2(clamp(cell, vec2(0.0), vec2(360.0, 180.0) * perDeg - 1.0)), 0).rg;
}
