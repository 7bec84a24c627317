// GL tier: the "done when" checks on small renders of the globe pass with the default
// atmosphere (tables cached under the test output directory after the first run).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "data/Elevation.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GlFixtures.hpp"

using namespace og;

namespace {

struct Shot {
  io::ImageRgbaF image;
  [[nodiscard]] glm::vec4 at(int x, int y) const {
    const float* p = &image.pixels[4 * static_cast<std::size_t>(y * image.width + x)];
    return {p[0], p[1], p[2], p[3]};
  }
  // Mean rgb over rows [y0, y1) and columns [x0, x1), sky pixels only (alpha 0).
  [[nodiscard]] glm::dvec3 meanSky(int x0, int x1, int y0, int y1) const {
    glm::dvec3 sum(0.0);
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x)
        if (at(x, y).a == 0.0f) {
          sum += glm::dvec3(at(x, y));
          ++n;
        }
    return n ? sum / double(n) : sum;
  }
  // Relative error of `other`'s rgb against this image's over the pixels `take(x, y)` selects,
  // each relative to its radiance here or to `floor`, whichever is larger.
  struct Errors {
    double worst = 0.0, mean = 0.0;
    int n = 0;
  };
  template <class Take>
  [[nodiscard]] Errors relativeErrors(const Shot& other, Take&& take, double floor) const {
    Errors e;
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        if (!take(x, y)) continue;
        const glm::vec3 a(at(x, y)), b(other.at(x, y));
        const double r = double(glm::length(b - a)) / std::max(double(glm::length(a)), floor);
        e.worst = std::max(e.worst, r);
        sum += r;
        ++e.n;
      }
    e.mean = e.n ? sum / e.n : 0.0;
    return e;
  }
};

class AtmosphereSky : public test::GlobeSuite {
 protected:
  static Shot shoot(double lat, double lon, double h, double heading, double pitch, double fov,
                    double sunElevation, double sunAzimuth, int w = 64, int ht = 48) {
    renderer_->render(test::frameOf({lat, lon, h, heading, pitch, fov, w, ht}, sunElevation, sunAzimuth));
    return {renderer_->radiance()};
  }
};
}  // namespace

TEST_F(AtmosphereSky, HighSunSkyFromSeaLevelIsBlue) {
  // Sun 60° high in the south; looking north, 50° up.
  const Shot s = shoot(0, -140, 2.0, 0, 50, 60, 60, 180);
  const glm::dvec3 sky = s.meanSky(0, 64, 0, 48);
  EXPECT_GT(sky.b, sky.g);
  EXPECT_GT(sky.b, 1.3 * sky.r);
  EXPECT_GT(sky.b, 0.01);  // daylight, not night
}

TEST_F(AtmosphereSky, SunsetIsRedNearTheSunAndDarkerOpposite) {
  // The Sun on the horizon in the west; a band just above the horizon around it.
  const Shot west = shoot(0, -140, 2.0, 270, 5, 30, 0.0, 270);
  const Shot east = shoot(0, -140, 2.0, 90, 5, 30, 0.0, 270);
  // The horizon sits ~5° below the centre: rows 24..31 of 48 are the lowest sky.
  const glm::dvec3 nearSun = west.meanSky(16, 48, 20, 31);
  const glm::dvec3 opposite = east.meanSky(16, 48, 20, 31);
  EXPECT_GT(nearSun.r, nearSun.g);
  EXPECT_GT(nearSun.r, nearSun.b);
  EXPECT_GT(nearSun.r + nearSun.g + nearSun.b, 2.0 * (opposite.r + opposite.g + opposite.b));
}

