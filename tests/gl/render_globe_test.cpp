// GL tier: the globe pass on a headless context, checked against the CPU camera maths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "gl/DriverProfile.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GlFixtures.hpp"
#include "support/GridFixtures.hpp"
#include "support/ImageCompare.hpp"

using namespace og;

namespace {
// 5° cells: land at 1000 m north of the equator and east of Greenwich, sea 4000 m deep elsewhere.
data::LatLonGrid halfLand() {
  return test::globalGrid("test", 5.0, [](double lat, double lon) {
    return lat > 0.0 && lon > 0.0 ? 1000.0 : -4000.0;
  });
}

render::FrameInput frame(double lat, double lon, double h, double pitch, int size = 64) {
  render::FrameInput f;
  f.camera.position = {lat, lon, h};
  f.camera.pitchDeg = pitch;
  f.width = f.height = size;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 60, 150);
  return f;
}

const float* px(const io::ImageRgbaF& img, int x, int y) {
  return &img.pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) +
                          static_cast<std::size_t>(x))];
}
}  // namespace

TEST(GlobeRender, GlobeInTheMiddleSpaceInTheCorners) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(halfLand());
  r.render(frame(10, -30, 2.0e7, -90));
  const io::ImageRgbaF img = r.radiance();
  EXPECT_FLOAT_EQ(px(img, 32, 32)[3], 1.0f);
  EXPECT_GT(px(img, 32, 32)[2], 0.0f);
  for (auto [x, y] : {std::pair{0, 0}, {63, 0}, {0, 63}, {63, 63}}) {
    EXPECT_EQ(px(img, x, y)[3], 0.0f);
    EXPECT_EQ(px(img, x, y)[0] + px(img, x, y)[1] + px(img, x, y)[2], 0.0f);
  }
  for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v));
}

TEST(GlobeRender, DepthIsNearOverDistanceAtEveryScale) {
  // Above the grid's ceiling the globe pass writes the depth of its pixel-centre ray: exact
  // over the sea, 20 km (kGlobeDepthPushM) farther over land (a fallback that must never stand
  // in front of a terrain tile's chords). viewDistance() (the depth AOV) is the distance to what
  // the pixel shows: the ellipsoid over the sea, the terrain's plateau over land. Below the
  // ceiling, no depth from the globe.
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(halfLand());
  struct Case {
    double lat, lon, h, surfaceM;
  };
  for (const Case c : {Case{-20, -100, 2.1e4, 0.0}, Case{-20, -100, 4.0e5, 0.0}, Case{-20, -100, 2.0e7, 0.0},
                       Case{45, 135, 4.0e5, 1000.0}, Case{20, 100, 1.0, 0.0}, Case{20, 100, 1000.0, 0.0}}) {
    // Over land below the ceiling the camera is under the 1000 m plateau, whose back faces
    // are culled: the globe pass alone.
    const render::FrameInput f = frame(c.lat, c.lon, c.h, -90);
    r.render(f);
    const geo::CameraView v = geo::makeCameraView(f.camera, f.width, f.height);
    const std::vector<float> depth = r.depth();
    const std::vector<float> distance = r.viewDistance();
    // Pixel (32, 32) (rows from the bottom): its centre ray, half a pixel off axis each way.
    const double d = static_cast<double>(depth[32 * 64 + 32]);
    const glm::dvec3 dir = v.rayDirection(0.5 / 32.0, 0.5 / 32.0);
    const std::optional<double> t = geo::intersectEllipsoid(v.positionEcef, dir, c.surfaceM);
    ASSERT_TRUE(t.has_value());
    if (c.h < render::kOceanGridMaxHeightM) {
      // Below the grid's ceiling the globe is drawn last, behind the terrain and the grid,
      // and writes no depth: with nothing else on this pixel it stays at the far plane.
      EXPECT_EQ(d, 0.0) << "height " << c.h;
      continue;
    }
    // viewDistance's rows run from the top: pixel (32, 31) from it is (32, 32) from the bottom.
    const double seen = static_cast<double>(distance[31 * 64 + 32]);
    if (c.surfaceM > 0.0) {
      EXPECT_NEAR(seen, *t, 600.0) << "the terrain's plateau (chords ~0.5 km off it), height " << c.h;
      continue;
    }
    const double expected = *t * glm::dot(dir, v.forward);
    EXPECT_NEAR(v.nearM / d, expected, expected * 1e-6) << "height " << c.h;
    EXPECT_NEAR(seen, *t, *t * 1e-6) << "height " << c.h;
  }
}

