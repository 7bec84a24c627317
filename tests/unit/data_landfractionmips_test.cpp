// The land fraction's mip pyramid (data::LandFractionMips): level 0 is the area fraction of
// 2 × 2 cells (a refined cell by its fine cells), each level the mean of the one below; its
// lookups are GL's trilinear filter (wrapping in longitude); the fraction blends from the mask's
// B-spline at one cell to the pyramid at two; a lake under the footprint fades into the land
// instead of standing at full strength; and boxContent never calls a box one class where a
// lookup in it is the other.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/Error.hpp"
#include "data/LandFractionMips.hpp"
#include "data/LandMask.hpp"

using og::data::LandFractionMips;
using og::data::LandMask;
using Content = og::data::LandMaskPyramid::Content;

namespace {

// A global 32 × 16 mask (11.25° cells) with land at columns 4-19 of rows 3-12, a lake cell at
// (10, 7), a refined water cell at (20, 8) holding 16 land fine cells, and refined land cells
// at (19, 8) and (19, 9) holding 60 and 1 (blocks row-major: (19, 8), (20, 8), (19, 9)).
LandMask testMask() {
  std::vector<std::uint8_t> cells(32 * 16, 0);
  for (int r = 3; r <= 12; ++r)
    for (int c = 4; c <= 19; ++c) cells[static_cast<std::size_t>(r * 32 + c)] = 1;
  cells[7 * 32 + 10] = 0;
  LandMask m(32, 16, -180.0, -90.0, 11.25, cells);
  std::vector<std::uint8_t> refined(m.packedBits().size(), 0);
  const auto refine = [&](int c, int r) {
    refined[static_cast<std::size_t>(r * m.bytesPerRow() + c / 8)] |= static_cast<std::uint8_t>(1u << (c % 8));
  };
  refine(19, 8);
  refine(20, 8);
  refine(19, 9);
  m.setFineLevel(refined, {0x0FFFFFFFFFFFFFFFull, 0xFFFFull, 0x1ull});
  return m;
}

double cellFraction(const LandMask& m, int c, int r) {
  return m.refined(c, r) ? std::popcount(m.block(c, r)) / 64.0 : (m.cell(c, r) ? 1.0 : 0.0);
}

}  // namespace

TEST(LandFractionMips, LevelsAreAreaFractionsAndTheirMeans) {
  const LandMask m = testMask();
  const LandFractionMips mips(m);
  ASSERT_EQ(mips.levels(), 4);  // 16 x 8, 8 x 4, 4 x 2, 2 x 1
  EXPECT_EQ(mips.levelWidth(0), 16);
  EXPECT_EQ(mips.levelHeight(3), 1);
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 16; ++c) {
      const double f = 0.25 * (cellFraction(m, 2 * c, 2 * r) + cellFraction(m, 2 * c + 1, 2 * r) +
                               cellFraction(m, 2 * c, 2 * r + 1) + cellFraction(m, 2 * c + 1, 2 * r + 1));
      EXPECT_EQ(mips.texel(0, c, r), static_cast<int>(std::lround(255.0 * f))) << c << ", " << r;
    }
  EXPECT_EQ(mips.texel(0, 5, 3), 191);  // the lake: three land cells of four
  EXPECT_EQ(mips.texel(0, 10, 4), 16);  // the refined water cell: 16 land fine cells of 256
  // Cells 18-19 × 8-9: two land cells, and the refined land ones' 60 and 1 fine cells.
  EXPECT_EQ(mips.texel(0, 9, 4), static_cast<int>(std::lround(255.0 * (128 + 60 + 1) / 256.0)));
  for (int level = 1; level < mips.levels(); ++level)
    for (int r = 0; r < mips.levelHeight(level); ++r)
      for (int c = 0; c < mips.levelWidth(level); ++c) {
        const int sum = mips.texel(level - 1, 2 * c, 2 * r) + mips.texel(level - 1, 2 * c + 1, 2 * r) +
                        mips.texel(level - 1, 2 * c, 2 * r + 1) + mips.texel(level - 1, 2 * c + 1, 2 * r + 1);
        EXPECT_EQ(mips.texel(level, c, r), (sum + 2) / 4) << level << ": " << c << ", " << r;
      }
  // A level whose side is odd halves to GL's size (rounded down), its texels the area mean of
  // what they span: a 28 x 14 mask (14 x 7, then 7 x 3: each coarse row spans 7/3 of a fine
  // one), rows unlike each other.
  std::vector<std::uint8_t> oddCells(28 * 14, 0);
  for (int r = 0; r < 14; ++r)
    for (int c = 0; c < 28; ++c) oddCells[static_cast<std::size_t>(r * 28 + c)] = (c + 3 * r) % 5 < 2 + r % 3 ? 1 : 0;
  const LandMask odd(28, 14, -180.0, -90.0, 180.0 / 14.0, oddCells);
  const LandFractionMips oddMips(odd);
  ASSERT_EQ(oddMips.levels(), 3);  // (then 3 x 1: the next would be 1 wide)
  EXPECT_EQ(oddMips.levelWidth(1), 7);
  EXPECT_EQ(oddMips.levelHeight(1), 3);
  for (int c = 0; c < 7; ++c) {
    // Coarse row 0: fine rows 0 and 1 whole and a third of row 2, fine columns 2c and 2c + 1.
    double sum = 0.0;
    for (int i = 0; i < 2; ++i)
      sum += oddMips.texel(0, 2 * c + i, 0) + oddMips.texel(0, 2 * c + i, 1) + oddMips.texel(0, 2 * c + i, 2) / 3.0;
    EXPECT_EQ(oddMips.texel(1, c, 0), static_cast<int>(std::floor(sum / (2.0 * 7.0 / 3.0) + 0.5))) << c;
    // Coarse row 1: two thirds of row 2, row 3 and two thirds of row 4.
    sum = 0.0;
    for (int i = 0; i < 2; ++i)
      sum += (2.0 * oddMips.texel(0, 2 * c + i, 2) + 2.0 * oddMips.texel(0, 2 * c + i, 4)) / 3.0 + oddMips.texel(0, 2 * c + i, 3);
    EXPECT_EQ(oddMips.texel(1, c, 1), static_cast<int>(std::floor(sum / (2.0 * 7.0 / 3.0) + 0.5))) << c;
  }
  // A regional mask or an odd one has no pyramid.
  const LandMask regional(4, 4, 0.0, 0.0, 1.0, std::vector<std::uint8_t>(16, 1));
  EXPECT_THROW(LandFractionMips{regional}, og::InternalError);
}

