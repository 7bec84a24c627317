// The blocks of 8 x 8 pixels below the grid's ceiling that hold a pixel the terrain and the grid
// left for the globe (render/UncoveredPixels): flagged by render/uncovered.frag, listed as
// triangles for the classifying draw by render/uncovered_blocks.comp, drawn by
// glDrawArraysIndirect from uDrawArgs (vertex count, instances 1, first 0, base instance 0).
// Blocks count from the frame's bottom-left corner, uBlocksPerRow to a row.
layout(std430, binding = OG_UNCOVERED_BLOCKS_BINDING) buffer UncoveredBlocks {
  uint uDrawArgs[4];
  uint uFlags[];
};
uniform int uBlocksPerRow;
