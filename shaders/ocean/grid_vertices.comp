#version 450 core
// The projected grid's vertices for the deferred sea's surface pass, all at once
// (ocean/grid_vertex_buffer.glsl): ocean/grid_vertex.glsl's gridVertex per invocation, its
// outputs stored for ocean/grid_cached.vert.
#define GRID_OUT
#define GRID_FLAT_OUT
#define GRID_VERTEX_STORE
#include "ocean/grid_vertex.glsl"
#include "ocean/grid_vertex_buffer.glsl"
layout(local_size_x = 64) in;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= uGridSize.x * uGridSize.y) return;
  storeGridVertex(i, gridVertex(i));
}
