#pragma once
// Where a shadow cascade's receivers can be (render/TerrainRenderer::renderShadowMap): a
// caster shades only points with its own position across the Sun's rays, so a cascade needs
// its map only over the receivers the screen shows in its range of distances, not over every
// tile within its reach (half of which may lie behind the eye or beside the view).
#include <glm/glm.hpp>

#include "geo/Camera.hpp"

namespace og::render {

/// A rectangle across the Sun's rays: x along lx, y along ly (unit, ECEF axes, normal to the
/// Sun's direction), metres, camera-relative. Empty until a point is added.
struct LightRect {
  glm::dvec2 lo{1e300};
  glm::dvec2 hi{-1e300};
  [[nodiscard]] bool empty() const { return !(hi.x >= lo.x && hi.y >= lo.y); }
  void add(const glm::dvec2& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

/// Rays over the screen that shadowReceiverRect follows, per side.
inline constexpr int kShadowReceiverRays = 32;

/// The rectangle (across the Sun's rays lx, ly) holding every point `view` can show whose
/// distance from the eye is in [nearM, farM] and whose height above the WGS84 ellipsoid is in
/// [lowM, highM] (the ellipsoid raised by each, as geo::intersectEllipsoid raises it): the
/// ends of each ray's stretches within that shell and slab, for (kShadowReceiverRays + 1)²
/// rays over the screen, widened by the angle between neighbouring rays at the farthest end
/// and by 2 % of its size (the stretches between the rays). All under lowM is ground: a ray
/// stops there, but where one between it and its neighbours may pass just over that floor the
/// stretch goes on to the farthest such a ray meets the slab. Empty when no ray meets the slab
/// within the distances.
[[nodiscard]] LightRect shadowReceiverRect(const geo::CameraView& view, const glm::dvec3& lx, const glm::dvec3& ly,
                                           double nearM, double farM, double lowM, double highM);

}  // namespace og::render
