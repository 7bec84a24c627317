// GL tier (issue 14): imagery layers stream as tiles (render/ImageryTiles). A large synthetic
// GeoTIFF (4096 × 2048, a checker of one-pixel cells, support/CheckerGeoTiff.hpp) shows its
// fine detail close up (the finest tile level, high pixel contrast) and only its whole texture
// far away (grey); tiles arrive in the background, the whole texture standing in for the first
// frame; the GPU cache never holds more than its budget; a file truncated mid-stream ends the
// frame with an og::InputError naming it. Images go to OG_TEST_OUT_DIR/imagery_tiles.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "data/Imagery.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"
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
  const std::size_t gpuBudget = std::size_t{1} << 20;  // three tiles with their mip-maps
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
