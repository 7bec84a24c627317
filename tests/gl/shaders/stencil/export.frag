#version 450 core
// Writes the stencil value, as the globe's and the sea's classifying programs do: compiles
// only where gl::Program defines OG_STENCIL_EXPORT (GlShader.StencilExportOnlyWhereTheDriverHasIt).
#if defined(OG_STENCIL_EXPORT)
#extension GL_ARB_shader_stencil_export : require
#endif
void main() { gl_FragStencilRefARB = 1; }
