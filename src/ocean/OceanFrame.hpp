#pragma once
// The local ocean frame (Bruneton 2010 §6, as Proland does it): a tangent plane at the sea point
// under the camera, rebuilt in double precision whenever the camera moves, with the wave phases
// carried across rebuilds so waves stay fixed to the Earth and never jump. The GPU only sees
// positions in this frame (metres, within a few hundred km of its origin) and the wave field's
// offset already folded modulo each wave pattern's tile (fieldOffsetModulo).
#include <glm/glm.hpp>

#include "geo/Wgs84.hpp"

namespace og::ocean {

class OceanFrame {
 public:
  /// Starts a fresh frame at the sea point under `camera` (height ignored): zero offsets.
  void reset(const geo::Geodetic& camera);
  /// Moves the frame to the sea point under `camera`, carrying the wave field: the new frame's
  /// offset is the old one plus the move, expressed in the new axes (parallel transport).
  void moveTo(const geo::Geodetic& camera);

  [[nodiscard]] const glm::dvec3& originEcef() const { return origin_; }
  [[nodiscard]] const geo::EnuFrame& axes() const { return axes_; }
  /// Horizontal position of this frame's origin in the wave field, metres (east, north).
  [[nodiscard]] const glm::dvec2& fieldOffsetM() const { return offset_; }
  /// Rotation of the wave field relative to this frame's east/north axes, radians
  /// (meridian convergence accumulated by moves).
  [[nodiscard]] double fieldRotationRad() const { return rotation_; }

  /// Position of this frame's origin in the wave field, in the field's own axes (the frame's
  /// axes turned by -fieldRotationRad), folded into [0, tileM) per axis, in double: what a
  /// periodic tile of that size shows at the frame's origin. tileM > 0.
  [[nodiscard]] glm::dvec2 fieldOffsetModulo(double tileM) const;

 private:
  glm::dvec3 origin_{0.0};
  geo::EnuFrame axes_;
  glm::dvec2 offset_{0.0};
  double rotation_ = 0.0;
};

}  // namespace og::ocean
