// Unit tier: the viewer's CPU side: camera controls over seven orders of magnitude of height,
// the pose a second ahead that imagery is prefetched for, the bitmap font, and keyframe files
// that `record` accepts.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "app/viewer/BitmapFont.hpp"
#include "app/viewer/FlightController.hpp"
#include "app/viewer/KeyframeLog.hpp"
#include "core/Error.hpp"
#include "geo/FlightPath.hpp"
#include "geo/Sun.hpp"
#include "geo/Wgs84.hpp"
#include "io/CameraPath.hpp"
#include "io/KmlTour.hpp"

namespace fs = std::filesystem;
using namespace og;
using namespace og::app::viewer;

namespace {

geo::CameraPose poseAt(double lat, double lon, double h, double heading = 0, double pitch = -90,
                       double roll = 0) {
  geo::CameraPose p;
  p.position = {lat, lon, h};
  p.headingDeg = heading;
  p.pitchDeg = pitch;
  p.rollDeg = roll;
  return p;
}

void expectSameView(const geo::CameraPose& a, const geo::CameraPose& b) {
  const geo::CameraView va = geo::makeCameraView(a, 4, 3), vb = geo::makeCameraView(b, 4, 3);
  EXPECT_LT(glm::length(va.forward - vb.forward), 1e-9);
  EXPECT_LT(glm::length(va.up - vb.up), 1e-9);
  EXPECT_LT(glm::length(va.positionEcef - vb.positionEcef), 1e-6);
}

// The viewer's scene as K saves it: a 320x180 window on 2024-06-20 15:00 UTC.
io::SceneSettings viewerScene() {
  io::SceneSettings scene;
  scene.width = 320;
  scene.height = 180;
  scene.time = UtcTime::fromCivil(2024, 6, 20, 15);
  return scene;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(OG_TEST_OUT_DIR) / "viewer";
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

}  // namespace

TEST(ViewerPose, OrientationRoundTripsEverywhere) {
  for (double lat : {-90.0, -45.0, 0.0, 36.5, 89.9, 90.0})
    for (double heading : {0.0, 45.0, 181.0, 359.0})
      for (double pitch : {-90.0, -89.0, -20.0, 0.0, 30.0, 90.0})
        for (double roll : {-170.0, 0.0, 25.0}) {
          const geo::CameraPose p = poseAt(lat, 12.0, 1000.0, heading, pitch, roll);
          const geo::CameraView v = geo::makeCameraView(p, 4, 3);
          const geo::CameraPose back = poseFromOrientation(p.position, v.forward, v.up, p.verticalFovDeg);
          ASSERT_FALSE(geo::validatePose(back).has_value());
          expectSameView(p, back);
        }
}

TEST(ViewerController, SpeedIsProportionalToHeightFromOrbitToSeaLevel) {
  for (double h : {1.0, 10.0, 1e3, 1e5, 1e7}) {
    FlightController c(poseAt(10, -30, h, 0, 0));
    EXPECT_NEAR(c.speedMs(), kSpeedPerHeight * h, 1e-6 * h);
    MoveInput in;
    in.forward = 1.0;
    const glm::dvec3 before = geo::geodeticToEcef(c.pose().position);
    c.update(in, 0.1);
    const double moved = glm::length(geo::geodeticToEcef(c.pose().position) - before);
    EXPECT_NEAR(moved, 0.1 * kSpeedPerHeight * h, 0.02 * h) << "at " << h << " m";
  }
}

TEST(ViewerController, DescendsFromOrbitToTheSeaButNeverBelowIt) {
  FlightController c(poseAt(20, -40, 2.0e7));  // looking straight down
  MoveInput in;
  in.forward = 1.0;
  in.speedFactor = 5.0;
  for (int i = 0; i < 400; ++i) {
    c.update(in, 0.25);  // slow frames, 5x speed: the largest steps there are
    ASSERT_GE(c.pose().position.heightM, kMinClearanceM - 1e-9);
  }
  EXPECT_NEAR(c.pose().position.heightM, kMinClearanceM, 1e-6);
  EXPECT_NEAR(c.pose().position.latitudeDeg, 20.0, 1e-6);
  MoveInput down;
  down.up = -1.0;
  c.update(down, 10.0);
  EXPECT_GE(c.pose().position.heightM, kMinClearanceM - 1e-9);
  MoveInput up;
  up.up = 1.0;
  c.update(up, 0.2);
  EXPECT_NEAR(c.heightAboveSurfaceM(), kMinClearanceM * std::exp(0.2), 1e-9);
}

TEST(ViewerController, StaysAboveLandAndOutOfThePlanet) {
  FlightController c(poseAt(0, 0, 100.0, 0, -30), [](double, double) { return 2000.0; });
  EXPECT_NEAR(c.pose().position.heightM, 2000.0 + kMinClearanceM, 1e-9);  // lifted at once
  c.setPose(poseAt(0, 0, -5000.0));
  EXPECT_NEAR(c.heightAboveSurfaceM(), kMinClearanceM, 1e-9);
  // Straight at the Earth's centre from 100 km: never through to the other side.
  FlightController d(poseAt(0, 0, 1e5));
  d.moveAlong(-geo::ellipsoidNormalAt(geo::geodeticToEcef({0, 0, 0})), 2.0e7);
  EXPECT_NEAR(d.pose().position.longitudeDeg, 0.0, 1e-6);
  EXPECT_GE(d.pose().position.heightM, kMinClearanceM - 1e-9);
}

TEST(ViewerController, LevelFlightFollowsTheCurvature) {
  FlightController c(poseAt(0, 0, 1000.0, 90.0, 0.0));
  MoveInput in;
  in.forward = 1.0;
  for (int i = 0; i < 100; ++i) c.update(in, 0.1);  // 10 s east at 1 km/s
  EXPECT_GT(c.pose().position.longitudeDeg, 0.08);
  EXPECT_NEAR(c.pose().position.heightM, 1000.0, 1.0);
  EXPECT_NEAR(c.pose().headingDeg, 90.0, 1e-9);
}

TEST(ViewerController, ScrollKeepsTheTargetUnderTheSamePixel) {
  FlightController c(poseAt(36, -9, 1e5, 30, -40, 5));
  const auto target = c.pick(0.3, -0.2, 320, 180);
  ASSERT_TRUE(target.has_value());
  const double before = glm::length(geo::geodeticToEcef(c.pose().position) - *target);
  c.moveToward(*target, 0.8);
  const double after = glm::length(geo::geodeticToEcef(c.pose().position) - *target);
  EXPECT_NEAR(after, 0.8 * before, 1e-6 * before);
  const auto again = c.pick(0.3, -0.2, 320, 180);
  ASSERT_TRUE(again.has_value());
  EXPECT_LT(glm::length(*again - *target), 1e-3 * after);
  // Towards the target over and over ends just above it, never beyond.
  for (int i = 0; i < 200; ++i) c.moveToward(*target, 0.5);
  EXPECT_NEAR(c.heightAboveSurfaceM(), kMinClearanceM, 0.1);
}

TEST(ViewerController, OrbitKeepsDistanceAndStaysAboveThePivotsHorizon) {
  FlightController c(poseAt(36, -9, 5000.0, 0, -45));
  const auto pivot = c.pick(0.0, 0.0, 320, 180);
  ASSERT_TRUE(pivot.has_value());
  const double d0 = glm::length(geo::geodeticToEcef(c.pose().position) - *pivot);
  c.orbit(*pivot, 0.5, 0.0);
  EXPECT_NEAR(glm::length(geo::geodeticToEcef(c.pose().position) - *pivot), d0, 1e-6 * d0);
  const auto still = c.pick(0.0, 0.0, 320, 180);  // still looking at the pivot
  ASSERT_TRUE(still.has_value());
  EXPECT_LT(glm::length(*still - *pivot), 1e-3 * d0);
  EXPECT_NEAR(c.pose().headingDeg, std::fmod(360.0 - 0.5 * 180.0 / std::numbers::pi, 360.0), 0.5);
  for (int i = 0; i < 50; ++i) c.orbit(*pivot, 0.0, 0.1);  // tilt far past the horizon
  EXPECT_GT(c.heightAboveSurfaceM(), 0.02 * d0);
  EXPECT_FALSE(geo::validatePose(c.pose()).has_value());
}

TEST(ViewerController, LookRollAndNorthUp) {
  FlightController c(poseAt(0, 0, 10.0, 350, 0));
  c.look(20.0, -120.0);
  EXPECT_NEAR(c.pose().headingDeg, 10.0, 1e-9);
  EXPECT_DOUBLE_EQ(c.pose().pitchDeg, -90.0);
  MoveInput in;
  in.roll = 1.0;
  c.update(in, 0.25);
  EXPECT_NEAR(c.pose().rollDeg, 0.25 * kRollRateDegS, 1e-9);
  c.resetNorthUp();
  EXPECT_DOUBLE_EQ(c.pose().headingDeg, 0.0);
  EXPECT_DOUBLE_EQ(c.pose().rollDeg, 0.0);
}

TEST(ViewerPrefetch, PoseAheadFollowsTheMotionButStopsAboveTheGround) {
  // Level flight east at 100 m/s from 1 km: a second on, 100 m east, same height and view.
  const geo::CameraPose now = poseAt(45.0, 10.0, 1000.0, 90.0, -20.0);
  const geo::EnuFrame enu = geo::enuFrameAt(45.0, 10.0);
  const geo::CameraPose ahead = poseAhead(now, 100.0 * enu.east, 1.0, 0.0);
  const glm::dvec3 moved = geo::geodeticToEcef(ahead.position) - geo::geodeticToEcef(now.position);
  EXPECT_NEAR(glm::dot(moved, enu.east), 100.0, 0.01);
  EXPECT_NEAR(ahead.position.heightM, 1000.0, 0.01);
  EXPECT_EQ(ahead.headingDeg, now.headingDeg);
  EXPECT_EQ(ahead.pitchDeg, now.pitchDeg);
  // Diving at 2 km/s from 1 km over land 200 m high: no lower than a quarter of the way down.
  const geo::CameraPose dive = poseAhead(now, -2000.0 * enu.up, 1.0, 200.0);
  EXPECT_NEAR(dive.position.heightM, 400.0, 1e-6);
  // At rest: where it is.
  EXPECT_NEAR(poseAhead(now, glm::dvec3(0.0), 1.0, 0.0).position.heightM, 1000.0, 1e-6);
}

TEST(ViewerPrefetch, VelocityEstimateFollowsSteadyMotionAndDampsATap) {
  const glm::dvec3 start(6.4e6, 0.0, 0.0), east(0.0, 1.0, 0.0);
  // Steady 100 m/s with uneven frames (16 and 50 ms): within 1 % after 1.5 s (6 time constants).
  VelocityEstimate steady;
  glm::dvec3 eye = start;
  EXPECT_EQ(steady.update(eye, 0.016), glm::dvec3(0.0));  // first call: at rest
  double t = 0.0;
  for (int i = 0; t < 1.5; ++i) {
    const double dt = i % 2 == 0 ? 0.016 : 0.050;
    eye += 100.0 * dt * east;
    t += dt;
    steady.update(eye, dt);
  }
  EXPECT_NEAR(steady.velocityEcef().y, 100.0, 1.0);
  // One 16 ms frame that moved 10 m (a key tap, 625 m/s raw) then rest: the estimate takes
  // 1 - exp(-0.016 / 0.25) of it, about 39 m/s, not 625, and decays afterwards.
  VelocityEstimate tap;
  tap.update(start, 0.016);
  const double afterTap = tap.update(start + 10.0 * east, 0.016).y;
  EXPECT_NEAR(afterTap, 625.0 * (1.0 - std::exp(-0.016 / VelocityEstimate::kTimeConstantS)), 1e-6);
  EXPECT_LT(tap.update(start + 10.0 * east, 0.25).y, 0.5 * afterTap);
  // A jump across the globe is not motion; a zero time step changes nothing.
  EXPECT_EQ(tap.update(-start, 0.016), glm::dvec3(0.0));
  EXPECT_EQ(tap.update(start, 0.0), glm::dvec3(0.0));
}

TEST(ViewerFont, EveryOverlayCharacterHasAGlyph) {
  for (unsigned char ch : std::string("abcdefghijklmnopqrstuvwxyz0123456789 .,:;/-+()[]%=_<>?!'\""))
    EXPECT_TRUE(hasGlyph(ch)) << ch;
  EXPECT_TRUE(hasGlyph(0xB0));
  EXPECT_FALSE(hasGlyph('{'));
}

TEST(ViewerFont, RasterisesLinesWithInkOutlineAndBackdrop) {
  const io::ImageRgba8 img = rasterizeText({"AB", "1\xC2\xB0"}, 2, 3);
  EXPECT_EQ(img.width, (2 * kCellWidth + 6) * 2);
  EXPECT_EQ(img.height, (2 * kCellHeight + 6) * 2);
  int ink = 0, backdrop = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
    if (img.pixels[i] == 255 && img.pixels[i + 3] == 255) ++ink;
    if (img.pixels[i] == 0 && img.pixels[i + 3] > 0) ++backdrop;
  }
  // 'A' 16 pixels of ink, 'B' 20, '1' 12, '°' 8; each 2x2 at scale 2.
  EXPECT_EQ(ink, (16 + 20 + 12 + 8) * 4);
  EXPECT_EQ(backdrop, img.width * img.height - ink);
}

