#version 450 core
// The overlay image (non-premultiplied RGBA8), drawn pixel for pixel with alpha blending.
layout(binding = OG_UNIT_OVERLAY_TEXT) uniform sampler2D uText;
in vec2 vUv;
out vec4 fragColor;
void main() { fragColor = texture(uText, vUv); }
