#version 450 core
// This frame's aerial perspective tables (render/aerial.glsl), phase-free, in RGBA32F:
//  * to sea level (AERIAL_TABLE, render/AerialTable): per entry of
//    AERIAL_TABLE_SIZE the path at nu (x) and length d (y) from the eye, into the three layers
//    of an array: (T.rgb, R.r), (R.gb, M.rg), (M.b, -, -, -);
//  * with AERIAL_TABLE_TERRAIN, to altitudes (TERRAIN_AERIAL_TABLE,
//    render/AerialTable): per entry of AERIAL_TERRAIN_SIZE the path at nu (x),
//    its length (y) and end altitude (z), the three parts in three blocks along x.
#include "render/aerial.glsl"

uniform vec3 uSunDir;  // unit, ECEF axes

#ifdef AERIAL_TABLE_TERRAIN
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, rgba32f) uniform writeonly image3D uTable;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, AERIAL_TERRAIN_SIZE))) return;
  vec3 x = vec3(p) / vec3(AERIAL_TERRAIN_SIZE - 1);
  vec2 path = aerialTerrainPath(x.yz);
  vec3 transmittance, rayleigh, mie;
  aerialScatteringToAltitude(path.x, path.y, 2.0 * x.x - 1.0, dot(uSunDir, uCamUp), transmittance, rayleigh, mie);
  int w = AERIAL_TERRAIN_SIZE.x;
  imageStore(uTable, p, vec4(transmittance, rayleigh.r));
  imageStore(uTable, p + ivec3(w, 0, 0), vec4(rayleigh.gb, mie.rg));
  imageStore(uTable, p + ivec3(2 * w, 0, 0), vec4(mie.b, 0.0, 0.0, 0.0));
}
#else
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform writeonly image2DArray uTable;

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
#endif
