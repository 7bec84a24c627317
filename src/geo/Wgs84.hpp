#pragma once
// The WGS84 ellipsoid: geodetic <-> ECEF and local East-North-Up frames, via GeographicLib.
// Everything here is double precision; floats appear only once a position has been made
// relative to the camera (see Camera.hpp).
#include <glm/glm.hpp>

namespace og::geo {

inline constexpr double kWgs84SemiMajorM = 6378137.0;                ///< a, metres
inline constexpr double kWgs84Flattening = 1.0 / 298.257223563;      ///< f
inline constexpr double kWgs84SemiMinorM = kWgs84SemiMajorM * (1.0 - kWgs84Flattening);  ///< b

/// A geodetic position on WGS84.
struct Geodetic {
  double latitudeDeg = 0.0;   ///< [-90, 90], positive north
  double longitudeDeg = 0.0;  ///< any value; treated modulo 360, positive east
  double heightM = 0.0;       ///< height above the ellipsoid, metres
};

/// Earth-centred, Earth-fixed position (metres) of a geodetic point.
glm::dvec3 geodeticToEcef(const Geodetic& g);

/// Geodetic position of an ECEF point (metres). Exact everywhere, including the poles and the
/// Earth's centre (GeographicLib's closed-form solution).
Geodetic ecefToGeodetic(const glm::dvec3& ecef);

/// Unit vectors of the local East-North-Up frame at a geodetic point, in ECEF axes.
/// At the poles "east" still follows the given longitude, so the frame is never degenerate.
struct EnuFrame {
  glm::dvec3 east{1, 0, 0};
  glm::dvec3 north{0, 1, 0};
  glm::dvec3 up{0, 0, 1};

  /// Columns east, north, up: maps ENU components to ECEF components.
  [[nodiscard]] glm::dmat3 enuToEcef() const { return {east, north, up}; }
  [[nodiscard]] glm::dvec3 toEcef(const glm::dvec3& enu) const {
    return enu.x * east + enu.y * north + enu.z * up;
  }
  [[nodiscard]] glm::dvec3 toEnu(const glm::dvec3& ecef) const {
    return {glm::dot(ecef, east), glm::dot(ecef, north), glm::dot(ecef, up)};
  }
};

EnuFrame enuFrameAt(double latitudeDeg, double longitudeDeg);

/// Outward unit normal of the ellipsoid at an ECEF point on (or near) it, gradient of
/// x²/a² + y²/a² + z²/b².
glm::dvec3 ellipsoidNormalAt(const glm::dvec3& ecef);

}  // namespace og::geo
