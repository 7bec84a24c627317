// Land and water from real coastlines (data::LandMask, render/LandMaskTexture): a global mask
// of 2′ cells from GSHHG, lakes as water, covering -180..180° E and -90..90° N, rows south to
// north, with a fine level of 15″ cells (8 × 8 per 2′ cell) where a 2′ cell's own fine cells
// are not all one class (the refined cells; their blocks in uLandMaskFine, its layout in
// render/LandMaskTexture.hpp). Texel x of a row (32 bits) holds columns 8x - 4 ... 8x + 11: bit
// k = column 8x - 4 + k is land, bit 16 + k is refined (wrapping in longitude), so any three
// neighbouring cells lie in one texel. Bound to unit OG_UNIT_LAND_MASK only where it decides
// the coast (a global elevation layer coarser than it); otherwise the unit holds a 1×1
// texture and landMaskOn() is false. The coastal-water code reads it here.
#include "common/constants.glsl"
layout(binding = OG_UNIT_LAND_MASK) uniform usampler2D uLandMask;
layout(binding = OG_UNIT_LAND_MASK_FINE) uniform usampler2D uLandMaskFine;
// The land fraction's mip pyramid (data::LandFractionMips, render/LandMaskTexture): R8, level 0
// the area fraction of 2 × 2 cells of the 2′ level; 1×1 in frames that do not read it
// (LandMaskTexture::bind: landFractionMipsOn() false, the B-spline at every footprint).
layout(binding = OG_UNIT_LAND_FRACTION) uniform sampler2D uLandFraction;

bool landMaskOn() { return textureSize(uLandMask, 0).y > 1; }
bool landMaskFineOn() { return textureSize(uLandMaskFine, 0).y > 1; }
bool landFractionMipsOn() { return textureSize(uLandFraction, 0).y > 1; }
// LANDMASK_FILTERED_ONLY (a frame whose every footprint weighs only the pyramid) implies that the
// fine level weighs nothing either, and that the pyramid is compiled in (LANDMASK_PYRAMID).
#if defined(LANDMASK_FILTERED_ONLY) && !defined(LANDMASK_COARSE_ONLY)
#define LANDMASK_COARSE_ONLY
#endif
#if defined(LANDMASK_FILTERED_ONLY) && !defined(LANDMASK_PYRAMID)
#define LANDMASK_PYRAMID
#endif

// No integer division or modulo by a value the compiler cannot see is constant: llvmpipe runs
// those lane by lane, which made them most of the lookups' cost.
// n / 96 for 0 <= n < 2^22, in float (vectorised; exact: the error is far below 1/96).
int landMaskDiv96(int n) { return int((float(n) + 0.5) * (1.0 / 96.0)); }

// The texel holding columns first ... first + 2 of a row (wrapping), shifted so that column
// `first` is bit 0 of the land bits (x) and of the refined bits (y). `first` in [0, cols).
uvec2 landMaskBitsFrom(int first, int row) {
  int t = (first + 4) >> 3;
  int width = textureSize(uLandMask, 0).x;
  uint word = texelFetch(uLandMask, ivec2(t >= width ? t - width : t, row), 0).r;  // (no %: see below)
  uint shift = uint(first + 4 - 8 * t);
  return uvec2((word & 0xFFFFu) >> shift, (word >> 16u) >> shift);
}

// The cell nearest a point (latitude, longitude radians) of a global grid of `rows` rows and
// 2 × rows columns from 180° W (the 2′ level's or the fine level's), and the point's offset
// from its centre in cells; columns wrap, rows clamp.
ivec2 landMaskCellAt(vec2 latLon, int rows, out vec2 offset) {
  float cell = PI / float(rows);
  vec2 xy = vec2((latLon.y + PI) / cell - 0.5, (latLon.x + 0.5 * PI) / cell - 0.5);
  xy.y = clamp(xy.y, 0.0, float(rows - 1));
  xy.x = mod(xy.x, float(2 * rows));
  ivec2 c = ivec2(floor(xy + 0.5));
  offset = xy - vec2(c);
  return c;
}

