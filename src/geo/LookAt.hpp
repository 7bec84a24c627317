#pragma once
// Views that look at a point, as Google Earth's KML <LookAt> states them, and orbits around one.
//
// A look-at view names the target and where the eye stands relative to it: `rangeM` metres away
// along the direction `headingDeg` (the way the eye looks, clockwise from north) tilted
// `tiltDeg` from the target's vertical (0 = looking straight down at it, 90 = level). The
// frame is the target's local East-North-Up frame, so the eye is exact at any range, from a
// few metres to orbit.
#include <optional>
#include <string>

#include "geo/Camera.hpp"

namespace og::geo {

struct LookAt {
  Geodetic target;          ///< the point looked at, height above the ellipsoid
  double rangeM = 1000.0;   ///< eye to target, metres, [0, 1e9]
  double headingDeg = 0.0;  ///< direction of view, clockwise from north at the target (mod 360)
  double tiltDeg = 0.0;     ///< 0 = straight down, 90 = level, [0, 90]
};

/// Why a look-at view cannot be used (one line naming the field), or nullopt when valid.
std::optional<std::string> validateLookAt(const LookAt& view);

/// The camera pose whose eye sees `view.target` at the centre of the image. Heading and pitch
/// are those of the same view direction in the eye's own frame (they differ from the target's
/// by the Earth's curvature between them); the image is upright (the target's vertical stays
/// vertical) before `rollDeg` is applied.
CameraPose cameraFromLookAt(const LookAt& view, double rollDeg, double verticalFovDeg);

/// The view direction (unit, ECEF axes) of a look-at view.
glm::dvec3 lookAtDirection(const LookAt& view);

}  // namespace og::geo
