// The GSHHG land mask decides the coast where the DEM's zero contour is wrong: Flevoland
// (reclaimed land below sea level; ETOPO's 20' cell is -2 m) is land, Lake Victoria (1128 m in
// the DEM) and Lake Michigan are water; the terrain's heights follow it for the default layer
// and keep their own zero contour for a regional layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "data/BitPng.hpp"
#include "data/Elevation.hpp"
#include "data/GeoRaster.hpp"
#include "data/LandMask.hpp"
#include "data/LandMaskPyramid.hpp"
#include "terrain/Heightfield.hpp"

using og::data::LandMask;

TEST(LandMask, DefaultMaskIsGlobalAtTwoArcMinutes) {
  const LandMask& m = og::data::defaultLandMask();
  EXPECT_EQ(m.width(), 10800);
  EXPECT_EQ(m.height(), 5400);
  EXPECT_NEAR(m.cellDeg(), 1.0 / 30.0, 1e-9);
  EXPECT_NEAR(m.westDeg(), -180.0, 1e-6);
  EXPECT_NEAR(m.southDeg(), -90.0, 1e-6);
  EXPECT_TRUE(m.isLand(23.0, 12.0));     // Sahara
  EXPECT_TRUE(m.isLand(-80.0, 0.0));     // Antarctica
  EXPECT_FALSE(m.isLand(0.0, -150.0));   // Pacific
  EXPECT_FALSE(m.isLand(36.0, -5.45));   // the Strait of Gibraltar (14 km wide)
  EXPECT_TRUE(m.isLand(36.25, -5.75));   // Spain north of Tarifa
}

TEST(LandMask, FineLevelDrawsWhatTheTwoMinuteCellsCannotHold) {
  // GSHHG-h at 15″ where a 2′ cell holds both land and water: the Rock of Gibraltar (1.2 km
  // wide: water in the 2′ B-spline) and the Bosphorus off Istanbul's Bebek (0.7–1.5 km wide:
  // land in it). The footprint picks the level: a pixel of 3 km sees the 2′ coast.
  const LandMask& m = og::data::defaultLandMask();
  ASSERT_TRUE(m.hasFineLevel());
  const struct {
    double lat, lon;
    bool land;
  } places[] = {{36.125, -5.345, true}, {41.10, 29.06, false}};
  for (const auto& p : places) {
    EXPECT_EQ(m.landFraction(p.lat, p.lon, 0.0) >= 0.5f, p.land) << p.lat << ", " << p.lon;
    EXPECT_EQ(m.landFraction(p.lat, p.lon) >= 0.5f, !p.land) << p.lat << ", " << p.lon;
    EXPECT_EQ(m.landFraction(p.lat, p.lon, 0.03), m.landFraction(p.lat, p.lon));
  }
  // Heights follow the fine coast: the Bosphorus is water for the terrain too.
  const og::terrain::Heightfield ground(og::data::defaultElevation());
  EXPECT_LT(ground.layerHeightM(41.10, 29.06), 0.0);
  EXPECT_GT(ground.layerHeightM(36.125, -5.345), 0.0);
}

TEST(LandMask, DecidesTheCoastWhereTheDemIsWrong) {
  const LandMask& m = og::data::defaultLandMask();
  const auto& dem = og::data::defaultElevation();
  ASSERT_TRUE(m.refines(dem));
  const og::terrain::Heightfield ground(dem);
  // Flevoland (Netherlands): land below sea level; the DEM's cell is at or below 0.
  EXPECT_LE(dem.sample(52.5, 5.5), 0.0f);
  EXPECT_TRUE(m.isLand(52.5, 5.5));
  EXPECT_GT(ground.layerHeightM(52.5, 5.5), 0.0);
  // Lake Victoria and Lake Michigan: lakes are water, whatever the DEM's height there.
  EXPECT_GT(dem.sample(-1.0, 33.0), 1000.0f);
  EXPECT_FALSE(m.isLand(-1.0, 33.0));
  EXPECT_LT(ground.layerHeightM(-1.0, 33.0), 0.0);
  EXPECT_FALSE(m.isLand(44.0, -87.0));
  EXPECT_LT(ground.layerHeightM(44.0, -87.0), 0.0);
  // The Everglades: land, never sea-speckled, across a transect of the southern tip.
  for (double lon = -81.0; lon <= -80.5; lon += 0.05) EXPECT_GT(ground.layerHeightM(25.6, lon), 0.0) << lon;
}