// The uniform quadratic B-spline's weights of the cells at offsets -1, 0, +1 from the nearest
// centre, for an offset t from it: columns' (first column) and rows' (second).
mat2x3 landMaskWeights(vec2 t) {
  vec2 wm = 0.5 * (0.5 - t) * (0.5 - t), w0 = 0.75 - t * t, wp = 0.5 * (0.5 + t) * (0.5 + t);
  return mat2x3(vec3(wm.x, w0.x, wp.x), vec3(wm.y, w0.y, wp.y));
}

// The fraction of land around (latitude, longitude) radians, [0, 1]: the quadratic B-spline
// of the 3 × 3 cells around the nearest centre, so the coast (the 0.5 contour) is a smooth
// curve without the raster's staircase (data::LandMask::landFraction, its CPU twin).
float landFraction(vec2 latLon) {
  int rows = textureSize(uLandMask, 0).y;
  vec2 t;
  ivec2 c = landMaskCellAt(latLon, rows, t);
  mat2x3 w = landMaskWeights(t);
  float v = 0.0;
  for (int j = 0; j < 3; ++j) {
    uint bits = landMaskBitsFrom(c.x >= 1 ? c.x - 1 : c.x - 1 + 2 * rows, clamp(c.y + j - 1, 0, rows - 1)).x;
    v += w[1][j] * dot(w[0], vec3(uvec3(bits, bits >> 1u, bits >> 2u) & 1u));
  }
  return v;
}

// Texel i of the fine level's list (render/LandMaskTexture: 4096 texels a row).
uvec4 landMaskFineTexel(int i) {
  return texelFetch(uLandMaskFine, ivec2(i & 4095, i >> 12), 0);
}

// The 8 × 8 fine cells of 2′ cell (column, row) as 64 bits (x: bits 0-31; bit 8 j + i = the
// fine cell i east and j north of its south-west corner): all land / all water from the cell's
// own class (`bits`: landMaskBitsFrom's for the column, bit 0 land, y's bit 0 refined), or
// the refined block from the rank index (data::LandMask::block).
uvec2 landMaskBlock(int column, int row, uvec2 bits) {
  uvec2 block = (bits.x & 1u) != 0u ? uvec2(~0u) : uvec2(0u);
  // Behind a condition (a loop of 0 or 1 trips): a GPU skips the fetches where no pixel of a
  // warp needs them. llvmpipe (Mesa 22.3) runs them for every pixel, masked, whatever the
  // condition: loops run their first trip even when no pixel enters (docs/performance.md,
  // "Ninth session").
  for (int k = 0; k < int(bits.y & 1u); ++k) {
    int rows = textureSize(uLandMask, 0).y;
    int perRow = landMaskDiv96(2 * rows + 95);
    int k96 = landMaskDiv96(column);
    uvec4 rank = landMaskFineTexel(row * perRow + k96);
    int b = column - 96 * k96;
    uint word = b < 32 ? rank.x : (b < 64 ? rank.y : rank.z);
    uint bit = 1u << uint(b & 31);
    int slot = int(rank.w) + bitCount(word & (bit - 1u)) + (b >= 32 ? bitCount(rank.x) : 0) +
               (b >= 64 ? bitCount(rank.y) : 0);
    uvec4 t = landMaskFineTexel(rows * perRow + (slot >> 1));
    block = (slot & 1) == 0 ? t.xy : t.zw;
  }
  return block;
}