TEST(ViewerKeyframes, AppendedViewsMakeAPathRecordAccepts) {
  const fs::path file = scratch("flight.toml");
  io::SceneSettings scene = viewerScene();
  scene.windLayers = {"a \"quoted\" name.nc:U,V"};
  const glm::dvec3 sun = geo::sunEphemeris(*scene.time).directionEcef;
  const geo::CameraPose a = poseAt(36.25, -9.125, 4e5, 90, -60, 0);
  const geo::CameraPose b = poseAt(36.5, -8.0, 12.5, 271.5, -3.25, 1.5);
  EXPECT_EQ(appendKeyframe(file, a, scene, sun).count, 1u);
  const AppendedKeyframe second = appendKeyframe(file, b, scene, sun);
  EXPECT_EQ(second.count, 2u);
  EXPECT_GE(second.timeS, 2.0);

  const io::CameraPath path = io::readCameraPath(file);
  ASSERT_EQ(path.keyframes.size(), 2u);
  expectSameView(path.keyframes[0].pose, a);
  EXPECT_EQ(path.keyframes[1].pose.position.heightM, 12.5);  // exact: shortest round-trip digits
  EXPECT_EQ(path.keyframes[1].pose.headingDeg, 271.5);
  EXPECT_DOUBLE_EQ(path.keyframes[1].timeS, second.timeS);
  EXPECT_EQ(path.scene.width, 320);
  ASSERT_EQ(path.scene.windLayers.size(), 1u);
  EXPECT_EQ(path.scene.windLayers[0], scene.windLayers[0]);
  // record shows the viewer's Sun at the last keyframe: time + time_s is the viewer's time.
  ASSERT_TRUE(path.scene.time.has_value());
  EXPECT_NEAR(path.scene.time->unixSeconds + second.timeS, scene.time->unixSeconds, 1.0);
  geo::FlightPath flight(path.keyframes);
  expectSameView(flight.at(flight.endS()), b);
}

