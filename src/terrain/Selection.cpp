#include "terrain/Selection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace og::terrain {
namespace {

glm::dvec3 toScaled(const glm::dvec3& p) {
  return p / glm::dvec3(geo::kWgs84SemiMajorM, geo::kWgs84SemiMajorM, geo::kWgs84SemiMinorM);
}

constexpr int kPolarMaxLevel = 7;

// Position in the depth-first walk (root, then children 0..3 at each level): sorting the
// selection by it gives the order the recursive walk produced, whatever the walk.
std::uint64_t depthFirstOrder(const TileKey& k) {
  std::uint64_t code = static_cast<std::uint64_t>(k.x >> k.level) << (2 * kMaxLevel + 1);
  for (int l = 1; l <= k.level; ++l) {
    const int shift = k.level - l;
    const auto digit = static_cast<std::uint64_t>(((k.x >> shift) & 1) | (((k.y >> shift) & 1) << 1));
    code |= digit << (2 * (kMaxLevel - l));
  }
  return code;
}

struct Request {
  TileKey key;
  double parentErrorPx;
};

}  // namespace

bool aboveHorizon(const glm::dvec3& eyeEcef, const glm::dvec3& centreEcef, double radiusM,
                  double occluderDepthM, double topHeightM) {
  // In the ellipsoid's scaled space the occluder is a sphere of radius s (inside the ellipsoid
  // lowered by occluderDepthM: no point of it is nearer the centre, scaled, than 1 - depth/b);
  // an affine map keeps lines of sight, and the tile's sphere maps into a sphere of radius r / b.
  const glm::dvec3 e = toScaled(eyeEcef), c = toScaled(centreEcef);
  const double r = radiusM / geo::kWgs84SemiMinorM;
  const double s = 1.0 - occluderDepthM / geo::kWgs84SemiMinorM;
  const double s2 = s * s;
  const double e2 = glm::dot(e, e);
  if (e2 <= s2) return true;
  // A point at radius rho is visible iff its distance to the eye is at most the sum of the two
  // tangent lengths, sqrt(|e|² - s²) + sqrt(rho² - s²); the sphere's nearest point is at
  // |c - e| - r and no point is farther out than |c| + r
  // (nor higher than topHeightM above the ellipsoid: by default 18 km, a layer's 10 km at most
  // plus at most 80 % of it in detail).
  const double rhoMax = std::min(std::sqrt(glm::dot(c, c)) + r, 1.0 + topHeightM / geo::kWgs84SemiMinorM);
  if (rhoMax * rhoMax <= s2) return false;
  const double reach = std::sqrt(e2 - s2) + std::sqrt(rhoMax * rhoMax - s2);
  return glm::length(c - e) - r <= reach;
}

bool aboveSeaHorizon(const glm::dvec3& eyeEcef, const Tile& tile) {
  // + 1 m: the morph's and the chords' rounding.
  return aboveHorizon(eyeEcef, tile.boundCentreEcef, tile.boundRadiusM, kSeaOccluderDepthM,
                      std::max(tile.maxHeightM, 0.0) + 1.0);
}

SeaHorizonCone seaHorizonCone(const geo::CameraView& view, double depthM) {
  // The meridian's radius of curvature under the eye, M = a (1 - e²) / (1 - e² sin² φ)^(3/2),
  // the tightest (the prime vertical's N ≥ M: the ellipsoid stays outside the sphere across).
  constexpr double a = geo::kWgs84SemiMajorM, f = geo::kWgs84Flattening, e2 = f * (2.0 - f);
  const double sinLat = std::sin(view.position.latitudeDeg * std::numbers::pi / 180.0);
  const double meridianM = a * (1.0 - e2) / std::pow(1.0 - e2 * sinLat * sinLat, 1.5);
  // Along a meridian the ellipsoid falls under its osculating sphere by |dκ/ds| d³ / 6 with
  // |dκ/ds| ≤ 1.5 e² / M²: ≤ 4.14e-17 d³ m, and ~0.2 m more at 500 km from higher orders;
  // 5e-17 keeps ~20 % besides (and 1 m for the shader's floats). The rays enter the sphere
  // within its tangent length of the eye, L = sqrt(2 M g) for a gap g under the eye: two
  // rounds for the margin that depends on it.
  const double eyeM = std::max(view.position.heightM, 0.0);
  double gapM = eyeM + depthM + 1.0;
  for (int i = 0; i < 2; ++i) {
    const double tangentM = std::sqrt(2.0 * meridianM * gapM);
    gapM = eyeM + depthM + 1.0 + 5e-17 * tangentM * tangentM * tangentM;
  }
  const double radiusM = meridianM - (gapM - eyeM);  // the sphere's
  const double centreM = eyeM + meridianM;           // its centre's distance from the eye
  const double tangentM = std::sqrt(gapM * (centreM + radiusM));
  return {-view.enu.up, centreM, radiusM, tangentM};
}

