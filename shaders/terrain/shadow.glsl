// Cast shadows of the terrain from the Sun: an orthographic depth map along the Sun's rays
// over the terrain in view (TerrainRenderer::renderShadowMap), looked up with 2x2 hardware
// comparisons at 4 offsets (a 3x3-texel soft edge, like the penumbra of relief a few km away).
layout(binding = 11) uniform sampler2DShadow uShadowMap;
uniform mat4 uShadowMatrix;   // camera-relative ECEF -> shadow map (uv in [0,1], depth [0,1])
uniform int uShadowOn;        // 0: no map this frame (Sun down, or seen from far out)
uniform float uShadowTexelM;  // texel size, m

// Fraction of the Sun seen from a point (camera-relative `rel`) with geometric normal `n`.
float sunVisibility(vec3 rel, vec3 n) {
  if (uShadowOn == 0) return 1.0;
  // Offset along the normal by a texel and a half: a surface never shadows itself.
  vec4 s = uShadowMatrix * vec4(rel + n * (1.5 * uShadowTexelM), 1.0);
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0))) || s.z <= 0.0) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0));
  float lit = 0.0;
  lit += texture(uShadowMap, vec3(s.xy + vec2(-0.5, -0.5) * texel, s.z));
  lit += texture(uShadowMap, vec3(s.xy + vec2(0.5, -0.5) * texel, s.z));
  lit += texture(uShadowMap, vec3(s.xy + vec2(-0.5, 0.5) * texel, s.z));
  lit += texture(uShadowMap, vec3(s.xy + vec2(0.5, 0.5) * texel, s.z));
  return 0.25 * lit;
}