TEST(LandMask, RegionalAndFineLayersKeepTheirOwnCoast) {
  og::data::LatLonGrid regional;
  regional.width = regional.height = 10;
  regional.lon0Deg = 0.0;
  regional.lat0Deg = 50.0;
  regional.dLonDeg = regional.dLatDeg = 0.5;
  regional.values.assign(100, -50.0f);
  EXPECT_FALSE(og::data::defaultLandMask().refines(regional));
  const og::terrain::Heightfield ground(regional);
  EXPECT_NEAR(ground.layerHeightM(52.0, 2.0), -50.0, 1e-6);  // would be land (England) in the mask
}

TEST(LandMask, FractionIsAQuadraticBSplineOfTheCells) {
  // A global 16 x 8 mask (22.5° cells) with one land cell at column 9, row 5. Weights of the
  // uniform quadratic B-spline: 3/4 at the centre, 1/8 at the neighbours' centres, 1/2 and 1/2
  // on a shared edge.
  std::vector<std::uint8_t> cells(16 * 8, 0);
  cells[5 * 16 + 9] = 1;
  const LandMask m(16, 8, -180.0, -90.0, 22.5, cells);
  const double lon = -180.0 + 9.5 * 22.5, lat = -90.0 + 5.5 * 22.5;
  EXPECT_FLOAT_EQ(m.landFraction(lat, lon), 0.5625f);  // a one-cell island survives (>= 0.5)
  EXPECT_FLOAT_EQ(m.landFraction(lat, lon + 22.5), 0.09375f);
  EXPECT_FLOAT_EQ(m.landFraction(lat, lon + 11.25), 0.375f);
  EXPECT_FLOAT_EQ(m.landFraction(lat + 11.25, lon + 11.25), 0.25f);
  EXPECT_FLOAT_EQ(m.landFraction(lat, lon + 33.75), 0.0f);  // outside the 3 x 3 support
  EXPECT_NEAR(m.constrainHeightM(-100.0, lat, lon), LandMask::kCoastRampM * 0.0625, 1e-6);
  EXPECT_NEAR(m.constrainHeightM(300.0, lat, lon + 22.5), -LandMask::kCoastRampM * 0.40625, 1e-6);
  // Longitude wraps: column 15 and column 0 are neighbours.
  EXPECT_FLOAT_EQ(m.landFraction(lat, lon + 360.0), 0.5625f);
  // A straight coast along a cell edge stays on it.
  std::vector<std::uint8_t> half(16 * 8, 0);
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c) half[r * 16 + c] = 1;
  const LandMask h(16, 8, -180.0, -90.0, 22.5, half);
  EXPECT_FLOAT_EQ(h.landFraction(10.0, 0.0), 0.5f);
  EXPECT_GT(h.landFraction(10.0, -1.0), 0.5f);
  EXPECT_LT(h.landFraction(10.0, 1.0), 0.5f);
}

