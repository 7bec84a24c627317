#version 450 core
// HDR radiance -> 8-bit sRGB for PNG output and the window (render/GlobeRenderer's display
// target, GL_SRGB8_ALPHA8, whose store encodes sRGB: GL_FRAMEBUFFER_SRGB on for this draw).
// Multisampled radiance is tone mapped per sample, then averaged: averaging linear HDR first
// lets a bright sample (sky) dominate the pixel, so bright-dark edges step again after the
// tone curve.
#include "common/color.glsl"
#ifdef TONEMAP_MULTISAMPLE
layout(binding = OG_UNIT_TONE_RADIANCE) uniform sampler2DMS uRadiance;
#else
layout(binding = OG_UNIT_TONE_RADIANCE) uniform sampler2D uRadiance;
#endif
uniform float uExposure;
out vec4 fragColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef TONEMAP_MULTISAMPLE
  int n = textureSamples(uRadiance);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; ++i) sum += toneMap(texelFetch(uRadiance, p, i).rgb, uExposure);
  fragColor = vec4(sum / float(n), 1.0);  // (the sRGB target's store encodes it)
#else
  vec4 hdr = texelFetch(uRadiance, p, 0);
  fragColor = vec4(toneMap(hdr.rgb, uExposure), 1.0);  // (the sRGB target's store encodes it)
#endif
}
