#include <gtest/gtest.h>

#include <cmath>

#include "geo/Camera.hpp"

using namespace og::geo;

namespace {
bool finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}
CameraPose pose(double lat, double lon, double h, double heading, double pitch, double roll = 0) {
  CameraPose p;
  p.position = {lat, lon, h};
  p.headingDeg = heading;
  p.pitchDeg = pitch;
  p.rollDeg = roll;
  return p;
}
void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol) {
  EXPECT_LT(glm::length(a - b), tol) << a.x << "," << a.y << "," << a.z << " vs " << b.x << ","
                                     << b.y << "," << b.z;
}
}  // namespace

TEST(Camera, OrientationFollowsHeadingPitchRoll) {
  const CameraView down = makeCameraView(pose(45, 10, 1000, 30, -90), 100, 100);
  expectNear(down.forward, -down.enu.up, 1e-12);
  // Straight down, heading 30: the top of the image points along heading 30.
  expectNear(down.up, std::cos(0.5236) * down.enu.north + std::sin(0.5236) * down.enu.east, 1e-4);

  const CameraView east = makeCameraView(pose(0, 0, 10, 90, 0), 100, 100);
  expectNear(east.forward, east.enu.east, 1e-12);
  expectNear(east.right, -east.enu.north, 1e-12);

  const CameraView rolled = makeCameraView(pose(0, 0, 10, 0, 0, 90), 100, 100);
  expectNear(rolled.right, -rolled.enu.up, 1e-12);  // clockwise roll: right side goes down
  expectNear(rolled.forward, rolled.enu.north, 1e-12);
}

TEST(Camera, DegenerateStatesAreFinite) {
  for (const CameraPose& p : {pose(90, 0, 1000, 0, -90), pose(-90, 123, 1000, 270, -90),
                              pose(90, 0, 10, 0, 90), pose(0, 0, 0, 0, -90),
                              pose(0, 0, -500, 0, 0), pose(89.9999999, 180, 1, 359.999, 0, 180),
                              pose(0, 720, 1e9, -3600, -90, -180)}) {
    ASSERT_FALSE(validatePose(p)) << *validatePose(p);
    const CameraView v = makeCameraView(p, 320, 200);
    EXPECT_TRUE(finite(v.viewProjection()));
    EXPECT_NEAR(glm::length(v.forward), 1, 1e-12);
    EXPECT_NEAR(glm::dot(v.forward, v.up), 0, 1e-12);
    EXPECT_NEAR(glm::dot(v.forward, v.right), 0, 1e-12);
    EXPECT_GE(v.position.heightM, kMinEyeHeightM);
    EXPECT_TRUE(std::isfinite(v.positionEcef.x + v.positionEcef.y + v.positionEcef.z));
  }
}

TEST(Camera, ValidationNamesTheField) {
  EXPECT_NE(validatePose(pose(95, 0, 10, 0, 0))->find("latitude"), std::string::npos);
  EXPECT_NE(validatePose(pose(0, 0, NAN, 0, 0))->find("height"), std::string::npos);
  EXPECT_NE(validatePose(pose(0, 0, 10, 0, -91))->find("pitch"), std::string::npos);
  CameraPose p = pose(0, 0, 10, 0, 0);
  p.verticalFovDeg = 0;
  EXPECT_NE(validatePose(p)->find("field of view"), std::string::npos);
}

TEST(Camera, ProjectionMapsRaysAndReversedDepth) {
  const CameraView v = makeCameraView(pose(30, 40, 5000, 10, -20), 400, 200);
  const glm::dmat4 vp = v.viewProjection();
  // A point 1000 m along the ray through NDC (0.5, -0.25) projects back to it.
  const glm::dvec3 dir = v.rayDirection(0.5, -0.25);
  const glm::dvec4 clip = vp * glm::dvec4(dir * 1000.0, 1.0);
  EXPECT_NEAR(clip.x / clip.w, 0.5, 1e-9);
  EXPECT_NEAR(clip.y / clip.w, -0.25, 1e-9);
  // Reversed-Z: depth = near / view distance.
  const double viewDist = 1000.0 * glm::dot(dir, v.forward);
  EXPECT_NEAR(clip.z / clip.w, v.nearM / viewDist, 1e-15);
}

TEST(Camera, ReversedFloatDepthResolvesOneMetreAndFortyThousandKm) {
  const CameraView v = makeCameraView(pose(0, 0, 2.0, 0, 0), 64, 64);
  auto depth = [&](double d) { return static_cast<float>(v.nearM / d); };
  EXPECT_NE(depth(1.0), depth(1.001));          // millimetres at 1 m
  EXPECT_NE(depth(4.0e7), depth(4.0e7 + 10.0)); // 10 m at 40 000 km
  EXPECT_GT(depth(4.0e7), 0.0f);                // never collapses to the far value
}

// Both crossings of the line (render/ShadowReceivers' slab): straight down from 100 m the near
// one at 100 m and the far one through the Earth; looking up, both behind the eye; from inside
// a raised ellipsoid, one behind and the exit ahead, where intersectEllipsoid puts it.
TEST(Camera, EllipsoidCrossingsBracketTheInside) {
  const CameraView down = makeCameraView(pose(12, -34, 100.0, 0, -90), 64, 64);
  const auto c = ellipsoidCrossings(down.positionEcef, down.forward);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->first, 100.0, 1e-3);
  EXPECT_GT(c->second, 1.2e7);
  const auto up = ellipsoidCrossings(down.positionEcef, -down.forward);
  ASSERT_TRUE(up);
  EXPECT_LT(up->second, 0.0);
  const auto inside = ellipsoidCrossings(down.positionEcef, down.forward, 200.0);
  ASSERT_TRUE(inside);
  EXPECT_LT(inside->first, 0.0);
  EXPECT_NEAR(inside->second, *intersectEllipsoid(down.positionEcef, down.forward, 200.0), 1e-3);
  // From 1000 m, 0.01 rad above level: the whole line passes over the ground (the horizon dips
  // 0.018 rad there).
  const CameraView level = makeCameraView(pose(0, 0, 1000, 0, 0), 64, 64);
  const glm::dvec3 aside = glm::normalize(level.forward + level.enu.up * 0.01);
  EXPECT_FALSE(ellipsoidCrossings(level.positionEcef, aside));
}

TEST(Camera, EllipsoidIntersectionIsAccurateNearTheSurface) {
  for (double h : {0.1, 1.0, 2.0, 100.0, 2.0e7}) {
    const CameraView v = makeCameraView(pose(12, -34, h, 0, -90), 64, 64);
    const auto t = intersectEllipsoid(v.positionEcef, v.forward);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, h, 1e-6 * std::max(1.0, h));
  }
  const CameraView horizon = makeCameraView(pose(0, 0, 1000, 0, 10), 64, 64);
  EXPECT_FALSE(intersectEllipsoid(horizon.positionEcef, horizon.forward));
  // Looking just below the horizon from 2 m: the sea is ~5 km away.
  const CameraView low = makeCameraView(pose(0, 0, 2, 0, -0.5), 64, 64);
  const auto t = intersectEllipsoid(low.positionEcef, low.forward);
  ASSERT_TRUE(t);
  EXPECT_GT(*t, 150.0);
  EXPECT_LT(*t, 5100.0);
}