// The blocks holding fine columns x0 ... x1 (x0 may be -1, x1 up to the columns: they wrap) and
// rows y0 ... y1 (in range), at most two blocks each way, south-west block (bx0, by0); `spline`
// false when they are all one class with no refined block (`value`: that class).
struct FineBlocks {
  int bx0, by0;
  uvec2 b00, b10, b01, b11;
  bool spline;
  float value;
};
FineBlocks landMaskFineBlocks(int x0, int x1, int y0, int y1, int rows) {
  int blockCols = rows >> 2;
  FineBlocks f;
  f.bx0 = x0 >> 3;
  f.by0 = y0 >> 3;
  int bx1 = x1 >> 3, by1 = y1 >> 3;
  // One mask fetch a block row gives both columns' land and refined bits.
  int first = f.bx0 < 0 ? f.bx0 + blockCols : (f.bx0 >= blockCols ? f.bx0 - blockCols : f.bx0);
  uvec2 south = landMaskBitsFrom(first, f.by0);
  uvec2 north = by1 != f.by0 ? landMaskBitsFrom(first, by1) : south;
  // No refined cell among them: the fine cells are their cells' classes (the open sea, inland,
  // a coast along 2′ edges); all one class is that class without the spline.
  uint columns = bx1 != f.bx0 ? 3u : 1u;
  uint refined = (south.y | north.y) & columns;
  uint land = (south.x & columns) | ((north.x & columns) << 2u);
  uint all = bx1 != f.bx0 ? (by1 != f.by0 ? 15u : 3u) : (by1 != f.by0 ? 5u : 1u);
  f.value = (land & 1u) != 0u ? 1.0 : 0.0;
  f.spline = refined != 0u || ((land & all) != 0u && (land & all) != all);
  f.b00 = f.b10 = f.b01 = f.b11 = uvec2(f.value > 0.5 ? ~0u : 0u);
  for (int once = 0; once < (f.spline ? 1 : 0); ++once) {  // (as in landMaskBlock)
    f.b00 = landMaskBlock(first, f.by0, south);
    int second = bx1 >= blockCols ? bx1 - blockCols : bx1;
    f.b10 = bx1 != f.bx0 ? landMaskBlock(second, f.by0, south >> 1u) : f.b00;
    f.b01 = by1 != f.by0 ? landMaskBlock(first, by1, north) : f.b00;
    f.b11 = by1 != f.by0 ? (bx1 != f.bx0 ? landMaskBlock(second, by1, north >> 1u) : f.b01) : f.b10;
  }
  return f;
}

// The quadratic B-spline of the 3 × 3 fine cells around fine cell c (offset t) from blocks
// that hold them (c's columns unwrapped as the blocks' were).
float landFractionFineAt(FineBlocks f, ivec2 c, vec2 t, int rows) {
  mat2x3 w = landMaskWeights(t);
  // A fine row's three cells: its byte of the west block and of the east one side by side
  // (16 cells), shifted to the first cell's column.
  uint firstColumn = uint(c.x - 1 - 8 * f.bx0);
  float v = 0.0;
  for (int j = 0; j < 3; ++j) {
    int y = clamp(c.y + j - 1, 0, rows - 1);
    bool inNorth = (y >> 3) != f.by0;
    uvec2 west = inNorth ? f.b01 : f.b00, east = inNorth ? f.b11 : f.b10;
    uint shift = uint((y & 3) * 8);
    bool high = (y & 7) >= 4;
    uint row = (((high ? west.y : west.x) >> shift) & 0xFFu) | ((((high ? east.y : east.x) >> shift) & 0xFFu) << 8u);
    uint three = row >> firstColumn;
    v += w[1][j] * dot(w[0], vec3(uvec3(three, three >> 1u, three >> 2u) & 1u));
  }
  return f.spline ? v : f.value;
}

// The quadratic B-spline of the 3 × 3 fine cells around (latitude, longitude) radians, [0, 1]
// (data::LandMask::fineFraction). Those cells lie in at most 2 × 2 blocks: each fetched once.
float landFractionFine(vec2 latLon) {
  int rows = 8 * textureSize(uLandMask, 0).y;
  vec2 t;
  ivec2 c = landMaskCellAt(latLon, rows, t);
  FineBlocks f = landMaskFineBlocks(c.x - 1, c.x + 1, max(c.y - 1, 0), min(c.y + 1, rows - 1), rows);
  return landFractionFineAt(f, c, t, rows);
}

// landFractionFine at a pixel's four samples, which lie within three fine cells of each other
// (a footprint the fine level weighs at all): their 6 × 6 cells or fewer still lie in at most
// 2 × 2 blocks, fetched once for the four (the globe's classifying draw tests every sample).
vec4 landFractionFine4(vec2 latLon0, vec2 latLon1, vec2 latLon2, vec2 latLon3) {
  int rows = 8 * textureSize(uLandMask, 0).y, cols = 2 * rows;
  vec2 t0, t1, t2, t3;
  ivec2 c0 = landMaskCellAt(latLon0, rows, t0), c1 = landMaskCellAt(latLon1, rows, t1);
  ivec2 c2 = landMaskCellAt(latLon2, rows, t2), c3 = landMaskCellAt(latLon3, rows, t3);
  // Columns unwrapped next to sample 0's (across the antimeridian).
  c1.x += c1.x - c0.x > rows ? -cols : (c0.x - c1.x > rows ? cols : 0);
  c2.x += c2.x - c0.x > rows ? -cols : (c0.x - c2.x > rows ? cols : 0);
  c3.x += c3.x - c0.x > rows ? -cols : (c0.x - c3.x > rows ? cols : 0);
  ivec2 lo = min(min(c0, c1), min(c2, c3)) - 1, hi = max(max(c0, c1), max(c2, c3)) + 1;
  FineBlocks f = landMaskFineBlocks(lo.x, hi.x, max(lo.y, 0), min(hi.y, rows - 1), rows);
  return vec4(landFractionFineAt(f, c0, t0, rows), landFractionFineAt(f, c1, t1, rows),
              landFractionFineAt(f, c2, t2, rows), landFractionFineAt(f, c3, t3, rows));
}

