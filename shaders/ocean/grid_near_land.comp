#version 450 core
// The deferred sea's surface pass in three draws (render/OceanRenderer::drawDeferred): the
// grid's triangles where land may be near (a vertex flagged by ocean/water_volume_vertex.glsl's
// seaClassLandWithin, so vNearLand > 0 inside), the others with a vertex whose floor is within
// the water's reach (the floor classes' triangles: ocean/sea_class.glsl's test on the
// interpolated depth, whose least is at a vertex), and the rest, as three copies of the grid's
// index list in which the other draws' triangles are degenerate (three times vertex 0: culled
// before any fragment), in the same order. llvmpipe runs every line of a fragment shader
// for every pixel whatever its conditions (docs/performance.md, "Ninth session"), so the coast
// test, compiled only into the near-land draw's program, costs those triangles' pixels alone,
// and the rest write the surface buffer's compact layout without the water's terms.
#define GRID_OUT
#define GRID_FLAT_OUT
#include "ocean/grid_vertex.glsl"  // the buffer's layout needs its outputs' declarations
#include "ocean/grid_vertex_buffer.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 5) readonly buffer GridIndices { uint gridIndices[]; };  // the grid's own
layout(std430, binding = 6) writeonly buffer FloorIndices { uint floorIndices[]; };
layout(std430, binding = 7) writeonly buffer NearLandIndices { uint nearLandIndices[]; };
layout(std430, binding = 3) writeonly buffer DeepIndices { uint deepIndices[]; };
uniform int uTriangleCount;

void main() {
  int t = int(gl_GlobalInvocationID.x);
  if (t >= uTriangleCount) return;
  uvec3 tri = uvec3(gridIndices[3 * t], gridIndices[3 * t + 1], gridIndices[3 * t + 2]);
  bool near = gridVertexNearLand(int(tri.x)) || gridVertexNearLand(int(tri.y)) || gridVertexNearLand(int(tri.z));
  bool floor = gridVertexFloor(int(tri.x)) || gridVertexFloor(int(tri.y)) || gridVertexFloor(int(tri.z));
  // A draw's other triangles all at vertex 0: its vertices shaded are its own triangles' (and
  // vertex 0's), not the whole grid's.
  const uvec3 none = uvec3(0u);
  uvec3 landward = near ? tri : none, floorward = !near && floor ? tri : none, deep = !near && !floor ? tri : none;
  for (int k = 0; k < 3; ++k) {
    floorIndices[3 * t + k] = floorward[k];
    nearLandIndices[3 * t + k] = landward[k];
    deepIndices[3 * t + k] = deep[k];
  }
}
