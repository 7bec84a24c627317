#version 450 core
// One mip level of the wave patterns from the level above (render/OceanPatterns::
// generateMipmaps): each texel the mean of the 2 x 2 texels under it, as glGenerateMipmap's box
// filter, for the displacement and the slopes' moments of every layer transformed this time
// (the first uPatternCount patterns of each set) in one dispatch a level. glGenerateMipmap on
// llvmpipe blits every layer and level through the whole pipeline: 140 draws for the two
// 10-layer textures, 14-30 ms a frame (docs/performance.md).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) readonly uniform image2DArray uDisplacementAbove;
layout(binding = 1, rgba16f) writeonly uniform image2DArray uDisplacement;
layout(binding = 2, rgba32f) readonly uniform image2DArray uSlopesAbove;
layout(binding = 3, rgba32f) writeonly uniform image2DArray uSlopes;
uniform int uPatternCount;  // layers per set to reduce
uniform int uLayersPerSet;  // PATTERN_COUNT: layer = set * uLayersPerSet + pattern

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(uDisplacement).xy;
  if (texel.x >= size.x || texel.y >= size.y) return;
  int z = int(gl_GlobalInvocationID.z);
  int layer = (z / uPatternCount) * uLayersPerSet + z % uPatternCount;
  ivec2 above = imageSize(uDisplacementAbove).xy;
  // A side already 1 texel above stays 1 (GL's level sizes): the pair along the other side.
  ivec2 a = min(2 * texel, above - 1), b = min(2 * texel + 1, above - 1);
  vec4 d = imageLoad(uDisplacementAbove, ivec3(a.x, a.y, layer)) + imageLoad(uDisplacementAbove, ivec3(b.x, a.y, layer)) +
           imageLoad(uDisplacementAbove, ivec3(a.x, b.y, layer)) + imageLoad(uDisplacementAbove, ivec3(b.x, b.y, layer));
  vec4 s = imageLoad(uSlopesAbove, ivec3(a.x, a.y, layer)) + imageLoad(uSlopesAbove, ivec3(b.x, a.y, layer)) +
           imageLoad(uSlopesAbove, ivec3(a.x, b.y, layer)) + imageLoad(uSlopesAbove, ivec3(b.x, b.y, layer));
  imageStore(uDisplacement, ivec3(texel, layer), 0.25 * d);
  imageStore(uSlopes, ivec3(texel, layer), 0.25 * s);
}
