// Land and water from real coastlines (data::LandMask, render/LandMaskTexture): a global mask
// of 2′ cells from GSHHG, lakes as water, packed 8 cells per texel along a row (bit k of texel
// x = column 8x + k), rows south to north, covering -180..180° E and -90..90° N. Bound to unit
// OG_UNIT_LAND_MASK only where it decides the coast (a global elevation layer coarser than it); otherwise the
// unit holds a 1×1 texture and landMaskOn() is false. The coastal-water code reads it here.
#include "common/constants.glsl"
layout(binding = OG_UNIT_LAND_MASK) uniform usampler2D uLandMask;

bool landMaskOn() { return textureSize(uLandMask, 0).y > 1; }

float landMaskCell(int column, int row) {
  uint bits = texelFetch(uLandMask, ivec2(column >> 3, row), 0).r;
  return float((bits >> uint(column & 7)) & 1u);
}

// The fraction of land around (latitude, longitude) radians, [0, 1]: bilinear over the four
// nearest cells, so the coast (the 0.5 contour) is a smooth curve (data::LandMask::landFraction).
float landFraction(vec2 latLon) {
  int rows = textureSize(uLandMask, 0).y;
  int cols = 2 * rows;
  float cell = PI / float(rows);
  vec2 xy = vec2((latLon.y + PI) / cell - 0.5, (latLon.x + 0.5 * PI) / cell - 0.5);
  xy.y = clamp(xy.y, 0.0, float(rows - 1));
  xy.x = mod(xy.x, float(cols));
  ivec2 c0 = ivec2(floor(xy));
  c0.x = min(c0.x, cols - 1);
  vec2 f = xy - vec2(c0);
  int c1 = (c0.x + 1) % cols;
  int r1 = min(c0.y + 1, rows - 1);
  return mix(mix(landMaskCell(c0.x, c0.y), landMaskCell(c1, c0.y), f.x),
             mix(landMaskCell(c0.x, r1), landMaskCell(c1, r1), f.x), f.y);
}

// A layer height (m) made to agree with the mask: at least / at most 20 m × (fraction − 0.5)
// on land / water (data::LandMask::constrainHeightM, kCoastRampM = 20).
float constrainByLandMask(float heightM, vec2 latLon) {
  if (!landMaskOn()) return heightM;
  float f = landFraction(latLon);
  float edge = 20.0 * (f - 0.5);
  return f >= 0.5 ? max(heightM, edge) : min(heightM, edge);
}
