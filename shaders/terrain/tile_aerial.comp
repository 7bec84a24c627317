#version 450 core
// The aerial perspective of every vertex of a terrain tile (terrain/tile_vertex.glsl), into
// the frame's tile aerial buffer at uFirstVertex: what terrain/terrain.vert computed per vertex,
// on every core instead of the draw's one thread (render/TerrainRenderer::computeTileAerial).
#define TERRAIN_AERIAL_STORE
#include "common/constants.glsl"
#include "common/types.glsl"
#include "atmosphere/model.glsl"
#include "render/aerial.glsl"
#include "terrain/tile_vertex.glsl"
#include "terrain/tile_grid.glsl"
layout(local_size_x = 64) in;

uniform int uVertexCount;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= uVertexCount) return;
  float heightM;
  vec3 relative = morphedTileVertex(tileVertexVec3(i, TILE_VERTEX_POSITION), tileVertexInfo(i),
                                    tileVertexVec3(i, TILE_VERTEX_MORPH), heightM);
  vec3 transmittance, inscatter;
  tileVertexAerial(relative, heightM, transmittance, inscatter);
  tileAerial[tileAerialSlot(i)] = vec4(transmittance, 0.0);
  tileAerial[tileAerialSlot(i) + 1] = vec4(inscatter, 0.0);
}
