#version 450 core
// The deferred sea's classes into the stencil where the driver cannot export stencil values
// from a fragment shader (no GL_ARB_shader_stencil_export: NVIDIA's drivers): one full-screen
// pass per bit of the class (1..5: three), writing that stencil bit (render/OceanRenderer's
// drawDeferred sets the write mask) where the pixel's class, in the lowest three bits of the
// surface buffer's layer 0's footprint (ocean/sea_surface.glsl's SEA_CLASS_BITS,
// SEA_CLASS_IN_SURFACE; 0 where no sea was drawn), has it.
layout(binding = OG_UNIT_SEA_SURFACE) uniform usampler2DArray uSeaSurface;
uniform int uClassBit;  // the bit this pass writes, 0..2

void main() {
  uint seaClass = texelFetch(uSeaSurface, ivec3(ivec2(gl_FragCoord.xy), 0), 0).y & uint(OG_SEA_CLASS_BITS);
  if ((seaClass & (1u << uint(uClassBit))) == 0u) discard;
}
