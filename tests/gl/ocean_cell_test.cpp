// GL tier: the projected grid's cells grow two- or four-fold (to at most 4.2° across) where the
// waves' geometry is sub-pixel and no sea is seen near grazing (render::OceanRenderer::geometryIsSubPixel): they then only
// interpolate smooth terms, so the picture is the 8-px grid's, for a third of the ocean pass.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "geo/Camera.hpp"
#include "gl/Context.hpp"
#include "gl/DriverProfile.hpp"
#include "gl/Objects.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GlFixtures.hpp"
#include "support/ImageCompare.hpp"

using namespace og;

namespace {
bool subPixel(double heightM, double pitchDeg, int width, int height, double fovDeg = 45.0) {
  geo::CameraPose pose;
  pose.position = {20.0, -40.0, heightM};
  pose.headingDeg = 270.0;
  pose.pitchDeg = pitchDeg;
  pose.verticalFovDeg = fovDeg;
  return render::OceanRenderer::geometryIsSubPixel(geo::makeCameraView(pose, width, height), height, 1.98);
}
// 8 km up over the open Atlantic, heading west, looking down pitchDeg through a lens fovDeg tall
// at 320x180, the Sun sunElevationDeg up at azimuth sunAzimuthDeg; the waves at 3 s.
render::FrameInput lookingDown(double pitchDeg, double fovDeg, double sunElevationDeg, double sunAzimuthDeg) {
  render::FrameInput f =
      test::frameOf({20.0, -40.0, 8000.0, 270.0, pitchDeg, fovDeg, 320, 180}, sunElevationDeg, sunAzimuthDeg);
  f.simulationTimeS = 3.0;
  return f;
}
}  // namespace

// The bench's views with their 1.98 m displacement bound (7 m/s): sea-8km grows at 720p (0.29 px
// at most: 10.1 km to the nearest sea, 1490 px/rad in the corners) but not at 2160p (0.88 px);
// sea-4m and sea-1km do not (metres of displacement; the horizon); 20 km with the horizon in
// view (OceanSwitch's view) does not, 20 km looking down with the nadir in view does.
TEST(OceanCell, GrowsOnlyWhereTheGeometryIsSubPixelAndNoHorizonIsInView) {
  EXPECT_TRUE(subPixel(8000.0, -30.0, 1280, 720));
  EXPECT_FALSE(subPixel(8000.0, -30.0, 3840, 2160));
  EXPECT_FALSE(subPixel(4.0, -10.0, 1280, 720));
  EXPECT_FALSE(subPixel(1000.0, -20.0, 1280, 720));
  EXPECT_FALSE(subPixel(19999.0, -30.0, 192, 108, 60.0));
  EXPECT_TRUE(subPixel(19999.0, -60.0, 192, 108, 60.0));
}

// Looking down from 8 km: the grown grid's picture against the 8-px grid's (16-px cells at
// 320x180, 4.2° across; 32-px cells at 640x360 and 1280x720 pass the same bound, measured).
TEST(OceanCell, GrownCellsDrawTheSameSea) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const render::FrameInput f = lookingDown(-30.0, 45.0, 20.0, 250.0);
  r.render(f);
  const io::ImageRgba8 grown = r.display();
  EXPECT_EQ(r.ocean().lastCellPixels(), 16);  // 32 px would be 8.4° across (kGrownCellMaxRad)
  r.ocean().setCellGrowth(false);
  r.render(f);
  const io::ImageRgba8 fine = r.display();
  EXPECT_EQ(r.ocean().lastCellPixels(), 8);
  const test::Comparison c = test::compareRgb(grown, fine, 2);
  if (!c.within({3, 0.1, 2, 0.01})) {
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / "ocean_cell_grown.png", grown);
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / "ocean_cell_grown.diff.png", c.diff);
  }
  EXPECT_TRUE(c.within({3, 0.1, 2, 0.01})) << c.describe();
}

