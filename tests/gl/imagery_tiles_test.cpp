// GL tier (issue 14): imagery layers stream as tiles (render/ImageryTiles). A large synthetic
// GeoTIFF (4096 × 2048, a checker of one-pixel cells, support/CheckerGeoTiff.hpp) shows its
// fine detail close up (the finest tile level, high pixel contrast) and only its whole texture
// far away (grey); tiles arrive in the background, the whole texture standing in for the first
// frame; the GPU cache never holds more than its budget; a file truncated mid-stream ends the
// frame with an og::InputError naming it; a grey ramp magnified across a tile edge shows no
// step there (the tiles' borders); in the background each tile's ancestors are asked for with
// it, and a view prefetched ahead is drawn complete without waiting. Images go to
// OG_TEST_OUT_DIR/imagery_tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "data/Imagery.hpp"
#include "geo/Camera.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"
#include "render/ImageryTiles.hpp"
#include "support/GeoTiffWriter.hpp"
#include "terrain/Tile.hpp"
#include "support/CheckerGeoTiff.hpp"

using namespace og;
namespace fs = std::filesystem;

namespace {

/// This test group's files and images, under the build's test output.
const fs::path& outDir() {
  static const fs::path dir = [] {
    fs::path d = fs::path(OG_TEST_OUT_DIR) / "imagery_tiles";
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

constexpr int kSize = 128;

fs::path checker() {
  static const fs::path file = test::writeCheckerGeoTiff(outDir() / "checker.tif");
  return file;
}

/// Straight down over the checker's centre from `heightM`.
render::FrameInput downFrom(double heightM) {
  render::FrameInput f;
  f.camera.position = {test::kCheckerLatDeg, test::kCheckerLonDeg, heightM};
  f.camera.pitchDeg = -90.0;
  f.camera.verticalFovDeg = 40.0;
  f.width = f.height = kSize;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 60.0, 150.0);
  return f;
}

/// Standard deviation of the display image's green in the central half, sRGB units.
double contrast(const io::ImageRgba8& img) {
  double s = 0.0, s2 = 0.0;
  int n = 0;
  for (int y = kSize / 4; y < 3 * kSize / 4; ++y)
    for (int x = kSize / 4; x < 3 * kSize / 4; ++x) {
      const double v = img.pixels[(static_cast<std::size_t>(y) * kSize + static_cast<std::size_t>(x)) * 4 + 1];
      s += v;
      s2 += v * v;
      ++n;
    }
  const double mean = s / n;
  return std::sqrt(std::max(0.0, s2 / n - mean * mean));
}

std::vector<data::GeoImage> checkerLayer(const fs::path& file) { return {data::loadImageryLayer(file)}; }

}  // namespace

TEST(ImageryTiles, FineDetailCloseUpCoarseFarAway) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.imagery().setLayers(checkerLayer(checker()));
  ASSERT_NE(r.imagery().tiles(), nullptr);
  r.render(downFrom(5000.0));
  const io::ImageRgba8 close = r.display();
  io::writePng(outDir() / "checker_5km.png", close);
  EXPECT_EQ(r.imagery().tileStats().finestLevel, 9) << "close up: the source's own resolution";
  r.render(downFrom(150000.0));
  const io::ImageRgba8 far = r.display();
  io::writePng(outDir() / "checker_150km.png", far);
  EXPECT_LT(r.imagery().tileStats().finestLevel, 9) << "far away: a coarser level (or the whole texture)";
  EXPECT_GT(contrast(close), 12.0);
  EXPECT_LT(contrast(far), 6.0);
  const render::ImageryTileStats s = r.imagery().tileStats();
  EXPECT_LE(s.cpuBytes, render::ImageryTextures::kDefaultCacheBytes);
  EXPECT_LE(s.gpuBytes, render::ImageryTextures::kDefaultCacheBytes);
}

TEST(ImageryTiles, TilesArriveInTheBackgroundWhileTheWholeTextureStandsIn) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.imagery().setTilesInBackground(true);
  r.imagery().setLayers(checkerLayer(checker()));
  r.render(downFrom(5000.0));
  const io::ImageRgba8 first = r.display();
  io::writePng(outDir() / "background_first.png", first);
  EXPECT_EQ(r.imagery().tileStats().finestLevel, -1) << "nothing resident yet: the whole texture";
  EXPECT_LT(contrast(first), 6.0);
  r.imagery().tiles()->waitIdle();
  r.render(downFrom(5000.0));
  const io::ImageRgba8 later = r.display();
  io::writePng(outDir() / "background_later.png", later);
  EXPECT_EQ(r.imagery().tileStats().finestLevel, 9);
  EXPECT_GT(contrast(later), 12.0);
}

