#version 450 core
// Evaluates terrain/landmask.glsl's landFraction at given points, for tests against its CPU
// twin data::LandMask::landFraction (render::LandMaskTexture::probeLandFraction).
#include "terrain/landmask.glsl"

layout(local_size_x = 1) in;
// In: xy = (latitude, longitude) radians, z = footprint radians; out: x = the land fraction, [0, 1].
layout(std430, binding = 0) buffer ProbeValues { vec4 probeValues[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  probeValues[i] = vec4(landFraction(probeValues[i].xy, probeValues[i].z), 0.0, 0.0, 0.0);
}