// The pixels of grown cells taking their radiance from the vertices' quadratic in their mean
// slope and covariance (ocean/radiance_terms.glsl) against each pixel's own radiance on the 8-px
// grid, the glint in view: 8 km up, looking down 50° through a narrow lens (10° tall; the
// nearest sea 10 km away, where the pixels resolve the most), the Sun 30°, 50° and 70° up. The
// glint's lobe is wide there (2 sigma cos 40° at 50°): 32-px cells (1.8°). Measured (max levels,
// pixels over 2 levels): 4 and 0.08 %, 4 and 0.06 %, 7 and 0.29 %. Mutated, the quadratic cut to
// its linear part gives 1.1 % at 50°, without the slopes' cross term 0.71 % at 30°, two terms'
// slots swapped 3.4 % (the foam's folding is the unit tests'). Looking down 12° at the Sun 5°
// up, the lobe across the view at the top of the screen is 1.8° wide: the pixels keep their own
// radiance (and the cells their 32 px). Also with the programs that read the wind and its
// tables per point (two bins).
TEST(OceanCell, RadianceFromTheVerticesDrawsTheSameSea) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const test::Tolerance bound{8, 0.35, 2, 0.005};
  const auto againstTheFineGrid = [&](const render::FrameInput& f, const char* name) {
    r.render(f);
    const io::ImageRgba8 terms = r.display();
    EXPECT_TRUE(r.ocean().lastRadianceTerms()) << name;
    EXPECT_EQ(r.ocean().lastCellPixels(), 32) << name;
    EXPECT_TRUE(r.ocean().lastDrawCoversScreen()) << name;  // the globe then draws nothing
    r.ocean().setCellGrowth(false);
    r.render(f);
    const io::ImageRgba8 fine = r.display();
    r.ocean().setCellGrowth(true);
    EXPECT_FALSE(r.ocean().lastRadianceTerms()) << name;
    const test::Comparison c = test::compareRgb(terms, fine, 2);
    if (!c.within(bound)) {
      const std::filesystem::path out = std::filesystem::path(OG_TEST_OUT_DIR) / (std::string("ocean_cell_terms_") + name);
      io::writePng(out.string() + ".png", terms);
      io::writePng(out.string() + ".diff.png", c.diff);
    }
    EXPECT_TRUE(c.within(bound)) << name << ": " << c.describe();
  };
  againstTheFineGrid(lookingDown(-50.0, 10.0, 30.0, 250.0), "sun30");
  againstTheFineGrid(lookingDown(-50.0, 10.0, 50.0, 250.0), "sun50");
  againstTheFineGrid(lookingDown(-50.0, 10.0, 70.0, 250.0), "sun70");
  // The programs for a wind that is not constant along one bin (per-pixel wind and tables).
  r.ocean().setOneBinAllowed(false);
  againstTheFineGrid(lookingDown(-50.0, 10.0, 50.0, 250.0), "sun50_two_bins");
  EXPECT_FALSE(r.ocean().lastDrawOneBin());
  r.ocean().setOneBinAllowed(true);

  r.render(lookingDown(-12.0, 10.0, 5.0, 270.0));
  EXPECT_FALSE(r.ocean().lastRadianceTerms());
  EXPECT_EQ(r.ocean().lastCellPixels(), 32);
}

// A display-only frame (FrameInput::displayOnly, as `record` to MP4 renders) with no land in
// view: the sea's one pass writes the display itself, tone mapped, and the tone map's pass
// reads only the sky's pixels, or none where the sea covers the screen (render/OceanRenderer::
// setDisplayTarget): the radiance terms' grown cells, the forward grid's, the deferred sea
// through the visibility buffer under the sky (the bench's sea-4m). Its picture and depth are
// the two-pass frame's; the radiance it never wrote cannot be read. Frames with land in view,
// multisampled ones and those with the switch off keep the tone map's pass. Measured: the
// same bytes in every pixel.
TEST(OceanCell, DisplayOnlyFramesTakeTheDisplayFromTheSeaPass) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  // (One sample a pixel: GPUs' auto is 4. The deferred sea has one pass through the visibility
  // buffer where the driver profile asks for it: llvmpipe's.)
  const bool visibility = gl::driverProfile().seaByVisibility;
  const auto sameFrame = [&](render::FrameInput f, bool folds, bool covers, const char* name, bool deferred = false) {
    f.samples = 1;
    folds = folds && (!deferred || visibility);
    f.displayOnly = false;
    r.render(f);
    EXPECT_FALSE(r.lastSeaWroteDisplay()) << name;
    const io::ImageRgba8 twoPasses = r.display();
    const std::vector<float> twoPassDepth = r.depth();
    // A pixel left unwritten would keep this colour (it would keep the frame's own otherwise).
    const float magenta[] = {1.0f, 0.0f, 1.0f, 1.0f};
    glClearNamedFramebufferfv(r.displayFramebuffer(), GL_COLOR, 0, magenta);
    f.displayOnly = true;
    r.render(f);
    EXPECT_EQ(r.lastSeaWroteDisplay(), folds) << name;
    EXPECT_EQ(r.ocean().lastDrawCoversScreen(), covers) << name;
    if (visibility) {
      EXPECT_EQ(r.ocean().lastDrawDeferred(), deferred) << name;
    }
    EXPECT_THROW((void)r.radiance(), InternalError) << name;
    const io::ImageRgba8 shown = r.display();
    const test::Comparison c = test::compareRgb(shown, twoPasses, 0);
    if (!c.within({1, 0.01, 0, 0.001})) {
      const std::filesystem::path out = std::filesystem::path(OG_TEST_OUT_DIR) / (std::string("display_only_") + name);
      io::writePng(out.string() + ".png", shown);
      io::writePng(out.string() + ".expected.png", twoPasses);
      io::writePng(out.string() + ".diff.png", c.diff);
    }
    EXPECT_TRUE(c.within({1, 0.01, 0, 0.001})) << name << ": " << c.describe();
    EXPECT_TRUE(r.depth() == twoPassDepth) << name;
  };
  sameFrame(lookingDown(-50.0, 10.0, 50.0, 250.0), true, true, "glint");
  sameFrame(lookingDown(-50.0, 10.0, 70.0, 250.0), true, true, "high_sun");
  r.ocean().setRadianceTerms(false);  // (the same cells forward, each pixel shading itself)
  sameFrame(lookingDown(-50.0, 10.0, 50.0, 250.0), true, false, "forward");
  r.ocean().setRadianceTerms(true);
  render::FrameInput horizon = test::frameOf({20.0, -40.0, 4.0, 270.0, -10.0, 45.0, 320, 180}, 20.0, 250.0);
  horizon.simulationTimeS = 3.0;
  sameFrame(horizon, true, false, "deferred_under_the_sky", true);
  // From 1 km the grid leaves gaps at the horizon that the globe's edge shades (0.2 % of the
  // pixels), within the sky's box (the tone map's second draw, over the blocks listed as
  // uncovered, is for gaps beyond it: none in these views nor in others tried, from 300 m to
  // 19 km, rolled or not).
  render::FrameInput high = test::frameOf({20.0, -40.0, 1000.0, 270.0, -20.0, 60.0, 320, 180}, 20.0, 250.0);
  high.simulationTimeS = 3.0;
  sameFrame(high, true, false, "deferred_from_1km", true);
  render::FrameInput coast =
      test::frameOf({36.0, -5.6, 8000.0, 270.0, -50.0, 45.0, 320, 180}, 50.0, 250.0);  // the Strait of Gibraltar
  sameFrame(coast, false, false, "coast");  // (the classes: drawn forward)
  render::FrameInput multisampled = lookingDown(-50.0, 10.0, 50.0, 250.0);
  multisampled.samples = 2;
  multisampled.displayOnly = true;
  r.render(multisampled);
  EXPECT_FALSE(r.lastSeaWroteDisplay());
  r.setSeaWritesDisplay(false);
  sameFrame(lookingDown(-50.0, 10.0, 50.0, 250.0), false, true, "switched_off");
}

