#include "geo/LookAt.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace og::geo {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

// Unit view direction and image-up vector in ECEF axes for a heading and tilt in `enu`.
void viewAxes(const EnuFrame& enu, double headingDeg, double tiltDeg, glm::dvec3& forward,
              glm::dvec3& up) {
  const double h = headingDeg * kDeg, t = tiltDeg * kDeg;
  const glm::dvec3 horizontal = std::cos(h) * enu.north + std::sin(h) * enu.east;
  forward = std::sin(t) * horizontal - std::cos(t) * enu.up;
  up = std::cos(t) * horizontal + std::sin(t) * enu.up;
}
}  // namespace

std::optional<std::string> validateLookAt(const LookAt& v) {
  const Geodetic& g = v.target;
  if (!std::isfinite(g.latitudeDeg) || g.latitudeDeg < -90.0 || g.latitudeDeg > 90.0)
    return "target latitude must be within [-90, 90] degrees";
  if (!std::isfinite(g.longitudeDeg) || std::abs(g.longitudeDeg) > 720.0)
    return "target longitude must be a finite number of degrees within [-720, 720]";
  if (!std::isfinite(g.heightM) || g.heightM < -12000.0 || g.heightM > 1.0e9)
    return "target height must be within [-12000, 1e9] metres";
  if (!std::isfinite(v.rangeM) || v.rangeM < 0.0 || v.rangeM > 1.0e9)
    return "range must be within [0, 1e9] metres";
  if (!std::isfinite(v.headingDeg) || std::abs(v.headingDeg) > 3600.0)
    return "heading must be a finite number of degrees within [-3600, 3600]";
  if (!std::isfinite(v.tiltDeg) || v.tiltDeg < 0.0 || v.tiltDeg > 90.0)
    return "tilt must be within [0, 90] degrees (0 looks straight down, 90 level)";
  return std::nullopt;
}

glm::dvec3 lookAtDirection(const LookAt& v) {
  glm::dvec3 forward, up;
  viewAxes(enuFrameAt(v.target.latitudeDeg, v.target.longitudeDeg), v.headingDeg, v.tiltDeg, forward, up);
  return forward;
}

CameraPose cameraFromLookAt(const LookAt& v, double rollDeg, double verticalFovDeg) {
  glm::dvec3 forward, up;
  viewAxes(enuFrameAt(v.target.latitudeDeg, v.target.longitudeDeg), v.headingDeg, v.tiltDeg, forward, up);
  const glm::dvec3 eye = geodeticToEcef(v.target) - v.rangeM * forward;

  CameraPose pose;
  pose.position = ecefToGeodetic(eye);
  pose.rollDeg = rollDeg;
  pose.verticalFovDeg = verticalFovDeg;
  // In the eye's frame: pitch from the view direction; heading from its horizontal part, or
  // when looking straight down (no horizontal part) from the image's up vector's, which is the
  // direction the top of the image faces then (geo/Camera.cpp rotates from it).
  const EnuFrame e = enuFrameAt(pose.position.latitudeDeg, pose.position.longitudeDeg);
  const double sinPitch = std::clamp(glm::dot(forward, e.up), -1.0, 1.0);
  glm::dvec3 horizontal = forward - sinPitch * e.up;
  if (glm::length(horizontal) < 1e-9) horizontal = (sinPitch < 0.0 ? 1.0 : -1.0) * (up - glm::dot(up, e.up) * e.up);
  double heading = std::atan2(glm::dot(horizontal, e.east), glm::dot(horizontal, e.north)) / kDeg;
  if (heading < 0.0) heading += 360.0;
  pose.headingDeg = heading;
  pose.pitchDeg = std::asin(sinPitch) / kDeg;
  return pose;
}

}  // namespace og::geo
