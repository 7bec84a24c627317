#version 450 core
// The caustics' curvature map (ocean/water_volume.glsl's causticGain), once per frame after the
// wave patterns (render/WaterVolume.cpp's CausticCurvature): the trace of the height's Hessian,
// tr H = d(s_x)/dx + d(s_y)/dy, of the CAUSTIC_PATTERNS finest patterns, per texel by central
// differences of their slopes (ocean/fft_finish.comp's output) in the tile's axes, in 1/texel
// (the sea shader divides by the texel's size in metres). The trace is invariant under the
// quarter turns the bins apply to the tile. Mip-mapped afterwards: the mean curvature over a
// footprint is the curvature of the footprint's mean surface (both are linear), so one lookup
// at a footprint's level replaces seed 001's finite differences of three filtered slopes.
// Layer (set * CAUSTIC_PATTERNS + j) holds pattern PATTERN_COUNT - CAUSTIC_PATTERNS + j of set.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 13) uniform sampler2DArray uSlopes;  // (s_u, s_c, |s|², j), render/OceanPatterns
layout(binding = 0, r16f) writeonly uniform image2DArray uCurvature;

// Slope in the tile's axes at texel q (wrapped) of layer `layer`; set `set`'s wind runs at
// set x 45 degrees to the tile's +x axis (fft_finish.comp), s = (along, across) it.
vec2 slopeAt(ivec2 q, int layer, vec2 along) {
  int n = textureSize(uSlopes, 0).x;
  vec2 s = texelFetch(uSlopes, ivec3((q + n) % n, layer), 0).xy;
  return s.x * along + s.y * vec2(-along.y, along.x);
}

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  int layer = int(gl_GlobalInvocationID.z);
  int set = layer / CAUSTIC_PATTERNS;
  int source = set * PATTERN_COUNT + PATTERN_COUNT - CAUSTIC_PATTERNS + layer % CAUSTIC_PATTERNS;
  float windAngle = float(set) * 0.25 * 3.14159265358979;
  vec2 along = vec2(cos(windAngle), sin(windAngle));
  float dsx = slopeAt(t + ivec2(1, 0), source, along).x - slopeAt(t - ivec2(1, 0), source, along).x;
  float dsy = slopeAt(t + ivec2(0, 1), source, along).y - slopeAt(t - ivec2(0, 1), source, along).y;
  imageStore(uCurvature, ivec3(t, layer), vec4(0.5 * (dsx + dsy), 0.0, 0.0, 0.0));
}
