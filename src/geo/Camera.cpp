#include "geo/Camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace og::geo {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

bool finite(double v) { return std::isfinite(v); }
}  // namespace

std::optional<std::string> validatePose(const CameraPose& p) {
  const auto& g = p.position;
  if (!finite(g.latitudeDeg) || g.latitudeDeg < -90.0 || g.latitudeDeg > 90.0)
    return "latitude must be within [-90, 90] degrees";
  if (!finite(g.longitudeDeg) || std::abs(g.longitudeDeg) > 720.0)
    return "longitude must be a finite number of degrees within [-720, 720]";
  if (!finite(g.heightM) || g.heightM < -12000.0 || g.heightM > 1.0e9)
    return "height must be within [-12000, 1e9] metres";
  if (!finite(p.headingDeg) || std::abs(p.headingDeg) > 3600.0)
    return "heading must be a finite number of degrees within [-3600, 3600]";
  if (!finite(p.pitchDeg) || p.pitchDeg < -90.0 || p.pitchDeg > 90.0)
    return "pitch must be within [-90, 90] degrees";
  if (!finite(p.rollDeg) || p.rollDeg < -180.0 || p.rollDeg > 180.0)
    return "roll must be within [-180, 180] degrees";
  if (!finite(p.verticalFovDeg) || p.verticalFovDeg < 0.1 || p.verticalFovDeg > 170.0)
    return "vertical field of view must be within [0.1, 170] degrees";
  return std::nullopt;
}

CameraView makeCameraView(const CameraPose& pose, int widthPx, int heightPx) {
  CameraView v;
  v.position = pose.position;
  v.position.heightM = std::max(pose.position.heightM, kMinEyeHeightM);
  v.positionEcef = geodeticToEcef(v.position);
  v.enu = enuFrameAt(v.position.latitudeDeg, v.position.longitudeDeg);
  v.verticalFovRad = pose.verticalFovDeg * kDeg;
  v.aspect = static_cast<double>(std::max(widthPx, 1)) / static_cast<double>(std::max(heightPx, 1));
  // Near plane shrinks with height so the camera can sit 0.1 m above the waves; reversed-Z
  // float depth keeps ~7 significant digits at every distance, so no far plane is needed.
  v.nearM = std::clamp(0.05 * v.position.heightM, 0.01, 1.0);

  // Start looking north along the horizon, then heading about up, pitch about right, roll
  // about forward. Rotations, not lookAt: no orientation is singular.
  const double h = pose.headingDeg * kDeg, p = pose.pitchDeg * kDeg, r = pose.rollDeg * kDeg;
  glm::dvec3 fwd = std::cos(h) * v.enu.north + std::sin(h) * v.enu.east;
  glm::dvec3 right = std::cos(h) * v.enu.east - std::sin(h) * v.enu.north;
  glm::dvec3 up = v.enu.up;
  const glm::dvec3 fwdP = std::cos(p) * fwd + std::sin(p) * up;
  up = std::cos(p) * up - std::sin(p) * fwd;
  fwd = fwdP;
  const glm::dvec3 rightR = std::cos(r) * right - std::sin(r) * up;
  up = std::cos(r) * up + std::sin(r) * right;
  right = rightR;
  v.forward = glm::normalize(fwd);
  v.right = glm::normalize(right);
  v.up = glm::normalize(up);
  return v;
}

glm::dmat3 CameraView::viewRotation() const {
  // Rows right, up, -forward (glm is column-major: build the transpose's columns).
  return glm::transpose(glm::dmat3(right, up, -forward));
}

glm::dmat4 CameraView::projection() const {
  const double f = 1.0 / std::tan(0.5 * verticalFovRad);
  glm::dmat4 m(0.0);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][3] = -1.0;  // clip w = -z_view
  m[3][2] = nearM; // clip z = near  ->  ndc z = near / distance
  return m;
}

glm::dmat4 CameraView::viewProjection() const { return projection() * glm::dmat4(viewRotation()); }

double smallestPixelAngleRad(const CameraView& view, int heightPx, double offAxisRad) {
  const double tanY = std::tan(0.5 * view.verticalFovRad);
  const double tanCorner2 = tanY * tanY * (1.0 + view.aspect * view.aspect);
  const double tanOff = std::tan(std::clamp(offAxisRad, 0.0, 0.5 * std::numbers::pi));
  return 2.0 * tanY / heightPx / (1.0 + std::min(tanOff * tanOff, tanCorner2));  // cos² = 1 / (1 + tan²)
}

double smallestGroundFootprintRad(const CameraView& view, int heightPx, double highestGroundM) {
  const double nearestM = view.position.heightM - highestGroundM;
  if (nearestM <= 0.0 || heightPx <= 0) return 0.0;
  return nearestM * smallestPixelAngleRad(view, heightPx) / kWgs84SemiMajorM;
}

glm::dvec3 CameraView::rayDirection(double ndcX, double ndcY) const {
  const double t = std::tan(0.5 * verticalFovRad);
  return glm::normalize(forward + (ndcX * t * aspect) * right + (ndcY * t) * up);
}

namespace {
// The line eye + t dir against the ellipsoid raised by heightM, in space scaled so that it is
// the unit sphere: A t² + 2 B t + C = 0, with the constant term C = |o|² - 1 in double (it
// keeps a metre above the sea).
struct ScaledCrossing {
  double A, B, C, disc;
};
ScaledCrossing scaledCrossing(const glm::dvec3& eye, const glm::dvec3& dir, double heightM) {
  const double a = kWgs84SemiMajorM + heightM, b = kWgs84SemiMinorM + heightM;
  const glm::dvec3 o{eye.x / a, eye.y / a, eye.z / b};
  const glm::dvec3 d{dir.x / a, dir.y / a, dir.z / b};
  const double A = glm::dot(d, d), B = glm::dot(o, d), C = glm::dot(o, o) - 1.0;
  return {A, B, C, B * B - A * C};
}
}  // namespace

std::optional<double> intersectEllipsoid(const glm::dvec3& eye, const glm::dvec3& dir,
                                         double heightM) {
  const auto [A, B, C, disc] = scaledCrossing(eye, dir, heightM);
  if (disc < 0.0) return std::nullopt;
  if (C < 0.0) return (-B + std::sqrt(disc)) / A;  // inside: the exit point
  if (B >= 0.0) return std::nullopt;               // outside and looking away
  return C / (-B + std::sqrt(disc));               // stable form of the near root
}

std::optional<std::pair<double, double>> ellipsoidCrossings(const glm::dvec3& eye, const glm::dvec3& dir,
                                                            double heightM) {
  const auto [A, B, C, disc] = scaledCrossing(eye, dir, heightM);
  if (disc < 0.0) return std::nullopt;
  const double root = std::sqrt(disc);
  return std::pair{(-B - root) / A, (-B + root) / A};
}

}  // namespace og::geo
