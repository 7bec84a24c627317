// Land and water from real coastlines (data::LandMask, render/LandMaskTexture): a global mask
// of 2′ cells from GSHHG, lakes as water, packed 8 cells per texel along a row (bit k of texel
// x = column 8x + k), rows south to north, covering -180..180° E and -90..90° N. Bound to unit
// 18 only where it decides the coast (a global elevation layer coarser than it); otherwise the
// unit holds a 1×1 texture and landMaskOn() is false. The coastal-water code reads it here.
#include "common/constants.glsl"
layout(binding = 18) uniform usampler2D uLandMask;

bool landMaskOn() { return textureSize(uLandMask, 0).y > 1; }

float landMaskCell(int column, int row) {
  uint bits = texelFetch(uLandMask, ivec2(column >> 3, row), 0).r;
  return float((bits >> uint(column & 7)) & 1u);
}

// The fraction of land around (latitude, longitude) radians, [0, 1]: the quadratic B-spline
// of the 3 × 3 cells around the nearest centre, so the coast (the 0.5 contour) is a smooth
// curve without the raster's staircase (data::LandMask::landFraction, its CPU twin).
float landFraction(vec2 latLon) {
  int rows = textureSize(uLandMask, 0).y;
  int cols = 2 * rows;
  float cell = PI / float(rows);
  vec2 xy = vec2((latLon.y + PI) / cell - 0.5, (latLon.x + 0.5 * PI) / cell - 0.5);
  xy.y = clamp(xy.y, 0.0, float(rows - 1));
  xy.x = mod(xy.x, float(cols));
  ivec2 c = ivec2(floor(xy + 0.5));
  vec2 t = xy - vec2(c);
  // Uniform quadratic B-spline weights of the cells at offsets -1, 0, +1.
  vec2 wm = 0.5 * (0.5 - t) * (0.5 - t), w0 = 0.75 - t * t, wp = 0.5 * (0.5 + t) * (0.5 + t);
  float v = 0.0;
  for (int j = -1; j <= 1; ++j) {
    int r = clamp(c.y + j, 0, rows - 1);
    int cm = (c.x - 1 + cols) % cols, c0 = c.x % cols, cp = (c.x + 1) % cols;
    float row = wm.x * landMaskCell(cm, r) + w0.x * landMaskCell(c0, r) + wp.x * landMaskCell(cp, r);
    v += (j < 0 ? wm.y : (j == 0 ? w0.y : wp.y)) * row;
  }
  return v;
}

// A layer height (m) made to agree with the mask: at least / at most 20 m × (fraction − 0.5)
// on land / water (data::LandMask::constrainHeightM, kCoastRampM = 20).
float constrainByLandMask(float heightM, vec2 latLon) {
  if (!landMaskOn()) return heightM;
  float f = landFraction(latLon);
  float edge = 20.0 * (f - 0.5);
  return f >= 0.5 ? max(heightM, edge) : min(heightM, edge);
}