// The fine level's weight for a footprint (radians of arc on the ground): 1 up to one fine
// cell, 0 from three (data::LandMask::fineWeight); 0 without a fine level.
// LANDMASK_COARSE_ONLY: a frame in which every pixel's footprint spans three fine cells or more
// (render::LandMaskTexture::fineLevelUnresolved: from ~2100 km up at 1280x720) — the weight is 0
// wherever it is asked, and as a constant it compiles the fine level's lookups out, which
// llvmpipe otherwise runs for every pixel, masked (a loop's first trip: docs/performance.md).
#ifdef LANDMASK_COARSE_ONLY
float landMaskFineWeight(float footprintRad) { return 0.0; }
#else
float landMaskFineWeight(float footprintRad) {
  if (!landMaskFineOn()) return 0.0;
  float fineCellRad = PI / float(8 * textureSize(uLandMask, 0).y);
  return 1.0 - smoothstep(1.0, 3.0, footprintRad / fineCellRad);
}
#endif

// A pixel's footprint on the ground for the mask's coast, radians of arc: its view distance
// `t` (m) times the angle `pixelRad` a pixel subtends, widened at grazing incidence
// (`cosIncidence`: the view's cosine to the vertical). Every pass that draws a side of the coast
// (globe, terrain, grid) takes it from this, not from its geometry's screen derivatives (which
// steep faces, waves and the mesh under the sea inflate), so all see one coast. CPU twin (in
// degrees): data::LandMask::coastFootprintDeg.
float coastFootprintRad(float t, float pixelRad, float cosIncidence) {
  return t * pixelRad / (WGS84_A * max(cosIncidence, 0.2));
}

// The pyramid's weight for a footprint (radians of arc on the ground): 0 up to one 2′ cell, 1
// from two (data::LandFractionMips::weight); 0 without the pyramid.
// Compiled in only with LANDMASK_PYRAMID (a frame some pixel of which may weigh it:
// render::LandMaskTexture::fractionMipsWeighed, from ~7 km up at 1280x720, for the globe's and
// the terrain's programs): llvmpipe runs its lookups, masked, for every pixel whatever the
// weight, +2-5 % of a frame. Without it the weight is the constant 0 and they compile out.
// LANDMASK_FILTERED_ONLY: a frame in which every pixel's footprint spans two cells or more
// (render::LandMaskTexture::fractionMipsOnly: from ~11 000 km up at 1280x720) — the weight is 1
// wherever it is asked, and the B-spline's and the fine level's lookups compile out.
#if !defined(LANDMASK_PYRAMID)
float landFractionMipsWeight(float footprintRad) { return 0.0; }
#elif defined(LANDMASK_FILTERED_ONLY)
float landFractionMipsWeight(float footprintRad) { return 1.0; }
#else
float landFractionMipsWeight(float footprintRad) {
  if (!landFractionMipsOn()) return 0.0;
  return smoothstep(1.0, 2.0, footprintRad * float(textureSize(uLandMask, 0).y) / PI);
}
#endif

// The area fraction of land around (latitude, longitude) radians at the scale of a footprint
// of `footprintRad`: the pyramid's trilinear lookup at level log2(footprint / 2 cells)
// (data::LandFractionMips::filtered). Lakes and islets under a pixel fade into their
// surroundings' class instead of flickering in and out with the pixel's centre.
float landFractionFiltered(vec2 latLon, float footprintRad) {
  float lod = log2(footprintRad * float(textureSize(uLandMask, 0).y) / (2.0 * PI));
  return textureLod(uLandFraction, vec2(latLon.y * (0.5 / PI) + 0.5, latLon.x / PI + 0.5), lod).r;
}