TEST(LandMask, FineLevelIsTheBSplineOfItsBlocksBlendedByFootprint) {
  // A global 16 x 8 mask (22.5° cells, fine cells 2.8125°): cell (9, 5) water but refined, its
  // block holding one land fine cell (i 3, j 4); cell (10, 5) land, not refined.
  std::vector<std::uint8_t> cells(16 * 8, 0);
  cells[5 * 16 + 10] = 1;
  LandMask m(16, 8, -180.0, -90.0, 22.5, cells);
  EXPECT_FALSE(m.hasFineLevel());
  EXPECT_DOUBLE_EQ(m.fineWeight(0.0), 0.0);
  std::vector<std::uint8_t> refined(m.packedBits().size(), 0);
  refined[5 * m.bytesPerRow() + 1] = 1u << 1;  // column 9
  EXPECT_THROW(m.setFineLevel(refined, {}), og::InternalError);  // one refined cell, no block
  m.setFineLevel(refined, {std::uint64_t{1} << (4 * 8 + 3)});
  ASSERT_TRUE(m.hasFineLevel());
  EXPECT_EQ(m.block(9, 5), std::uint64_t{1} << 35);
  EXPECT_EQ(m.block(10, 5), ~std::uint64_t{0});
  EXPECT_EQ(m.block(8, 5), std::uint64_t{0});
  const double f = 22.5 / 8.0;
  const auto lonOf = [&](int fineColumn) { return -180.0 + (fineColumn + 0.5) * f; };
  const auto latOf = [&](int fineRow) { return -90.0 + (fineRow + 0.5) * f; };
  // The one-fine-cell island survives at the fine level; the coarse level does not see it.
  EXPECT_FLOAT_EQ(m.fineFraction(latOf(44), lonOf(75)), 0.5625f);
  EXPECT_LT(m.landFraction(latOf(44), lonOf(75)), 0.5f);
  // Inside the land cell, and at its west edge next to the refined cell's water.
  EXPECT_FLOAT_EQ(m.fineFraction(latOf(44), lonOf(82)), 1.0f);
  EXPECT_FLOAT_EQ(m.fineFraction(latOf(44), lonOf(80)), 0.875f);
  // The footprint: the fine level up to one fine cell, the coarse from three, half at two.
  EXPECT_DOUBLE_EQ(m.fineWeight(0.5 * f), 1.0);
  EXPECT_DOUBLE_EQ(m.fineWeight(2.0 * f), 0.5);
  EXPECT_DOUBLE_EQ(m.fineWeight(3.0 * f), 0.0);
  const double lat = latOf(44), lon = lonOf(75);
  EXPECT_FLOAT_EQ(m.landFraction(lat, lon, 0.0), m.fineFraction(lat, lon));
  EXPECT_FLOAT_EQ(m.landFraction(lat, lon, 5.0 * f), m.landFraction(lat, lon));
  EXPECT_NEAR(m.landFraction(lat, lon, 2.0 * f), 0.5f * (m.landFraction(lat, lon) + m.fineFraction(lat, lon)), 1e-6);
  // Heights follow the finest level by default.
  EXPECT_GT(m.constrainHeightM(-100.0, lat, lon), 0.0);
  EXPECT_LT(m.constrainHeightM(-100.0, lat, lon, 0.0, 5.0 * f), 0.0);
}

TEST(LandMask, RasterStaircaseCoastIsSmoothed) {
  // A coast rasterised as a staircase (2 columns per row): the 0.5 contour's largest distance
  // from its fitted straight line is 0.40 cells with the B-spline, 0.56 with a bilinear blend
  // (whose contour keeps the raster's straight runs and corners).
  const int w = 64, h = 32;
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(w * h), 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) cells[static_cast<std::size_t>(r * w + c)] = c >= 2 * r + 10 ? 1 : 0;
  const double cell = 360.0 / w;
  const LandMask m(w, h, -180.0, -90.0, cell, cells);
  std::vector<std::pair<double, double>> contour;  // (row, column) of the 0.5 crossing
  for (double y = 4.0; y <= 12.0; y += 0.05) {
    double lo = 0.0, hi = 50.0;
    for (int i = 0; i < 50; ++i) {
      const double mid = 0.5 * (lo + hi);
      (m.landFraction(-90.0 + (y + 0.5) * cell, -180.0 + (mid + 0.5) * cell) >= 0.5f ? hi : lo) = mid;
    }
    contour.emplace_back(y, lo);
  }
  double sy = 0, sx = 0, syy = 0, sxy = 0;
  for (const auto& [y, x] : contour) {
    sy += y;
    sx += x;
    syy += y * y;
    sxy += y * x;
  }
  const double n = static_cast<double>(contour.size());
  const double b = (n * sxy - sy * sx) / (n * syy - sy * sy), a = (sx - b * sy) / n;
  double worst = 0.0;
  for (const auto& [y, x] : contour) worst = std::max(worst, std::abs(x - (a + b * y)));
  EXPECT_NEAR(b, 2.0, 0.05);
  EXPECT_LT(worst, 0.45);
}

