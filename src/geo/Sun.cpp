#include "geo/Sun.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace og::geo {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

double wrap360(double deg) {
  double w = std::fmod(deg, 360.0);
  if (w < 0.0) w += 360.0;
  return w >= 360.0 ? 0.0 : w;  // -1e-17 + 360 rounds to 360
}
}  // namespace

SunEphemeris sunEphemeris(const UtcTime& time) {
  const double n = time.daysSinceJ2000();
  // Astronomical Almanac, C5: mean longitude, mean anomaly, ecliptic longitude, obliquity.
  const double L = wrap360(280.460 + 0.9856474 * n);
  const double g = wrap360(357.528 + 0.9856003 * n) * kDeg;
  const double lambda = (L + 1.915 * std::sin(g) + 0.020 * std::sin(2.0 * g)) * kDeg;
  const double epsilon = (23.439 - 0.0000004 * n) * kDeg;

  SunEphemeris e;
  e.rightAscensionDeg =
      wrap360(std::atan2(std::cos(epsilon) * std::sin(lambda), std::cos(lambda)) / kDeg);
  e.declinationDeg = std::asin(std::sin(epsilon) * std::sin(lambda)) / kDeg;
  e.distanceAu = 1.00014 - 0.01671 * std::cos(g) - 0.00014 * std::cos(2.0 * g);
  // GMST (Meeus eq. 12.4; the T² term is below 0.01° before 2100).
  e.gmstDeg = wrap360(280.46061837 + 360.98564736629 * n);
  double eot = L - e.rightAscensionDeg;  // degrees of rotation, 4 min each
  eot = eot > 180.0 ? eot - 360.0 : (eot < -180.0 ? eot + 360.0 : eot);
  e.equationOfTimeMin = 4.0 * eot;

  // Hour angle at Greenwich turns the equatorial direction into ECEF.
  const double ha = (e.rightAscensionDeg - e.gmstDeg) * kDeg;
  const double dec = e.declinationDeg * kDeg;
  e.directionEcef = {std::cos(dec) * std::cos(ha), std::cos(dec) * std::sin(ha), std::sin(dec)};
  return e;
}

glm::dvec3 sunDirectionFromHorizontal(const Geodetic& where, double elevationDeg,
                                      double azimuthDeg) {
  const EnuFrame f = enuFrameAt(where.latitudeDeg, where.longitudeDeg);
  const double el = elevationDeg * kDeg, az = azimuthDeg * kDeg;
  return glm::normalize(f.toEcef({std::cos(el) * std::sin(az), std::cos(el) * std::cos(az),
                                  std::sin(el)}));
}

HorizontalAngles horizontalAngles(const Geodetic& where, const glm::dvec3& directionEcef) {
  const EnuFrame f = enuFrameAt(where.latitudeDeg, where.longitudeDeg);
  const glm::dvec3 enu = f.toEnu(glm::normalize(directionEcef));
  HorizontalAngles h;
  h.elevationDeg = std::asin(std::clamp(enu.z, -1.0, 1.0)) / kDeg;
  h.azimuthDeg = (enu.x == 0.0 && enu.y == 0.0) ? 0.0 : wrap360(std::atan2(enu.x, enu.y) / kDeg);
  return h;
}

bool sunMayBeDownInView(const glm::dvec3& eyeUpEcef, double eyeHeightM, const glm::dvec3& sunDirEcef,
                        double maxSurfaceHeightM) {
  // The ellipsoid's local radius differs from the mean by < 0.4 %: a degree of margin covers
  // it and the ellipsoid's normal against the sphere's (< 0.2°).
  constexpr double kRadiusM = 6371000.0;
  constexpr double kMarginRad = 1.0 * std::numbers::pi / 180.0;
  const double horizonRad = std::acos(kRadiusM / (kRadiusM + std::max(eyeHeightM, 0.0))) +
                            std::acos(kRadiusM / (kRadiusM + std::max(maxSurfaceHeightM, 0.0)));
  const double sunFromZenithRad = std::acos(std::clamp(glm::dot(eyeUpEcef, sunDirEcef), -1.0, 1.0));
  // A point at angle θ from the nadir has the Sun at most sunFromZenith + θ from its zenith.
  return sunFromZenithRad + horizonRad + kMarginRad >= 0.5 * std::numbers::pi;
}

}  // namespace og::geo
