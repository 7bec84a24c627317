#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Time.hpp"
#include "geo/Sun.hpp"

using namespace og;
using namespace og::geo;

// Reference values from the Astronomical Almanac / USNO: equinox and solstice instants of
// 2024 (declination 0 and ±obliquity, 23.436° in 2024), the equation of time's extremes, and
// the Sun at J2000.0 (declination -23.03°, equation of time -3.3 min).
TEST(Sun, DeclinationAtEquinoxesAndSolstices) {
  EXPECT_NEAR(sunEphemeris(*UtcTime::parseIso8601("2024-03-20T03:06Z")).declinationDeg, 0.0, 0.02);
  EXPECT_NEAR(sunEphemeris(*UtcTime::parseIso8601("2024-09-22T12:44Z")).declinationDeg, 0.0, 0.02);
  EXPECT_NEAR(sunEphemeris(*UtcTime::parseIso8601("2024-06-20T20:51Z")).declinationDeg, 23.436, 0.02);
  EXPECT_NEAR(sunEphemeris(*UtcTime::parseIso8601("2024-12-21T09:21Z")).declinationDeg, -23.436, 0.02);
}

TEST(Sun, EquationOfTime) {
  EXPECT_NEAR(sunEphemeris(*UtcTime::parseIso8601("2024-11-03T12:00Z")).equationOfTimeMin, 16.4, 0.3);
  EXPECT_NEAR(sunEphemeris(*UtcTime::parseIso8601("2024-02-11T12:00Z")).equationOfTimeMin, -14.2, 0.3);
}

TEST(Sun, SubsolarPointAtJ2000) {
  const SunEphemeris e = sunEphemeris(*UtcTime::parseIso8601("2000-01-01T12:00:00Z"));
  EXPECT_NEAR(e.declinationDeg, -23.03, 0.03);
  EXPECT_NEAR(e.equationOfTimeMin, -3.3, 0.2);
  const Geodetic sub = ecefToGeodetic(e.directionEcef * 1.0e7);
  // Before apparent noon at Greenwich the Sun stands east of it by |EoT| * 0.25°/min.
  EXPECT_NEAR(sub.longitudeDeg, 3.3 * 0.25, 0.1);
}

TEST(Sun, OverheadAtSubsolarPointAndSetOnTheTerminator) {
  const SunEphemeris e = sunEphemeris(*UtcTime::parseIso8601("2024-06-20T20:51Z"));
  const double lon = std::atan2(e.directionEcef.y, e.directionEcef.x) * 180.0 / 3.14159265358979;
  // Geocentric and geodetic latitude differ by <0.2°; elevation is measured geodetically.
  const HorizontalAngles overhead = horizontalAngles({e.declinationDeg, lon, 0}, e.directionEcef);
  EXPECT_GT(overhead.elevationDeg, 89.8);
  const HorizontalAngles opposite = horizontalAngles({-e.declinationDeg, lon + 180, 0}, e.directionEcef);
  EXPECT_LT(opposite.elevationDeg, -89.8);
}

TEST(Sun, HorizontalRoundTrip) {
  const Geodetic where{-33.9, 18.4, 0};
  for (double el : {-20.0, 0.0, 5.0, 45.0, 89.0})
    for (double az : {0.0, 90.0, 181.0, 300.0}) {
      const HorizontalAngles h = horizontalAngles(where, sunDirectionFromHorizontal(where, el, az));
      EXPECT_NEAR(h.elevationDeg, el, 1e-9);
      EXPECT_NEAR(std::remainder(h.azimuthDeg - az, 360.0), 0.0, 1e-9);
      EXPECT_GE(h.azimuthDeg, 0.0);
      EXPECT_LT(h.azimuthDeg, 360.0);
    }
}

// Brute force: points of a sphere (radius R + H) seen from the eye over the sphere of radius
// R (the segment between them does not enter it); whenever one has the Sun below its horizon
// the test must say "may be down".
TEST(Sun, MayBeDownInViewIsConservativeAndNotTooMuch) {
  constexpr double R = 6371000.0;
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const auto visible = [&](const glm::dvec3& eye, const glm::dvec3& p) {
    const glm::dvec3 d = p - eye;
    const double t = std::clamp(-glm::dot(eye, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(eye + t * d) >= R - 1e-6;
  };
  int downSeen = 0;
  for (double h : {2.0, 4000.0, 15000.0, 3.0e5, 2.0e6}) {
    const glm::dvec3 eye = (R + h) * up;
    for (double sunElevDeg = -30.0; sunElevDeg <= 90.0; sunElevDeg += 2.5) {
      const double e = sunElevDeg * std::numbers::pi / 180.0;
      const glm::dvec3 sun(std::cos(e), 0.0, std::sin(e));
      bool anyDown = false;
      for (double H : {0.0, 4000.0, 8800.0})
        for (double theta = 0.0; theta < 0.5 * std::numbers::pi && !anyDown; theta += 0.002)
          for (double az = 0.0; az < 2.0 * std::numbers::pi; az += std::numbers::pi / 8.0) {
            const glm::dvec3 n(std::sin(theta) * std::cos(az), std::sin(theta) * std::sin(az), std::cos(theta));
            if (visible(eye, (R + H) * n) && glm::dot(n, sun) < 0.0) anyDown = true;
          }
      const bool said = og::geo::sunMayBeDownInView(up, h, sun, 9000.0);
      if (anyDown) {
        ++downSeen;
        EXPECT_TRUE(said) << "h " << h << " m, Sun " << sunElevDeg << " deg";
      }
    }
  }
  EXPECT_GT(downSeen, 20);
  // Not everything: at 15 km the ground and peaks in view span ~7°; the Sun 10° up is day there,
  // 5° up it may set behind the horizon's peaks.
  const auto sunAt = [](double deg) {
    const double e = deg * std::numbers::pi / 180.0;
    return glm::dvec3(std::cos(e), 0.0, std::sin(e));
  };
  EXPECT_FALSE(og::geo::sunMayBeDownInView(up, 15000.0, sunAt(10.0), 9000.0));
  EXPECT_TRUE(og::geo::sunMayBeDownInView(up, 15000.0, sunAt(5.0), 9000.0));
  EXPECT_FALSE(og::geo::sunMayBeDownInView(up, 4.0, sunAt(60.0), 9000.0));
  EXPECT_TRUE(og::geo::sunMayBeDownInView(up, 2.0e7, sunAt(60.0), 9000.0));  // the whole disc
}
