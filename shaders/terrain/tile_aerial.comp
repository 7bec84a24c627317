#version 450 core
// The aerial perspective of the vertices of the frame's terrain tiles (terrain/tile_vertex.glsl)
// that the eye may see, into the frame's tile aerial buffer: what terrain/terrain.vert computed
// per vertex, on every core instead of the draw's one thread
// (render/TerrainRenderer::computeTileAerial). One dispatch for all the tiles (llvmpipe's
// dispatches each cost ~0.2 ms of waiting) over a list of those vertices: tile k's from
// k x TILE_VERTEX_COUNT on in the frame's copy of their buffers and in the aerial buffer
// (tile_aerial.glsl's slots, uFirstVertex = k x TILE_VERTEX_COUNT).
#define TERRAIN_AERIAL_STORE
#include "common/constants.glsl"
#include "common/types.glsl"
#include "atmosphere/model.glsl"
#include "render/aerial.glsl"
#include "terrain/tile_vertex.glsl"
#include "terrain/tile_grid.glsl"
layout(local_size_x = 64) in;

// Per tile: its centre minus the eye (m) and its morph scale, as its draws' uTileOffset and
// uMorphScale.
layout(std430, binding = OG_TILE_AERIAL_TILES_BINDING) readonly buffer TileAerialTiles { vec4 tileAerialTiles[]; };

// The vertices to do: their indices among the frame's (tile k's from k x TILE_VERTEX_COUNT
// on), those the eye may see (render/TerrainRenderer::listTileAerialVertices; llvmpipe runs
// every invocation dispatched in full, those that return at once too), in rows of work groups.
layout(std430, binding = OG_TILE_AERIAL_LIST_BINDING) readonly buffer TileAerialList { int tileAerialList[]; };
uniform int uListed;  // the list's length

void main() {
  int at = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64 + int(gl_LocalInvocationID.x);
  if (at >= uListed) return;
  int v = tileAerialList[at];
  vec4 t = tileAerialTiles[v / TILE_VERTEX_COUNT];  // (llvmpipe divides by a uniform lane by lane)
  float heightM;
  vec3 relative = morphedTileVertexOf(t.xyz, t.w, tileVertexVec3(v, TILE_VERTEX_POSITION), tileVertexInfo(v),
                                      tileVertexVec3(v, TILE_VERTEX_MORPH), heightM);
  vec3 transmittance, inscatter;
  tileVertexAerial(relative, heightM, transmittance, inscatter);
  tileAerial[tileAerialSlotOf(v)] = vec4(transmittance, 0.0);
  tileAerial[tileAerialSlotOf(v) + 1] = vec4(inscatter, 0.0);
}