// From 2 m above the sea, the horizon must appear on the row the CPU ellipsoid maths puts it.
TEST(GlobeRender, HorizonRowMatchesCpuAtTwoMetres) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(halfLand());
  render::FrameInput f = frame(40, -20, 2.0, 0, 128);
  f.camera.verticalFovDeg = 2.0;  // ~0.016° per pixel: the horizon dip (0.045°) spans rows
  r.render(f);
  const io::ImageRgbaF img = r.radiance();
  const geo::CameraView v = geo::makeCameraView(f.camera, f.width, f.height);
  int gpuRow = -1, cpuRow = -1;
  for (int y = 0; y < 128; ++y) {
    const double ndcY = 1.0 - 2.0 * (y + 0.5) / 128.0;
    const bool hitCpu = geo::intersectEllipsoid(v.positionEcef, v.rayDirection(0.0, ndcY)).has_value();
    if (cpuRow < 0 && hitCpu) cpuRow = y;
    if (gpuRow < 0 && px(img, 64, y)[3] > 0.5f) gpuRow = y;
  }
  ASSERT_GE(cpuRow, 0);
  EXPECT_GT(cpuRow, 64);  // the sea horizon dips below eye level
  EXPECT_NEAR(gpuRow, cpuRow, 1);
}

TEST(GlobeRender, EglAndOsMesaAgree) {
  io::ImageRgba8 images[2];
  int i = 0;
  for (gl::Backend b : {gl::Backend::Egl, gl::Backend::OsMesa}) {
    auto ctx = gl::createHeadlessContext(b);
    render::GlobeRenderer r(halfLand());
    r.render(frame(10, -30, 2.0e7, -90, 96));
    images[i++] = r.display();
  }
  const test::Comparison c = test::compareRgb(images[0], images[1], 1);
  EXPECT_LE(c.maxDiff, 1) << c.describe();
}

TEST(GlobeRender, OneClassifyingDrawMatchesOneDrawPerStep) {
  // Where the driver lets a shader write the stencil (GL_ARB_shader_stencil_export) the globe
  // classifies its pixels in one draw; OCEANGLOBE_STENCIL_EXPORT=0 takes the draw-per-step path.
  // Both must give the same picture: from orbit (open sea, land, coasts, limb, space), from
  // 300 km over the coast corner (the land's and the sea's parts, nested steps), and from 2 km
  // (below the grid's ceiling, globe drawn last; the one draw over the blocks of pixels left,
  // render/UncoveredPixels), also from 4 m in a frame of no whole number of blocks.
  const render::FrameInput frames[] = {frame(10, -30, 2.0e7, -90, 96), frame(2, 2, 3.0e5, -60, 96),
                                       frame(-1, -1, 2000.0, -2, 96), frame(-1, -1, 4.0, 1.0, 99)};
  std::vector<io::ImageRgbaF> images[2];
  for (int path = 0; path < 2; ++path) {
    const std::optional<test::ScopedEnv> off =
        path == 1 ? std::optional<test::ScopedEnv>(std::in_place, "OCEANGLOBE_STENCIL_EXPORT", "0")
                  : std::nullopt;
    // (Without export the sea in one forward program: its triangles in classes, the default
    // there, are CoastWater.ForwardSplitDrawsTheSamePicture's, within a level.)
    const std::optional<test::ScopedEnv> oneProgram =
        path == 1 ? std::optional<test::ScopedEnv>(std::in_place, "OCEANGLOBE_SEA", "forward") : std::nullopt;
    auto ctx = gl::createHeadlessContext();
    if (path == 1) {
      EXPECT_FALSE(gl::driverProfile().stencilExport);
    }
    if (path == 0 && !gl::driverProfile().stencilExport) GTEST_SKIP() << "no stencil export here";
    render::GlobeRenderer r(halfLand());
    r.setCountPartSamples(true);
    // The deferred sea needs stencil export too; its picture against the forward one is
    // CoastWater.DeferredSeaMatchesTheGridsOwnFragments' (within a level, not bit for bit).
    r.ocean().setDeferred(false);
    // So do the tiles over the land's class alone (their own test:
    // TerrainRender.TilesOverTheGlobesLandClassKeepThePicture).
    r.setTilesOverLandClass(false);
    for (const render::FrameInput& f : frames) {
      r.render(f);
      images[path].push_back(r.radiance());
      if (&f == &frames[1]) {  // 300 km over the coast: the land's and the sea's parts (and steps) in use
        std::uint64_t landSea = 0;
        for (const auto& [name, samples] : r.partSamples()) landSea += name == "land" || name == "sea" ? samples : 0;
        EXPECT_GT(landSea, 96u * 96u / 4u) << "path " << path;
      }
    }
  }
  for (std::size_t i = 0; i < images[0].size(); ++i) {
    ASSERT_EQ(images[0][i].pixels.size(), images[1][i].pixels.size());
    std::size_t differ = 0;
    for (std::size_t k = 0; k < images[0][i].pixels.size(); ++k)
      differ += images[0][i].pixels[k] != images[1][i].pixels[k] ? 1 : 0;
    EXPECT_EQ(differ, 0u) << "frame " << i;
  }
}

