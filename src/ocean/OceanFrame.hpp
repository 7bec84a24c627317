#pragma once
// The local ocean frame (Bruneton 2010 §6, as Proland does it): a tangent plane at the sea point
// under the camera, rebuilt in double precision whenever the camera moves, with the wave phases
// carried across rebuilds so waves stay fixed to the Earth and never jump. The GPU only sees
// positions in this frame (metres, within a few hundred km of its origin) and per-wave phases
// already reduced modulo 2 pi.
#include <glm/glm.hpp>

#include <vector>

#include "geo/Wgs84.hpp"
#include "ocean/WaveSet.hpp"

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

  /// Per-wave phases at time t for this frame: theta_i(x) = phase_i - k_i . x with x the
  /// position in this frame's tangent plane (east, north, metres); reduced modulo 2 pi in double.
  /// Also returns the wave vectors in this frame's axes.
  struct WavePhases {
    std::vector<glm::dvec2> k;      ///< rad/m, east/north in this frame
    std::vector<double> phaseRad;   ///< [0, 2 pi)
  };
  [[nodiscard]] WavePhases phases(const WaveSet& waves, double timeS) const;

 private:
  glm::dvec3 origin_{0.0};
  geo::EnuFrame axes_;
  glm::dvec2 offset_{0.0};
  double rotation_ = 0.0;
};

}  // namespace og::ocean