namespace {
geo::CameraView poseView(double heightM, double pitchDeg, double rollDeg, int width, int height, double fovDeg = 60.0) {
  geo::CameraPose pose;
  pose.position = {20.0, -40.0, heightM};
  pose.headingDeg = 270.0;
  pose.pitchDeg = pitchDeg;
  pose.rollDeg = rollDeg;
  pose.verticalFovDeg = fovDeg;
  return geo::makeCameraView(pose, width, height);
}
// The highest of `ys` steps over [bottom, top] at which a ray with NDC x among `columns` + 1
// even steps over [left, right] meets the ellipsoid (geo::intersectEllipsoid), or bottom - 1.
double highestHitNdc(const geo::CameraView& view, double left, double right, int columns, double bottom, double top,
                     int ys) {
  double highest = bottom - 1.0;
  for (int k = 0; k <= columns; ++k)
    for (int j = ys; j >= 0; --j) {
      const double x = left + (right - left) * k / columns, y = bottom + (top - bottom) * j / ys;
      if (y <= highest) break;
      if (geo::intersectEllipsoid(view.positionEcef, view.rayDirection(x, y))) {
        highest = y;
        break;
      }
    }
  return highest;
}
}  // namespace

// The projected grid's rows stop at the sea's top (render::OceanRenderer::seaTopNdc): the
// highest NDC y at which a ray meets the ellipsoid, solved per column of rays. Against rays
// stepped 1/4000 of the range apart at the same columns, and at four times as many columns
// (between seaTopNdc's, the horizon's curve may rise above its columns' by no more than a
// fraction of the kGridRowsOverSeaTop fine rows it keeps over it: 2 rows of 8 px at 180 px are
// 0.18 NDC; measured under 1e-3). Views over x in [-2, 2] (the grid's side margins from 2 m):
// 2 m looking level (the horizon near the middle), rolled 30° (the horizon tilted: highest at
// a side), 4 m looking 10° down, 8 km looking 30° down (the horizon at the wide grid's
// corners), 8 km looking 80° down (every ray meets the sea: the range's top) and 2 m looking
// 80° up over y in [-1.5, 1.1] (none does).
TEST(OceanGrid, SeaTopIsWhereTheRaysStopMeetingTheSea) {
  struct Case {
    const char* name;
    geo::CameraView view;
    double bottom;
  };
  const std::vector<Case> cases{{"level_2m", poseView(2.0, 2.0, 0.0, 320, 180), -4.0},
                                {"rolled_2m", poseView(2.0, 2.0, 30.0, 320, 180), -4.0},
                                {"down_4m", poseView(4.0, -10.0, 0.0, 320, 180), -4.0},
                                {"down_8km", poseView(8000.0, -30.0, 0.0, 320, 180), -4.0},
                                {"nadir_8km", poseView(8000.0, -80.0, 0.0, 320, 180), -4.0},
                                {"up_2m", poseView(2.0, 80.0, 0.0, 320, 180), -1.5}};
  const double left = -2.0, right = 2.0, top = 1.1;
  for (const Case& c : cases) {
    const double solved = render::OceanRenderer::seaTopNdc(c.view, left, right, c.bottom, top);
    const int columns = render::OceanRenderer::kSeaTopColumns;
    const double stepped = highestHitNdc(c.view, left, right, columns, c.bottom, top, 4000);
    const double between = highestHitNdc(c.view, left, right, 4 * columns, c.bottom, top, 4000);
    std::printf("%s: solved %.5f, stepped %.5f, at 4x the columns %.5f\n", c.name, solved, stepped, between);
    if (stepped < c.bottom) {
      EXPECT_LT(solved, c.bottom) << c.name;
      continue;
    }
    EXPECT_GE(solved, stepped - 1e-9) << c.name;
    EXPECT_LE(solved, stepped + (top - c.bottom) / 4000.0) << c.name;
    EXPECT_LE(between, solved + 0.01) << c.name;
  }
  const auto solved = [&](std::size_t k) {
    return render::OceanRenderer::seaTopNdc(cases[k].view, left, right, cases[k].bottom, top);
  };
  EXPECT_LT(solved(0), 0.0);  // below the middle: the axis 2° up
  EXPECT_GT(solved(1), solved(0) + 0.5);  // tilted
  EXPECT_LT(solved(3), top);
  EXPECT_DOUBLE_EQ(solved(4), top);
  EXPECT_LT(solved(5), cases[5].bottom);
}

