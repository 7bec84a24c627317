// ETOPO5's -10 m shallow-bank placeholder (data/ShallowBanks): the detector finds the Great
// Bahama Bank's plateau in ETOPO5 and in the embedded ETOPO20 and leaves varied relief alone;
// the corrected depths lie in the charted range and the land mask keeps them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "data/LandMask.hpp"
#include "data/ShallowBanks.hpp"
#include "terrain/Heightfield.hpp"

using og::data::LatLonGrid;

namespace {
const char* kEtopo5 = "/usr/share/ferret-vis/data/etopo5.cdf";

LatLonGrid field(int width, int height, double cellDeg, double (*f)(int, int)) {
  LatLonGrid g;
  g.name = "synthetic";
  g.width = width;
  g.height = height;
  g.lat0Deg = 20.0;
  g.lon0Deg = -80.0;
  g.dLatDeg = g.dLonDeg = cellDeg;
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) g.values.push_back(static_cast<float>(f(c, r)));
  return g;
}

// Whether a plateau of `plateaus` covers (lat, lon) within one cell.
bool covers(const std::vector<og::data::Plateau>& plateaus, const LatLonGrid& g, double lat, double lon) {
  for (const auto& p : plateaus)
    for (std::size_t i : p.cells) {
      const double la = g.lat0Deg + static_cast<double>(i / static_cast<std::size_t>(g.width)) * g.dLatDeg;
      const double lo = g.lon0Deg + static_cast<double>(i % static_cast<std::size_t>(g.width)) * g.dLonDeg;
      if (std::abs(la - lat) <= g.dLatDeg && std::abs(std::remainder(lo - lon, 360.0)) <= g.dLonDeg) return true;
    }
  return false;
}
}  // namespace

// Varied relief, whole metres, with -10 m cells scattered through it, a slope whose -10 m
// contour is a line of cells, and a gentle slope's terrace: none is a placeholder plateau.
TEST(ShallowBanks, LeavesVariedReliefAlone) {
  const LatLonGrid varied = field(120, 120, 1.0 / 12.0, [](int c, int r) {
    return std::round(-30.0 + 18.0 * std::sin(0.7 * c) * std::cos(0.45 * r) + 6.0 * std::sin(1.3 * c + 2.1 * r));
  });
  int tens = 0;
  for (float v : varied.values) tens += v == -10.0f ? 1 : 0;
  ASSERT_GT(tens, 50);  // the field does hold -10 m cells
  EXPECT_TRUE(og::data::findPlaceholderPlateaus(varied).empty());
  const LatLonGrid slope = field(120, 120, 1.0 / 12.0, [](int, int r) { return 5.0 - 1.0 * r; });
  EXPECT_TRUE(og::data::findPlaceholderPlateaus(slope).empty());
  const LatLonGrid terraces = field(120, 120, 1.0 / 12.0, [](int, int r) { return std::round(5.0 - 0.2 * r); });
  EXPECT_TRUE(og::data::findPlaceholderPlateaus(terraces).empty());
  LatLonGrid corrected = slope;
  EXPECT_EQ(og::data::correctShallowBanks(corrected, nullptr).cells, 0u);
  EXPECT_EQ(corrected.values, slope.values);
}

