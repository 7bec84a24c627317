// Cast shadows of the terrain from the Sun: orthographic depth maps along the Sun's rays over
// the terrain in view (TerrainRenderer::renderShadowMap), two cascades (near: an eighth of the
// far one's reach), looked up with 2x2 hardware comparisons at 4 offsets (a 3x3-texel soft
// edge, like the penumbra of relief a few km away).
const int SHADOW_CASCADES = 2;
layout(binding = OG_UNIT_SHADOW_MAP) uniform sampler2DArrayShadow uShadowMap;
uniform mat4 uShadowMatrix[SHADOW_CASCADES];  // camera-relative ECEF -> uv of the cascade's texels, depth [0,1]
uniform float uShadowTexelM[SHADOW_CASCADES]; // texel size, m
// The part of a cascade's map its lookups may read, (u0, v0, u1, v1) of uv: its first texels
// (TerrainRenderer::shadowCascadeTexels: fewer where the screen does not resolve them), over
// the receivers the screen shows (render/ShadowReceivers); outside it every point is lit.
uniform vec4 uShadowCropUv[SHADOW_CASCADES];
uniform float uShadowSplitM;  // distance from the eye where the near cascade hands over, m
uniform int uShadowOn;        // 0: no maps this frame (Sun down, or seen from far out)

// The maps' answer for a point (camera-relative `rel`) with geometric normal `n`.
float sunVisibilityFromMaps(vec3 rel, vec3 n) {
  int c = length(rel) < uShadowSplitM ? 0 : 1;
  // Offset along the normal by a texel and a half: a surface never shadows itself.
  vec4 s = uShadowMatrix[c] * vec4(rel + n * (1.5 * uShadowTexelM[c]), 1.0);
  if (any(lessThan(s.xy, uShadowCropUv[c].xy)) || any(greaterThan(s.xy, uShadowCropUv[c].zw)) || s.z <= 0.0) return 1.0;
  // A point farther from the Sun than every caster (depth beyond 1: the open sea between the
  // eye and a far coast towards a low Sun) is lit unless a caster stands over it: the cleared
  // map's 1 must pass the comparison (a float depth map does not clamp the reference).
  s.z = min(s.z, 1.0);
  vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0).xy);
  float layer = float(c);
  float lit = 0.0;
  lit += texture(uShadowMap, vec4(s.xy + vec2(-0.5, -0.5) * texel, layer, s.z));
  lit += texture(uShadowMap, vec4(s.xy + vec2(0.5, -0.5) * texel, layer, s.z));
  lit += texture(uShadowMap, vec4(s.xy + vec2(-0.5, 0.5) * texel, layer, s.z));
  lit += texture(uShadowMap, vec4(s.xy + vec2(0.5, 0.5) * texel, layer, s.z));
  return 0.25 * lit;
}

// Fraction of the Sun seen from a point (camera-relative `rel`) with geometric normal `n`.
// The lookups sit in a loop of uShadowOn trips; a program that knows it has no maps this frame
// compiles them out (SHADOWS_OFF: render/OceanRenderer's variants), since llvmpipe runs a
// loop's first trip, masked, even when no pixel enters it.
float sunVisibility(vec3 rel, vec3 n) {
  float visible = 1.0;
#ifndef SHADOWS_OFF
  for (int on = 0; on < uShadowOn; ++on) visible = sunVisibilityFromMaps(rel, n);
#endif
  return visible;
}
