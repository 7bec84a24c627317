#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/Error.hpp"
#include "geo/FlightPath.hpp"

using namespace og::geo;

namespace {

Keyframe key(double t, double lat, double lon, double h, double heading = 0, double pitch = -90,
             double fov = 45, Easing easing = Easing::Smooth) {
  Keyframe k;
  k.timeS = t;
  k.pose.position = {lat, lon, h};
  k.pose.headingDeg = heading;
  k.pose.pitchDeg = pitch;
  k.pose.verticalFovDeg = fov;
  k.easing = easing;
  return k;
}

// Every channel as a vector; heading as a unit vector so 359.9 -> 0.1 is continuous.
std::vector<double> channels(const FlightPath& path, double t) {
  const CameraPose p = path.at(t);
  const glm::dvec3 e = geodeticToEcef(p.position);
  const double rad = std::numbers::pi / 180.0;
  return {e.x, e.y, e.z, std::log(p.position.heightM + 1.0),
          std::sin(p.headingDeg * rad), std::cos(p.headingDeg * rad), p.pitchDeg, p.verticalFovDeg};
}

// Second-order one-sided derivative: direction +1 looks forward, -1 backward.
std::vector<double> derivative(const FlightPath& path, double t, double direction) {
  const double h = 1e-4 * direction;
  const auto f0 = channels(path, t), f1 = channels(path, t + h), f2 = channels(path, t + 2 * h);
  std::vector<double> d(f0.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = (-3 * f0[i] + 4 * f1[i] - f2[i]) / (2 * h);
  return d;
}

// A descent with a turn, uneven timing and a sharp change of pace.
FlightPath descent() {
  return FlightPath({key(0, 30, -20, 4.0e5, 80, -90, 50), key(6, 33, -12, 5.0e4, 120, -60, 45),
                     key(9, 34.5, -9.5, 3.0e3, 100, -20, 40), key(15, 34.8, -9.0, 20, 95, -2, 60),
                     key(20, 34.81, -8.99, 2, 90, 0, 60)});
}

}  // namespace

TEST(FlightPath, IsC1ThroughKeyframes) {
  const FlightPath path = descent();
  for (std::size_t k = 1; k + 1 < path.keyframes().size(); ++k) {
    const double t = path.keyframes()[k].timeS;
    const auto left = derivative(path, t, -1), right = derivative(path, t, +1);
    const auto value = channels(path, t);
    for (std::size_t i = 0; i < left.size(); ++i) {
      // One-sided differences err by O(h^2 f'''): allow that, relative to the speed.
      const double tol = 1e-3 * std::max(1.0, std::abs(left[i]));
      EXPECT_NEAR(left[i], right[i], tol) << "keyframe " << k << " channel " << i;
    }
    // And C0: the keyframe itself is hit.
    const CameraPose p = path.at(t);
    EXPECT_NEAR(p.position.latitudeDeg, path.keyframes()[k].pose.position.latitudeDeg, 1e-9);
    EXPECT_NEAR(p.position.heightM, path.keyframes()[k].pose.position.heightM,
                1e-9 * path.keyframes()[k].pose.position.heightM);
    EXPECT_NEAR(value[6], path.keyframes()[k].pose.pitchDeg, 1e-9);
  }
}

TEST(FlightPath, TwoKeyframesFollowTheGeodesic) {
  const auto& g = GeographicLib::Geodesic::WGS84();
  const double lat1 = 40.6, lon1 = -73.8, lat2 = 51.6, lon2 = -0.5;  // JFK -> LHR
  const FlightPath path({key(0, lat1, lon1, 1e4), key(10, lat2, lon2, 1e4)});
  const GeographicLib::GeodesicLine line = g.InverseLine(lat1, lon1, lat2, lon2);
  for (double u : {0.25, 0.5, 0.75}) {
    double lat = 0, lon = 0;
    line.Position(u * line.Distance(), lat, lon);
    const CameraPose p = path.at(10 * u);
    double s = 0;
    g.Inverse(lat, lon, p.position.latitudeDeg, p.position.longitudeDeg, s);
    EXPECT_LT(s, 1e-3) << "u = " << u;  // millimetres over 5 500 km
    EXPECT_NEAR(p.position.heightM, 1e4, 1e-6);
  }
}

TEST(FlightPath, EasedSegmentStaysOnTheGeodesicAndStartsAtRest) {
  const auto& g = GeographicLib::Geodesic::WGS84();
  const FlightPath path({key(0, 10, 170, 1e5, 0, -90, 45, Easing::EaseInOut), key(8, -5, -170, 1e5)});
  double lat = 0, lon = 0;
  g.InverseLine(10, 170, -5, -170).Position(0.5 * g.InverseLine(10, 170, -5, -170).Distance(), lat, lon);
  const CameraPose mid = path.at(4);
  double s = 0;
  g.Inverse(lat, lon, mid.position.latitudeDeg, mid.position.longitudeDeg, s);
  EXPECT_LT(s, 1e-3);  // symmetric easing: still the midpoint, across the antimeridian
  for (double t : {0.0, 8.0}) {
    const auto d = derivative(path, t, t == 0 ? 1 : -1);
    EXPECT_LT(std::hypot(d[0], d[1], d[2]), 5.0) << t;  // ~0 m/s (vs ~280 km/s mid-segment)
  }
}

TEST(FlightPath, HeightIsLogarithmicAndMonotoneFrom400kmTo2m) {
  const FlightPath path({key(0, 36, -9, 4.0e5), key(20, 36.5, -8, 2.0)});
  EXPECT_DOUBLE_EQ(path.at(0).position.heightM, 4.0e5);
  EXPECT_NEAR(path.at(20).position.heightM, 2.0, 1e-9);
  // Equal ratios in equal times: halfway is the geometric mean (heights from the 1 m floor).
  EXPECT_NEAR(path.at(10).position.heightM + 1.0, std::sqrt(400001.0 * 3.0), 1e-6);
  const FlightPath three({key(0, 36, -9, 4.0e5), key(7, 36.3, -8.5, 1.0e4), key(20, 36.5, -8, 2.0)});
  for (const FlightPath* p : {&path, &three}) {
    double previous = 1e300;
    for (int i = 0; i <= 2000; ++i) {
      const double h = p->at(20.0 * i / 2000).position.heightM;
      ASSERT_LT(h, previous) << "sample " << i;
      ASSERT_GE(h, 2.0 - 1e-9);
      previous = h;
    }
  }
}

TEST(FlightPath, HeadingTakesTheShortArcThroughNorth) {
  const FlightPath path({key(0, 0, 0, 100, 350), key(4, 0, 0.001, 100, 10)});
  EXPECT_NEAR(std::remainder(path.at(2).headingDeg, 360.0), 0.0, 1e-9);
  for (int i = 0; i <= 100; ++i) {
    const double h = path.at(4.0 * i / 100).headingDeg;
    EXPECT_TRUE(h >= 350.0 - 1e-9 || h <= 10.0 + 1e-9) << h;
    EXPECT_GE(h, 0.0);
    EXPECT_LT(h, 360.0);
  }
  // Many turns in one direction are kept, not unwound: 0 -> 170 -> 340 -> 150 (= 510).
  const FlightPath spin({key(0, 0, 0, 100, 0), key(1, 0, 0, 100, 170), key(2, 0, 0, 100, 340),
                         key(3, 0, 0, 100, 150)});
  EXPECT_NEAR(spin.at(2.5).headingDeg, std::fmod(425.0, 360.0), 15.0);
}

TEST(FlightPath, NothingOvershootsTheKeyframes) {
  // A fast approach then a short final segment: the ground track must not fly past the end.
  const auto& g = GeographicLib::Geodesic::WGS84();
  const FlightPath path({key(0, 30, -20, 4e5, 0, -90), key(10, 34, -9, 1e3, 0, -90),
                         key(20, 34.0005, -8.9995, 2, 0, 0)});
  double total = 0;
  g.Inverse(34, -9, 34.0005, -8.9995, total);
  for (int i = 0; i <= 200; ++i) {
    const CameraPose p = path.at(10 + 10.0 * i / 200);
    double s = 0;
    g.Inverse(34, -9, p.position.latitudeDeg, p.position.longitudeDeg, s);
    EXPECT_LE(s, total + 1e-6);
    EXPECT_GE(p.pitchDeg, -90.0);
    EXPECT_LE(p.pitchDeg, 0.0 + 1e-12);
  }
  EXPECT_EQ(path.at(-5).position.heightM, 4e5);  // clamped to the ends
  EXPECT_NEAR(path.at(99).position.heightM, 2.0, 1e-9);
}

TEST(FlightPath, RejectsBadKeyframes) {
  EXPECT_THROW(FlightPath({}), og::InputError);
  EXPECT_THROW(FlightPath({key(0, 0, 0, 100), key(0, 1, 0, 100)}), og::InputError);
  EXPECT_THROW(FlightPath({key(2, 0, 0, 100), key(1, 1, 0, 100)}), og::InputError);
  EXPECT_THROW(FlightPath({key(0, 95, 0, 100)}), og::InputError);
  EXPECT_THROW(FlightPath({key(0, 0, 0, 100), key(NAN, 1, 0, 100)}), og::InputError);
  const FlightPath single({key(0, 1, 2, 300)});
  EXPECT_EQ(single.durationS(), 0.0);
  EXPECT_EQ(single.at(5).position.heightM, 300.0);
}

TEST(FlightPath, EasingNamesRoundTrip) {
  for (Easing e : {Easing::Smooth, Easing::EaseIn, Easing::EaseOut, Easing::EaseInOut})
    EXPECT_EQ(parseEasing(easingName(e)), e);
  EXPECT_FALSE(parseEasing("bouncy"));
}