// A flat -10 m plateau between an island and deep water is found; near the island it is made
// shallow, rising 0.1 m per km from 1 m at the shore, and far from land it keeps 10 m.
TEST(ShallowBanks, ReplacesAPlateauByDepthRisingFromTheShore) {
  LatLonGrid g = field(200, 60, 1.0 / 12.0, [](int c, int r) {
    if (c < 5) return 20.0;                // an island's coast along the west edge
    if (r > 50) return -800.0;             // deep water to the north
    return c < 170 ? -10.0 : -300.0;       // the bank, then its edge
  });
  const auto plateaus = og::data::findPlaceholderPlateaus(g);
  ASSERT_EQ(plateaus.size(), 1u);
  EXPECT_GT(plateaus[0].areaKm2, 100000.0);
  const auto c = og::data::correctShallowBanks(g, nullptr);
  EXPECT_EQ(c.plateaus, 1);
  EXPECT_GT(c.cells, 400u);
  // Along row 25 (22.08°N) a cell is 8.6 km; column 4 is the island's last.
  const double cellKm = 111.32 / 12.0 * std::cos(22.0833 * 3.14159265358979 / 180.0);
  EXPECT_NEAR(-g.at(5, 25), 1.0 + 0.1 * cellKm, 0.01);
  EXPECT_NEAR(-g.at(10, 25), 1.0 + 0.1 * 6.0 * cellKm, 0.01);
  EXPECT_FLOAT_EQ(g.at(30, 25), -10.0f);  // 220 km from land: the placeholder's 10 m
  EXPECT_FLOAT_EQ(g.at(180, 25), -300.0f);
  EXPECT_FLOAT_EQ(g.at(2, 25), 20.0f);
  EXPECT_FLOAT_EQ(g.keepDepth[5 + 25 * 200], 1.0f);
  EXPECT_FLOAT_EQ(g.keepDepth[30 + 25 * 200], 0.0f);
}

// ETOPO5 (5'): the Great Bahama Bank is a placeholder plateau; corrected with the GSHHG mask its
// cells west of Andros lie in the charted 2-7 m, none shallower than the 1 m shore depth.
TEST(ShallowBanks, FindsTheBahamaPlateauInEtopo5) {
  if (!std::filesystem::exists(kEtopo5)) GTEST_SKIP() << kEtopo5 << " not installed (package ferret-datasets)";
  LatLonGrid g = og::data::readElevationFile(kEtopo5);
  const auto plateaus = og::data::findPlaceholderPlateaus(g);
  EXPECT_TRUE(covers(plateaus, g, 24.25, -78.6));   // the bank west of Andros
  EXPECT_FALSE(covers(plateaus, g, 24.0, -77.25));  // the Tongue of the Ocean
  const auto c = og::data::correctShallowBanks(g, &og::data::defaultLandMask());
  std::printf("ETOPO5: %d plateaus, %zu cells set to %.1f-%.1f m; west of Andros %.1f m\n", c.plateaus, c.cells,
              double{c.minDepthM}, double{c.maxDepthM}, double{g.sample(24.25, -78.6)});
  EXPECT_GE(c.minDepthM, 1.0f);
  EXPECT_LT(c.maxDepthM, 10.0f);
  const float bank = -g.sample(24.25, -78.6);
  EXPECT_GE(bank, 2.0f);
  EXPECT_LE(bank, 7.0f);
  EXPECT_GT(g.sampleKeepDepth(24.25, -78.6), 0.99f);
  EXPECT_LT(g.sample(24.0, -77.25), -500.0f);
}

// The embedded default (ETOPO5 at its own 5', data/README.md) comes corrected: the bank west of Andros
// is a few metres deep, also after the land mask constrains the terrain's heights (which would
// otherwise push all open water down to 10 m).
TEST(ShallowBanks, DefaultLayerHasTheBahamaBankAtChartedDepth) {
  const LatLonGrid raw = og::data::uncorrectedDefaultElevation();
  const LatLonGrid& g = og::data::defaultElevation();
  // West of Andros at 24.17°N 78.5°W, a point of the 5' grid on the bank's placeholder
  // (the former 20' default had a cell centred there too).
  const double lat = 24.0 + 1.0 / 6.0, lon = -78.5;
  EXPECT_TRUE(covers(og::data::findPlaceholderPlateaus(raw), raw, lat, lon));
  EXPECT_FLOAT_EQ(raw.sample(lat, lon), -10.0f);
  const double bank = -g.sample(lat, lon);
  EXPECT_GE(bank, 2.0);
  EXPECT_LE(bank, 7.0);
  EXPECT_FLOAT_EQ(g.sampleKeepDepth(lat, lon), 1.0f);
  // The terrain's heights (the land mask constrains them): the bank keeps its depth, where
  // the raw layer's open water is pushed down to 10 m.
  const og::terrain::Heightfield ground{g}, rawGround{raw};
  EXPECT_NEAR(ground.layerHeightM(lat, lon), -bank, 1e-3);
  EXPECT_LE(rawGround.layerHeightM(lat, lon), -9.99);
  EXPECT_EQ(og::data::loadElevationLayer("", og::data::ElevationCorrection::None).values, raw.values);
  EXPECT_THROW(og::data::parseElevationCorrection("banks"), og::InputError);
}

