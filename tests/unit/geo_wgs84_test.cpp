#include <gtest/gtest.h>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include "geo/Wgs84.hpp"

using namespace og::geo;

TEST(Wgs84, KnownPoints) {
  const glm::dvec3 equator = geodeticToEcef({0, 0, 0});
  EXPECT_NEAR(equator.x, kWgs84SemiMajorM, 1e-6);
  EXPECT_NEAR(equator.y, 0, 1e-6);
  const glm::dvec3 pole = geodeticToEcef({90, 0, 0});
  EXPECT_NEAR(pole.z, kWgs84SemiMinorM, 1e-6);
  EXPECT_NEAR(glm::length(glm::dvec2(pole)), 0, 1e-6);
  const glm::dvec3 east = geodeticToEcef({0, 90, 1000});
  EXPECT_NEAR(east.y, kWgs84SemiMajorM + 1000, 1e-6);
}

TEST(Wgs84, RoundTripAgreesWithGeographicLib) {
  const auto& g = GeographicLib::Geocentric::WGS84();
  for (double lat = -90; lat <= 90; lat += 7.5)
    for (double lon = -180; lon < 180; lon += 22.5)
      for (double h : {-11000.0, 0.0, 1.0, 8848.0, 4.0e5, 3.6e7}) {
        const glm::dvec3 p = geodeticToEcef({lat, lon, h});
        double x, y, z;
        g.Forward(lat, lon, h, x, y, z);
        EXPECT_NEAR(p.x, x, 1e-9);
        EXPECT_NEAR(p.y, y, 1e-9);
        EXPECT_NEAR(p.z, z, 1e-9);
        const Geodetic back = ecefToGeodetic(p);
        EXPECT_NEAR(back.latitudeDeg, lat, 1e-9);
        EXPECT_NEAR(back.heightM, h, 1e-6);
        if (std::abs(lat) < 90) {
          EXPECT_NEAR(std::remainder(back.longitudeDeg - lon, 360.0), 0.0, 1e-9);
        }
        // The round trip is what matters in metres.
        EXPECT_LT(glm::length(geodeticToEcef(back) - p), 1e-6);
      }
}

TEST(Wgs84, EnuFrameMatchesLocalCartesianAndNormal) {
  for (double lat : {-90.0, -45.0, 0.0, 33.3, 89.999, 90.0})
    for (double lon : {-170.0, 0.0, 45.0}) {
      const EnuFrame f = enuFrameAt(lat, lon);
      EXPECT_NEAR(glm::dot(f.east, f.north), 0, 1e-12);
      EXPECT_NEAR(glm::dot(f.east, f.up), 0, 1e-12);
      EXPECT_NEAR(glm::length(glm::cross(f.east, f.north) - f.up), 0, 1e-12);
      const glm::dvec3 p = geodeticToEcef({lat, lon, 0});
      EXPECT_NEAR(glm::length(ellipsoidNormalAt(p) - f.up), 0, 1e-9);
      // A point 100 m east, 50 m north, 10 m up in GeographicLib's local frame.
      GeographicLib::LocalCartesian lc(lat, lon, 0);
      double plat, plon, ph;
      lc.Reverse(100, 50, 10, plat, plon, ph);
      const glm::dvec3 ours = p + f.toEcef({100, 50, 10});
      EXPECT_LT(glm::length(ours - geodeticToEcef({plat, plon, ph})), 1e-6);
    }
}
