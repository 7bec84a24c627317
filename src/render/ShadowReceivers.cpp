#include "render/ShadowReceivers.hpp"

#include <algorithm>
#include <cmath>

namespace og::render {

LightRect shadowReceiverRect(const geo::CameraView& view, const glm::dvec3& lx, const glm::dvec3& ly,
                             double nearM, double farM, double lowM, double highM) {
  LightRect rect;
  double farthestM = 0.0;
  auto addPoint = [&](const glm::dvec3& dir, double t) {
    const glm::dvec3 p = t * dir;
    rect.add({glm::dot(p, lx), glm::dot(p, ly)});
    farthestM = std::max(farthestM, t);
  };
  // A stretch [a, b] of the ray within the distances.
  auto addStretch = [&](const glm::dvec3& dir, double a, double b) {
    a = std::max(a, nearM);
    b = std::min(b, farM);
    if (a > b) return;
    addPoint(dir, a);
    addPoint(dir, b);
  };
  constexpr int n = kShadowReceiverRays;
  const double tanY = std::tan(0.5 * view.verticalFovRad), tanX = tanY * view.aspect;
  const double stepRad = std::sqrt(2.0) * 2.0 * std::max(tanX, tanY) / n;  // to a diagonal neighbour, at most
  // The farthest a ray that passes just over the floor meets the slab: to the floor's tangent
  // point, then on to the upper surface (spheres of the eye's geocentric radius less its
  // height, and 1 % for the ellipsoid's curvature against them).
  const double eyeR = glm::length(view.positionEcef), groundR = eyeR - view.position.heightM;
  const double lowR = groundR + lowM, highR = groundR + highM;
  const double overFloorM =
      1.01 * (std::sqrt(std::max(eyeR * eyeR - lowR * lowR, 0.0)) + std::sqrt(std::max(highR * highR - lowR * lowR, 0.0)));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const glm::dvec3 dir = view.rayDirection(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n);
      const auto below = geo::ellipsoidCrossings(view.positionEcef, dir, highM);
      if (!below || below->second < 0.0) continue;
      const double enter = std::max(below->first, 0.0), leave = below->second;
      // The slab is the inside of the upper surface less the inside of the lower one.
      const auto under = geo::ellipsoidCrossings(view.positionEcef, dir, lowM);
      if (!under || under->second < enter || under->first > leave) {
        addStretch(dir, enter, leave);
        continue;
      }
      // Below lowM all is ground: a ray that reaches it from above stops there; one from an eye
      // below it leaves it.
      if (under->first > enter) {
        addStretch(dir, enter, under->first);
        // But a ray between it and its neighbours may pass just over the floor and meet the
        // slab beyond it, out to overFloorM: where this ray's chord through the floor's shell
        // is as short as a ray step's turn allows (half-chord L with L² < 2 ρ t δ, t the
        // chord's middle, ρ the shell's radius, δ the step), out to there along this ray. (Not
        // its own stretch past the chord: for a longer chord that lies behind the planet,
        // 12 700 km on from 2 m.)
        const double half = 0.5 * (under->second - under->first), middle = 0.5 * (under->first + under->second);
        if (half * half < 2.0 * lowR * middle * stepRad) addStretch(dir, under->first, overFloorM);
      } else if (under->second < leave) {
        addStretch(dir, under->second, leave);
      }
    }
  if (rect.empty()) return rect;
  // Between neighbouring rays: their angle (at most a step of tan) at the farthest point, and
  // a share of the size for the stretches' ends, which move faster near grazing.
  const double pad = farthestM * 2.0 * std::max(tanX, tanY) / n + 0.02 * std::max(rect.hi.x - rect.lo.x, rect.hi.y - rect.lo.y);
  rect.lo -= pad;
  rect.hi += pad;
  return rect;
}

}  // namespace og::render
