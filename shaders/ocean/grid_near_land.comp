#version 450 core
// The deferred sea's surface pass in two draws (render/OceanRenderer::drawDeferred): the grid's
// triangles where land may be near (a vertex flagged by ocean/water_volume_vertex.glsl's
// seaClassLandWithin, so vNearLand > 0 inside) and the others, as two copies of the grid's index
// list in which the other draw's triangles are degenerate (three times the same index: culled
// before any fragment), in the same order. llvmpipe runs every line of a fragment shader for
// every pixel whatever its conditions (docs/performance.md, "Ninth session"), so the coast test,
// compiled only into the near-land draw's program, costs those triangles' pixels alone.
#define GRID_OUT
#define GRID_FLAT_OUT
#include "ocean/grid_vertex.glsl"  // the buffer's layout needs its outputs' declarations
#include "ocean/grid_vertex_buffer.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 5) readonly buffer GridIndices { uint gridIndices[]; };  // the grid's own
layout(std430, binding = 6) writeonly buffer OpenIndices { uint openIndices[]; };
layout(std430, binding = 7) writeonly buffer NearLandIndices { uint nearLandIndices[]; };
uniform int uTriangleCount;

void main() {
  int t = int(gl_GlobalInvocationID.x);
  if (t >= uTriangleCount) return;
  uvec3 tri = uvec3(gridIndices[3 * t], gridIndices[3 * t + 1], gridIndices[3 * t + 2]);
  bool near = gridVertexNearLand(int(tri.x)) || gridVertexNearLand(int(tri.y)) || gridVertexNearLand(int(tri.z));
  uvec3 open = near ? tri.xxx : tri, landward = near ? tri : tri.xxx;
  for (int k = 0; k < 3; ++k) {
    openIndices[3 * t + k] = open[k];
    nearLandIndices[3 * t + k] = landward[k];
  }
}