namespace {
// Cells of `g` with the coastal checkerboard's signature that scripts/derive_default_data.sh
// cleans (data/README.md): under the sea and shallower than 50 m, both row neighbours (across
// the seam) or both column neighbours at least 100 m deeper and within 10 m of each other.
std::vector<std::size_t> checkerboardCells(const LatLonGrid& g) {
  std::vector<std::size_t> cells;
  const auto w = static_cast<std::size_t>(g.width), h = static_cast<std::size_t>(g.height);
  const auto at = [&](std::size_t r, std::size_t c) { return std::floor(g.values[r * w + c % w] + 0.5f); };
  const auto pair = [](float v, float a, float b) { return a <= v - 100.0f && b <= v - 100.0f && std::abs(a - b) <= 10.0f; };
  for (std::size_t r = 1; r + 1 < h; ++r)
    for (std::size_t c = 0; c < w; ++c) {
      const float v = at(r, c);
      if (v < 0.0f && v > -50.0f &&
          (pair(v, at(r, c + 1), at(r, c + w - 1)) || pair(v, at(r + 1, c), at(r - 1, c))))
        cells.push_back(r * w + c);
    }
  return cells;
}
}  // namespace

// ETOPO5's coastal checkerboard (rows alternating a shallow placeholder and the shelf's depth,
// -8, -198, -8, -197 m off Tetouan) is cleaned in the embedded layer: the former lone shallow
// cells off Tetouan (a turquoise cross from 300 km) are as deep as their neighbours, the grid
// keeps a fifth of the source's signature cells (those the 100 m rounding made), and the real
// shallows stay: the Bahama Bank's placeholder plateau and the beach cells at Tetouan.
TEST(ShallowBanks, DefaultLayerHasNoCoastalCheckerboard) {
  const LatLonGrid raw = og::data::uncorrectedDefaultElevation();
  // The source has 344 (below); the layer 66, whose sides were unequal in the source (real
  // relief, kept) and became equal when the floor below -200 m was rounded to 100 m.
  const std::size_t left = checkerboardCells(raw).size();
  std::printf("checkerboard signature cells left in the default layer: %zu\n", left);
  EXPECT_LE(left, 70u);
  // Former checkerboard cells off Tetouan (ETOPO5: -23, -14, -8 m between ~-200 m cells in
  // their row, -11 m between -202 and -199 m in its column).
  EXPECT_LT(raw.sample(35.0 + 10.0 / 12.0, -5.0 - 4.0 / 12.0), -100.0f);
  EXPECT_LT(raw.sample(35.0 + 7.0 / 12.0, -5.0 - 2.0 / 12.0), -100.0f);
  EXPECT_LT(raw.sample(35.0 + 8.0 / 12.0, -5.25), -100.0f);
  EXPECT_LT(raw.sample(35.0 + 5.0 / 12.0, -5.0), -100.0f);
  // Real shallows kept: the beach cell at Martil (-3 m) and the bank west of Andros (-10 m).
  EXPECT_NEAR(raw.sample(35.0 + 7.0 / 12.0, -5.25), -3.0f, 0.5f);
  EXPECT_FLOAT_EQ(raw.sample(24.0 + 1.0 / 6.0, -78.5), -10.0f);
}

// The source has the checkerboard (so the test above fails without the cleaning): 344
// cells worldwide, among them the ones off Tetouan.
TEST(ShallowBanks, Etopo5SourceHasTheCoastalCheckerboard) {
  if (!std::filesystem::exists(kEtopo5)) GTEST_SKIP() << kEtopo5 << " not installed (package ferret-datasets)";
  const LatLonGrid g = og::data::readElevationFile(kEtopo5);
  const std::vector<std::size_t> cells = checkerboardCells(g);
  EXPECT_EQ(cells.size(), 344u);
  EXPECT_GT(g.sample(35.0 + 10.0 / 12.0, -5.0 - 4.0 / 12.0), -30.0f);  // -23 m
}
