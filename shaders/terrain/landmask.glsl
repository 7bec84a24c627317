// Land and water from real coastlines (data::LandMask, render/LandMaskTexture): a global mask
// of 2′ cells from GSHHG, lakes as water, covering -180..180° E and -90..90° N, rows south to
// north. Texel x of a row (16 bits) holds columns 8x - 4 ... 8x + 11 (bit k = column 8x - 4 + k,
// wrapping in longitude), so any three neighbouring cells lie in one texel. Bound to unit
// OG_UNIT_LAND_MASK only where it decides the coast (a global elevation layer coarser than it); otherwise the
// unit holds a 1×1 texture and landMaskOn() is false. The coastal-water code reads it here.
#include "common/constants.glsl"
layout(binding = OG_UNIT_LAND_MASK) uniform usampler2D uLandMask;

bool landMaskOn() { return textureSize(uLandMask, 0).y > 1; }

// The texel holding columns first ... first + 2 of a row (wrapping), shifted so that column
// `first` is bit 0. `first` in [0, cols).
uint landMaskBitsFrom(int first, int row) {
  int t = (first + 4) >> 3;
  uint word = texelFetch(uLandMask, ivec2(t % textureSize(uLandMask, 0).x, row), 0).r;
  return word >> uint(first + 4 - 8 * t);
}

float landMaskCell(int column, int row) {
  return float(landMaskBitsFrom(column, row) & 1u);
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
  vec3 wx = vec3(wm.x, w0.x, wp.x);
  vec3 wy = vec3(wm.y, w0.y, wp.y);
  float v = 0.0;
  for (int j = 0; j < 3; ++j) {
    uint bits = landMaskBitsFrom((c.x - 1 + cols) % cols, clamp(c.y + j - 1, 0, rows - 1));
    v += wy[j] * dot(wx, vec3(uvec3(bits, bits >> 1u, bits >> 2u) & 1u));
  }
  return v;
}

// A layer height (m) made to agree with the mask: at least / at most 20 m × (fraction − 0.5)
// on land / water (data::LandMask::constrainHeightM, kCoastRampM = 20), the water's bound
// scaled by 1 − keepDepth (the layer's corrected shallow banks keep their depth).
float constrainByLandMask(float heightM, float keepDepth, vec2 latLon) {
  if (!landMaskOn()) return heightM;
  float f = landFraction(latLon);
  float edge = 20.0 * (f - 0.5);
  return f >= 0.5 ? max(heightM, edge) : min(heightM, edge * (1.0 - keepDepth));
}
