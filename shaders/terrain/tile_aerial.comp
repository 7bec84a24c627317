#version 450 core
// The aerial perspective of every vertex of the frame's terrain tiles (terrain/tile_vertex.glsl),
// into the frame's tile aerial buffer: what terrain/terrain.vert computed per vertex, on every
// core instead of the draw's one thread (render/TerrainRenderer::computeTileAerial). One
// dispatch for all the tiles, a row of work groups a tile (llvmpipe's dispatches each cost
// ~0.2 ms of waiting): tile k's vertices from k x uVertexCount on in the frame's copy of their
// buffers and in the aerial buffer (tile_aerial.glsl's slots, uFirstVertex = k x uVertexCount).
#define TERRAIN_AERIAL_STORE
#include "common/constants.glsl"
#include "common/types.glsl"
#include "atmosphere/model.glsl"
#include "render/aerial.glsl"
#include "terrain/tile_vertex.glsl"
#include "terrain/tile_grid.glsl"
layout(local_size_x = 64) in;

uniform int uVertexCount;  // a tile's
// Per tile: its centre minus the eye (m) and its morph scale, as its draws' uTileOffset and
// uMorphScale.
layout(std430, binding = OG_TILE_AERIAL_TILES_BINDING) readonly buffer TileAerialTiles { vec4 tileAerialTiles[]; };

void main() {
  int tile = int(gl_WorkGroupID.y);
  int i = int(gl_GlobalInvocationID.x);
  if (i >= uVertexCount) return;
  int v = tile * uVertexCount + i;
  vec4 t = tileAerialTiles[tile];
  float heightM;
  vec3 relative = morphedTileVertexOf(t.xyz, t.w, tileVertexVec3(v, TILE_VERTEX_POSITION), tileVertexInfo(v),
                                      tileVertexVec3(v, TILE_VERTEX_MORPH), heightM);
  vec3 transmittance, inscatter;
  tileVertexAerial(relative, heightM, transmittance, inscatter);
  tileAerial[tileAerialSlotOf(v)] = vec4(transmittance, 0.0);
  tileAerial[tileAerialSlotOf(v) + 1] = vec4(inscatter, 0.0);
}
