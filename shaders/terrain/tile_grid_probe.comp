#version 450 core
// Evaluates terrain/tile_grid.glsl for a tile's vertex buffer (bound as TileVertices), for
// tests against the tile's vertices on the CPU (tests/gl/tile_grid_gpu_test.cpp).
#include "terrain/tile_grid.glsl"

layout(std430, binding = 0) buffer ProbeValues { vec4 probeValues[]; };

layout(local_size_x = 1) in;
// In: w = 0: x = a vertex's index, its place from tileGridPlace; w = 1: xy = a place in the grid.
// Out: xyz = the normal there, w = the height (lowered down a skirt), as terrain.frag takes them
// (TERRAIN_COARSE).
// In: w = 2: xy = a place in the grid. Out: x = the detail amplitude there.

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 in_ = probeValues[i];
  vec3 place = in_.w == 0.0 ? tileGridPlace(int(in_.x)) : vec3(in_.xy, 0.0);
  TileGridSample s = tileGridSample(tileGridTriangle(place.xy), place.z);
  probeValues[i] = in_.w == 2.0 ? vec4(s.detailAmplitudeM, 0.0, 0.0, 0.0) : s.normalHeight;
}
