#version 450 core
// Triangles given in normalised device coordinates (render/GlobeBlocks: the globe's
// classifying draws over blocks of pixels); vNdc as render/fullscreen.vert gives it.
layout(location = 0) in vec2 aNdc;
out vec2 vNdc;
void main() {
  vNdc = aNdc;
  gl_Position = vec4(aNdc, 0.0, 1.0);
}
