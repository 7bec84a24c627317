#include "ocean/OceanFrame.hpp"

#include <cmath>

namespace og::ocean {

void OceanFrame::reset(const geo::Geodetic& camera) {
  origin_ = geo::geodeticToEcef({camera.latitudeDeg, camera.longitudeDeg, 0.0});
  axes_ = geo::enuFrameAt(camera.latitudeDeg, camera.longitudeDeg);
  offset_ = glm::dvec2(0.0);
  rotation_ = 0.0;
}

void OceanFrame::moveTo(const geo::Geodetic& camera) {
  const glm::dvec3 newOrigin = geo::geodeticToEcef({camera.latitudeDeg, camera.longitudeDeg, 0.0});
  const geo::EnuFrame newAxes = geo::enuFrameAt(camera.latitudeDeg, camera.longitudeDeg);
  // The move in the old tangent plane.
  const glm::dvec3 d = axes_.toEnu(newOrigin - origin_);
  // Old east axis seen in the new frame: the rotation between the two tangent planes' axes
  // about the vertical (meridian convergence for east-west moves).
  const double angle = std::atan2(glm::dot(axes_.east, newAxes.north), glm::dot(axes_.east, newAxes.east));
  const glm::dvec2 moved = offset_ + glm::dvec2(d.x, d.y);
  const double c = std::cos(angle), s = std::sin(angle);
  offset_ = {c * moved.x - s * moved.y, s * moved.x + c * moved.y};
  rotation_ += angle;
  origin_ = newOrigin;
  axes_ = newAxes;
}

glm::dvec2 OceanFrame::fieldOffsetModulo(double tileM) const {
  const double c = std::cos(rotation_), s = std::sin(rotation_);
  const glm::dvec2 field{c * offset_.x + s * offset_.y, -s * offset_.x + c * offset_.y};
  auto fold = [tileM](double v) {
    const double r = std::fmod(v, tileM);
    return r < 0.0 ? r + tileM : r;
  };
  return {fold(field.x), fold(field.y)};
}

}  // namespace og::ocean