TEST(ViewerKeyframes, SunAnglesHoldAtTheLastKeyframeAndBadFilesAreKept) {
  const fs::path file = scratch("angles.json");
  io::SceneSettings scene;
  const geo::CameraPose a = poseAt(0, 0, 1e4);
  const glm::dvec3 sun = geo::sunDirectionFromHorizontal(a.position, 10.0, 250.0);
  appendKeyframe(file, a, scene, sun);
  const geo::CameraPose b = poseAt(5, 5, 100);
  appendKeyframe(file, b, scene, sun);
  const io::CameraPath path = io::readCameraPath(file);
  ASSERT_EQ(path.keyframes.size(), 2u);
  ASSERT_TRUE(path.scene.sunElevationDeg && path.scene.sunAzimuthDeg);
  const glm::dvec3 again =
      geo::sunDirectionFromHorizontal(b.position, *path.scene.sunElevationDeg, *path.scene.sunAzimuthDeg);
  EXPECT_LT(glm::length(again - sun), 1e-9);

  const fs::path bad = scratch("bad.toml");
  std::ofstream(bad) << "[[keyframe]]\nlatitude_deg = 'x'\n";
  EXPECT_THROW(appendKeyframe(bad, a, scene, sun), InputError);
  std::ifstream in(bad);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "[[keyframe]]");  // untouched
}

