#pragma once
// The Sun's direction. From a UTC time by the Astronomical Almanac's low-precision formulae
// (section C, "Low precision formulas for the Sun": good to 0.01° in 1950-2050), or from an
// elevation and azimuth given at a point.
#include <glm/glm.hpp>

#include "core/Time.hpp"
#include "geo/Wgs84.hpp"

namespace og::geo {

struct SunEphemeris {
  glm::dvec3 directionEcef;       ///< unit vector from the Earth towards the Sun, ECEF axes
  double rightAscensionDeg = 0.0; ///< [0, 360)
  double declinationDeg = 0.0;    ///< [-23.5, 23.5]
  double distanceAu = 1.0;
  double gmstDeg = 0.0;           ///< Greenwich mean sidereal time as an angle, [0, 360)
  double equationOfTimeMin = 0.0; ///< apparent minus mean solar time, minutes
};

SunEphemeris sunEphemeris(const UtcTime& time);

/// Direction to the Sun (ECEF unit vector) from its elevation above the local horizon and its
/// azimuth clockwise from north, both in degrees, at a geodetic point.
glm::dvec3 sunDirectionFromHorizontal(const Geodetic& where, double elevationDeg,
                                      double azimuthDeg);

struct HorizontalAngles {
  double elevationDeg = 0.0;  ///< above the ellipsoid's tangent plane, [-90, 90]
  double azimuthDeg = 0.0;    ///< clockwise from north, [0, 360)
};

/// Elevation and azimuth of an ECEF direction seen from a geodetic point.
HorizontalAngles horizontalAngles(const Geodetic& where, const glm::dvec3& directionEcef);

/// Whether the Sun may be below the horizon (its zenith cosine < 0) at some surface point a
/// camera sees: conservative (true whenever it is, possibly when it is not). The visible
/// surface is taken as the cap within the eye's horizon plus the farther ground that rises to
/// `maxSurfaceHeightM` (metres; peaks seen beyond the sea's horizon), on a sphere of the
/// Earth's mean radius; `eyeUpEcef` and `sunDirEcef` are unit vectors, `eyeHeightM` metres
/// above the ellipsoid (≥ 0). Renderers use it to compile night-only terms (city lights) out
/// of frames where no pixel can need them.
bool sunMayBeDownInView(const glm::dvec3& eyeUpEcef, double eyeHeightM, const glm::dvec3& sunDirEcef,
                        double maxSurfaceHeightM);

}  // namespace og::geo
