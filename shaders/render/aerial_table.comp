#version 450 core
// This frame's aerial perspective to sea level (render/aerial.glsl's AERIAL_TABLE): per entry
// of AERIAL_TABLE_SIZE, the path at nu (x) and length d (y) from the eye, phase-free, into the
// three layers of an RGBA32F array: (T.rgb, R.r), (R.gb, M.rg), (M.b, -, -, -).
#include "render/aerial.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform writeonly image2DArray uTable;
uniform vec3 uSunDir;  // unit, ECEF axes

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, AERIAL_TABLE_SIZE))) return;
  vec2 x = vec2(p) / vec2(AERIAL_TABLE_SIZE - 1);
  float nu = 2.0 * x.x - 1.0;
  vec3 transmittance, rayleigh, mie;
  aerialScatteringToSeaLevel(aerialTableDistance(x.y), nu, dot(uSunDir, uCamUp), transmittance, rayleigh, mie);
  imageStore(uTable, ivec3(p, 0), vec4(transmittance, rayleigh.r));
  imageStore(uTable, ivec3(p, 1), vec4(rayleigh.gb, mie.rg));
  imageStore(uTable, ivec3(p, 2), vec4(mie.b, 0.0, 0.0, 0.0));
}
