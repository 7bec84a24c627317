// Imagery layers as streamed tiles (data/ImageryTiles): a layer finer than its whole texture
// streams the levels between that texture's resolution and its own; a tile read from the file
// holds the source's pixels where they are (the fine checker) and alpha 0 outside the layer;
// its mip chain averages in linear light; its border holds its neighbours' edge texels (across
// the antimeridian too); the CPU cache never holds more than its budget
// (tiny budgets evict); a file truncated after it was opened fails the read with its name,
// handed from the background worker to the render thread.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "core/Error.hpp"
#include "data/Imagery.hpp"
#include "data/ImageryTiles.hpp"
#include "support/CheckerGeoTiff.hpp"
#include "support/DataFixtures.hpp"
#include "support/ExpectError.hpp"
#include "support/GeoTiffWriter.hpp"

namespace fs = std::filesystem;
using og::data::ImageryTileKey;

namespace {

fs::path checker() {
  static const fs::path file = og::test::writeCheckerGeoTiff(og::test::fixtureDir("data_imagerytiles") / "checker.tif");
  return file;
}

/// The tile of `level` at (lat, lon) degrees, layer 0.
ImageryTileKey tileAt(int level, double latDeg, double lonDeg) {
  const double size = 180.0 / (1 << level);
  return {0, level, static_cast<int>(std::floor((lonDeg + 180.0) / size)),
          static_cast<int>(std::floor((latDeg + 90.0) / size))};
}

}  // namespace

TEST(ImageryTiles, LevelsSpanTheWholeTextureToTheSourceResolution) {
  const og::data::ImageryTileSource s(checker().string(), 0, og::data::kImageryLayerSizePx);
  // Whole texture: 5.625°/2048 = 0.00275° texels; source 0.00137°. Tile texels 180°/2^L/256:
  // level 8 0.00275° (no finer than the texture), level 9 0.00137° (the source's).
  EXPECT_EQ(s.minLevel(), 9);
  EXPECT_EQ(s.maxLevel(), 9);
  EXPECT_TRUE(s.overlaps(tileAt(9, 12.0, 24.0)));
  EXPECT_FALSE(s.overlaps(tileAt(9, 12.0, 30.0)));
  EXPECT_FALSE(s.overlaps(tileAt(9, -12.0, 24.0)));
  // A layer no finer than its texture streams nothing.
  const og::data::ImageryTileSource coarse(checker().string(), 0, 8192);
  EXPECT_GT(coarse.minLevel(), coarse.maxLevel());
}

namespace {

/// Mean absolute difference of red between horizontal neighbours of an n × n RGBA image.
double meanJump(const std::uint8_t* rgba, int n) {
  double jump = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(n) + static_cast<std::size_t>(x)) * 4;
      jump += std::abs(static_cast<double>(rgba[i]) - static_cast<double>(rgba[i + 4]));
    }
  return jump / (n * (n - 1));
}

