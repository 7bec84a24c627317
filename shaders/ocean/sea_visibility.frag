#version 450 core
// The visibility buffer's surface pass (ocean/sea_visibility.glsl): each pixel's nearest grid
// triangle (depth-tested against the terrain), its index in the grid's index list + 1 (the grid
// drawn whole, from its first triangle: render/OceanRenderer::drawDeferred). 0 stays where no
// sea was drawn (the buffer is cleared).
layout(location = 0) out uint seaTriangle;

void main() { seaTriangle = uint(gl_PrimitiveID) + 1u; }
