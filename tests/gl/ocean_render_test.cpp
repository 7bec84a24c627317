// GL tier: the projected-grid ocean on its own (no atmosphere), checked for precision at planet
// scale and for temporal stability against the classic model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "geo/Sun.hpp"
#include "geo/Wgs84.hpp"
#include "gl/Context.hpp"
#include "gl/Readback.hpp"
#include "render/OceanRenderer.hpp"
#include "support/ImageCompare.hpp"

using namespace og;

namespace {

struct OceanShot {
  geo::CameraPose pose;
  int width = 160, height = 90;
  double timeS = 10.0;
  double sunElevationDeg = 12.0, sunAzimuthDeg = 265.0;
  render::OceanModel model = render::OceanModel::Bruneton;
};

class OceanFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = gl::createHeadlessContext();
    ocean_ = std::make_unique<render::OceanRenderer>();
    wind_ = std::make_unique<render::WindTextures>();
    ocean::WavePatternParams p;
    p.referenceWindMs = 8.0;
    patterns_ = std::make_unique<render::OceanPatterns>(
        std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p)));
    wind_->setConstantWind(og::geo::Wind::blowingTowards(8.0, 250.0));
  }

  // Linear radiance, RGBA, top row first.
  std::vector<float> render(const OceanShot& s, const ocean::OceanFrame& frame) {
    const geo::CameraView view = geo::makeCameraView(s.pose, s.width, s.height);
    render::OceanLighting light;
    light.sunDirectionEcef =
        geo::sunDirectionFromHorizontal(s.pose.position, s.sunElevationDeg, s.sunAzimuthDeg);
    gl::RenderTarget target = gl::createRenderTarget(s.width, s.height, GL_RGBA32F, true);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
    glViewport(0, 0, s.width, s.height);
    const float zero = 0.0f, clear[] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(target.fbo.id(), GL_COLOR, 0, clear);
    glClearNamedFramebufferfv(target.fbo.id(), GL_DEPTH, 0, &zero);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    patterns_->update(s.timeS);
    ocean_->draw(view, s.width, s.height, *patterns_, frame, s.timeS, light, 1.0, s.model, *wind_);
    return gl::readRgbaF(target.fbo.id(), s.width, s.height);
  }

  static double meanAbsDiff(const std::vector<float>& a, const std::vector<float>& b, int width,
                            int rowBegin, int rowEnd) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = rowBegin; y < rowEnd; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c) {
          const auto i = static_cast<std::size_t>(4 * (y * width + x) + c);
          sum += std::abs(double(a[i]) - double(b[i]));
          ++n;
        }
    return sum / double(n);
  }

  std::unique_ptr<gl::Context> ctx_;
  std::unique_ptr<render::OceanRenderer> ocean_;
  std::unique_ptr<render::WindTextures> wind_;
  std::unique_ptr<render::OceanPatterns> patterns_;
};

}  // namespace

// Moving the camera by 1 mm at 1 m above the sea, far from the frame's first origin and near the
// antimeridian, must not move the waves: the picture changes by at most what 1 mm of parallax
// explains (tiny), never by a jump of the wave pattern.
TEST_F(OceanFixture, MillimetreMovesDoNotJitterAnywhereOnEarth) {
  for (const geo::Geodetic where : {geo::Geodetic{60.0, 179.9999, 1.0}, geo::Geodetic{-35.0, 20.0, 1.0},
                                    geo::Geodetic{0.0, -140.0, 1.0}}) {
    OceanShot s;
    s.pose.position = where;
    s.pose.headingDeg = 250;
    s.pose.pitchDeg = -20;
    ocean::OceanFrame frame;
    // Start the frame 5 km away and fly to the spot, as a recording would: offsets are large.
    geo::Geodetic start = where;
    start.latitudeDeg -= 0.045;
    frame.reset(start);
    for (int i = 1; i <= 50; ++i) {
      geo::Geodetic p = start;
      p.latitudeDeg += 0.045 * i / 50.0;
      frame.moveTo(p);
    }
    const std::vector<float> a = render(s, frame);
    s.pose.position.longitudeDeg += 1e-3 / (111320.0 * std::cos(where.latitudeDeg * M_PI / 180.0));
    frame.moveTo(s.pose.position);
    const std::vector<float> b = render(s, frame);
    double mean = 0.0, meanLevel = 0.0;
    mean = meanAbsDiff(a, b, s.width, 0, s.height);
    for (std::size_t i = 0; i < a.size(); i += 4) meanLevel += double(a[i]) + double(a[i + 1]) + double(a[i + 2]);
    meanLevel /= double(a.size() / 4 * 3);
    EXPECT_LT(mean, 0.02 * meanLevel) << "at " << where.latitudeDeg << ", " << where.longitudeDeg;
  }
}

