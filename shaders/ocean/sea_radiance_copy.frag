#version 450 core
// A multisampled frame's deferred sea (render/OceanRenderer::drawDeferred with the visibility
// buffer, ocean/sea_visibility.glsl): each pixel's sea radiance, shaded once into a
// single-sampled image, written to the pixel's samples with sea (the stencil's class, per
// sample), as a forward draw's fragment is written to the samples its triangle covers.
layout(binding = OG_UNIT_SEA_SURFACE) uniform sampler2D uSeaRadiance;
#include "render/outputs.glsl"

void main() {
  fragRadiance = texelFetch(uSeaRadiance, ivec2(gl_FragCoord.xy), 0);
  fragAux = vec4(0.0);  // (unattached: the visibility buffer's multisampled frames have no --aov)
}
