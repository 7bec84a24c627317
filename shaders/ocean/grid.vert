#version 450 core
// The projected grid's vertex shader (ocean/grid_vertex.glsl): each vertex computed as it is
// drawn (the forward sea; the deferred sea's surface pass reads them from the compute pass,
// ocean/grid_cached.vert).
#define GRID_OUT out
#define GRID_FLAT_OUT flat out
#include "ocean/grid_vertex.glsl"
// The same position in every program of the grid (the sea's classes: render/OceanRenderer).
invariant gl_Position;

void main() { gl_Position = gridVertex(gl_VertexID); }
