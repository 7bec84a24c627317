#version 450 core
// The visibility buffer's surface pass (ocean/sea_visibility.glsl): the projected grid's
// vertices as ocean/grid_vertices.comp computed them this frame, their positions alone (and
// with SEA_VISIBILITY_CLASSES their shadows' flag: ocean/sea_visibility.frag).
#define GRID_OUT
#define GRID_FLAT_OUT
#include "ocean/grid_vertex.glsl"  // the buffer's layout needs its outputs' declarations
#include "ocean/grid_vertex_buffer.glsl"
#ifdef SEA_VISIBILITY_CLASSES
layout(location = 0) out float vNearShadowOut;  // (the fragment shader's vNearShadow)
#endif

void main() {
  int at = gl_VertexID * GRID_VERTEX_VEC4S;
  gl_Position = texelFetch(uGridVertexTexels, at);
#ifdef SEA_VISIBILITY_CLASSES
  vNearShadowOut = texelFetch(uGridVertexTexels, at + 9).x;  // (storeGridVertex's vNearShadow)
#endif
}
