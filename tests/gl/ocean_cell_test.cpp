// GL tier: the projected grid's cells grow two- or four-fold (to at most 4.2° across) where the
// waves' geometry is sub-pixel and no sea is seen near grazing (render::OceanRenderer::geometryIsSubPixel): they then only
// interpolate smooth terms, so the picture is the 8-px grid's, for a third of the ocean pass.
#include <gtest/gtest.h>

#include <filesystem>

#include "data/Elevation.hpp"
#include "geo/Camera.hpp"
#include "gl/Context.hpp"
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
// nearest sea 10 km away, where the pixels resolve the most), the Sun 50° up. The glint's lobe
// is wide there (2 sigma cot 40°): 32-px cells (1.8°). Measured max 4, mean 0.26, 0.08 % of the
// pixels over 2 levels; the quadratic cut to its linear part gives more than 1 %. Looking down
// 12° at the Sun 5° up, the lobe across the view at the top of the screen is 1.8° wide: the
// pixels keep their own radiance (and the cells their 32 px). Also with the programs that read
// the wind and its tables per point (two bins).
TEST(OceanCell, RadianceFromTheVerticesDrawsTheSameSea) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const render::FrameInput f = lookingDown(-50.0, 10.0, 50.0, 250.0);
  r.render(f);
  const io::ImageRgba8 terms = r.display();
  EXPECT_TRUE(r.ocean().lastRadianceTerms());
  EXPECT_EQ(r.ocean().lastCellPixels(), 32);
  EXPECT_TRUE(r.ocean().lastDrawCoversScreen());  // the globe then draws nothing
  r.ocean().setCellGrowth(false);
  r.render(f);
  const io::ImageRgba8 fine = r.display();
  EXPECT_FALSE(r.ocean().lastRadianceTerms());
  const test::Comparison c = test::compareRgb(terms, fine, 2);
  const test::Tolerance bound{5, 0.35, 2, 0.003};
  if (!c.within(bound)) {
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / "ocean_cell_terms.png", terms);
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / "ocean_cell_terms.diff.png", c.diff);
  }
  EXPECT_TRUE(c.within(bound)) << c.describe();

  // The programs for a wind that is not constant along one bin (per-pixel wind and tables):
  // the same sea.
  r.ocean().setCellGrowth(true);
  r.ocean().setOneBinAllowed(false);
  r.render(f);
  EXPECT_TRUE(r.ocean().lastRadianceTerms());
  EXPECT_FALSE(r.ocean().lastDrawOneBin());
  const test::Comparison twoBins = test::compareRgb(r.display(), fine, 2);
  EXPECT_TRUE(twoBins.within(bound)) << twoBins.describe();
  r.ocean().setOneBinAllowed(true);

  r.render(lookingDown(-12.0, 10.0, 5.0, 270.0));
  EXPECT_FALSE(r.ocean().lastRadianceTerms());
  EXPECT_EQ(r.ocean().lastCellPixels(), 32);
}
