#pragma once
// Camera flight paths through keyframes, usable from orbit (400 km) down to a few metres.
//
// Every channel is a piecewise cubic Hermite curve in time, C1 through the keyframes:
//   - ground track: a cubic Bézier built by de Casteljau's construction with *geodesic*
//     interpolation on the WGS84 ellipsoid (GeographicLib), so two keyframes are joined along
//     their geodesic and the velocity is continuous where segments meet;
//   - height: interpolated in log space, so the descent covers equal ratios in equal times and
//     the perceived speed stays even from 400 km to 2 m;
//   - heading along the shortest arc (350° -> 10° passes through 0°), pitch, roll and field of
//     view as plain scalars (no quaternion round trip, so no flips at pitch -90°).
// Tangents are shape-preserving (Fritsch-Carlson style): a channel that is monotone between
// keyframes stays monotone, and nothing overshoots past a keyframe.
#include <string>
#include <string_view>
#include <optional>
#include <vector>

#include "geo/Camera.hpp"

namespace og::geo {

/// How the camera moves through the segment that starts at a keyframe. Easing is expressed
/// through the tangents so the path stays C1: an eased end of a segment is a point where the
/// camera comes to rest (zero velocity in every channel).
enum class Easing {
  Smooth,     ///< pass through without stopping (default)
  EaseIn,     ///< start the segment from rest
  EaseOut,    ///< come to rest at the end of the segment
  EaseInOut,  ///< both
};

/// "smooth" | "ease-in" | "ease-out" | "ease-in-out"; nullopt for anything else.
std::optional<Easing> parseEasing(std::string_view name);
const char* easingName(Easing e);

struct Keyframe {
  CameraPose pose;
  double timeS = 0.0;             ///< seconds from the start of the path, strictly increasing
  Easing easing = Easing::Smooth; ///< for the segment from this keyframe to the next
};

class FlightPath {
 public:
  /// At least one keyframe, times strictly increasing and finite, poses valid (validatePose).
  /// Throws og::InputError naming the keyframe (1-based) otherwise.
  explicit FlightPath(std::vector<Keyframe> keyframes);

  /// Time of the first and last keyframe, seconds.
  [[nodiscard]] double startS() const { return keys_.front().timeS; }
  [[nodiscard]] double endS() const { return keys_.back().timeS; }
  [[nodiscard]] double durationS() const { return endS() - startS(); }
  [[nodiscard]] const std::vector<Keyframe>& keyframes() const { return keys_; }

  /// The camera at time `t` seconds (clamped to [startS, endS]). Heading is returned in
  /// [0, 360), longitude in [-180, 180].
  [[nodiscard]] CameraPose at(double t) const;

 private:
  struct Channel {  // one scalar per keyframe and its tangent (units per second)
    std::vector<double> value, slope;
    [[nodiscard]] double eval(std::size_t k, double u, double dt) const;
  };
  struct Segment {
    double latC1 = 0, lonC1 = 0;  // Bézier control point leaving keyframe k
    double latC2 = 0, lonC2 = 0;  // control point arriving at keyframe k+1
  };

  std::vector<Keyframe> keys_;
  std::vector<Segment> segments_;
  double heightFloorM_ = 0.0;  // log space is log(height - floor)
  Channel logHeight_, heading_, pitch_, roll_, fov_;
};

}  // namespace og::geo
