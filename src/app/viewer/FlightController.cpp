#include "app/viewer/FlightController.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace og::app::viewer {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Rodrigues' rotation of v about the unit axis a by angle (right-handed).
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(a, v) * s + a * glm::dot(a, v) * (1.0 - c);
}

double wrapHeading(double deg) {
  const double h = std::fmod(deg, 360.0);
  return h < 0.0 ? h + 360.0 : h;
}

double wrapRoll(double deg) {
  double r = std::fmod(deg + 180.0, 360.0);
  if (r < 0.0) r += 360.0;
  return r - 180.0;
}

}  // namespace

geo::CameraPose poseFromOrientation(const geo::Geodetic& position, const glm::dvec3& forward,
                                    const glm::dvec3& up, double verticalFovDeg) {
  const geo::EnuFrame enu = geo::enuFrameAt(position.latitudeDeg, position.longitudeDeg);
  const glm::dvec3 f = enu.toEnu(forward), u = enu.toEnu(up);
  geo::CameraPose pose;
  pose.position = position;
  pose.verticalFovDeg = verticalFovDeg;
  const double horizontal = std::hypot(f.x, f.y);
  const double pitch = std::atan2(f.z, horizontal);
  pose.pitchDeg = pitch / kDeg;
  if (horizontal > 1e-9) {
    // Undo makeCameraView's rotations: heading from the forward vector, then the roll that
    // takes the un-rolled image-up (up0) to the actual one.
    const double h = std::atan2(f.x, f.y);
    const glm::dvec3 fh{std::sin(h), std::cos(h), 0.0}, r0{std::cos(h), -std::sin(h), 0.0};
    const glm::dvec3 up0 = std::cos(pitch) * glm::dvec3(0, 0, 1) - std::sin(pitch) * fh;
    pose.headingDeg = wrapHeading(h / kDeg);
    pose.rollDeg = std::atan2(glm::dot(u, r0), glm::dot(u, up0)) / kDeg;
  } else {
    // Straight down the image's up is the heading's direction; straight up, its opposite.
    const double s = f.z < 0.0 ? 1.0 : -1.0;
    pose.headingDeg = wrapHeading(std::atan2(s * u.x, s * u.y) / kDeg);
    pose.rollDeg = 0.0;
    pose.pitchDeg = f.z < 0.0 ? -90.0 : 90.0;
  }
  return pose;
}

geo::CameraPose poseAhead(const geo::CameraPose& pose, const glm::dvec3& velocityEcef, double aheadS, double surfaceM) {
  geo::CameraPose ahead = pose;
  ahead.position = geo::ecefToGeodetic(geo::geodeticToEcef(pose.position) + aheadS * velocityEcef);
  const double floorM = surfaceM + 0.25 * std::max(pose.position.heightM - surfaceM, 0.0);
  ahead.position.heightM = std::max(ahead.position.heightM, floorM);
  return ahead;
}

glm::dvec3 VelocityEstimate::update(const glm::dvec3& eyeEcef, double dtS) {
  if (!(dtS > 0.0)) return velocity_;
  const glm::dvec3 step = eyeEcef - lastEye_;
  if (!hasLast_ || glm::length(step) > kJumpM) {
    velocity_ = glm::dvec3(0.0);
  } else {
    const double blend = 1.0 - std::exp(-dtS / kTimeConstantS);
    velocity_ += blend * (step / dtS - velocity_);
  }
  lastEye_ = eyeEcef;
  hasLast_ = true;
  return velocity_;
}

FlightController::FlightController(const geo::CameraPose& pose, SurfaceHeight surface)
    : pose_(pose), surface_(std::move(surface)) {
  clamp();
}

void FlightController::setPose(const geo::CameraPose& pose) {
  pose_ = pose;
  clamp();
}

double FlightController::surfaceAt(const geo::Geodetic& g) const {
  return surface_ ? surface_(g.latitudeDeg, g.longitudeDeg) : 0.0;
}

double FlightController::surfaceHeightM() const { return surfaceAt(pose_.position); }

double FlightController::heightAboveSurfaceM() const {
  return pose_.position.heightM - surfaceHeightM();
}

double FlightController::speedMs() const {
  return kSpeedPerHeight * std::max(heightAboveSurfaceM(), kMinClearanceM);
}

void FlightController::clamp() {
  auto& g = pose_.position;
  if (!std::isfinite(g.latitudeDeg)) g.latitudeDeg = 0.0;
  if (!std::isfinite(g.longitudeDeg)) g.longitudeDeg = 0.0;
  g.latitudeDeg = std::clamp(g.latitudeDeg, -90.0, 90.0);
  g.longitudeDeg = wrapRoll(g.longitudeDeg);  // [-180, 180], same wrap as roll
  const double floor = surfaceAt(g) + kMinClearanceM;
  g.heightM = std::isfinite(g.heightM) ? std::clamp(g.heightM, floor, kMaxHeightM) : floor;
  pose_.headingDeg = std::isfinite(pose_.headingDeg) ? wrapHeading(pose_.headingDeg) : 0.0;
  pose_.pitchDeg = std::isfinite(pose_.pitchDeg) ? std::clamp(pose_.pitchDeg, -90.0, 90.0) : -90.0;
  pose_.rollDeg = std::isfinite(pose_.rollDeg) ? wrapRoll(pose_.rollDeg) : 0.0;
}