TEST(ImageryTiles, GpuCacheStaysWithinATinyBudget) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::size_t gpuBudget = std::size_t{1} << 20;  // two tiles with their borders and mip-maps
  r.imagery().setCacheBudgets(std::size_t{2} << 20, gpuBudget);
  r.imagery().setLayers(checkerLayer(checker()));
  for (const double lonDeg : {21.0, 21.4, 21.8, 22.2}) {  // a different level-9 tile each time
    render::FrameInput f = downFrom(5000.0);
    f.camera.position.longitudeDeg = lonDeg;
    r.render(f);
    const render::ImageryTileStats s = r.imagery().tileStats();
    EXPECT_LE(s.gpuBytes, gpuBudget) << lonDeg;
    EXPECT_LE(s.cpuBytes, std::size_t{2} << 20) << lonDeg;
    EXPECT_EQ(s.finestLevel, 9) << lonDeg;
  }
  EXPECT_GT(r.imagery().tileStats().gpuEvictions, 0u);
}

TEST(ImageryTiles, FileTruncatedMidStreamEndsTheFrameNamingIt) {
  auto ctx = gl::createHeadlessContext();
  const fs::path file = outDir() / "truncated.tif";
  fs::copy_file(checker(), file, fs::copy_options::overwrite_existing);
  render::GlobeRenderer r(data::defaultElevation());
  r.imagery().setLayers(checkerLayer(file));
  r.render(downFrom(150000.0));  // far: no tiles read yet
  fs::resize_file(file, fs::file_size(file) / 4);
  try {
    r.render(downFrom(5000.0));
    ADD_FAILURE() << "a truncated layer was read without an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
  }
}

namespace {

/// Mean display green of each column over the central rows (the relief's shading averaged out).
std::vector<double> columnProfile(const io::ImageRgba8& img) {
  std::vector<double> p(static_cast<std::size_t>(img.width), 0.0);
  const int y0 = img.height / 8, y1 = img.height - img.height / 8;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < img.width; ++x)
      p[static_cast<std::size_t>(x)] += img.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) +
                                                    static_cast<std::size_t>(x)) * 4 + 1];
  for (double& v : p) v /= (y1 - y0);
  return p;
}

}  // namespace

TEST(ImageryTiles, NoStepWhereTwoTilesMeetMagnified) {
  // Straight down over kCheckerLonDeg, the edge between level-9 tiles 575 and 576 (and of the
  // coarser levels), from ~2.6 km above the ground: a level-9 texel (150 m) spans ~10 pixels,
  // so the ramp's 12 grey levels a texel are a gentle slope, which bilinear filtering carries
  // straight across the edge when the tiles have borders. Without, each tile clamps at its
  // own edge: a flat half-texel on either side and the whole texel's step at the edge.
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  static const fs::path ramp = test::writeRampGeoTiff(outDir() / "ramp.tif");
  r.imagery().setLayers(checkerLayer(ramp));
  r.render(downFrom(3000.0));
  ASSERT_EQ(r.imagery().tileStats().finestLevel, 9);
  const io::ImageRgba8 img = r.display();
  io::writePng(outDir() / "ramp_edge_3km.png", img);
  const std::vector<double> p = columnProfile(img);
  // The slope away from the edge (median step between neighbouring columns) ...
  std::vector<double> slope;
  for (int x = 16; x + 1 < kSize - 16; ++x)
    if (std::abs(x - kSize / 2) > 10) slope.push_back(p[static_cast<std::size_t>(x) + 1] - p[static_cast<std::size_t>(x)]);
  std::nth_element(slope.begin(), slope.begin() + static_cast<std::ptrdiff_t>(slope.size() / 2), slope.end());
  const double median = slope[slope.size() / 2];
  ASSERT_GT(median, 0.2) << "the ramp must rise eastwards across the view";
  // ... and the largest step within 4 pixels of the edge (the image's middle).
  double edge = 0.0;
  for (int x = kSize / 2 - 4; x < kSize / 2 + 4; ++x)
    edge = std::max(edge, std::abs(p[static_cast<std::size_t>(x) + 1] - p[static_cast<std::size_t>(x)]));
  EXPECT_LT(edge, 2.0 * median + 0.5) << "a step at the tile edge: " << edge << " grey levels, slope " << median;
}

