#version 450 core
// The projected grid's vertices as ocean/grid_vertices.comp computed them this frame
// (ocean/grid_vertex_buffer.glsl), for the deferred sea's surface pass: ocean/grid.vert's
// outputs without its work.
#define GRID_OUT out
#define GRID_FLAT_OUT flat out
#include "ocean/grid_vertex.glsl"  // the outputs' declarations (its code goes unused)
#include "ocean/grid_vertex_buffer.glsl"

void main() { gl_Position = loadGridVertex(gl_VertexID); }