TEST_F(AtmosphereSky, SkyAtLowResolutionBelowTheCeilingMatchesThePerPixelSky) {
  // Below 20 km the sky is drawn one texel per 0.3° of view and read per pixel, bilinearly
  // (GlobeRenderer::drawSkyLow): into a sunset from 2 m and from 15 km (the sky's fastest
  // change: the horizon's reddening beside the Sun) and a high Sun from 100 m, narrow views so
  // that 160 x 90 pixels are three times finer than the texels, against the sky per pixel.
  struct View { double h, pitch, sunElevation; };
  for (const View v : {View{2.0, 3.0, 2.0}, View{15000.0, 0.0, 10.0}, View{100.0, 20.0, 50.0}}) {
    renderer_->setSkyLow(false);
    const Shot reference = shoot(20, -40, v.h, 270, v.pitch, 8, v.sunElevation, 270, 160, 90);
    EXPECT_EQ(renderer_->lastSkyLowFactor(), 1);
    renderer_->setSkyLow(true);
    const Shot low = shoot(20, -40, v.h, 270, v.pitch, 8, v.sunElevation, 270, 160, 90);
    EXPECT_GE(renderer_->lastSkyLowFactor(), 3) << "the low-resolution sky is in use";
    const auto [worst, mean, n] = reference.relativeErrors(
        low, [&](int x, int y) { return reference.at(x, y).a == 0.0f && low.at(x, y).a == 0.0f; },  // sky pixels only
        1e-6);
    ASSERT_GT(n, 160 * 20) << "sky in view at " << v.h << " m";
    // Measured (3 x 3 pixels a texel, 0.27°, as at 1280 x 720): worst 1.6 %, 4.4 % (15 km: the
    // horizon's kink, where the texels below it hold the horizon's sky, a band of 2-3 pixels),
    // 0.33 %; mean 0.07 %, 0.19 %, 0.05 %. Reading the texels one pixel off gives means of
    // 0.26-2.1 %.
    EXPECT_LT(worst, 0.06) << "at " << v.h << " m";
    EXPECT_LT(mean, 0.0025) << "at " << v.h << " m";
  }
  renderer_->setSkyLow(true);
}

TEST_F(AtmosphereSky, LowResolutionSkyOnlyOverTheSkysBoxKeepsThePicture) {
  // Below 20 km the low-resolution sky is drawn only over the texels the sky's pixels read: the
  // box of the rays that miss the ellipsoid (render::rayScissors), two texels more each side
  // for the bilinear lookups; the sky's part draws over that box too. Against both over the
  // whole frame (setEllipsoidScissor(false)), with the horizon low, in the middle and high in
  // narrow views (the texels 3 pixels or more a side), after a frame of another sky left its
  // texels; bit-identical. Mutated, the texels' box starting 5 texels higher fails it.
  for (const double pitch : {3.0, 1.0, -2.0}) {
    renderer_->setEllipsoidScissor(false);
    const Shot reference = shoot(20, -40, 2.0, 270, pitch, 8, 10.0, 250, 160, 90);
    renderer_->setEllipsoidScissor(true);
    (void)shoot(20, -40, 2.0, 90, 8.0, 8, 60.0, 250, 160, 90);  // other texels left in the texture
    const Shot boxed = shoot(20, -40, 2.0, 270, pitch, 8, 10.0, 250, 160, 90);
    EXPECT_GE(renderer_->lastSkyLowFactor(), 3) << "the low-resolution sky is in use";
    double differs = 0.0;
    int sky = 0;
    for (int y = 0; y < 90; ++y)
      for (int x = 0; x < 160; ++x) {
        differs = std::max(differs, double(glm::length(glm::vec4(reference.at(x, y)) - glm::vec4(boxed.at(x, y)))));
        sky += reference.at(x, y).a == 0.0f ? 1 : 0;
      }
    EXPECT_EQ(differs, 0.0) << "pitch " << pitch;
    EXPECT_GT(sky, 160 * 10) << "pitch " << pitch;
    EXPECT_LT(sky, 160 * 85) << "pitch " << pitch;  // (the horizon in view)
  }
}

