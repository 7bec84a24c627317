#version 450 core
// The visibility buffer's surface pass (ocean/sea_visibility.glsl): each pixel's nearest grid
// triangle (depth-tested against the terrain), its index in the grid's index list + 1 (the grid
// drawn whole, from its first triangle, or the deep third of splitNearLand's copies, which keep
// the order: render/OceanRenderer::drawDeferred). 0 stays where no sea was drawn (the buffer is
// cleared).
// SEA_VISIBILITY_CLASSES: the deep triangles of a frame in classes (no floor within reach, no
// land near), their class exported: the open sea's or the shadows' through the visibility
// buffer (OceanRenderer::kVisibilityClass and the next; ocean/sea_class.glsl's test).
#if defined(SEA_VISIBILITY_CLASSES) && defined(OG_STENCIL_EXPORT)  // (OG_STENCIL_EXPORT: gl::Program)
#extension GL_ARB_shader_stencil_export : require
#endif
#ifdef SEA_VISIBILITY_CLASSES
layout(location = 0) in float vNearShadow;  // > 0 where the terrain's shadows may reach into the triangle
uniform int uVisibilityClass;
// Whether each of the two classes has a pixel (after ocean/sea_class.glsl's rows: the same buffer,
// OceanRenderer::resetClassRows), so that an empty one's full-screen pass is not drawn.
layout(std430, binding = 3) buffer SeaVisibilityClasses {
  int seaClassRows[10];
  int seaVisibilityClassSeen[2];
};
#endif
layout(location = 0) out uint seaTriangle;

void main() {
  seaTriangle = uint(gl_PrimitiveID) + 1u;
#ifdef SEA_VISIBILITY_CLASSES
  int k = vNearShadow > 0.0 ? 1 : 0;
  gl_FragStencilRefARB = uVisibilityClass + k;
  if (seaVisibilityClassSeen[k] == 0) seaVisibilityClassSeen[k] = 1;  // (every writer writes 1)
#endif
}
