#version 450 core
// Lists the flagged blocks (render/uncovered_blocks.glsl) within the box of blocks uBlockBox
// as two triangles each, in normalised device coordinates (render/blocks.vert's input), and
// counts their vertices into the draw's arguments.
layout(local_size_x = 8, local_size_y = 8) in;
#include "render/uncovered_blocks.glsl"
layout(std430, binding = OG_UNCOVERED_TRIANGLES_BINDING) writeonly buffer UncoveredTriangles {
  vec2 uNdc[];
};
uniform ivec4 uBlockBox;  // blocks: x0, y0, x1, y1 (exclusive)
uniform vec2 uBlockNdc;   // a block's size in normalised device coordinates
uniform int uEveryBlock;  // 1: every block, flagged or not (the tests' reference)
void main() {
  ivec2 b = uBlockBox.xy + ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(b, uBlockBox.zw))) return;
  if (uFlags[b.y * uBlocksPerRow + b.x] == 0u && uEveryBlock == 0) return;
  uint first = atomicAdd(uDrawArgs[0], 6u);
  vec2 lo = vec2(b) * uBlockNdc - 1.0, hi = vec2(b + 1) * uBlockNdc - 1.0;
  uNdc[first] = lo;
  uNdc[first + 1u] = vec2(hi.x, lo.y);
  uNdc[first + 2u] = hi;
  uNdc[first + 3u] = lo;
  uNdc[first + 4u] = hi;
  uNdc[first + 5u] = vec2(lo.x, hi.y);
}
