#version 450 core
// Evaluates ocean/lighting.glsl (seaRadianceWithFoam and the validation's seaRadianceMirror) at
// given inputs with the analytic sky, for the tests against its C++ twin (ocean/Lighting.cpp,
// tests/gl/ocean_lighting_twin_test.cpp): the GPU's single precision against the CPU's double.
#define OCEAN_SIMPLE_SKY
#define OCEAN_LIGHTING_TERMS
#define OCEAN_VALIDATION_REFERENCE
#include "common/types.glsl"
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"

layout(local_size_x = 1) in;
// Per probe, 8 vec4: to the eye, normal, wind, up, to the Sun (xyz, unit), slope covariance
// (xyz) and foam coverage (w), then out: seaRadianceWithFoam (rgb), seaRadianceMirror (rgb)
// with the covariance as the patch's.
layout(std430, binding = 0) buffer LightingProbes { vec4 probes[]; };
uniform float uSunVisibility;

void main() {
  uint i = gl_GlobalInvocationID.x * 8u;
  gSeaSunVisibility = uSunVisibility;
  vec3 vE = probes[i].xyz, nE = probes[i + 1u].xyz, windE = probes[i + 2u].xyz;
  vec3 upE = probes[i + 3u].xyz, sunE = probes[i + 4u].xyz, cov = probes[i + 5u].xyz;
  float coverage = probes[i + 5u].w;
  probes[i + 6u] = vec4(seaRadianceWithFoam(vE, nE, windE, cov, upE, sunE, coverage), 0.0);
  probes[i + 7u] = vec4(seaRadianceMirror(vE, nE, windE, cov, upE, sunE), 0.0);
}
