#version 450 core
// The sea's pixels of the blocks render/sea_lattice.comp passed, drawn over the sea's and the
// open sea's blocks before their parts: the lattice's radiance (every 4 pixels,
// render/globe.frag's GLOBE_LATTICE) interpolated bilinearly by the sampler at the pixel's
// centre; the others are discarded and left to the part (render/SeaLattice). No early
// fragment tests: a discarded pixel keeps its stencil value.
#include "render/outputs.glsl"
layout(binding = OG_UNIT_SEA_LATTICE) uniform sampler2D uLattice;  // radiance, whitecaps
layout(binding = OG_UNIT_SEA_LATTICE_BLOCKS) uniform usampler2D uBlockInterpolated;
void main() {
  if (texelFetch(uBlockInterpolated, ivec2(gl_FragCoord.xy) >> 3, 0).r == 0u) discard;
  // Lattice point i lies at the frame's pixel coordinate 4 i, its texel's centre at (i + 0.5) / size.
  vec4 v = texture(uLattice, (gl_FragCoord.xy * 0.25 + 0.5) / vec2(textureSize(uLattice, 0)));
  fragRadiance = vec4(v.rgb, 1.0);
  fragAux = vec4(v.a, 0.0, 0.0, 0.0);
}
