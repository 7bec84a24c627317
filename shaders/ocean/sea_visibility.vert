#version 450 core
// The visibility buffer's surface pass (ocean/sea_visibility.glsl): the projected grid's
// vertices as ocean/grid_vertices.comp computed them this frame, their positions alone.
#define GRID_OUT
#define GRID_FLAT_OUT
#include "ocean/grid_vertex.glsl"  // the buffer's layout needs its outputs' declarations
#include "ocean/grid_vertex_buffer.glsl"

void main() { gl_Position = texelFetch(uGridVertexTexels, gl_VertexID * GRID_VERTEX_VEC4S); }