bool seaHorizonMayHide(const SeaHorizonCone& c, const glm::dvec3& centreRelative, double radiusM) {
  // (A point inside the cone's sphere is hidden wherever it lies.)
  const double lowest = glm::length(centreRelative - c.centreM * c.axis) - radiusM;
  if (lowest <= c.radiusM) return true;
  const double ownTangentM = std::sqrt((lowest - c.radiusM) * (lowest + c.radiusM));
  return glm::length(centreRelative) + radiusM > c.tangentM + ownTangentM;
}

double seaHorizonClip(const SeaHorizonCone& c, const glm::dvec3& relative) {
  const double along = glm::dot(relative, c.axis);
  const double across = glm::length(relative - along * c.axis);
  return std::max(across * c.cosHalfAngle() - along * c.sinHalfAngle(), c.capM() - along);
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

double tileSpacingPx(const geo::CameraView& view, int heightPx, const Tile& tile, double distanceM) {
  const double pixelsPerRadian = heightPx / (2.0 * std::tan(0.5 * view.verticalFovRad));
  const double weight = tile.coveredBySea() ? 0.25 : 1.0;
  return weight * tile.spacingM / distanceM * pixelsPerRadian;
}

bool deepSeaFloorOnly(const Tile& tile, double unseenFloorDepthM) {
  return tile.coveredBySea() && tile.maxHeightM < -(unseenFloorDepthM + kHiddenRisePerSpacing * tile.spacingM);
}

double tileErrorPx(const geo::CameraView& view, int heightPx, const Tile& tile) {
  const double distance =
      std::max(glm::length(tile.boundCentreEcef - view.positionEcef) - tile.boundRadiusM, 1.0);
  return tileSpacingPx(view, heightPx, tile, distance);
}

std::vector<const Tile*> selectTiles(TileCache& cache, const geo::CameraView& view,
                                     const SelectionParams& p, SelectionStats* stats) {
  cache.beginFrame();
  std::vector<const Tile*> out;
  std::vector<Request> requests;
  SelectionStats st;
  // Progressive mode still builds the few coarse levels now: they are all the globe needs.
  const int syncBelow = std::max(p.minLevel, 1);
  std::vector<TileKey> level{TileKey{0, 0, 0}, TileKey{0, 1, 0}}, next;
  while (!level.empty()) {
    const int l = level.front().level;
    if (p.wait || l < syncBelow) cache.buildMissing(level);  // in parallel
    next.clear();
    for (const TileKey& key : level) {
      const Tile& t = cache.get(key);
      ++st.visited;
      if (!inFrustum(view, p.widthPx, p.heightPx, t.boundCentreEcef, t.boundRadiusM)) {
        ++st.culledFrustum;
        continue;
      }
      if (!aboveHorizon(view.positionEcef, t.boundCentreEcef, t.boundRadiusM)) {
        ++st.culledHorizon;
        continue;
      }
      // Tiles touching a pole are wedges that all meet there: splitting them at the same rate
      // as elsewhere multiplies tiles around the whole ring (2^(level+1) of them) for a few
      // metres of east-west extent. They stop at kPolarMaxLevel (~4 km spacing); tiles off the
      // pole split on.
      const bool polar = key.southDeg() <= -90.0 + 1e-9 || key.southDeg() + key.sizeDeg() >= 90.0 - 1e-9;
      const int maxLevel = polar ? std::min(p.maxLevel, kPolarMaxLevel) : p.maxLevel;
      const double errorPx = tileErrorPx(view, p.heightPx, t);
      const bool split = key.level < maxLevel && (key.level < p.minLevel || errorPx > p.maxSpacingPx);
      if (!split) {
        out.push_back(&t);
        continue;
      }
      if (key.level >= p.minLevel && deepSeaFloorOnly(t, p.unseenFloorDepthM)) {
        out.push_back(&t);
        ++st.deepSeaFloor;
        continue;
      }
      if (!p.wait && l + 1 >= syncBelow) {
        bool ready = true;
        for (int i = 0; i < 4; ++i)
          if (!cache.contains(key.child(i))) {
            ready = false;
            requests.push_back({key.child(i), errorPx});
          }
        if (!ready) {  // drawn until all four children are built (no partial overlap)
          out.push_back(&t);
          ++st.standIns;
          continue;
        }
      }
      for (int i = 0; i < 4; ++i) next.push_back(key.child(i));
    }
    std::swap(level, next);
  }
  // Coarse levels first (they unblock the finer ones), then the worst error. An empty list
  // drops requests of earlier frames no longer needed.
  std::stable_sort(requests.begin(), requests.end(), [](const Request& a, const Request& b) {
    return a.key.level != b.key.level ? a.key.level < b.key.level : a.parentErrorPx > b.parentErrorPx;
  });
  std::vector<TileKey> keys;
  keys.reserve(requests.size());
  for (const Request& r : requests) keys.push_back(r.key);
  cache.request(keys);
  st.pending = cache.pending();

  std::sort(out.begin(), out.end(), [](const Tile* a, const Tile* b) {
    return depthFirstOrder(a->key) < depthFirstOrder(b->key);
  });
  for (const Tile* t : out) st.finestLevel = std::max(st.finestLevel, t->key.level);
  if (stats != nullptr) *stats = st;
  return out;
}

}  // namespace og::terrain
