// GL tier: the switch between the projected-grid ocean (below 20 km) and the BRDF-only globe
// (above) must not be visible, and below it the grid's waves must really be drawn.
#include <gtest/gtest.h>

#include "data/Elevation.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GlFixtures.hpp"
#include "support/ImageCompare.hpp"

using namespace og;

namespace {
render::FrameInput view(double heightM) {
  render::FrameInput f = test::frameOf({20.0, -40.0, heightM, 90.0, -30.0, 60.0, 192, 108}, 30.0, 100.0);
  f.wind.speedMs = 9.0;
  f.wind.towardsDeg = 60.0;
  return f;
}
}  // namespace

// Stated tolerance: identical away from the horizon; along the horizon line the grid's single
// sample per pixel meets the globe's four, which moves single pixels by a few levels: at
// most 12 levels, a mean of 0.2, and no more than the horizon's two rows over 2 levels.
TEST(OceanSwitch, InvisibleAtTwentyKilometres) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.render(view(19999.0));
  const io::ImageRgba8 below = r.display();
  r.render(view(20001.0));
  const io::ImageRgba8 above = r.display();
  const test::Comparison c = test::compareRgb(below, above, 2);
  EXPECT_TRUE(c.within({12, 0.2, 2, 0.03})) << c.describe();  // 0.03: two rows of 108
}

TEST(OceanSwitch, GridDrawsWavesBelowAndFadesThemOut) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  // At 300 m the waves make the sea visibly different from the smooth far-field model...
  render::FrameInput low = view(300.0);
  r.render(low);
  const io::ImageRgba8 waves = r.display();
  low.oceanCellPixels = 8;
  low.wind.speedMs = 0.0;  // ...which a calm sea (no resolved waves) approaches.
  r.render(low);
  const io::ImageRgba8 calm = r.display();
  EXPECT_GT(test::compareRgb(waves, calm, 2).meanDiff, 1.0);
}
