#version 450 core
// The work groups that shade the listed pixels (render/globe_pixels.glsl), for
// glDispatchComputeIndirect.
layout(local_size_x = 1) in;
#include "render/globe_pixels.glsl"
void main() {
  uint groups = (uCount + GLOBE_PIXELS_GROUP - 1u) / GLOBE_PIXELS_GROUP;
  uArgs[0] = min(groups, GLOBE_PIXELS_ROW);
  uArgs[1] = (groups + GLOBE_PIXELS_ROW - 1u) / GLOBE_PIXELS_ROW;
  uArgs[2] = 1u;
}
