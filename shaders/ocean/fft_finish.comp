#version 450 core
// The transformed fields into the textures the sea samples (mip-mapped afterwards, so every
// footprint gets the mean and second moments it covers: Dupuy & Bruneton 2012 §3, and LEAN
// mapping's moments for the slopes, Olano & Baker 2010):
//   displacement: (lambda Dx, lambda Dy, h, 0), m, in the tile's axes (0, 0, h undisplaced)
//   slopes:       (s_u, s_c, s_u² + s_c², j): slopes along/across the set's wind, their second
//                 moment, and j = lambda (dDx/dx + dDy/dy), the Jacobian's linear term (Dupuy
//                 2012 Eq. 7 without its quadratic part, src/ocean/WavePatterns.hpp). j's
//                 variance in a footprint is lambda² times the slopes' (the two fields have
//                 the same power spectrum, lambda² |k|² P_h), so it needs no channel of its own
//                 and the sea reads one texture per pattern (ocean/patterns.glsl).
#include "ocean/fft_common.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) readonly uniform image2DArray uFields;
layout(binding = 1, rgba16f) writeonly uniform image2DArray uDisplacement;
layout(binding = 2, rgba32f) writeonly uniform image2DArray uSlopes;
uniform float uChoppiness[PATTERN_COUNT];
uniform int uPatternCount;  // the first patterns transformed this time (the others are left)

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int set = int(gl_GlobalInvocationID.z);
  vec2 slots[FFT_SLOTS];
  for (int l = 0; l < FFT_LAYERS_PER_SET; ++l) {
    vec4 v = imageLoad(uFields, ivec3(texel, set * FFT_LAYERS_PER_SET + l));
    slots[2 * l] = v.xy;
    slots[2 * l + 1] = v.zw;
  }
  // Set 0's wind runs along the tile's +x axis, set 1's at 45 degrees to it.
  float windAngle = float(set) * 0.25 * FFT_PI;
  vec2 along = vec2(cos(windAngle), sin(windAngle));
  int slot = 0;
  for (int p = 0; p < uPatternCount; ++p) {
    ivec3 at = ivec3(texel, set * PATTERN_COUNT + p);
    float lambda = uChoppiness[p];
    vec2 a = slots[slot++];  // h, dh/dx
    vec2 b = slots[slot++];  // dh/dy, t
    vec2 d = patternDisplaced(p) ? lambda * slots[slot++] : vec2(0.0);
    vec2 slope = vec2(a.y, b.x);
    vec2 s = vec2(dot(slope, along), dot(slope, vec2(-along.y, along.x)));
    float j = lambda * b.y;
    imageStore(uDisplacement, at, vec4(d, a.x, 0.0));
    imageStore(uSlopes, at, vec4(s, dot(s, s), j));
  }
}