// The same picture below the grid's ceiling with a setting `set` off and on (`width` x
// `height` frames), from 2 m to 15 km: the horizon level, tilted by a roll, looking down with no
// sky and up with no ellipsoid.
namespace {
void expectBelowTheCeilingAlike(render::GlobeRenderer& r, const std::function<void(bool)>& set, int width = 160,
                                int height = 90) {
  struct Case {
    double lat, lon, h, pitch, roll;
  };
  for (const Case& c : {Case{-1, -1, 2.0, 1.0, 0.0}, Case{-1, -1, 15000.0, -3.0, 0.0}, Case{3, 3, 500.0, 2.0, 25.0},
                        Case{-1, -1, 4.0, -60.0, 0.0}, Case{-1, -1, 4.0, 60.0, 0.0}}) {
    render::FrameInput f = frame(c.lat, c.lon, c.h, c.pitch, width);
    f.height = height;
    f.camera.rollDeg = c.roll;
    const test::OffAndOn images = test::renderOffAndOn(r, f, set);
    EXPECT_EQ(test::radianceChange(images.off, images.on, 0.0, 4).over, 0)
        << "at " << c.h << " m, pitch " << c.pitch << ", roll " << c.roll;
  }
}
}  // namespace

// Below the grid's ceiling the classifying draws are scissored to the pixels whose rays can
// meet the ellipsoid (render::rayScissors' hits): the sky above the horizon has nothing to class;
// and the sky's part to those whose rays can miss it (render::rayScissors' sky). With sky in
// view the query of uncovered pixels looks only within the first box and the globe's parts are
// drawn without its condition (looking up from 4 m it finds nothing: drawn on it, the sky went
// black). The same picture as over the whole screen; the rectangles are the horizon's, one
// each side.
TEST(GlobeRender, ClassifyingBelowTheCeilingOnlyWhereRaysMeetTheEllipsoid) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(halfLand());
  expectBelowTheCeilingAlike(r, [&r](bool on) { r.setEllipsoidScissor(on); });
  // The rectangle: level at 2 m, the horizon at the middle row (pitch 0): the lower half.
  render::FrameInput f = frame(-1, -1, 2.0, 0.0, 160);
  f.height = 90;
  const render::RayScissors both = render::rayScissors(geo::makeCameraView(f.camera, f.width, f.height), f.width, f.height);
  const std::array<int, 4>& box = both.hits;
  EXPECT_EQ(box[1], 0);
  EXPECT_GT(box[3], 45);
  EXPECT_LT(box[3], 45 + 2 * render::kHitScanPx + 4);
  EXPECT_EQ(both.sky[1] + both.sky[3], 90);  // the upper half and a margin
  EXPECT_LT(both.sky[1], 45);
  EXPECT_GT(both.sky[1], 45 - 2 * render::kHitScanPx - 4);
  EXPECT_EQ(both.sky[2], 160);
  f.camera.pitchDeg = 60.0;
  EXPECT_EQ(render::rayScissors(geo::makeCameraView(f.camera, f.width, f.height), f.width, f.height).hits[2], 0);
  EXPECT_EQ(render::rayScissors(geo::makeCameraView(f.camera, f.width, f.height), f.width, f.height).sky,
            (std::array<int, 4>{0, 0, 160, 90}));
  f.camera.pitchDeg = -60.0;  // (no sky)
  EXPECT_EQ(render::rayScissors(geo::makeCameraView(f.camera, f.width, f.height), f.width, f.height).sky[2], 0);
}

// Below the ceiling the classifying draw that writes the stencil from its shader (which llvmpipe
// then tests late, running it for every pixel it covers) covers only the blocks of 8 x 8
// pixels that hold a pixel the terrain and the grid left (render/UncoveredPixels): the same
// picture as over every block of the ellipsoid's box (in frames of whole blocks and not; against
// the full-screen draws per step: OneClassifyingDrawMatchesOneDrawPerStep), and from 2 m with
// the horizon at the middle row only the blocks along it, not the grid's half.
TEST(GlobeRender, ClassifyingBelowTheCeilingOnlyOverTheBlocksLeftUncovered) {
  auto ctx = gl::createHeadlessContext();
  if (!gl::driverProfile().stencilExport) GTEST_SKIP() << "the driver cannot export stencil values";
  render::GlobeRenderer r(halfLand());
  expectBelowTheCeilingAlike(r, [&r](bool on) { r.setUncoveredBlocks(on); });
  expectBelowTheCeilingAlike(r, [&r](bool on) { r.setUncoveredBlocks(on); }, 163, 91);
  render::FrameInput f = frame(-1, -1, 2.0, 0.0, 160);
  f.height = 90;
  r.setUncoveredBlocks(false);
  r.render(f);
  const int every = r.uncoveredBlocksListed();  // the box's: the lower half and a margin
  EXPECT_GE(every, 20 * 6);
  r.setUncoveredBlocks(true);
  r.render(f);
  EXPECT_GT(r.uncoveredBlocksListed(), 0);
  EXPECT_LE(r.uncoveredBlocksListed(), 20 * 2) << "of " << every;
}
