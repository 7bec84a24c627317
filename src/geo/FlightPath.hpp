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
//
// Two ways through the keyframes, chosen per path (Interpolation):
//   - Geodesic (the default): the above; the ground track and the height are separate curves.
//   - Smooth: one centripetal Catmull-Rom curve through the keyframes in a space of ECEF ground
//     point and log height, so the direction of flight (in 3D, height included) turns
//     continuously through every keyframe; its knots are spaced by the square root of the
//     perceived distance (ground distance over the mean height, and the log of the height
//     ratio), which keeps it free of loops and cusps. The log-height tangents are limited
//     (Fritsch-Carlson) so the height never dips below the lower keyframe of a segment: no
//     overshoot into the sea or the ground.
//
// Look-at keyframes (geo/LookAt.hpp) give a target instead of an eye. When every keyframe of a
// path looks at a point, the target, the range (log space), heading and tilt are interpolated
// and the eye follows from them: keyframes circling one target orbit it at a constant range.
// Otherwise look-at keyframes fly like the camera keyframes they stand for.
#include <string>
#include <string_view>
#include <optional>
#include <vector>

#include "geo/Camera.hpp"
#include "geo/LookAt.hpp"

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

/// How the camera passes through keyframes (see the top of this file).
enum class Interpolation {
  Geodesic,  ///< geodesic ground track and log height as separate C1 curves (default)
  Smooth,    ///< one centripetal Catmull-Rom curve: continuous direction in 3D
};

/// "geodesic" | "smooth"; nullopt for anything else.
std::optional<Interpolation> parseInterpolation(std::string_view name);
const char* interpolationName(Interpolation i);

struct Keyframe {
  /// The camera. For a look-at keyframe it is derived: cameraFromLookAt(*lookAt, pose.rollDeg,
  /// pose.verticalFovDeg) (FlightPath recomputes it; use lookAtKeyframe to make one).
  CameraPose pose;
  std::optional<LookAt> lookAt;   ///< set for a keyframe that looks at a point
  double timeS = 0.0;             ///< seconds from the start of the path, strictly increasing
  Easing easing = Easing::Smooth; ///< for the segment from this keyframe to the next
};

/// A keyframe looking at `view.target`, with its camera pose derived.
Keyframe lookAtKeyframe(const LookAt& view, double rollDeg, double verticalFovDeg, double timeS,
                        Easing easing = Easing::Smooth);

/// A circle around a point: the eye keeps the range and tilt and turns its heading.
struct Orbit {
  LookAt start;              ///< target, range, tilt and the heading at the start
  double degrees = 360.0;    ///< how far round; positive turns clockwise seen from above
  double durationS = 30.0;   ///< > 0
  double rollDeg = 0.0;
  double verticalFovDeg = 45.0;
  Easing easing = Easing::Smooth;  ///< ease-in: start from rest, ease-out: stop at the end
};

/// Look-at keyframes for an orbit, one every 30 degrees or less at even times, so that the
/// path turns at a constant rate (eased at the ends as asked). Throws og::InputError.
std::vector<Keyframe> orbitKeyframes(const Orbit& orbit);

class FlightPath {
 public:
  /// At least one keyframe, times strictly increasing and finite, poses valid (validatePose,
  /// validateLookAt). Throws og::InputError naming the keyframe (1-based) otherwise.
  explicit FlightPath(std::vector<Keyframe> keyframes,
                      Interpolation interpolation = Interpolation::Geodesic);

  /// Time of the first and last keyframe, seconds.
  [[nodiscard]] double startS() const { return keys_.front().timeS; }
  [[nodiscard]] double endS() const { return keys_.back().timeS; }
  [[nodiscard]] double durationS() const { return endS() - startS(); }
  [[nodiscard]] const std::vector<Keyframe>& keyframes() const { return keys_; }
  [[nodiscard]] Interpolation interpolation() const { return interpolation_; }
  /// Every keyframe looks at a point: the targets are interpolated, the eye follows.
  [[nodiscard]] bool followsTargets() const { return followsTargets_; }

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
  /// What is interpolated at a keyframe: the eye (camera keyframes) or the target (when every
  /// keyframe looks at one). `spanM` is the height (eye) or the range (target), taken in log
  /// space; `targetHeightM` is the target's height; `pitchDeg` is the pitch or the tilt.
  struct State {
    double latDeg = 0, lonDeg = 0, spanM = 0, targetHeightM = 0;
    double headingDeg = 0, pitchDeg = 0, rollDeg = 0, fovDeg = 0;
  };

  [[nodiscard]] State stateOf(const Keyframe& key) const;
  [[nodiscard]] CameraPose poseOf(const State& state) const;
  void buildGeodesicTrack(const std::vector<State>& states);
  void buildSmoothTrack(const std::vector<State>& states);
  [[nodiscard]] bool atRest(std::size_t k) const;
  [[nodiscard]] double interval(std::size_t k) const { return keys_[k + 1].timeS - keys_[k].timeS; }
  void fitChannel(Channel& c) const;

  std::vector<Keyframe> keys_;
  Interpolation interpolation_ = Interpolation::Geodesic;
  bool followsTargets_ = false;
  std::vector<State> states_;           // per keyframe
  std::vector<Segment> segments_;       // geodesic track
  std::vector<double> knots_;           // smooth track: curve parameter at each keyframe
  std::vector<glm::dvec4> points_, tangents_;  // smooth track: (ECEF ground point, log span)
  double floorM_ = 0.0;  // log space is log(span - floor)
  Channel logSpan_, targetHeight_, heading_, pitch_, roll_, fov_, progress_;
};

}  // namespace og::geo