TEST_F(AtmosphereSky, SunDiscDrawnOverItsBoxKeepsThePicture) {
  // Below 20 km the low-resolution sky's part leaves the Sun's disc out and draws it again only
  // over the box around it (GlobeRenderer::drawSunDisc, render::sunDiscScissor): llvmpipe ran
  // the disc's rays for every sky pixel. Against the disc drawn over the whole sky: the Sun in
  // the middle of a narrow view, at its right edge (the box clamped to the screen), half out of
  // it, and behind the eye; bit-identical.
  struct View { double heading, pitch; };
  // (The view is 8° tall, 14.2° wide: the Sun 6.8° and 7.1° right of its centre at the edge.)
  for (const View v : {View{270.0, 3.0}, View{263.2, 3.0}, View{262.9, 3.0}, View{90.0, 3.0}}) {
    renderer_->setSunDiscBox(false);
    const Shot reference = shoot(20, -40, 2.0, v.heading, v.pitch, 8, 3.0, 270, 160, 90);
    renderer_->setSunDiscBox(true);
    const Shot boxed = shoot(20, -40, 2.0, v.heading, v.pitch, 8, 3.0, 270, 160, 90);
    EXPECT_GE(renderer_->lastSkyLowFactor(), 3) << "the low-resolution sky is in use";
    double differs = 0.0, brightest = 0.0;
    for (int y = 0; y < 90; ++y)
      for (int x = 0; x < 160; ++x) {
        differs = std::max(differs, double(glm::length(glm::vec3(reference.at(x, y)) - glm::vec3(boxed.at(x, y)))));
        brightest = std::max(brightest, double(reference.at(x, y).r));
      }
    EXPECT_EQ(differs, 0.0) << "heading " << v.heading;
    // The disc is there when in view (its radiance is hundreds of times the sky's).
    if (v.heading > 180.0) EXPECT_GT(brightest, 1.0) << "heading " << v.heading;
    else EXPECT_LT(brightest, 1.0);
  }
  // The box: the disc plus a pixel's angle, widened by half, and two pixels; empty behind.
  geo::CameraPose pose;
  pose.position = {20.0, -40.0, 2.0};
  pose.headingDeg = 270.0;
  pose.verticalFovDeg = 8.0;
  const geo::CameraView view = geo::makeCameraView(pose, 160, 90);
  const auto box = render::sunDiscScissor(view, 160, 90, view.forward, 0.004675);
  ASSERT_TRUE(box.has_value());
  EXPECT_GT((*box)[2], 4);
  EXPECT_LT((*box)[2], 24);  // a cone 1.2° wide in a view 8° tall: 13 pixels and the margins
  EXPECT_EQ((*render::sunDiscScissor(view, 160, 90, -view.forward, 0.004675))[2], 0);
  // Half out of the view, the box reaches its edge (clamped there).
  pose.headingDeg = 262.9;
  pose.pitchDeg = 3.0;
  const geo::CameraView edge = geo::makeCameraView(pose, 160, 90);
  const auto clamped = render::sunDiscScissor(edge, 160, 90, geo::sunDirectionFromHorizontal(pose.position, 3.0, 270.0), 0.004675);
  ASSERT_TRUE(clamped.has_value());
  EXPECT_EQ((*clamped)[0] + (*clamped)[2], 160);
  EXPECT_GT((*clamped)[2], 2);
}