namespace {

/// A long thin layer finer than its whole texture by three levels (16384 × 64 pixels of
/// level-12 texels over 19.6875..22.5°E, 11.953125..11.964111°N; the whole texture's texels
/// are level 9's): it streams levels 10-12, so tiles have streamed ancestors.
const fs::path& stripLayer() {
  static const fs::path file = [] {
    const double texel = 180.0 / 4096 / 256;
    const test::GeoBox box{19.6875, 22.5, 11.953125, 11.953125 + 64 * texel};
    return test::writeGeoRaster(outDir() / "strip.tif", 4326, 16384, 64, box, [](double lat, double lon) {
      return test::Rgb8{static_cast<std::uint8_t>(std::lround(std::fmod(lon * 4000.0, 200.0))),
                        static_cast<std::uint8_t>(std::lround(std::fmod(lat * 9000.0, 200.0))), 90};
    });
  }();
  return file;
}

constexpr double kStripLatDeg = 11.9586;

}  // namespace

TEST(ImageryTiles, AncestorsAreAskedForWithEveryTile) {
  // One frame's requests on a fresh cache, in the background (the viewer): every tile asked
  // for has its parent asked for too (or resident), down to the layer's first streamed level,
  // so a coarser tile can stand in before the whole texture has to.
  auto ctx = gl::createHeadlessContext();
  auto source = std::make_shared<const data::ImageryTileSource>(stripLayer().string(), 0, data::kImageryLayerSizePx);
  ASSERT_EQ(source->minLevel(), 10);
  ASSERT_EQ(source->maxLevel(), 12);
  render::ImageryTiles tiles({source}, render::ImageryTextures::kDefaultCacheBytes, render::ImageryTextures::kDefaultCacheBytes);
  std::vector<terrain::TileKey> drawn;  // level-14 terrain tiles along the strip
  const double size = 180.0 / (1 << 14);
  for (int i = 0; i < 8; ++i)
    drawn.push_back({14, static_cast<int>((20.0 + 0.3 * i + 180.0) / size), static_cast<int>((kStripLatDeg + 90.0) / size)});
  tiles.prepare(drawn, false);
  int checked = 0;
  for (const terrain::TileKey& t : drawn) {
    const data::ImageryTileKey k = tiles.wanted(0, t);
    ASSERT_EQ(k.level, 12);
    EXPECT_TRUE(tiles.residentOrRequested(k));
    for (data::ImageryTileKey a = k.ancestor(1); a.level >= source->minLevel(); a = a.ancestor(1), ++checked)
      EXPECT_TRUE(tiles.residentOrRequested(a)) << "level " << a.level << " (" << a.x << ", " << a.y << ")";
  }
  EXPECT_EQ(checked, 16);
  tiles.waitIdle();
}

TEST(ImageryTiles, PrefetchedViewDrawsCompleteWithoutWaiting) {
  // The viewer asks for the tiles of the camera a second ahead: a frame there, drawn without
  // waiting for imagery, already has every tile it wants (no request left) and looks as a
  // frame that waited for them.
  auto ctx = gl::createHeadlessContext();
  render::FrameInput f = downFrom(3000.0);
  f.camera.position = {kStripLatDeg, 21.0, 2500.0};
  f.camera.pitchDeg = -50.0;
  f.camera.verticalFovDeg = 60.0;
  render::GlobeRenderer waited(data::defaultElevation());
  waited.imagery().setLayers(checkerLayer(stripLayer()));
  waited.render(f);
  const io::ImageRgba8 reference = waited.display();
  ASSERT_EQ(waited.imagery().tileStats().finestLevel, 12);

  render::GlobeRenderer r(data::defaultElevation());
  r.imagery().setTilesInBackground(true);
  r.imagery().setLayers(checkerLayer(stripLayer()));
  r.imagery().prefetchTiles(geo::makeCameraView(f.camera, f.width, f.height), f.width, f.height);
  r.imagery().tiles()->waitIdle();
  r.render(f);
  const io::ImageRgba8 img = r.display();
  io::writePng(outDir() / "prefetched.png", img);
  const render::ImageryTileStats s = r.imagery().tileStats();
  EXPECT_EQ(s.pending, 0u) << "the frame asked for tiles the prefetch did not";
  EXPECT_EQ(s.finestLevel, 12);
  int differ = 0;
  for (std::size_t i = 0; i < img.pixels.size(); ++i) differ += std::abs(img.pixels[i] - reference.pixels[i]) > 1;
  EXPECT_EQ(differ, 0);
}
