#pragma once
// The geodetic camera. State is kept in double precision; the GPU only receives directions and
// camera-relative quantities (a float step at Earth radius is 0.5 m).
#include <glm/glm.hpp>
#include <numbers>
#include <optional>
#include <utility>
#include <string>

#include "geo/Wgs84.hpp"

namespace og::geo {

/// The camera as a user states it.
struct CameraPose {
  Geodetic position{0.0, 0.0, 1.0e7};
  double headingDeg = 0.0;      ///< clockwise from north, any finite value (mod 360)
  double pitchDeg = -90.0;      ///< 0 = horizontal, -90 = straight down, +90 = straight up
  double rollDeg = 0.0;         ///< clockwise about the view direction, [-180, 180]
  double verticalFovDeg = 45.0; ///< (0.1, 170)
};

/// Why a pose cannot be used (a one-line message naming the field), or nullopt when valid.
std::optional<std::string> validatePose(const CameraPose& pose);

/// The lowest eye height above the ellipsoid the renderer uses; lower requests (0, negative)
/// are lifted to it so the eye is never inside the planet.
inline constexpr double kMinEyeHeightM = 0.1;

/// Everything the renderer needs, derived from a pose in double precision.
struct CameraView {
  Geodetic position;        ///< the pose's position with the height clamped
  glm::dvec3 positionEcef;  ///< eye, ECEF metres
  EnuFrame enu;             ///< local frame under the eye
  glm::dvec3 forward;       ///< unit view direction, ECEF axes
  glm::dvec3 right;         ///< unit, ECEF axes
  glm::dvec3 up;            ///< unit, ECEF axes (image up)
  double verticalFovRad = 0.0;
  double aspect = 1.0;      ///< width / height
  double nearM = 0.05;      ///< near plane; there is no far plane (reversed-Z, infinite)

  /// Rotation taking a camera-relative ECEF vector to view space (x right, y up, -z forward).
  [[nodiscard]] glm::dmat3 viewRotation() const;
  /// Reversed-Z infinite perspective for glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE):
  /// depth = near / distance along the view axis, 1 at the near plane, -> 0 at infinity.
  [[nodiscard]] glm::dmat4 projection() const;
  /// projection * view for camera-relative ECEF positions (what vertex shaders get, as float).
  [[nodiscard]] glm::dmat4 viewProjection() const;
  /// Unit ray through normalised device coordinates (-1..1), ECEF axes.
  [[nodiscard]] glm::dvec3 rayDirection(double ndcX, double ndcY) const;
  /// Position relative to the eye: the only form in which positions reach the GPU.
  [[nodiscard]] glm::dvec3 relative(const glm::dvec3& ecef) const { return ecef - positionEcef; }
};

/// Builds the view for an image of width x height pixels. The pose must be valid
/// (validatePose); heading/pitch/roll are applied as rotations, so straight down at a pole or
/// straight up are as well defined as any other orientation.
CameraView makeCameraView(const CameraPose& pose, int widthPx, int heightPx);

/// The smallest angle between neighbouring pixels' rays (rad) in `view` (`heightPx` pixels
/// tall) within `offAxisRad` of its axis: 2 tan(fov / 2) / height at the centre, times cos² of
/// the ray's angle to the axis (d atan) at worst; no smaller than at the screen's corners.
double smallestPixelAngleRad(const CameraView& view, int heightPx, double offAxisRad = std::numbers::pi);
/// A lower bound of a pixel's footprint on the ground anywhere in `view` (`heightPx` pixels
/// tall), radians of arc: the ground's least distance (the eye's height less `highestGroundM`)
/// times the smallest angle between neighbouring pixels' rays (at the screen's corners), over
/// the semi-major axis. What the shaders' per-pixel footprints (terrain/landmask.glsl's
/// coastFootprintRad, the terrain's detail footprint) cannot fall below; 0 when the eye is not
/// above `highestGroundM`.
double smallestGroundFootprintRad(const CameraView& view, int heightPx, double highestGroundM);
/// Above the highest ground on Earth (Everest, 8849 m), m.
inline constexpr double kHighestGroundM = 9000.0;

/// Exact near intersection of a ray from the eye with the ellipsoid raised by `heightM`,
/// as a distance in metres, or nullopt when the ray misses. Computed in the ellipsoid's scaled
/// space with the constant term taken in double, so it stays accurate at 1 m above the sea.
std::optional<double> intersectEllipsoid(const glm::dvec3& eyeEcef, const glm::dvec3& dir,
                                         double heightM = 0.0);

/// Both distances (near, far; negative behind the eye) where the line from the eye along `dir`
/// crosses the ellipsoid raised by `heightM`, as intersectEllipsoid computes them, or nullopt
/// when it misses: the line is inside between them.
std::optional<std::pair<double, double>> ellipsoidCrossings(const glm::dvec3& eyeEcef, const glm::dvec3& dir,
                                                            double heightM = 0.0);

}  // namespace og::geo
