#version 450 core
// A flat screen-filling triangle at a given distance in front of the eye (view space), for
// depth-precision checks and debug overlays. Positions are camera-relative, never world.
uniform mat4 uViewProjection;
uniform float uDistance;  // metres along the view axis
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
  // Scale x, y with distance so the triangle covers the view at any depth.
  gl_Position = uViewProjection * vec4(p * uDistance * 2.0, -uDistance, 1.0);
}
