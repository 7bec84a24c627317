#version 450 core
// Lists the pixels that pass the stencil test (one of the globe's scattered parts) for
// render/globe.frag's compute variant (render/globe_pixels.glsl). Tested before the shader;
// it writes no colour.
layout(early_fragment_tests) in;
#include "render/globe_pixels.glsl"
void main() {
  uint i = atomicAdd(uCount, 1u);
  uPixels[i] = uint(gl_FragCoord.x) | (uint(gl_FragCoord.y) << 16);
}