TEST(ViewerKeyframes, AKmlFileGrowsIntoAGoogleEarthTour) {
  const fs::path file = scratch("flight.kml");
  const io::SceneSettings scene = viewerScene();
  const glm::dvec3 sun = geo::sunEphemeris(*scene.time).directionEcef;
  const geo::CameraPose views[] = {poseAt(36.25, -9.125, 4e5, 90, -60), poseAt(36.4, -8.5, 2e4, 95, -30),
                                   poseAt(36.5, -8.0, 12.5, 271.5, -3.25, 1.5)};
  for (const auto& v : views) appendKeyframe(file, v, scene, sun);

  const io::KmlTour tour = io::readKmlTour(file);
  ASSERT_EQ(tour.keys.size(), 3u);
  // One smooth flight: at rest at the ends only (no stop where each view was appended).
  EXPECT_EQ(tour.keys[0].easing, geo::Easing::EaseIn);
  EXPECT_EQ(tour.keys[1].easing, geo::Easing::EaseOut);
  ASSERT_TRUE(tour.settings);  // the viewer's scene travels inside the tour
  EXPECT_EQ(tour.settings->scene.width, 320);
  ASSERT_TRUE(tour.settings->scene.time);
  EXPECT_NEAR(tour.settings->scene.time->unixSeconds + tour.keys[2].timeS, scene.time->unixSeconds, 1.0);
  const auto keys = io::kmlKeyframes(tour, 320.0 / 180.0, {});
  for (std::size_t k = 0; k < 3; ++k) expectSameView(keys[k].pose, views[k]);
  EXPECT_NEAR(keys[2].pose.verticalFovDeg, views[2].verticalFovDeg, 1e-9);  // via gx:horizFov
}