TEST(LandMask, SyntheticGlobesKeepTheirOwnCoast) {
  // A global 0.25° layer that is land everywhere: not Earth's relief, so no mask.
  og::data::LatLonGrid flat;
  flat.width = 1440;
  flat.height = 720;
  flat.lon0Deg = -179.875;
  flat.lat0Deg = -89.875;
  flat.dLonDeg = flat.dLatDeg = 0.25;
  flat.wrapsLongitude = true;
  flat.values.assign(1440u * 720u, 300.0f);
  EXPECT_FALSE(og::data::defaultLandMask().refines(flat));
  const og::terrain::Heightfield ground(flat);
  EXPECT_NEAR(ground.layerHeightM(0.3, 0.0), 300.0, 1e-3);  // the Gulf of Guinea in the mask
}

// The embedded mask is decoded straight from its 1-bit PNG into packed bits (data/BitPng):
// bit for bit what GDAL's general reader gives. Its speed is measured by `bench --startup`
// (the "embedded land mask" stage), not by a timed assertion here.
namespace og::embedded::data {
std::optional<std::string_view> find(std::string_view path);
}

TEST(LandMask, FastDecodeMatchesGdalBitForBit) {
  const auto png = og::embedded::data::find("gshhg_landmask_2m.png");
  const auto pgw = og::embedded::data::find("gshhg_landmask_2m.pgw");
  ASSERT_TRUE(png && pgw);
  const og::data::PackedBitImage image = og::data::decodeBitPng(*png, "embedded mask");
  const LandMask& fast = og::data::defaultLandMask();
  const auto raster = og::data::readGeographicBytesMemory(*png, *pgw, "png", "gdal");
  const LandMask slow(raster.width, raster.height, raster.westDeg, raster.southDeg, raster.cellLatDeg,
                      raster.values);
  EXPECT_EQ(fast.width(), slow.width());
  EXPECT_EQ(fast.height(), slow.height());
  EXPECT_NEAR(fast.westDeg(), slow.westDeg(), 1e-9);
  EXPECT_NEAR(fast.southDeg(), slow.southDeg(), 1e-9);
  EXPECT_NEAR(fast.cellDeg(), slow.cellDeg(), 1e-12);
  EXPECT_TRUE(fast.packedBits() == slow.packedBits());
  EXPECT_TRUE(image.bits == slow.packedBits());
}

