#version 450 core
// The Sun layers' radial sums' mip levels (render/SkyRadialSums): level uLevel from the one
// below, a 2 x 2 box (one row where the level below has one), every layer in one dispatch (z).
// glGenerateTextureMipmap made them ~50 ms slower on llvmpipe (a draw per layer and level).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) readonly uniform image2DArray uFiner;     // level uLevel - 1
layout(binding = 1, rgba32f) writeonly uniform image2DArray uCoarser;  // level uLevel

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  ivec3 size = imageSize(uCoarser), finer = imageSize(uFiner);
  if (any(greaterThanEqual(p.xy, size.xy))) return;
  ivec2 a = 2 * p.xy, b = min(a + 1, finer.xy - 1);
  vec4 sum = imageLoad(uFiner, ivec3(a, p.z)) + imageLoad(uFiner, ivec3(b.x, a.y, p.z)) +
             imageLoad(uFiner, ivec3(a.x, b.y, p.z)) + imageLoad(uFiner, ivec3(b, p.z));
  imageStore(uCoarser, p, 0.25 * sum);
}