TEST(LandFractionMips, LookupsAreGlsTrilinearFilterWrappingInLongitude) {
  const LandMask m = testMask();
  const LandFractionMips mips(m);
  const double texelDeg = 22.5;  // level 0
  // At a texel's centre, its own value; halfway between two, their mean.
  const double lat = -90.0 + 3.5 * texelDeg, lon = -180.0 + 5.5 * texelDeg;
  EXPECT_FLOAT_EQ(mips.filtered(lat, lon, 0.0), mips.texel(0, 5, 3) / 255.0f);
  EXPECT_NEAR(mips.filtered(lat, lon + 0.5 * texelDeg, 0.0), (mips.texel(0, 5, 3) + mips.texel(0, 6, 3)) / 510.0, 1e-6);
  EXPECT_NEAR(mips.filtered(lat, lon, -3.0), mips.filtered(lat, lon, 0.0), 1e-7);  // (lods clamp)
  // Between two levels, the mix of their lookups; past the last, the last.
  EXPECT_NEAR(mips.filtered(lat, lon, 1.25),
              0.75 * static_cast<double>(mips.filtered(lat, lon, 1.0)) + 0.25 * static_cast<double>(mips.filtered(lat, lon, 2.0)), 1e-6);
  EXPECT_FLOAT_EQ(mips.filtered(lat, lon, 9.0), mips.filtered(lat, lon, 3.0));
  // Across the antimeridian: the first and the last columns are neighbours.
  EXPECT_NEAR(mips.filtered(lat, 180.0, 0.0), (mips.texel(0, 0, 3) + mips.texel(0, 15, 3)) / 510.0, 1e-6);
  EXPECT_FLOAT_EQ(mips.filtered(lat, lon + 360.0, 0.7), mips.filtered(lat, lon, 0.7));
  // Rows clamp at the poles.
  EXPECT_FLOAT_EQ(mips.filtered(-90.0, lon, 0.0), mips.texel(0, 5, 0) / 255.0f);
}

TEST(LandFractionMips, FractionBlendsFromTheBSplineAtOneCellToThePyramidAtTwo) {
  const LandMask m = testMask();
  const LandFractionMips mips(m);
  const double cell = m.cellDeg();
  EXPECT_DOUBLE_EQ(mips.weight(cell), 0.0);
  EXPECT_DOUBLE_EQ(mips.weight(1.5 * cell), 0.5);
  EXPECT_DOUBLE_EQ(mips.weight(2.0 * cell), 1.0);
  EXPECT_DOUBLE_EQ(mips.levelOf(2.0 * cell), 0.0);
  EXPECT_DOUBLE_EQ(mips.levelOf(8.0 * cell), 2.0);
  for (double lat = -80.0; lat < 80.0; lat += 7.3)
    for (double lon = -179.0; lon < 180.0; lon += 11.9) {
      EXPECT_FLOAT_EQ(mips.landFraction(lat, lon, 0.5 * cell), m.landFraction(lat, lon, 0.5 * cell));
      EXPECT_FLOAT_EQ(mips.landFraction(lat, lon, 3.0 * cell), mips.filtered(lat, lon, std::log2(1.5)));
      EXPECT_NEAR(mips.landFraction(lat, lon, 1.5 * cell),
                  0.5 * static_cast<double>(m.landFraction(lat, lon, 1.5 * cell) + mips.filtered(lat, lon, std::log2(0.75))), 1e-6);
    }
}

