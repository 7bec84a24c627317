#version 450 core
// The radial sums' mip levels (render/SkyRadialSums): level uLevel from the one below, a 2 x 2
// box (one row where the level below has one). The Sun layers' every layer in one dispatch (z);
// with SKY_RADIAL_FRAME the frame layer's 2-D texture. glGenerateTextureMipmap made the layers
// ~50 ms slower on llvmpipe (a draw per layer and level), and cost the frame layer ~40 ms of
// the main thread at every Sun zenith the camera's motion brings (a recording near the sea).
layout(local_size_x = 8, local_size_y = 8) in;
#ifdef SKY_RADIAL_FRAME
layout(binding = 0, rgba32f) readonly uniform image2D uFiner;     // level uLevel - 1
layout(binding = 1, rgba32f) writeonly uniform image2D uCoarser;  // level uLevel
#define AT(xy, z) (xy)
#else
layout(binding = 0, rgba32f) readonly uniform image2DArray uFiner;
layout(binding = 1, rgba32f) writeonly uniform image2DArray uCoarser;
#define AT(xy, z) ivec3(xy, z)
#endif

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  ivec2 size = imageSize(uCoarser).xy, finer = imageSize(uFiner).xy;
  if (any(greaterThanEqual(p.xy, size))) return;
  ivec2 a = 2 * p.xy, b = min(a + 1, finer - 1);
  vec4 sum = imageLoad(uFiner, AT(a, p.z)) + imageLoad(uFiner, AT(ivec2(b.x, a.y), p.z)) +
             imageLoad(uFiner, AT(ivec2(a.x, b.y), p.z)) + imageLoad(uFiner, AT(b, p.z));
  imageStore(uCoarser, AT(p.xy, p.z), 0.25 * sum);
}
