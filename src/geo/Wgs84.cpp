#include "geo/Wgs84.hpp"

#include <GeographicLib/Geocentric.hpp>

#include <cmath>
#include <vector>

namespace og::geo {
namespace {
const GeographicLib::Geocentric& wgs84() { return GeographicLib::Geocentric::WGS84(); }
}  // namespace

glm::dvec3 geodeticToEcef(const Geodetic& g) {
  glm::dvec3 p;
  wgs84().Forward(g.latitudeDeg, g.longitudeDeg, g.heightM, p.x, p.y, p.z);
  return p;
}

Geodetic ecefToGeodetic(const glm::dvec3& p) {
  Geodetic g;
  wgs84().Reverse(p.x, p.y, p.z, g.latitudeDeg, g.longitudeDeg, g.heightM);
  return g;
}

EnuFrame enuFrameAt(double latitudeDeg, double longitudeDeg) {
  // GeographicLib's rotation matrix M (row-major) has columns east, north, up in ECEF.
  std::vector<double> m(9);
  double x = 0, y = 0, z = 0;
  wgs84().Forward(latitudeDeg, longitudeDeg, 0.0, x, y, z, m);
  EnuFrame f;
  f.east = {m[0], m[3], m[6]};
  f.north = {m[1], m[4], m[7]};
  f.up = {m[2], m[5], m[8]};
  return f;
}

glm::dvec3 ellipsoidNormalAt(const glm::dvec3& p) {
  const double a2 = kWgs84SemiMajorM * kWgs84SemiMajorM;
  const double b2 = kWgs84SemiMinorM * kWgs84SemiMinorM;
  const glm::dvec3 n{p.x / a2, p.y / a2, p.z / b2};
  const double len = glm::length(n);
  return len > 0.0 ? n / len : glm::dvec3{0, 0, 1};
}

}  // namespace og::geo
