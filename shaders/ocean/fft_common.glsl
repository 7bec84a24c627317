// Shared by the FFT wave-pattern passes (render/OceanPatterns.cpp, Dupuy & Bruneton 2012 §4).
// Pattern p of direction set s is layer s * PATTERN_COUNT + p of the spectra and of the output
// textures. Its fields travel through the FFT two real fields per complex "slot", slots two per
// RGBA32F texel of the FFT buffers, FFT_LAYERS_PER_SET layers per set, in pattern order:
//   (h + i dh/dx), (dh/dy + i t), and for displaced patterns (Dx + i Dy),
// t = dDx/dx + dDy/dy the Jacobian's linear term, D = -i k/|k| h the choppy displacement.
// The program defines PATTERN_COUNT, PATTERN_DISPLACED (bit p: pattern p is displaced),
// FFT_LAYERS_PER_SET (and FFT_SIZE, FFT_LOG2 for the line transform).
const float FFT_PI = 3.14159265358979;
const int FFT_SLOTS = 2 * FFT_LAYERS_PER_SET;

bool patternDisplaced(int p) { return ((PATTERN_DISPLACED >> p) & 1) != 0; }

vec2 complexMul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
