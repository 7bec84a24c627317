#version 450 core
// The sky maps' radial rip-map (render/SkyRipMap, read by atmosphere/skymap.glsl with
// SKY_RIP_MAP): the frame layer (the last of uSkyMap, atmosphere/skymap_frame.comp) in layers
// blurred along the map's radial direction (away from the zenith at its centre) by a box of 1, 2,
// 4, 8 texels of each mip level. The sea's reflected footprints at grazing angles are ellipses
// stretched radially: a slope along the view's azimuth tilts the mirror ray in elevation, one
// across it turns the ray's azimuth by only ~2 slope x its elevation. So the layer whose blur
// matches an ellipse's radial extent over its tangential one, read with the gradients' radial
// part shrunk by the same factor, filters the ellipse in ONE isotropic textureGrad, where the
// paper's §7.3 averages up to nine (Bruneton, Neyret & Holzschuch 2010; rip-maps, McReynolds &
// Blythe 2005 §7.6, here along the radial direction instead of the texture's axes).
// One mip level per dispatch, every layer at once (z = the layer).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = OG_UNIT_SKY_MAP) uniform sampler2DArray uSkyMap;
layout(binding = 0, rgba16f) writeonly uniform image2DArray uRip;  // level uLevel, all layers
uniform int uLevel;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  ivec3 size = imageSize(uRip);
  if (any(greaterThanEqual(p, size))) return;
  vec2 tc = (vec2(p.xy) + 0.5) / vec2(size.xy);
  vec2 centred = tc - 0.5;
  float r = length(centred);
  vec2 radial = r > 1e-6 ? centred / r : vec2(1.0, 0.0);
  float frameLayer = float(textureSize(uSkyMap, 0).z - 1);
  int taps = 1 << p.z;
  vec4 sum = vec4(0.0);
  // Taps one texel of this level apart along the radius, never past the centre: a box wider
  // than the radius (coarse levels) stays in its own azimuth instead of reaching the opposite
  // sky (the Sun's glow behind a view away from it).
  for (int i = 0; i < taps; ++i) {
    float radius = max(r + (float(i) + 0.5 - 0.5 * float(taps)) / float(size.x), 0.0);
    sum += textureLod(uSkyMap, vec3(0.5 + radius * radial, frameLayer), float(uLevel));
  }
  imageStore(uRip, p, sum / float(taps));
}