// The rows over the sea's top all lay on the horizon: without them the picture is the same.
// From 2 m looking level, rolled 10°, and 15° up (the horizon low on the screen), with the
// deferred sea's visibility buffer, surface buffer and the forward draw; at 640 x 360 (fine
// rows of 8 px in bands of 16: the horizon's band is the second of five over the screen at 15°
// up). Measured: the same bytes. Mutated, the rows kept ending at the sea's top less 2 bands:
// the sea's far part gone (sky over 22-28 % of the pixels, up to 220 levels).
TEST(OceanGrid, RowsOverTheSeaTopLeftOutDrawTheSamePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  struct Case {
    const char* name;
    double pitchDeg, rollDeg;
    const char* surface;
  };
  for (const Case& c : {Case{"level", 2.0, 0.0, "visibility"}, Case{"rolled", 2.0, 10.0, "buffer"},
                        Case{"up15", 15.0, 0.0, "visibility"}, Case{"up15_forward", 15.0, 0.0, nullptr}}) {
    render::FrameInput f = test::frameOf({20.0, -40.0, 2.0, 270.0, c.pitchDeg, 60.0, 640, 360}, 20.0, 250.0);
    f.camera.rollDeg = c.rollDeg;
    f.simulationTimeS = 3.0;
    if (c.surface != nullptr)
      setenv("OCEANGLOBE_SEA_SURFACE", c.surface, 1);
    r.ocean().setDeferred(c.surface != nullptr);
    r.render(f);
    const io::ImageRgba8 cut = r.display();
    const int drawn = r.ocean().lastGridRowsDrawn(), rows = r.ocean().lastGridRows();
    r.ocean().setGridToSeaTop(false);
    r.render(f);
    const io::ImageRgba8 whole = r.display();
    EXPECT_EQ(r.ocean().lastGridRowsDrawn(), r.ocean().lastGridRows()) << c.name;
    r.ocean().setGridToSeaTop(true);
    r.ocean().setDeferred(true);
    unsetenv("OCEANGLOBE_SEA_SURFACE");
    std::printf("%s: %d of %d vertex rows\n", c.name, drawn, rows);
    EXPECT_LT(drawn, rows) << c.name;
    const test::Comparison cmp = test::compareRgb(cut, whole, 1);
    if (!cmp.within({1, 0.001, 1, 0.0})) {
      const std::filesystem::path out = std::filesystem::path(OG_TEST_OUT_DIR) / (std::string("ocean_grid_sea_top_") + c.name);
      io::writePng(out.string() + ".png", cut);
      io::writePng(out.string() + ".diff.png", cmp.diff);
    }
    EXPECT_TRUE(cmp.within({1, 0.001, 1, 0.0})) << c.name << ": " << cmp.describe();
  }
}
