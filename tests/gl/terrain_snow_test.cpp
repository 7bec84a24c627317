// GL tier (issue 14): the snow line follows latitude (terrain/material.glsl, terrainSnowLineM)
// and, where imagery covers the ground, the imagery's colour wins over procedural snow at
// coarse scale. From orbit the Tibetan plateau (4500-5200 m at 30-36° N) is dry and brown in
// the Blue Marble; a snow line that only fell with latitude (5600 m at the equator to sea
// level at 75°, ~4900 m at 33°) painted it white. The beaches' sand takes only a beach's width
// of a pixel's footprint: from orbit it lit every coast pixel where the imagery shows water.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>

#include "support/GlFixtures.hpp"

using namespace og;

namespace {

class TerrainSnow : public test::GlobeSuite {};

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
};

// Mean display (sRGB, 0-255) colour of the centre's 5x5 pixels.
Rgb centreColour(const io::ImageRgba8& img) {
  Rgb c;
  for (int y = img.height / 2 - 2; y <= img.height / 2 + 2; ++y)
    for (int x = img.width / 2 - 2; x <= img.width / 2 + 2; ++x) {
      const std::uint8_t* p = &img.pixels[4 * static_cast<std::size_t>(y * img.width + x)];
      c.r += p[0] / 25.0;
      c.g += p[1] / 25.0;
      c.b += p[2] / 25.0;
    }
  return c;
}

}  // namespace

TEST_F(TerrainSnow, TibetanPlateauFromOrbitIsNotWhite) {
  // Straight down on the Changtang (33° N, 88° E; ~4900 m in the default layer) from 2000 km,
  // the Sun 60° up.
  test::View v;
  v.latDeg = 33.0;
  v.lonDeg = 88.0;
  v.heightM = 2.0e6;
  v.pitchDeg = -90.0;
  v.fovDeg = 30.0;
  v.width = 128;
  v.height = 96;
  renderer_->render(test::frameOf(v, 60.0, 180.0));
  test::savePng(*renderer_, "snow_tibet_2000km");
  const Rgb c = centreColour(renderer_->display());
  std::printf("Tibetan plateau from 2000 km: sRGB (%.0f, %.0f, %.0f)\n", c.r, c.g, c.b);
  // Measured: (171, 156, 140), brown like the imagery; (209, 206, 208) with the old snow line,
  // snow. White would be bright in every channel and as blue as it is red.
  EXPECT_LT(std::min({c.r, c.g, c.b}), 160.0) << "the plateau should not be snow-white";
  EXPECT_GT(c.r - c.b, 15.0) << "the plateau should be brown (red over blue), as in the imagery";
}

namespace {

class TerrainBeach : public test::GlobeSuite {};

// Pixels brighter than the median of their 3 x 3 neighbourhood by more than `levels` (display
// sRGB, the mean of the channels): isolated bright dots.
int brightDots(const io::ImageRgba8& img, double levels) {
  auto luma = [&](int x, int y) {
    const std::uint8_t* p = &img.pixels[4 * static_cast<std::size_t>(y * img.width + x)];
    return (p[0] + p[1] + p[2]) / 3.0;
  };
  int dots = 0;
  for (int y = 1; y + 1 < img.height; ++y)
    for (int x = 1; x + 1 < img.width; ++x) {
      std::array<double, 9> n{};
      for (int k = 0; k < 9; ++k) n[static_cast<std::size_t>(k)] = luma(x - 1 + k % 3, y - 1 + k / 3);
      std::nth_element(n.begin(), n.begin() + 4, n.end());
      dots += luma(x, y) - n[4] > levels ? 1 : 0;
    }
  return dots;
}

}  // namespace

TEST_F(TerrainBeach, CoastsFromOrbitAreNotDottedWithSand) {
  // South-western Europe from 4000 km (pixels ~14 km): the terrain's coast pixels where the
  // imagery shows water take the procedural material at sea level, whose sand band (0-25 m)
  // painted a pale dot on every such pixel (the Azores, the Balearics, Italy's coasts).
  renderer_->render(test::frameOf(
      {.latDeg = 41.0, .lonDeg = -4.0, .heightM = 4.0e6, .pitchDeg = -90.0, .fovDeg = 30.0, .width = 160, .height = 96},
      60.0, 180.0));
  test::savePng(*renderer_, "beach_iberia_4000km");
  const int dots = brightDots(renderer_->display(), 30.0);
  std::printf("bright dots from 4000 km: %d\n", dots);
  // Measured: 6 (islets and headlands the imagery shows); 20 with sand on every coast pixel.
  EXPECT_LE(dots, 10) << "coast pixels should not sparkle with sand from orbit";
}
