#version 450 core
// The sea's classes into the stencil (render/OceanRenderer's split, as the globe's parts:
// render/GlobeRenderer::classifyGlobe): one cheap draw of the projected grid (ocean/grid.vert,
// its per-vertex floor depth and land flag; the linker drops the rest) writes per pixel
//   1: the open sea: no floor within the water's reach, no land near: no water volume, no coast test
//   2: the terrain's shadows may reach, no floor within reach, no land near: the surface's
//      shadow lookups only
//   3: a floor within reach (the water volume), no shadow can reach, no land near
//   4: a floor within reach and the shadows may reach: the water volume with the surface's and
//      the floor's shadow lookups, no land near
//   5: land may be near (the coast test, with the water volume and the shadows when the frame
//      has them)
// The floor and the shadows combine independently (classes 2-4): the shadows' reach from
// mountains under a low Sun covers most of the sea in view, and open sea there must not pay
// for the water volume. When the frame does not route its shadows (uShadowBesideCastersM < 0: no
// shadow maps, or the Sun within 1 degree of the horizon) classes 1 and 3 keep them.
// As the stencil's value the largest of the grid's overlapping fragments in a pixel wins
// (GL_GEQUAL, REPLACE): each class's program has every feature of the classes below it but
// one: where a fold puts a class-2 fragment (shadows) and a class-3 one (floor) in the same
// pixel, the pixel is drawn without the shadows. Folds join neighbouring rows of the grid,
// whose flags come from conservative bounds over kilometres; the pixel has to lie on the
// shadows' reach and on the floor's at once.
// Each class is then drawn by a program compiled with only its code, stencil-tested before
// its shader runs: llvmpipe runs every line of a shader, both sides of each `if`, for every
// fragment that reaches it (docs/performance.md).
// Without stencil export (SEA_CLASS_IN_SURFACE: the classes go into the surface buffer) the
// program serves only OceanRenderer::seaShows' occlusion query, and writes nothing.
#if !defined(SEA_CLASS_IN_SURFACE) && defined(OG_STENCIL_EXPORT)  // (OG_STENCIL_EXPORT: gl::Program)
#extension GL_ARB_shader_stencil_export : require
#endif

#include "ocean/sea_class.glsl"

void main() {
#ifndef SEA_CLASS_IN_SURFACE
  gl_FragStencilRefARB = seaClassOfFragment();
#endif
}
