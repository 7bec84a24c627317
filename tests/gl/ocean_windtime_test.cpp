// Wind layers that follow the clock on the GPU: the wind texture is uploaded only when the
// layers' steps or quantised weights change, and the frame's UTC time drives the sea's wind.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "data/Elevation.hpp"
#include "data/WindLayers.hpp"
#include "gl/Context.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/DataFixtures.hpp"

namespace fs = std::filesystem;
using namespace og;

namespace {

/// A global layer blowing east at 3 m/s at 00:00 UTC and 20 m/s at 06:00 UTC, in a file of the
/// running test's own (CTest runs this file's tests in parallel).
fs::path writeTwoSteps() {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path file = test::fixtureDir("ocean_windtime") / (test + "_two.nc");
  test::TimedWind wind;
  wind.times = {0.0, 6.0};
  wind.units = "hours since 2024-06-20 00:00:00";
  wind.eastMs = {3.0, 20.0};
  test::writeTimedWind(file, wind);
  return file;
}

double mean(const std::vector<float>& v) {
  double s = 0.0;
  for (float x : v) s += static_cast<double>(x);
  return s / static_cast<double>(v.size());
}

}  // namespace

TEST(OceanWindTime, TextureFollowsTheFrameTimeAndUploadsOnlyOnAChange) {
  auto ctx = gl::createHeadlessContext();
  const UtcTime start = *UtcTime::parseIso8601("2024-06-20T00:00:00Z");
  auto layers = std::make_shared<const data::WindLayers>(
      data::WindLayers::load({writeTwoSteps().string()}, data::WindVector{}, start));
  render::GlobeRenderer renderer(data::defaultElevation());
  renderer.setWindLayers(layers);
  EXPECT_EQ(renderer.wind().uploads(), 1);
  EXPECT_NEAR(renderer.wind().maxLayerSpeedMs(), 20.0, 1e-4);  // every step: no wave rebuilds

  render::FrameInput f;
  f.camera.position = {5.0, 150.0, 200.0};
  f.camera.pitchDeg = -90;
  f.width = f.height = 48;
  f.samples = 1;
  f.auxiliaryOutputs = true;
  const auto coverageAt = [&](double hours) {
    f.utcTime = UtcTime{start.unixSeconds + hours * 3600.0};
    f.simulationTimeS = hours;  // the waves' clock barely moves
    renderer.render(f);
    return mean(renderer.whitecap());
  };
  const double calm = coverageAt(0.0);
  EXPECT_EQ(renderer.wind().uploads(), 1);  // the load time: nothing to upload
  // 30 frames of a 30 fps recording in real time: one rounded weight (6 h / 100 = 216 s).
  for (int i = 1; i <= 30; ++i) (void)coverageAt(i / 30.0 / 3600.0);
  EXPECT_EQ(renderer.wind().uploads(), 1);
  const double storm = coverageAt(6.0);
  EXPECT_EQ(renderer.wind().uploads(), 2);
  (void)coverageAt(6.0 + 1.0 / 3600.0);  // clamped after the last step: the same winds
  EXPECT_EQ(renderer.wind().uploads(), 2);
  const double half = coverageAt(3.0);
  EXPECT_EQ(renderer.wind().uploads(), 3);
  std::printf("whitecap coverage at 3, 11.5 and 20 m/s: %.4f %.4f %.4f\n", calm, half, storm);
  EXPECT_LT(calm, 0.002);
  EXPECT_GT(storm, 0.02);
  EXPECT_GT(half, calm);
  EXPECT_LT(half, storm);
}

TEST(OceanWindTime, EveryChangeOfTheRoundedWeightUploadsOnce) {
  auto ctx = gl::createHeadlessContext();
  const UtcTime start = *UtcTime::parseIso8601("2024-06-20T00:00:00Z");
  auto layers = std::make_shared<const data::WindLayers>(
      data::WindLayers::load({writeTwoSteps().string()}, data::WindVector{}, start));
  render::WindTextures wind;
  wind.setLayers(layers);
  // A 6-hour lapse in 20 s at 30 fps: 600 frames, 36 s of UTC each, over one pair of 6-hourly
  // steps: the texture changes once per 216 s of UTC (every 6th frame), 100 times in all.
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 1; i <= 600; ++i) wind.setTime(UtcTime{start.unixSeconds + i * 36.0});
  glFinish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(wind.uploads(), 1 + 100);
  std::printf("600 frames of a 6 h time lapse: %d uploads of the 720x360 wind texture, %.1f ms per frame\n",
              wind.uploads() - 1, 1000.0 * seconds / 600.0);
  wind.setTime(std::nullopt);  // no time: the winds stay
  EXPECT_EQ(wind.uploads(), 101);
}
