// Look-at views, orbits and the smooth (centripetal Catmull-Rom) interpolation of flight paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/Error.hpp"
#include "geo/FlightPath.hpp"
#include "geo/LookAt.hpp"

using namespace og::geo;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Keyframe key(double t, double lat, double lon, double h, double heading = 0, double pitch = -30,
             Easing easing = Easing::Smooth) {
  Keyframe k;
  k.timeS = t;
  k.pose.position = {lat, lon, h};
  k.pose.headingDeg = heading;
  k.pose.pitchDeg = pitch;
  k.easing = easing;
  return k;
}

LookAt view(double lat, double lon, double h, double range, double heading, double tilt) {
  LookAt v;
  v.target = {lat, lon, h};
  v.rangeM = range;
  v.headingDeg = heading;
  v.tiltDeg = tilt;
  return v;
}

glm::dvec3 eye(const FlightPath& path, double t) { return geodeticToEcef(path.at(t).position); }

// Velocity of the eye in ECEF (m/s), second-order one-sided: direction +1 forward, -1 back.
glm::dvec3 velocity(const FlightPath& path, double t, double direction) {
  const double h = 1e-4 * direction;
  return (-3.0 * eye(path, t) + 4.0 * eye(path, t + h) - eye(path, t + 2 * h)) / (2 * h);
}

double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) / kDeg;
}

// A low flight with sharp turns and climbs: 3 km down to 2 m over the sea and up again.
std::vector<Keyframe> lowFlight() {
  return {key(0, 36.00, -9.00, 3000, 60), key(10, 36.05, -8.90, 300, 100),
          key(16, 36.02, -8.85, 20, 150), key(25, 36.06, -8.80, 2, 20),
          key(30, 36.07, -8.82, 150, 300)};
}

}  // namespace

TEST(LookAt, EyeIsAtTheRangeAndLooksAtTheTarget) {
  for (const LookAt& v : {view(45.83, 6.86, 4800, 12000, 200, 65), view(-70, 170, 0, 3e6, 10, 30),
                          view(89.99, 0, 0, 500, 90, 0), view(0, 0, -20, 5, 270, 90)}) {
    const CameraPose pose = cameraFromLookAt(v, 0, 40);
    ASSERT_FALSE(validatePose(pose)) << *validatePose(pose);
    const glm::dvec3 target = geodeticToEcef(v.target), e = geodeticToEcef(pose.position);
    EXPECT_NEAR(glm::length(target - e), v.rangeM, 1e-6 * std::max(1.0, v.rangeM));
    // The camera the renderer builds from the pose looks straight at the target.
    const CameraView cam = makeCameraView(pose, 160, 90);
    EXPECT_LT(angleDeg(cam.forward, target - e), 1e-6);
    // Upright: the image's right vector is level at the target (no roll from the conversion).
    const EnuFrame enu = enuFrameAt(v.target.latitudeDeg, v.target.longitudeDeg);
    if (v.tiltDeg > 0) {
      EXPECT_NEAR(glm::dot(cam.right, enu.up), 0.0, 1e-3 * (1 + v.rangeM / 6.4e6));
    }
  }
  // KML's conventions: tilt 0 looks straight down, 90 level; the heading is the view's.
  const CameraPose down = cameraFromLookAt(view(10, 20, 0, 1000, 30, 0), 0, 40);
  EXPECT_NEAR(down.pitchDeg, -90.0, 1e-6);
  EXPECT_NEAR(down.position.heightM, 1000.0, 1e-6);
  const CameraPose level = cameraFromLookAt(view(10, 20, 0, 1000, 30, 90), 0, 40);
  EXPECT_NEAR(level.pitchDeg, 0.0, 0.01);
  EXPECT_NEAR(level.headingDeg, 30.0, 0.01);
  EXPECT_NEAR(level.position.heightM, 0.0, 0.1);  // 1 km away, the Earth drops 8 cm
  EXPECT_FALSE(validateLookAt(view(10, 20, 0, 1000, 30, 91)) == std::nullopt);
  EXPECT_FALSE(validateLookAt(view(10, 20, 0, -1, 30, 45)) == std::nullopt);
}

TEST(LookAt, PathsBetweenTargetsKeepTheRangeAndCircleTheTarget) {
  // Two views of one summit from 90 degrees apart: the eye swings round it at the range; a
  // camera interpolation would cut the corner (0.71 x the range at the middle).
  const LookAt a = view(45.83, 6.86, 4800, 10000, 0, 60), b = view(45.83, 6.86, 4800, 10000, 90, 60);
  for (Interpolation i : {Interpolation::Geodesic, Interpolation::Smooth}) {
    const FlightPath path({lookAtKeyframe(a, 0, 45, 0), lookAtKeyframe(b, 0, 45, 8)}, i);
    EXPECT_TRUE(path.followsTargets());
    const glm::dvec3 target = geodeticToEcef(a.target);
    for (int s = 0; s <= 16; ++s) {
      const CameraPose p = path.at(0.5 * s);
      EXPECT_NEAR(glm::length(geodeticToEcef(p.position) - target), 10000.0, 1e-3) << s;
      EXPECT_LT(angleDeg(makeCameraView(p, 64, 64).forward, target - geodeticToEcef(p.position)), 1e-5);
    }
  }
  // A camera keyframe among them: the look-at keyframes fly as the cameras they stand for.
  const FlightPath mixed({lookAtKeyframe(a, 0, 45, 0), key(5, 45.9, 6.9, 9000)});
  EXPECT_FALSE(mixed.followsTargets());
  EXPECT_NEAR(mixed.at(0).position.heightM, mixed.keyframes()[0].pose.position.heightM, 1e-9);
}

