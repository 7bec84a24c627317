// The tile aerial buffer (TERRAIN_AERIAL_BUFFER; written by terrain/tile_aerial.comp,
// TERRAIN_AERIAL_STORE): per vertex of the frame's tiles the eye may see, at uFirstVertex +
// its index, the transmittance and the in-scatter of the eye's path to it as two vec4s
// (render/TerrainRenderer::computeTileAerial; the others' slots hold what they held).
#if defined(TERRAIN_AERIAL_BUFFER) || defined(TERRAIN_AERIAL_STORE)
#ifdef TERRAIN_AERIAL_STORE
layout(std430, binding = OG_TERRAIN_AERIAL_BINDING) writeonly buffer TileAerial { vec4 tileAerial[]; };
#else
layout(std430, binding = OG_TERRAIN_AERIAL_BINDING) readonly buffer TileAerial { vec4 tileAerial[]; };
#endif
uniform int uFirstVertex;  // the tile's first vertex in the buffer

// Where the frame's vertex `frameVertex` (its tile's uFirstVertex + its index) has its
// transmittance in the buffer (its in-scatter: the next); tileAerialSlot: the tile's `vertex`.
int tileAerialSlotOf(int frameVertex) { return 2 * frameVertex; }
int tileAerialSlot(int vertex) { return tileAerialSlotOf(uFirstVertex + vertex); }
#endif
