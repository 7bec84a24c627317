#version 450 core
// Evaluates the per-point lighting of atmosphere/skymap.glsl at given Sun zenith angles, for
// tests against the CPU reference (og::render::Atmosphere::probeSunIrradiance).
#include "atmosphere/skymap.glsl"

layout(local_size_x = 1) in;
// In: x = the Sun's zenith angle (radians); out: rgb = sunIrradiance, a = 0.
layout(std430, binding = 0) buffer ProbeValues { vec4 probeValues[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  probeValues[i] = vec4(sunIrradiance(probeValues[i].x), 0.0);
}