TEST(LookAt, OrbitTurnsAtAConstantRateAtAConstantRange) {
  Orbit orbit;
  orbit.start = view(-13.16, -72.54, 2430, 3000, 45, 70);  // Machu Picchu
  orbit.degrees = -360;
  orbit.durationS = 24;
  const std::vector<Keyframe> keys = orbitKeyframes(orbit);
  EXPECT_EQ(keys.size(), 13u);  // every 30 degrees
  const FlightPath path(keys, Interpolation::Smooth);
  const glm::dvec3 target = geodeticToEcef(orbit.start.target);
  const EnuFrame enu = enuFrameAt(orbit.start.target.latitudeDeg, orbit.start.target.longitudeDeg);
  double previous = 0;
  for (int s = 0; s <= 96; ++s) {
    const double t = 24.0 * s / 96;
    const glm::dvec3 e = geodeticToEcef(path.at(t).position);
    EXPECT_NEAR(glm::length(e - target), 3000.0, 1e-4);
    // The eye's bearing from the target turns by -360° / 24 s: -3.75° per sample.
    const glm::dvec3 d = enu.toEnu(e - target);
    const double bearing = std::atan2(d.x, d.y) / kDeg;
    if (s > 0) {
      EXPECT_NEAR(std::remainder(bearing - previous, 360.0), -3.75, 1e-6) << t;
    }
    previous = bearing;
  }
  orbit.easing = Easing::EaseInOut;
  const FlightPath eased(orbitKeyframes(orbit));
  EXPECT_LT(glm::length(eye(eased, 1e-3) - eye(eased, 0)), 1e-3);  // starts from rest
  EXPECT_THROW(orbitKeyframes(Orbit{orbit.start, 0.0, 10}), og::InputError);
}

TEST(SmoothPath, DirectionIsContinuousThroughKeyframes) {
  const FlightPath path(lowFlight(), Interpolation::Smooth);
  for (std::size_t k = 1; k + 1 < path.keyframes().size(); ++k) {
    const double t = path.keyframes()[k].timeS;
    const glm::dvec3 in = velocity(path, t, -1), out = velocity(path, t, +1);
    EXPECT_LT(angleDeg(in, out), 0.05) << "keyframe " << k;
    EXPECT_NEAR(glm::length(in), glm::length(out), 1e-3 * glm::length(in)) << "keyframe " << k;
    EXPECT_GT(glm::length(in), 0.1) << "the camera does not stop at keyframe " << k;
    // Through the keyframe itself.
    EXPECT_LT(glm::length(eye(path, t) - geodeticToEcef(path.keyframes()[k].pose.position)), 1e-6);
  }
}

TEST(SmoothPath, NeverDipsBelowTheLowerKeyframe) {
  const FlightPath path(lowFlight(), Interpolation::Smooth);
  const auto& keys = path.keyframes();
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    const double low = std::min(keys[k].pose.position.heightM, keys[k + 1].pose.position.heightM);
    for (int s = 0; s <= 400; ++s) {
      const double t = keys[k].timeS + (keys[k + 1].timeS - keys[k].timeS) * s / 400;
      ASSERT_GE(path.at(t).position.heightM, low - 1e-9) << "t = " << t;
    }
  }
  // Heights are interpolated in log space: halfway from 400 km to 2 m is the geometric mean.
  const FlightPath descent({key(0, 36, -9, 4.0e5), key(20, 36.5, -8, 2.0)}, Interpolation::Smooth);
  EXPECT_NEAR(descent.at(10).position.heightM + 1.0, std::sqrt(400001.0 * 3.0), 1e-6);
}

TEST(SmoothPath, HoldsStillBetweenTwoKeyframesAtOnePlace) {
  std::vector<Keyframe> keys = {key(0, 36, -9, 500, 0), key(5, 36.02, -9, 100, 0),
                                key(8, 36.02, -9, 100, 90), key(12, 36.04, -8.98, 50, 90)};
  const FlightPath path(keys, Interpolation::Smooth);
  const glm::dvec3 hold = geodeticToEcef(keys[1].pose.position);
  for (double t : {5.0, 6.0, 7.0, 8.0}) EXPECT_LT(glm::length(eye(path, t) - hold), 1e-6) << t;
  EXPECT_NEAR(path.at(6.5).headingDeg, 45.0, 10.0);  // turning on the spot
  EXPECT_EQ(parseInterpolation(interpolationName(Interpolation::Smooth)), Interpolation::Smooth);
  EXPECT_FALSE(parseInterpolation("spline"));
}
