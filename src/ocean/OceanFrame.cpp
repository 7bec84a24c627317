#include "ocean/OceanFrame.hpp"

#include <cmath>
#include <numbers>

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

OceanFrame::WavePhases OceanFrame::phases(const WaveSet& waves, double timeS) const {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  WavePhases out;
  out.k.reserve(waves.waves.size());
  out.phaseRad.reserve(waves.waves.size());
  const double c = std::cos(rotation_), s = std::sin(rotation_);
  for (const Wave& w : waves.waves) {
    const glm::dvec2 k{c * w.kEast - s * w.kNorth, s * w.kEast + c * w.kNorth};
    // theta = omega t + phase0 - k . (x + offset): fold everything but k . x here, in double.
    const double phase = std::fmod(w.omegaRadS * timeS + w.phaseRad - glm::dot(k, offset_), kTwoPi);
    out.k.push_back(k);
    out.phaseRad.push_back(phase < 0.0 ? phase + kTwoPi : phase);
  }
  return out;
}

}  // namespace og::ocean