TEST_F(AtmosphereSky, AerialTableMatchesThePerPixelAerialPerspective) {
  // From 20 km to 500 km up the globe reads the aerial perspective to sea level from a table of
  // path length and angle to the Sun made per frame (GlobeRenderer::drawAerialTable): the limb
  // from 400 km, the flythrough's descent at 149 km towards a Sun 7° up, 480 km straight down
  // over the terminator (the Sun 2° up at the nadir), 25 km looking at the horizon, against the
  // atmosphere's tables per pixel. Relative error of the surface pixels' radiance.
  struct View { double lat, lon, h, heading, pitch, fov, sunElevation, sunAzimuth; };
  for (const View v : {View{20, -40, 4.0e5, 90, -15, 40, 30, 250}, View{37.8, -13.4, 1.49e5, 70, -20, 50, 7, 80},
                       View{30, -20, 4.8e5, 0, -90, 60, 2, 90}, View{38, -12, 2.5e4, 74, -3, 50, 7, 80}}) {
    renderer_->setAerialTable(false);
    const Shot reference = shoot(v.lat, v.lon, v.h, v.heading, v.pitch, v.fov, v.sunElevation, v.sunAzimuth, 192, 108);
    renderer_->setAerialTable(true);
    const Shot table = shoot(v.lat, v.lon, v.h, v.heading, v.pitch, v.fov, v.sunElevation, v.sunAzimuth, 192, 108);
    // Errors relative to the pixel's radiance, or to 1 % of the picture's brightest where the
    // pixel is darker (the night side's nearly black pixels).
    double brightest = 0.0;
    for (int y = 0; y < 108; ++y)
      for (int x = 0; x < 192; ++x) brightest = std::max(brightest, double(glm::length(glm::vec3(reference.at(x, y)))));
    const auto [worst, mean, n] = reference.relativeErrors(
        table, [&](int x, int y) { return reference.at(x, y).a != 0.0f; }, 0.01 * brightest);  // the surface (alpha 1)
    ASSERT_GT(n, 192 * 20) << "surface in view at " << v.h << " m";
    // Measured: worst 0.025 %, 0.052 %, 1.7 % (the terminator), 0.0002 %; mean 0.006 %, 0.006 %,
    // 0.02 %, 0. (From 950 km the terminator's worst is 4.7 %, from 20 000 km the limb's 26 %:
    // per pixel there.)
    EXPECT_GT(worst, 0.0) << "at " << v.h << " m: the table unused";
    EXPECT_LT(worst, 0.04) << "at " << v.h << " m";
    EXPECT_LT(mean, 0.001) << "at " << v.h << " m";
  }
  renderer_->setAerialTable(true);
}

TEST_F(AtmosphereSky, SunTwentyDegreesBelowHorizonIsDark) {
  const Shot s = shoot(0, -140, 2.0, 270, 20, 90, -20.0, 270);
  double maxValue = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < s.image.pixels.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      maxValue = std::max(maxValue, double(s.image.pixels[i + c]));
      sum += double(s.image.pixels[i + c]);
    }
  // Even at exposure 10 these stay within the lowest few 8-bit levels.
  EXPECT_LT(maxValue, 2e-3);
  EXPECT_LT(sum / double(s.image.pixels.size() * 3 / 4), 5e-4);
  // Daylight for comparison is > 0.01 (HighSunSkyFromSeaLevelIsBlue).
}

TEST_F(AtmosphereSky, LimbFrom400kmIsAThinBrightBandBelowBlackSpace) {
  // Horizon dip at 400 km: acos(R / (R + h)) ~ 19.8°. Look at the lit limb towards the Sun.
  const Shot s = shoot(20, -40, 4.0e5, 250, -19.6, 8, 20, 250, 48, 64);
  const int x = 24;
  int firstGlobe = -1;
  for (int y = 0; y < 64 && firstGlobe < 0; ++y)
    if (s.at(x, y).a > 0.5f) firstGlobe = y;
  ASSERT_GT(firstGlobe, 8) << "the limb should be in the lower part of the view";
  auto lum = [&](int y) {
    const glm::dvec4 p(s.at(x, y));
    return 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
  };
  double band = 0.0;
  for (int y = 0; y < firstGlobe; ++y) band = std::max(band, lum(y));
  EXPECT_GT(band, 0.01) << "a bright atmosphere band above the limb";
  int bright = 0;
  for (int y = 0; y < firstGlobe; ++y) bright += lum(y) > 0.1 * band ? 1 : 0;
  EXPECT_LE(bright, 12) << "the band is thin (about 1° of the 8° view)";
  EXPECT_GE(bright, 1);
  for (int y = 0; y < 4; ++y) EXPECT_LT(lum(y), 1e-4) << "black space above, row " << y;
}
