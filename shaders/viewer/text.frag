#version 450 core
// The overlay image (non-premultiplied RGBA8), drawn pixel for pixel with alpha blending.
uniform sampler2D uText;
in vec2 vUv;
out vec4 fragColor;
void main() { fragColor = texture(uText, vUv); }
