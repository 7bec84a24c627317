#include "terrain/Selection.hpp"

#include <algorithm>
#include <cmath>

namespace og::terrain {
namespace {

// The occluder: WGS84 scaled by (1 - 11.5 km / b), inside every point of relief or bathymetry.
constexpr double kOccluderScale = 1.0 - 11500.0 / geo::kWgs84SemiMinorM;

glm::dvec3 toScaled(const glm::dvec3& p) {
  return p / glm::dvec3(geo::kWgs84SemiMajorM, geo::kWgs84SemiMajorM, geo::kWgs84SemiMinorM);
}

constexpr int kPolarMaxLevel = 7;

void selectRecursive(TileCache& cache, const geo::CameraView& view, const SelectionParams& p,
                     const TileKey& key, std::vector<const Tile*>& out, SelectionStats& stats) {
  const Tile& t = cache.get(key);
  ++stats.visited;
  if (!inFrustum(view, p.widthPx, p.heightPx, t.boundCentreEcef, t.boundRadiusM)) {
    ++stats.culledFrustum;
    return;
  }
  if (!aboveHorizon(view.positionEcef, t.boundCentreEcef, t.boundRadiusM)) {
    ++stats.culledHorizon;
    return;
  }
  // Tiles touching a pole are wedges that all meet there: splitting them at the same rate as
  // elsewhere multiplies tiles around the whole ring (2^(level+1) of them) for a few metres of
  // east-west extent. They stop at kPolarMaxLevel (~4 km spacing); tiles off the pole split on.
  const bool polar = key.southDeg() <= -90.0 + 1e-9 || key.southDeg() + key.sizeDeg() >= 90.0 - 1e-9;
  const int maxLevel = polar ? std::min(p.maxLevel, kPolarMaxLevel) : p.maxLevel;
  const bool split = key.level < maxLevel &&
                     (key.level < p.minLevel || tileErrorPx(view, p.heightPx, t) > p.maxSpacingPx);
  if (!split) {
    out.push_back(&t);
    stats.finestLevel = std::max(stats.finestLevel, key.level);
    return;
  }
  for (int i = 0; i < 4; ++i) selectRecursive(cache, view, p, key.child(i), out, stats);
}

}  // namespace

bool aboveHorizon(const glm::dvec3& eyeEcef, const glm::dvec3& centreEcef, double radiusM) {
  // In the ellipsoid's scaled space the occluder is a sphere of radius s; an affine map keeps
  // lines of sight, and the tile's sphere maps into a sphere of radius r / b.
  const glm::dvec3 e = toScaled(eyeEcef), c = toScaled(centreEcef);
  const double r = radiusM / geo::kWgs84SemiMinorM;
  const double s2 = kOccluderScale * kOccluderScale;
  const double e2 = glm::dot(e, e);
  if (e2 <= s2) return true;
  // A point at radius rho is visible iff its distance to the eye is at most the sum of the two
  // tangent lengths, sqrt(|e|² - s²) + sqrt(rho² - s²); the sphere's nearest point is at
  // |c - e| - r and no point is farther out than |c| + r
  // (and none is higher than the highest summit: 9 km above the ellipsoid).
  const double rhoMax = std::min(std::sqrt(glm::dot(c, c)) + r, 1.0 + 9000.0 / geo::kWgs84SemiMinorM);
  if (rhoMax * rhoMax <= s2) return false;
  const double reach = std::sqrt(e2 - s2) + std::sqrt(rhoMax * rhoMax - s2);
  return glm::length(c - e) - r <= reach;
}

bool inFrustum(const geo::CameraView& view, int widthPx, int heightPx, const glm::dvec3& centreEcef,
               double radiusM) {
  const double tanY = std::tan(0.5 * view.verticalFovRad);
  const double tanX = tanY * static_cast<double>(widthPx) / static_cast<double>(heightPx);
  const glm::dvec3 d = centreEcef - view.positionEcef;
  // Inward normals of the side planes through the eye.
  const glm::dvec3 planes[4] = {glm::normalize(tanX * view.forward + view.right),
                                glm::normalize(tanX * view.forward - view.right),
                                glm::normalize(tanY * view.forward + view.up),
                                glm::normalize(tanY * view.forward - view.up)};
  for (const auto& n : planes)
    if (glm::dot(n, d) < -radiusM) return false;
  return true;
}

double tileErrorPx(const geo::CameraView& view, int heightPx, const Tile& tile) {
  const double distance =
      std::max(glm::length(tile.boundCentreEcef - view.positionEcef) - tile.boundRadiusM, 1.0);
  const double pixelsPerRadian = heightPx / (2.0 * std::tan(0.5 * view.verticalFovRad));
  const double weight = tile.maxHeightM < -50.0 ? 0.25 : 1.0;
  return weight * tile.spacingM / distance * pixelsPerRadian;
}

std::vector<const Tile*> selectTiles(TileCache& cache, const geo::CameraView& view,
                                     const SelectionParams& params, SelectionStats* stats) {
  cache.beginFrame();
  std::vector<const Tile*> out;
  SelectionStats local;
  for (int x = 0; x < 2; ++x) selectRecursive(cache, view, params, TileKey{0, x, 0}, out, local);
  if (stats != nullptr) *stats = local;
  return out;
}

}  // namespace og::terrain
