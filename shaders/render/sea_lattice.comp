#version 450 core
// Which of the sea's blocks of 8 x 8 pixels the lattice may shade (render/SeaLattice):
// a block's nine lattice points (every 4 pixels, render/globe.frag's GLOBE_LATTICE) against
// what its four corners alone interpolate bilinearly at the other five, in display levels (the
// frame's exposure, the tone curve and sRGB, 0-255). Where those stay within uMaxLevels the
// lattice's own interpolation, at half the spacing, errs about four times less (a smooth
// radiance's error grows as the spacing's square), and within uMaxRelative of the radiance
// itself (an EXR's linear values, regraded, or another exposure): the block is interpolated.
// A point the lattice marked (alpha < 0: globe.frag's GLOBE_LATTICE says why) keeps the block
// per pixel, as does a block none of whose points was listed (the flags are cleared to 0
// every frame).
#include "common/color.glsl"
layout(local_size_x = OG_GLOBE_PIXELS_GROUP) in;
layout(binding = 0, rgba32f) uniform readonly image2D uLattice;
layout(binding = 1, r8ui) uniform writeonly uimage2D uBlockInterpolated;
layout(std430, binding = OG_SEA_LATTICE_BLOCKS_BINDING) readonly buffer SeaLatticeBlocks {
  uint uBlockCount;
  uint uUnused[3];  // (render/SeaLattice lays its lists out as globe_pixels.glsl's)
  uint uBlocks[];  // x | y << 16, in blocks from the frame's lower-left corner
};
uniform float uExposure;
uniform float uMaxLevels;
uniform float uMaxRelative;

vec3 displayLevels(vec3 radiance) { return 255.0 * linearToSrgb(toneMap(radiance, uExposure)); }

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= uBlockCount) return;
  ivec2 block = ivec2(uBlocks[k] & 0xffffu, uBlocks[k] >> 16);
  vec4 v[9];
  bool ok = true;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      v[3 * j + i] = imageLoad(uLattice, 2 * block + ivec2(i, j));
      ok = ok && v[3 * j + i].a >= 0.0;
    }
  // The five points between the corners (0, 2, 6, 8) and the corners' bilinear values there.
  const int mids[5] = int[5](1, 3, 4, 5, 7);
  vec4 predicted[5] = vec4[5](0.5 * (v[0] + v[2]), 0.5 * (v[0] + v[6]), 0.25 * (v[0] + v[2] + v[6] + v[8]),
                              0.5 * (v[2] + v[8]), 0.5 * (v[6] + v[8]));
  float worst = 0.0, worstRelative = 0.0;
  for (int m = 0; m < 5; ++m) {
    vec3 d = abs(displayLevels(predicted[m].rgb) - displayLevels(v[mids[m]].rgb));
    worst = max(worst, max(d.r, max(d.g, d.b)));
    vec3 r = abs(predicted[m].rgb - v[mids[m]].rgb) / max(v[mids[m]].rgb, vec3(1e-4));
    worstRelative = max(worstRelative, max(r.r, max(r.g, r.b)));
  }
  imageStore(uBlockInterpolated, block, uvec4(ok && worst <= uMaxLevels && worstRelative <= uMaxRelative ? 1u : 0u));
}