TEST(LandFractionMips, ALakeUnderTheFootprintFadesIntoTheLand) {
  // The one-cell lake is water by the B-spline (a pixel a cell wide sees it); from a footprint
  // of four cells it is land: the mean around it, as a pixel that wide sees the ground.
  const LandMask m = testMask();
  const LandFractionMips mips(m);
  const double lat = -90.0 + 7.5 * m.cellDeg(), lon = -180.0 + 10.5 * m.cellDeg();
  EXPECT_LT(mips.landFraction(lat, lon, 0.5 * m.cellDeg()), 0.5f);
  EXPECT_GT(mips.landFraction(lat, lon, 4.0 * m.cellDeg()), 0.5f);
  // The coast of the land, 16 cells wide, stays between its columns 19 and 20 at the scales
  // that resolve it.
  const double coastLon = -180.0 + 20.0 * m.cellDeg(), midLat = -90.0 + 6.0 * m.cellDeg();
  for (double footprint : {0.5, 1.5, 3.0}) {
    EXPECT_GT(mips.landFraction(midLat, coastLon - 0.8 * m.cellDeg(), footprint * m.cellDeg()), 0.5f) << footprint;
    EXPECT_LT(mips.landFraction(midLat, coastLon + 1.6 * m.cellDeg(), footprint * m.cellDeg()), 0.5f) << footprint;
  }
}

TEST(LandFractionMips, BoxContentHoldsForEveryLookupInTheBox) {
  // Random boxes and level ranges over the default 2′ mask's coasts and lakes (Finland's,
  // Gibraltar's): where boxContent names a class, every lookup at points of the box and levels
  // of the range is over kLandByte / 255 (land) or under kWaterByte / 255 (water).
  const LandMask& m = og::data::defaultLandMask();
  const LandFractionMips mips(m);
  EXPECT_EQ(mips.levels(), 5);  // 5400 x 2700 down to 337 x 168 (4′ to 64′)
  EXPECT_EQ(mips.levelHeight(3), 337);
  // Level 0 is the refined cells' fine counts: at random texels of the whole globe.
  std::mt19937 pick(3);
  for (int k = 0; k < 2000; ++k) {
    const int c = static_cast<int>(pick() % 5400u), r = static_cast<int>(pick() % 2700u);
    int fine = 0;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) fine += std::popcount(m.block(2 * c + i, 2 * r + j));
    ASSERT_EQ(mips.texel(0, c, r), (fine * 255 + 128) / 256) << c << ", " << r;
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int named = 0, wrong = 0;
  for (int box = 0; box < 4000; ++box) {
    // Finland's lakes, Gibraltar's coasts, Fiji across the antimeridian (the rows' two runs),
    // and within a texel of the poles (the rows' clamp).
    const int where = box % 4;
    const double lat0 = where == 0 ? 60.0 + 5.0 * unit(rng) : where == 1 ? 35.0 + 2.0 * unit(rng)
                        : where == 2 ? -18.0 + 2.0 * unit(rng) : (box % 8 == 3 ? 89.5 : -90.4) + 0.6 * unit(rng);
    const double lon0 = where == 0 ? 22.0 + 8.0 * unit(rng) : where == 1 ? -7.0 + 3.0 * unit(rng)
                        : where == 2 ? 178.5 + 1.5 * unit(rng) : -180.0 + 360.0 * unit(rng);
    const double side = 0.05 + 1.5 * unit(rng);
    const double lod0 = 3.5 * unit(rng) - 0.5, lod1 = lod0 + 1.2 * unit(rng);
    const Content c = mips.boxContent(lat0, std::min(lat0 + side, 90.0), lon0, lon0 + side, lod0, lod1);
    if (c == Content::Both) continue;
    ++named;
    for (int k = 0; k < 40; ++k) {
      const float f = mips.filtered(std::min(lat0 + side * unit(rng), 90.0), lon0 + side * unit(rng),
                                    lod0 + (lod1 - lod0) * unit(rng));
      wrong += c == Content::Land ? (f < LandFractionMips::kLandByte / 255.0f ? 1 : 0)
                                  : (f > LandFractionMips::kWaterByte / 255.0f ? 1 : 0);
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(named, 400);  // (it does name classes: ~600)
}
