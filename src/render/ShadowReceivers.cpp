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
      // Below lowM all is ground: a ray that reaches it from above stops there (the stretch
      // past its far crossing lies behind the planet); one from an eye below it leaves it.
      if (under->first > enter)
        addStretch(dir, enter, under->first);
      else if (under->second < leave)
        addStretch(dir, under->second, leave);
    }
  if (rect.empty()) return rect;
  // Between neighbouring rays: their angle (at most a step of tan) at the farthest point, and
  // a share of the size for the stretches' ends, which move faster near grazing.
  const double tanY = std::tan(0.5 * view.verticalFovRad), tanX = tanY * view.aspect;
  const double pad = farthestM * 2.0 * std::max(tanX, tanY) / n + 0.02 * std::max(rect.hi.x - rect.lo.x, rect.hi.y - rect.lo.y);
  rect.lo -= pad;
  rect.hi += pad;
  return rect;
}

}  // namespace og::render