// The fraction of land as a footprint of `footprintRad` (radians of arc, >= 0) sees it: the
// fine level where the footprint resolves it, the 2′ level where not, the pyramid where the
// footprint spans several 2′ cells, blended between (data::LandFractionMips::landFraction).
float landFraction(vec2 latLon, float footprintRad) {
  float m = landFractionMipsWeight(footprintRad);
  float w = landMaskFineWeight(footprintRad);
  float coarse = 0.0, fine = 0.0, filtered = 0.0;
  for (int once = 0; once < (m > 0.0 ? 1 : 0); ++once) filtered = landFractionFiltered(latLon, footprintRad);
  for (int once = 0; once < (w < 1.0 && m < 1.0 ? 1 : 0); ++once) coarse = landFraction(latLon);  // (as in landMaskBlock)
  for (int once = 0; once < (w > 0.0 ? 1 : 0); ++once) fine = landFractionFine(latLon);
  return mix(mix(coarse, fine, w), filtered, m);
}

// landFraction without the fine level (the 2′ level's B-spline and the pyramid), for a test at
// the pixel's centre that runs for every pixel (globe.frag's depth of the land).
float landFractionCoarse(vec2 latLon, float footprintRad) {
  float m = landFractionMipsWeight(footprintRad);
  float coarse = 0.0, filtered = 0.0;
  for (int once = 0; once < (m > 0.0 ? 1 : 0); ++once) filtered = landFractionFiltered(latLon, footprintRad);
  for (int once = 0; once < (m < 1.0 ? 1 : 0); ++once) coarse = landFraction(latLon);
  return mix(coarse, filtered, m);
}

// landFraction at a pixel's four samples with the pixel's footprint, the fine level's blocks
// fetched once for the four (landFractionFine4).
vec4 landFraction4(vec2 latLon0, vec2 latLon1, vec2 latLon2, vec2 latLon3, float footprintRad) {
  float m = landFractionMipsWeight(footprintRad);
  float w = landMaskFineWeight(footprintRad);
  vec4 coarse = vec4(0.0), fine = vec4(0.0), filtered = vec4(0.0);
  for (int once = 0; once < (m > 0.0 ? 1 : 0); ++once)
    filtered = vec4(landFractionFiltered(latLon0, footprintRad), landFractionFiltered(latLon1, footprintRad),
                    landFractionFiltered(latLon2, footprintRad), landFractionFiltered(latLon3, footprintRad));
  for (int once = 0; once < (w < 1.0 && m < 1.0 ? 1 : 0); ++once)
    coarse = vec4(landFraction(latLon0), landFraction(latLon1), landFraction(latLon2), landFraction(latLon3));
  for (int once = 0; once < (w > 0.0 ? 1 : 0); ++once) fine = landFractionFine4(latLon0, latLon1, latLon2, latLon3);
  return mix(mix(coarse, fine, w), filtered, m);
}

// A layer height (m) made to agree with the mask: at least / at most 20 m × (fraction − 0.5)
// on land / water (data::LandMask::constrainHeightM, kCoastRampM = 20), the water's bound
// scaled by 1 − keepDepth (the layer's corrected shallow banks keep their depth), for a land
// fraction `f`.
float constrainByLandFraction(float heightM, float keepDepth, float f) {
  float edge = 20.0 * (f - 0.5);
  return f >= 0.5 ? max(heightM, edge) : min(heightM, edge * (1.0 - keepDepth));
}
// The fraction as a footprint of `footprintRad` sees it.
float constrainByLandMask(float heightM, float keepDepth, vec2 latLon, float footprintRad) {
  return landMaskOn() ? constrainByLandFraction(heightM, keepDepth, landFraction(latLon, footprintRad)) : heightM;
}
// The 2′ level's fraction, without the fine level's code (which llvmpipe would run, masked,
// behind any branch: readers that blur over kilometres and run often take this one).
float constrainByCoarseLandMask(float heightM, float keepDepth, vec2 latLon) {
  return landMaskOn() ? constrainByLandFraction(heightM, keepDepth, landFraction(latLon)) : heightM;
}