double srgbToLinear(double byte) {
  const double c = byte / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

TEST(ImageryTiles, TileHoldsTheFineCheckerAndMipsAverageIt) {
  const og::data::ImageryTileSource s(checker().string(), 0, og::data::kImageryLayerSizePx);
  const og::data::ImageryTile t = s.read(tileAt(9, 12.0, 24.0));
  ASSERT_EQ(t.rgba.size(), og::data::imageryTileBytes());
  const int n = og::data::kImageryTilePx, stored = og::data::kImageryTileStoredPx;
  // Level 0: texels are the source's pixels: neighbours differ by the checker's contrast
  // (205), where the whole-layer texture (two source columns a texel) is flat grey.
  EXPECT_GT(meanJump(t.rgba.data(), stored), 200.0) << "the checker is not resolved";
  const og::data::GeoImage whole = og::data::loadImageryLayer(checker());
  EXPECT_LT(meanJump(whole.rgba.data(), 256), 6.0);  // its south-west 256² corner
  EXPECT_EQ(t.rgba[3], 255);
  // Level 1's first interior texel (texel (2, 2) of its 132², past the 2-texel border): the
  // linear-light mean of level 0's interior 2 × 2 block at (0, 0).
  const auto lvl0 = [&](int x, int y) { return srgbToLinear(t.texel(x, y, 0)); };
  const double mean = 0.25 * (lvl0(0, 0) + lvl0(1, 0) + lvl0(0, 1) + lvl0(1, 1));
  const std::size_t lvl1 = og::data::imageryTileMipOffset(1) + (2 * static_cast<std::size_t>(og::data::imageryTileMipPx(1)) + 2) * 4;
  EXPECT_NEAR(srgbToLinear(t.rgba[lvl1]), mean, 0.004);
  // Placement: the layer's south-west tile has the layer's south-west cell (dark, i + j = 0)
  // at interior texel (0, 0), rows from the south; its border west and south of it is outside
  // the layer (alpha 0).
  const og::data::ImageryTile sw = s.read({0, 9, 568, 286});
  const auto red = [&](int x, int y) { return sw.texel(x, y, 0); };
  EXPECT_EQ(red(0, 0), og::test::kCheckerDark[0]);
  EXPECT_EQ(red(1, 0), og::test::kCheckerLight[0]);
  EXPECT_EQ(red(0, 1), og::test::kCheckerLight[0]);
  EXPECT_EQ(red(255, 255), og::test::kCheckerDark[0]);
  EXPECT_EQ(red(256, 255), og::test::kCheckerLight[0]) << "the east border: the next tile's first column";
  EXPECT_EQ(sw.texel(-1, 10, 3), 0);
  EXPECT_EQ(sw.texel(10, -1, 3), 0);
  EXPECT_EQ(sw.texel(0, 0, 3), 255);
  // A tile over the layer's west edge (level 5: 16.875..22.5°E, 11.25..16.875°N) is
  // transparent west of it; its row n/8 (11.95°N) is inside the layer at its east end.
  const og::data::ImageryTile edge = s.read(tileAt(5, 12.0, 20.0));
  EXPECT_EQ(edge.texel(0, n / 8, 3), 0);
  EXPECT_EQ(edge.texel(n - 1, n / 8, 3), 255);
}

TEST(ImageryTiles, BordersHoldTheNeighboursEdgeTexels) {
  // Two level-9 tiles side by side and one above, inside the checker: each tile's border is its
  // neighbour's edge, texel for texel (the same grid, read past the tile), at level 0 and at
  // mip level 2 (one border texel: the mean of the same 4 × 4 source texels on both sides).
  const og::data::ImageryTileSource s(checker().string(), 0, og::data::kImageryLayerSizePx);
  const ImageryTileKey a = tileAt(9, 12.0, 22.0);
  const og::data::ImageryTile west = s.read(a), east = s.read({0, 9, a.x + 1, a.y}), north = s.read({0, 9, a.x, a.y + 1});
  constexpr int n = og::data::kImageryTilePx, b = og::data::kImageryTileBorderPx;
  static_assert(b >= 4, "a border of at least a whole texel of mip level 2");
  int differ = 0;
  for (int y = -b; y < n + b; ++y)
    for (int k = 0; k < b; ++k)
      for (int c = 0; c < 4; ++c) {
        differ += west.texel(n + k, y, c) != east.texel(k, y, c);            // west's east border
        differ += east.texel(-1 - k, y, c) != west.texel(n - 1 - k, y, c);   // east's west border
        differ += west.texel(y, n + k, c) != north.texel(y, k, c);           // its north border
      }
  EXPECT_EQ(differ, 0);
  const int s2 = og::data::imageryTileMipPx(2);  // 66: 64 inside, 1 each side
  const auto lvl2 = [&](const og::data::ImageryTile& t, int x, int y) {
    return t.rgba[og::data::imageryTileMipOffset(2) + (static_cast<std::size_t>(y) * static_cast<std::size_t>(s2) + static_cast<std::size_t>(x)) * 4];
  };
  for (int y = 0; y < s2; ++y) {
    EXPECT_EQ(lvl2(west, s2 - 1, y), lvl2(east, 1, y)) << y;
    EXPECT_EQ(lvl2(east, 0, y), lvl2(west, s2 - 2, y)) << y;
  }
}

TEST(ImageryTiles, BordersWrapRoundTheGlobeAndRepeatAtThePoles) {
  // A global layer (2560 × 1280, finer than its whole texture: streams level 3) whose red rises
  // eastwards from -180° to 180°: the westernmost tile's west border comes from the east end
  // (red near 255, opaque), not from past the footprint (alpha 0); the southernmost row's border
  // south of the pole repeats its edge row.
  const fs::path file = og::test::writeGeoRaster(og::test::fixtureDir("data_imagerytiles") / "global_ramp.tif", 4326, 2560,
                                                 1280, og::test::GeoBox{-180.0, 180.0, -90.0, 90.0}, [](double lat, double lon) {
                                                   return og::test::Rgb8{static_cast<std::uint8_t>(std::lround((lon + 180.0) / 360.0 * 255.0)),
                                                                         static_cast<std::uint8_t>(std::lround((lat + 90.0) / 180.0 * 255.0)), 0};
                                                 });
  const og::data::ImageryTileSource s(file.string(), 0, og::data::kImageryLayerSizePx);
  ASSERT_EQ(s.minLevel(), 3);
  const og::data::ImageryTile westmost = s.read({0, 3, 0, 0}), eastmost = s.read({0, 3, 15, 0});
  constexpr int n = og::data::kImageryTilePx, b = og::data::kImageryTileBorderPx;
  for (int k = 1; k <= b; ++k)
    for (const int y : {-b, 0, n / 2, n + b - 1}) {
      EXPECT_EQ(westmost.texel(-k, y, 3), 255) << k << ' ' << y;
      EXPECT_NEAR(westmost.texel(-k, y, 0), eastmost.texel(n - k, y, 0), 1) << k << ' ' << y;
      EXPECT_GT(westmost.texel(-k, y, 0), 240) << k << ' ' << y;
      EXPECT_NEAR(eastmost.texel(n - 1 + k, y, 0), westmost.texel(k - 1, y, 0), 1) << k << ' ' << y;
      EXPECT_EQ(westmost.texel(y, -k, 1), westmost.texel(y, 0, 1)) << k << ' ' << y;
    }
}

TEST(ImageryTiles, CpuCacheStaysWithinItsBudget) {
  auto source = std::make_shared<const og::data::ImageryTileSource>(checker().string(), 0, og::data::kImageryLayerSizePx);
  const std::size_t budget = 3 * (og::data::imageryTileBytes() + sizeof(og::data::ImageryTile));
  og::data::ImageryTileCache cache({source}, budget, 2);
  std::vector<ImageryTileKey> keys;
  for (int i = 0; i < 8; ++i) keys.push_back(tileAt(9, 10.7 + 0.36 * (i % 4), 20.2 + 0.36 * (i / 4)));
  cache.request(keys);
  for (int frame = 0; frame < 200 && cache.readCount() < keys.size(); ++frame) {
    cache.collect();
    EXPECT_LE(cache.bytes(), budget);
    if (cache.readCount() < keys.size()) cache.waitIdle();
  }
  cache.collect();
  EXPECT_EQ(cache.readCount(), keys.size());
  EXPECT_LE(cache.bytes(), budget);
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_EQ(cache.evictions(), keys.size() - 3);
  // The most recently read are kept; a blocking build brings an evicted one back.
  const std::vector<ImageryTileKey> again = cache.build(std::span(keys.data(), 1));
  ASSERT_EQ(again.size(), 1u);
  EXPECT_NE(cache.find(keys[0]), nullptr);
  EXPECT_LE(cache.bytes(), budget);
}

TEST(ImageryTiles, FileTruncatedMidStreamFailsWithItsName) {
  const fs::path file = og::test::fixtureDir("data_imagerytiles") / "truncated.tif";
  fs::copy_file(checker(), file, fs::copy_options::overwrite_existing);
  auto source = std::make_shared<const og::data::ImageryTileSource>(file.string(), 0, og::data::kImageryLayerSizePx);
  og::data::ImageryTileCache cache({source}, std::size_t{64} << 20, 1);
  fs::resize_file(file, fs::file_size(file) / 4);  // rows north first: the southern ones are gone
  const ImageryTileKey south = tileAt(9, 10.7, 22.5);
  og::test::expectInputError(file.string(), "", [&] { (void)source->read(south); });
  // From the background worker: the render thread's collect() rethrows it.
  cache.request(std::span(&south, 1));
  cache.waitIdle();
  og::test::expectInputError(file.string(), "", [&] { (void)cache.collect(); });
}

TEST(ImageryTiles, WebMercatorTilesLandWhereTheyBelong) {
  // 4096 × 256 pixels over 20..22°E, 10..10.125°N in EPSG:3857 (finer than its whole texture):
  // red south of 10.06°N, blue north of it; reprojected per tile.
  const og::test::GeoBox box{20.0, 22.0, 10.0, 10.125};
  const fs::path file = og::test::writeGeoRaster(og::test::fixtureDir("data_imagerytiles") / "split3857.tif", 3857, 4096,
                                                 256, box, [](double lat, double) {
                                                   return lat < 10.06 ? og::test::Rgb8{255, 0, 0} : og::test::Rgb8{0, 0, 255};
                                                 });
  const og::data::ImageryTileSource s(file.string(), 0, og::data::kImageryLayerSizePx);
  ASSERT_LE(s.minLevel(), 11);
  ASSERT_GE(s.maxLevel(), 11);
  const ImageryTileKey key = tileAt(11, 10.06, 21.0);
  const og::data::ImageryTile t = s.read(key);
  const double texelDeg = key.texelDeg();
  const auto texelAt = [&](double latDeg, int c) {
    const int row = static_cast<int>(std::floor((latDeg - key.southDeg()) / texelDeg));
    const int col = static_cast<int>(std::floor((21.0 - key.westDeg()) / texelDeg));
    return t.texel(col, row, c);
  };
  // Two texels (0.0007°) either side of the split.
  EXPECT_GT(texelAt(10.06 - 2 * texelDeg, 0), 200);
  EXPECT_LT(texelAt(10.06 - 2 * texelDeg, 2), 50);
  EXPECT_LT(texelAt(10.06 + 2 * texelDeg, 0), 50);
  EXPECT_GT(texelAt(10.06 + 2 * texelDeg, 2), 200);
}
