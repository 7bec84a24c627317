#version 450 core
// A whole inverse FFT along the rows (uVertical = 0) or the columns of every layer, one work
// group per line: the line is loaded into shared memory in bit-reversed order, transformed in
// place by log2(n) radix-2 stages (Cooley-Tukey, decimation in time) and stored once. Each
// texel holds two complex numbers. f(x) = sum_k F(k) e^{+2 pi i k x / n}, no 1/n.
// FFT_SIZE (n, a power of two) and FFT_LOG2 are defined by the program (render/OceanPatterns).
#include "ocean/fft_common.glsl"
layout(local_size_x = FFT_SIZE / 2) in;
layout(binding = 0, rgba32f) readonly uniform image2DArray uSource;
layout(binding = 1, rgba32f) writeonly uniform image2DArray uTarget;
uniform int uVertical;

shared vec4 sLine[FFT_SIZE];

ivec3 texel(int i, int line, int layer) {
  return uVertical == 0 ? ivec3(i, line, layer) : ivec3(line, i, layer);
}

int bitReverse(int i) { return int(bitfieldReverse(uint(i)) >> uint(32 - FFT_LOG2)); }

void main() {
  int t = int(gl_LocalInvocationID.x);
  int line = int(gl_WorkGroupID.x);
  // Work groups (line, layer within the set, set): only the layers of the patterns needed.
  int layer = int(gl_WorkGroupID.z) * FFT_LAYERS_PER_SET + int(gl_WorkGroupID.y);
  sLine[bitReverse(t)] = imageLoad(uSource, texel(t, line, layer));
  sLine[bitReverse(t + FFT_SIZE / 2)] = imageLoad(uSource, texel(t + FFT_SIZE / 2, line, layer));
  barrier();
  for (int s = 0; s < FFT_LOG2; ++s) {
    int half_ = 1 << s;
    int pos = t & (half_ - 1);
    int i0 = ((t >> s) << (s + 1)) + pos;
    float angle = FFT_PI * float(pos) / float(half_);
    vec2 w = vec2(cos(angle), sin(angle));
    vec4 a = sLine[i0];
    vec4 b = sLine[i0 + half_];
    b = vec4(complexMul(b.xy, w), complexMul(b.zw, w));
    sLine[i0] = a + b;  // each butterfly owns its two elements within a stage
    sLine[i0 + half_] = a - b;
    barrier();
  }
  imageStore(uTarget, texel(t, line, layer), sLine[t]);
  imageStore(uTarget, texel(t + FFT_SIZE / 2, line, layer), sLine[t + FFT_SIZE / 2]);
}
