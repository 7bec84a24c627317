#version 450 core
// HDR radiance -> 8-bit sRGB for PNG output and the window.
#include "common/color.glsl"
layout(binding = 0) uniform sampler2D uRadiance;
uniform float uExposure;
out vec4 fragColor;
void main() {
  vec4 hdr = texelFetch(uRadiance, ivec2(gl_FragCoord.xy), 0);
  fragColor = vec4(linearToSrgb(toneMap(hdr.rgb, uExposure)), 1.0);
}
