// render/OpenSeaMap on the GPU (OpenSeaTexture): per 1° cell (columns from 180° W eastwards,
// rows from 90° S northwards), .r the great-circle radius (rad) around any point of it holding
// only open deep sea (render/globe.frag's open-sea part), .g the same around land alone, the
// land mask's fine cells included (ocean/water_volume_vertex.glsl's sea classes); 0: none.
layout(binding = OG_UNIT_OPEN_SEA) uniform sampler2D uOpenSea;

// The map's texel under (latitude, longitude), radians.
vec2 openSeaMapAt(vec2 latLon) {
  vec2 cell = floor(degrees(vec2(latLon.y + PI, latLon.x + 0.5 * PI)));
  return texelFetch(uOpenSea, ivec2(clamp(cell, vec2(0.0), vec2(359.0, 179.0))), 0).rg;
}