void FlightController::placeEye(const glm::dvec3& eyeEcef, bool keepSpace) {
  const geo::Geodetic g = geo::ecefToGeodetic(eyeEcef);
  if (keepSpace) {
    const geo::CameraView view = geo::makeCameraView(pose_, 1, 1);
    pose_ = poseFromOrientation(g, view.forward, view.up, pose_.verticalFovDeg);
  } else {
    pose_.position = g;
  }
  clamp();
}

void FlightController::moveAlong(const glm::dvec3& dir, double distanceM) {
  const geo::CameraView view = geo::makeCameraView(pose_, 1, 1);
  glm::dvec3 d = glm::normalize(dir);
  if (distanceM < 0.0) {
    d = -d;
    distanceM = -distanceM;
  }
  // Stop short of the surface ahead: each step covers at most 90% of the way to it, so the
  // approach slows down instead of tunnelling through the planet from orbit.
  if (const auto hit = geo::intersectEllipsoid(view.positionEcef, d, surfaceHeightM()))
    distanceM = std::min(distanceM, 0.9 * *hit);
  placeEye(view.positionEcef + d * distanceM, true);
}

void FlightController::update(const MoveInput& in, double dtS) {
  const double dt = std::clamp(dtS, 0.0, kMaxStepS);
  if (dt <= 0.0 || !in.any()) return;
  const double rate = kSpeedPerHeight * in.speedFactor;
  const geo::CameraView view = geo::makeCameraView(pose_, 1, 1);
  const glm::dvec3 d = in.forward * view.forward + in.right * view.right;
  const double length = glm::length(d);
  if (length > 0.0) {
    const double distance = rate * std::max(heightAboveSurfaceM(), kMinClearanceM) * dt *
                            std::min(length, 1.0);
    // Keys keep heading/pitch/roll relative to the ground, so flying level follows the
    // Earth's curvature instead of climbing away along a tangent.
    const glm::dvec3 dir = d / length;
    glm::dvec3 eye = view.positionEcef;
    double step = distance;
    if (const auto hit = geo::intersectEllipsoid(eye, dir, surfaceHeightM()))
      step = std::min(step, 0.9 * *hit);
    eye += dir * step;
    placeEye(eye, false);
  }
  if (in.up != 0.0) {
    // Exponential in the height above the surface: equal ratios in equal times, never below.
    const double surface = surfaceHeightM();
    const double above = std::max(pose_.position.heightM - surface, kMinClearanceM);
    pose_.position.heightM = surface + above * std::exp(in.up * rate * dt);
  }
  pose_.rollDeg += in.roll * kRollRateDegS * dt;
  clamp();
}

void FlightController::look(double headingDeg, double pitchDeg) {
  pose_.headingDeg += headingDeg;
  pose_.pitchDeg += pitchDeg;
  clamp();
}

void FlightController::orbit(const glm::dvec3& pivot, double yawRad, double tiltRad) {
  const geo::CameraView view = geo::makeCameraView(pose_, 1, 1);
  // About the Earth's centre (when the cursor is on the sky) yaw spins the globe about its
  // polar axis; about a surface point it turns about the local vertical there.
  const bool centre = glm::length(pivot) < 1.0e6;
  const glm::dvec3 n = centre ? glm::dvec3(0, 0, 1) : geo::ellipsoidNormalAt(pivot);
  glm::dvec3 rel = rotate(view.positionEcef - pivot, n, yawRad);
  glm::dvec3 fwd = rotate(view.forward, n, yawRad);
  glm::dvec3 up = rotate(view.up, n, yawRad);
  const glm::dvec3 right = rotate(view.right, n, yawRad);
  glm::dvec3 axis = centre ? right : right - glm::dot(right, n) * n;
  if (tiltRad != 0.0 && glm::length(axis) > 1e-9) {
    axis = glm::normalize(axis);
    const glm::dvec3 rel2 = rotate(rel, axis, tiltRad);
    const double minSin = std::sin(2.0 * kDeg);
    if (centre || glm::dot(glm::normalize(rel2), n) >= minSin) {
      rel = rel2;
      fwd = rotate(fwd, axis, tiltRad);
      up = rotate(up, axis, tiltRad);
    }
  }
  const geo::Geodetic g = geo::ecefToGeodetic(pivot + rel);
  pose_ = poseFromOrientation(g, glm::normalize(fwd), glm::normalize(up), pose_.verticalFovDeg);
  clamp();
}

void FlightController::moveToward(const glm::dvec3& target, double factor) {
  const geo::CameraView view = geo::makeCameraView(pose_, 1, 1);
  placeEye(target + (view.positionEcef - target) * std::max(factor, 0.0), true);
}

void FlightController::resetNorthUp() {
  pose_.headingDeg = 0.0;
  pose_.rollDeg = 0.0;
  clamp();
}

std::optional<glm::dvec3> FlightController::pick(double ndcX, double ndcY, int width, int height) const {
  const geo::CameraView view = geo::makeCameraView(pose_, width, height);
  const glm::dvec3 dir = view.rayDirection(ndcX, ndcY);
  const auto t = geo::intersectEllipsoid(view.positionEcef, dir, 0.0);
  if (!t) return std::nullopt;
  return view.positionEcef + dir * *t;
}

}  // namespace og::app::viewer
