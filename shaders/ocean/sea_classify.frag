#version 450 core
// The sea's classes into the stencil (render/OceanRenderer's split, as the globe's parts:
// render/GlobeRenderer::classifyGlobe): one cheap draw of the projected grid (ocean/grid.vert,
// its per-vertex floor depth and land flag; the linker drops the rest) writes per pixel
//   1: the open sea: no floor within the water's reach, no land near: no water volume, no coast test
//   2: a floor within reach (the water volume), no land near
//   3: the terrain's shadows may reach (the surface's and the floor's shadow lookups, with the
//      water volume when the frame has it), no land near; when the frame routes its shadows
//      (uShadowReachM >= 0) classes 1 and 2 are drawn without them
//   4: land may be near (the coast test, with the water volume and the shadows when the frame
//      has them)
// Each class's program has every feature of the classes below it, so the largest wins:
// as the stencil's value, the largest of the grid's overlapping fragments (GL_GEQUAL, REPLACE).
// Each class is then drawn by a program compiled with only its code, stencil-tested before
// its shader runs: llvmpipe runs every line of a shader, both sides of each `if`, for every
// fragment that reaches it (docs/performance.md).
#extension GL_ARB_shader_stencil_export : require

in float vFloorDepthM;  // m below sea level under the pixel (ocean/water_volume_vertex.glsl)
in float vNearLand;     // > 0 where land may be within the triangle
in float vNearShadow;   // > 0 where the terrain's shadows may reach into the triangle

uniform float uWaterReachM;  // the water volume's d_max (ocean::waterMaxPathM), m; -1: no volume
uniform int uCoastClass;     // 1: the frame's coast test is routed to class 4

void main() {
  // The water volume returns the deep sea's colour where the floor under the pixel (the same
  // interpolated vFloorDepthM) is deeper than d_max (ocean/water_volume.glsl): the same test.
  int seaClass = vFloorDepthM <= uWaterReachM ? 2 : 1;
  if (vNearShadow > 0.0) seaClass = 3;
  if (uCoastClass == 1 && vNearLand > 0.0) seaClass = 4;
  gl_FragStencilRefARB = seaClass;
}
