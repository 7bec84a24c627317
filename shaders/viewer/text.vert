#version 450 core
// One quad (triangle strip, 4 vertices) covering uRect = (x0, y0, x1, y1) in NDC; vUv has
// v = 0 at the top edge, matching the overlay image's rows (top first).
uniform vec4 uRect;
out vec2 vUv;
void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1));
  vUv = vec2(corner.x, 1.0 - corner.y);
  gl_Position = vec4(mix(uRect.xy, uRect.zw, corner), 0.0, 1.0);
}
