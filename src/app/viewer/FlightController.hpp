#pragma once
// Camera controls for the interactive viewer, usable from 0.5 m above the sea to 100 000 km:
// every speed is proportional to the height above the surface, so one key press covers the
// same fraction of the view at any height. State is a geo::CameraPose in double precision.
// No GL and no window system here: the viewer feeds it key states, drags and scroll steps.
#include <functional>
#include <optional>

#include <glm/glm.hpp>

#include "geo/Camera.hpp"

namespace og::app::viewer {

/// Height of the surface the camera must stay above at a point (degrees), metres above the
/// ellipsoid: the sea (0) or the land's elevation.
using SurfaceHeight = std::function<double(double latitudeDeg, double longitudeDeg)>;

/// Closest the eye may come to the surface, metres.
inline constexpr double kMinClearanceM = 0.5;
/// Highest the eye may go, metres above the ellipsoid (a quarter of the way to the Moon).
inline constexpr double kMaxHeightM = 1.0e8;
/// Translation speed per metre of height above the surface, 1/s: in one second the camera
/// moves as far as it is high (a descent from 20 000 km to 1 m takes about 17 s).
inline constexpr double kSpeedPerHeight = 1.0;
/// Roll rate of the roll keys, degrees per second.
inline constexpr double kRollRateDegS = 60.0;
/// Longest time step one update integrates, seconds (a slow frame must not fling the camera).
inline constexpr double kMaxStepS = 0.25;

/// Held movement keys for one update, each axis in [-1, 1].
struct MoveInput {
  double forward = 0.0;  ///< + along the view direction
  double right = 0.0;    ///< + towards the image's right
  double up = 0.0;       ///< + away from the surface (local vertical)
  double roll = 0.0;     ///< + clockwise
  double speedFactor = 1.0;  ///< e.g. 5 with Shift, 0.2 with Ctrl
  [[nodiscard]] bool any() const { return forward != 0.0 || right != 0.0 || up != 0.0 || roll != 0.0; }
};

/// The pose whose view (geo::makeCameraView) looks along `forward` with image-up `up` (unit
/// ECEF vectors, perpendicular) from `position`. Straight up or down, the heading follows the
/// image's up and the roll is 0.
geo::CameraPose poseFromOrientation(const geo::Geodetic& position, const glm::dvec3& forward,
                                    const glm::dvec3& up, double verticalFovDeg);

/// Where a camera now at `pose` and moving at `velocityEcef` (m/s) will be `aheadS` seconds on,
/// for fetching what that view needs before it is reached: the straight line, orientation kept
/// (heading, pitch, roll), but no nearer the surface `surfaceM` (metres above the ellipsoid)
/// than a quarter of its height above it now, since speeds scale with that height and a
/// descent slows as it nears the ground.
geo::CameraPose poseAhead(const geo::CameraPose& pose, const glm::dvec3& velocityEcef, double aheadS, double surfaceM);

/// The camera's velocity for prediction (poseAhead), smoothed over frames: each update moves the
/// estimate towards the last frame's displacement / time step by 1 − exp(−dt / kTimeConstantS),
/// so a single key tap or an uneven frame does not fling the prediction, while steady motion is
/// followed within ~3 time constants. A jump farther than kJumpM in one step (a path restarted, a
/// bookmark) starts the estimate afresh at rest.
class VelocityEstimate {
 public:
  /// Smoothing time constant, seconds.
  static constexpr double kTimeConstantS = 0.25;
  /// Farther than this in one update (metres) is a jump, not motion.
  static constexpr double kJumpM = 1.0e7;

  /// Takes the eye's position now (ECEF metres) after `dtS` seconds (> 0; else ignored) and
  /// returns the smoothed velocity, m/s (zero at the first call).
  glm::dvec3 update(const glm::dvec3& eyeEcef, double dtS);
  [[nodiscard]] const glm::dvec3& velocityEcef() const { return velocity_; }

 private:
  glm::dvec3 lastEye_{0.0};
  glm::dvec3 velocity_{0.0};
  bool hasLast_ = false;
};

class FlightController {
 public:
  /// `surface` may be empty: then the surface is the sea everywhere.
  explicit FlightController(const geo::CameraPose& pose, SurfaceHeight surface = {});

  [[nodiscard]] const geo::CameraPose& pose() const { return pose_; }
  /// Replaces the pose (e.g. from a path being played), lifted above the surface if needed.
  void setPose(const geo::CameraPose& pose);

  /// Surface height under the camera and the camera's height above it, metres.
  [[nodiscard]] double surfaceHeightM() const;
  [[nodiscard]] double heightAboveSurfaceM() const;
  /// Translation speed at factor 1, m/s.
  [[nodiscard]] double speedMs() const;

  /// Integrates held keys over `dtS` seconds (capped at kMaxStepS).
  void update(const MoveInput& input, double dtS);
  /// Turns the view in place: heading clockwise, pitch up, degrees (pitch clamped to ±90).
  void look(double headingDeg, double pitchDeg);
  /// Rotates eye and view about `pivotEcef`: `yawRad` about the surface normal there (positive
  /// counter-clockwise seen from above), then `tiltRad` about the horizontal axis along the
  /// image's right (positive lowers the eye towards the pivot's horizon). A tilt that would
  /// take the eye below 2° above that horizon or into the surface is dropped.
  void orbit(const glm::dvec3& pivotEcef, double yawRad, double tiltRad);
  /// Moves the eye along the straight line to `targetEcef`, keeping the view's orientation in
  /// space (so the target stays under the same pixel): the distance is multiplied by `factor`
  /// (< 1 closer, > 1 farther).
  void moveToward(const glm::dvec3& targetEcef, double factor);
  /// Moves along the unit ECEF direction `dir` by `distanceM` (negative: backwards), keeping
  /// the orientation in space, never through the surface.
  void moveAlong(const glm::dvec3& dir, double distanceM);
  /// Heading 0 (north at the top) and roll 0; position and pitch unchanged.
  void resetNorthUp();

  /// The point of the sea surface (the ellipsoid) under normalised device coordinates
  /// (-1..1, y up) of a width x height view, ECEF metres, or nullopt where the ray misses.
  [[nodiscard]] std::optional<glm::dvec3> pick(double ndcX, double ndcY, int width, int height) const;

 private:
  [[nodiscard]] double surfaceAt(const geo::Geodetic& g) const;
  // Puts the eye at `eyeEcef`; with `keepSpace` the view keeps its orientation in ECEF,
  // otherwise heading/pitch/roll stay as they are relative to the new local frame.
  void placeEye(const glm::dvec3& eyeEcef, bool keepSpace);
  void clamp();

  geo::CameraPose pose_;
  SurfaceHeight surface_;
};

}  // namespace og::app::viewer