TEST(LandMask, BadBitPngIsAnInputErrorNamingTheFile) {
  const auto png = og::embedded::data::find("gshhg_landmask_2m.png");
  ASSERT_TRUE(png);
  const auto message = [](std::string_view bytes) {
    try {
      (void)og::data::decodeBitPng(bytes, "mask.png");
    } catch (const og::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(png->substr(0, png->size() / 2)).find("mask.png: "), std::string::npos);
  EXPECT_NE(message("not a png at all").find("mask.png: not a PNG"), std::string::npos);
  const auto jpg = og::embedded::data::find("blue_marble_2048x1024.jpg");
  ASSERT_TRUE(jpg);
  EXPECT_NE(message(*jpg).find("mask.png: not a PNG"), std::string::npos);
  EXPECT_THROW((void)og::data::parseWorldFile("0.1 0 0 -0.1 5", "w.pgw"), og::InputError);
  EXPECT_THROW((void)og::data::parseWorldFile("0.1 0.2 0 -0.1 5 6", "w.pgw"), og::InputError);
  const auto grid = og::data::parseWorldFile("0.5 0 0 -0.5 -179.75 89.75", "w.pgw");
  EXPECT_DOUBLE_EQ(grid.westDeg, -180.0);
  EXPECT_DOUBLE_EQ(grid.northDeg, 90.0);
}

TEST(LandMask, WaterAroundHasNoLandFractionWithinItsRadius) {
  // Where waterAround holds, the fraction is 0 at every point within the radius, at either
  // level and any footprint (terrain.frag's coast test there discards, so terrain.vert may clip
  // the floor); the largest radius that holds reaches land just beyond it. Around the Strait of
  // Gibraltar (coasts 2-15 km apart, fine cells), off Tarifa's beach, the open Atlantic.
  const LandMask& mask = og::data::defaultLandMask();
  struct Place {
    double lat, lon;
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tested = 0;
  for (const Place p : {Place{36.0, -5.5}, Place{35.995, -5.595}, Place{35.95, -5.45}, Place{20.0, -40.0}}) {
    for (const bool fine : {true, false}) {
      double r = 0.0;
      for (double step = 32768.0; step >= 16.0; step *= 0.5)
        if (mask.waterAround(p.lat, p.lon, r + step, fine)) r += step;
      if (r == 0.0) continue;
      ++tested;
      for (int k = 0; k < 4000; ++k) {
        // A point within r (m) on the ellipsoid's tightest curvature (the test's own margin).
        const double s = r * std::sqrt(unit(rng)) / 6.4e6, az = 2.0 * std::numbers::pi * unit(rng);
        const double lat = p.lat + s * std::cos(az) * 180.0 / std::numbers::pi;
        const double lon = p.lon + s * std::sin(az) * 180.0 / std::numbers::pi / std::cos(lat * std::numbers::pi / 180.0);
        ASSERT_EQ(fine ? mask.fineFraction(lat, lon) : mask.landFraction(lat, lon), 0.0f)
            << p.lat << ", " << p.lon << (fine ? " fine" : " coarse") << " within " << r << " m";
      }
      // Short of the search's end, land lies within twice the radius and the cells' reach.
      const double cellM = mask.cellDeg() / (fine ? LandMask::kFinePerCell : 1) * 111000.0;
      if (r < 60000.0) {
        EXPECT_FALSE(mask.waterAround(p.lat, p.lon, 2.0 * r + 4.0 * cellM + 32.0, fine)) << p.lat << ", " << p.lon;
      }
      std::printf("%.3f, %.3f %s: water within %.0f m\n", p.lat, p.lon, fine ? "fine" : "coarse", r);
    }
  }
  EXPECT_GE(tested, 5);
  EXPECT_TRUE(mask.waterAround(20.0, -40.0, 30000.0, true));  // the open Atlantic
  EXPECT_FALSE(mask.waterAround(36.0, -5.5, 5000.0, true));    // Spain 3 km north
  EXPECT_FALSE(mask.waterAround(89.5, 0.0, 10.0, false));      // no certificate at the pole
}

// The pyramid's answer for a rectangle holds what a scan of its cells finds (a refined cell is
// both), at every size, across the antimeridian and at the poles' clamped rows.
TEST(LandMaskPyramid, RectanglesHoldWhatTheirCellsHold) {
  const og::data::LandMask& mask = og::data::defaultLandMask();
  const og::data::LandMaskPyramid pyramid(mask);
  using Content = og::data::LandMaskPyramid::Content;
  auto scan = [&](int c0, int c1, int r0, int r1) {
    int bits = 0;
    for (int r = std::clamp(r0, 0, mask.height() - 1); r <= std::clamp(r1, 0, mask.height() - 1); ++r)
      for (int c = c0; c <= c1; ++c) {
        const int column = ((c % mask.width()) + mask.width()) % mask.width();
        bits |= mask.refined(column, r) ? 3 : (mask.cell(column, r) ? 2 : 1);
      }
    return static_cast<Content>(bits);
  };
  std::mt19937 rng(7);
  int counts[4] = {0, 0, 0, 0};
  int agree = 0;
  for (int i = 0; i < 3000; ++i) {
    const int span = 1 << std::uniform_int_distribution<int>(0, 9)(rng);
    const int w = std::uniform_int_distribution<int>(1, span)(rng), h = std::uniform_int_distribution<int>(1, span)(rng);
    // Around the coasts of Europe and West Africa, the antimeridian and the poles.
    const int area = i % 3;
    const int c0 = area == 1 ? std::uniform_int_distribution<int>(mask.width() - 40, mask.width() + 10)(rng)
                             : std::uniform_int_distribution<int>(4800, 6000)(rng);
    const int r0 = area == 2 ? std::uniform_int_distribution<int>(-5, 30)(rng) + (i % 2 ? mask.height() - 30 : 0)
                             : std::uniform_int_distribution<int>(3000, 4000)(rng);
    const Content expected = scan(c0, c0 + w - 1, r0, r0 + h - 1);
    const Content got = pyramid.cells(c0, c0 + w - 1, r0, r0 + h - 1);
    // Never less than the cells hold (the coarse levels see up to their own cell's size around
    // the rectangle); exact up to 32 x 32 cells.
    ASSERT_EQ(static_cast<int>(got) & static_cast<int>(expected), static_cast<int>(expected))
        << "columns " << c0 << "+" << w << ", rows " << r0 << "+" << h;
    if (std::max(w, h) <= 32) {
      ASSERT_EQ(got, expected) << "columns " << c0 << "+" << w << ", rows " << r0 << "+" << h;
    }
    ++counts[static_cast<int>(expected)];
    agree += got == expected ? 1 : 0;
  }
  // All three answers were asked for, and most answered exactly.
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 100);
  EXPECT_GT(counts[3], 100);
  EXPECT_GT(agree, 2400);
}

// The fine level's rectangles: exactly what their fine cells hold (a refined cell's block, any
// other cell's class), across the antimeridian too.
TEST(LandMaskPyramid, FineRectanglesHoldExactlyTheirFineCells) {
  const og::data::LandMask& mask = og::data::defaultLandMask();
  ASSERT_TRUE(mask.hasFineLevel());
  const og::data::LandMaskPyramid pyramid(mask);
  constexpr int n = og::data::LandMask::kFinePerCell;
  const int fineColumns = mask.width() * n;
  auto fineLand = [&](int fx, int fy) {
    const int wrapped = ((fx % fineColumns) + fineColumns) % fineColumns;
    const int cx = wrapped / n, cy = fy / n;
    return ((mask.block(cx, cy) >> (8 * (fy % n) + wrapped % n)) & 1u) != 0;
  };
  std::mt19937 rng(11);
  int counts[4] = {0, 0, 0, 0};
  for (int i = 0; i < 4000; ++i) {
    const int w = std::uniform_int_distribution<int>(1, 24)(rng), h = std::uniform_int_distribution<int>(1, 24)(rng);
    const int fc0 = i % 4 == 0 ? std::uniform_int_distribution<int>(fineColumns - 30, fineColumns + 10)(rng)
                               : std::uniform_int_distribution<int>(5300 * n, 5500 * n)(rng);  // the Alboran Sea's coasts
    const int fr0 = std::uniform_int_distribution<int>(3750 * n, 3800 * n)(rng);
    int bits = 0;
    for (int fy = fr0; fy < fr0 + h; ++fy)
      for (int fx = fc0; fx < fc0 + w; ++fx) bits |= fineLand(fx, fy) ? 2 : 1;
    ASSERT_EQ(static_cast<int>(pyramid.fineCells(fc0, fc0 + w - 1, fr0, fr0 + h - 1)), bits)
        << "fine columns " << fc0 << "+" << w << ", rows " << fr0 << "+" << h;
    ++counts[bits];
  }
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 100);
  EXPECT_GT(counts[3], 100);
}
