#version 450 core
// The patterns' spectra at time t (Tessendorf 2001 Eq. 43, waves towards +k):
//   h(k, t) = h0(k) e^{-i w t} + conj(h0(-k)) e^{i w t},
// and the spectra of the fields the sea needs, packed in slots (ocean/fft_common.glsl):
// A + iB transforms to a + ib when a and b are real.
// w t is exact: w = steps * 2 pi / period (src/ocean/WavePatterns.hpp), and the CPU passes
// tau = (t mod period) / period as uTimeSteps / 4096 + uTimeFine, so
// w t / 2 pi = fract(steps * uTimeSteps / 4096) + steps * uTimeFine, the first part in integers.
#include "ocean/fft_common.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) readonly uniform image2DArray uH0;      // h0(k), conj(h0(-k))
layout(binding = 1, r32ui) readonly uniform uimage2DArray uSteps;    // w / (2 pi / period)
layout(binding = 2, rgba32f) writeonly uniform image2DArray uFields;
uniform float uPatternSizeM[PATTERN_COUNT];  // tile sizes, m
uniform uint uTimeSteps;     // floor(tau * 4096)
uniform float uTimeFine;     // tau - uTimeSteps / 4096, [0, 1/4096)
uniform int uPatternCount;   // the first patterns to transform (the others' slots stay 0)

vec2 timesI(vec2 z) { return vec2(-z.y, z.x); }

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int set = int(gl_GlobalInvocationID.z);
  int n = imageSize(uH0).x;
  ivec2 m = texel - n * ivec2(greaterThanEqual(texel, ivec2(n / 2)));
  vec2 slots[FFT_SLOTS];
  for (int s = 0; s < FFT_SLOTS; ++s) slots[s] = vec2(0.0);
  int slot = 0;
  for (int p = 0; p < uPatternCount; ++p) {
    ivec3 at = ivec3(texel, set * PATTERN_COUNT + p);
    vec2 k = vec2(m) * (2.0 * FFT_PI / uPatternSizeM[p]);
    float kl = max(length(k), 1e-9);
    vec4 h0 = imageLoad(uH0, at);
    uint steps = imageLoad(uSteps, at).r;
    float cycles = float((steps * uTimeSteps) & 4095u) / 4096.0 + fract(float(steps) * uTimeFine);
    float phase = 2.0 * FFT_PI * fract(cycles);
    vec2 e = vec2(cos(phase), sin(phase));
    vec2 h = complexMul(h0.xy, vec2(e.x, -e.y)) + complexMul(h0.zw, e);
    vec2 ih = timesI(h);
    // Each slot multiplied out, no timesI nested in another: NVIDIA's driver (580.159) gave the
    // nested form h + timesI(k.x * timesI(h)) as h + k.x * timesI(h), which put dh/dx into the
    // heights and left the x slopes 0 (docs/performance.md, "Tenth session").
    slots[slot++] = (1.0 - k.x) * h;          // h + i dh/dx = h + i (i kx h)
    slots[slot++] = (k.y + kl) * ih;          // dh/dy + i t = i ky h + i |k| h
    if (patternDisplaced(p)) slots[slot++] = (k.y * h - k.x * ih) / kl;  // Dx + i Dy = -i kx/|k| h + i (-i ky/|k| h)
  }
  for (int l = 0; l < FFT_LAYERS_PER_SET; ++l)
    imageStore(uFields, ivec3(texel, set * FFT_LAYERS_PER_SET + l), vec4(slots[2 * l], slots[2 * l + 1]));
}
