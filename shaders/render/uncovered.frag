#version 450 core
// Finds whether any pixel is left for the globe below 20 km (GlobeRenderer::classifyGlobe): drawn
// over the whole screen behind the terrain and the grid inside an occlusion query, it passes
// only where they left the far depth. Depth-tested before the shader, which does nothing.
layout(early_fragment_tests) in;
void main() {}
