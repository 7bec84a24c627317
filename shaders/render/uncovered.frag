#version 450 core
// Finds whether any pixel is left for the globe below 20 km (GlobeRenderer::classifyGlobe): drawn
// over the whole screen (with sky in view, over the box of rays that meet the ellipsoid) behind
// the terrain and the grid inside an occlusion query, it passes only where they left the far
// depth. Depth-tested before the shader, which does nothing but,
// with UNCOVERED_BLOCKS, flag the 8 x 8 block of pixels that holds the fragment where it lies
// within the classifying draw's box (render/UncoveredPixels: render/uncovered_blocks.comp
// lists the flagged blocks for that draw).
layout(early_fragment_tests) in;
#ifdef UNCOVERED_BLOCKS
#include "render/uncovered_blocks.glsl"
uniform ivec4 uBox;  // pixels: x0, y0, x1, y1 (exclusive)
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (all(greaterThanEqual(p, uBox.xy)) && all(lessThan(p, uBox.zw)))
    uFlags[(p.y >> 3) * uBlocksPerRow + (p.x >> 3)] = 1u;
}
#else
void main() {}
#endif