// Issue 4: in a 30 fps sequence looking at the horizon, the far field of the filtered model
// flickers far less than the classic model. Flicker = mean absolute frame-to-frame difference
// in the band just below the horizon, relative to the band's mean radiance.
TEST_F(OceanFixture, FarFieldFlickersFarLessThanClassic) {
  double flicker[2] = {0, 0};
  const render::OceanModel models[2] = {render::OceanModel::Bruneton, render::OceanModel::Classic};
  for (int m = 0; m < 2; ++m) {
    OceanShot s;
    s.pose.position = {20.0, -40.0, 10.0};
    s.pose.headingDeg = 270;  // into a low Sun: the glitter path crosses the far band
    s.pose.pitchDeg = 0;
    s.pose.verticalFovDeg = 30;
    s.sunAzimuthDeg = 270;
    s.sunElevationDeg = 10;
    s.width = 192;
    s.height = 108;
    s.model = models[m];
    ocean::OceanFrame frame;
    frame.reset(s.pose.position);
    // Far band: from just below the horizon (row ~54 + dip) down 12 rows.
    const int top = s.height / 2 + 1, bottom = top + 12;
    std::vector<float> previous;
    double diff = 0.0, level = 0.0;
    for (int f = 0; f < 8; ++f) {
      s.timeS = 10.0 + f / 30.0;
      const std::vector<float> img = render(s, frame);
      for (int y = top; y < bottom; ++y)
        for (int x = 0; x < s.width; ++x) level += double(img[static_cast<std::size_t>(4 * (y * s.width + x) + 2)]);
      if (!previous.empty()) diff += meanAbsDiff(img, previous, s.width, top, bottom);
      previous = img;
    }
    level /= 8.0 * 12.0 * s.width;
    flicker[m] = diff / 7.0 / level;
  }
  std::printf("far-band flicker: bruneton %.5f, classic %.5f\n", flicker[0], flicker[1]);
  RecordProperty("flicker_bruneton", std::to_string(flicker[0]));
  RecordProperty("flicker_classic", std::to_string(flicker[1]));
  EXPECT_LT(flicker[0], 0.35 * flicker[1]) << "bruneton " << flicker[0] << " classic " << flicker[1];
}

// The sky maps' frame layer is read where the sea in view lies within 1° of the camera's nadir
// (OceanRenderer::kFrameSkyMaxAngleRad): from a few metres (the horizon), looking down from
// 8 km (the screen's top edge meets the sea ~75 km away), not from 1 km with the horizon in view.
TEST(OceanFrameSky, FarthestSeaAngleFollowsTheHorizonAndTheTopOfTheScreen) {
  constexpr double kDegPerRad = 180.0 / std::numbers::pi;
  auto angleDeg = [](double heightM, double pitchDeg) {
    geo::CameraPose pose;
    pose.position = {20.0, -40.0, heightM};
    pose.headingDeg = 270.0;
    pose.pitchDeg = pitchDeg;
    return render::OceanRenderer::farthestSeaAngleRad(geo::makeCameraView(pose, 1280, 720)) * kDegPerRad;
  };
  const double a = geo::kWgs84SemiMajorM;
  EXPECT_NEAR(angleDeg(4.0, -10.0), std::acos(a / (a + 4.0)) * kDegPerRad, 1e-4);  // the horizon
  // 8 km, 30° down, 45° tall 16:9 screen: the top corners' rays 6.6° below the horizontal.
  EXPECT_NEAR(angleDeg(8000.0, -30.0), 0.70, 0.01);
  EXPECT_NEAR(angleDeg(1000.0, -20.0), std::acos(a / (a + 1000.0)) * kDegPerRad, 1e-4);
  const double limitDeg = render::OceanRenderer::kFrameSkyMaxAngleRad * kDegPerRad;
  EXPECT_LT(angleDeg(8000.0, -30.0), limitDeg);
  EXPECT_GT(angleDeg(1000.0, -20.0), limitDeg);  // 1.01°
}
