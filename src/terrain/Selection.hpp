#pragma once
// View-dependent choice of tiles: a tile is split while its vertex spacing, seen from the
// camera, exceeds a pixel threshold; tiles outside the view frustum or wholly below the
// horizon are dropped. Everything in double precision. The quadtree is walked level by level, so
// the tiles a level needs are built together (in parallel) or, in progressive mode, asked for in
// the background while a built ancestor stands in.
#include <cstddef>
#include <limits>
#include <vector>

#include "geo/Camera.hpp"
#include "terrain/TileCache.hpp"

namespace og::terrain {

struct SelectionParams {
  int widthPx = 640;
  int heightPx = 360;
  /// Largest allowed screen-space error: a tile's vertex spacing in pixels at its nearest point.
  double maxSpacingPx = 12.0;
  int minLevel = 2;        ///< always split down to this level (45° tiles keep the shape round)
  int maxLevel = kMaxLevel;
  /// true: build every tile the view needs before returning (deterministic, complete: render,
  /// record, bench). false (interactive): never wait for a build below minLevel; a tile whose
  /// children are not built yet is drawn in their place and the children are requested from
  /// the background workers, arriving in a later frame.
  bool wait = true;
  /// Sea floor deeper than this below sea level (m, ≥ 0; infinity: off) is out of sight: no
  /// pass draws a tile the sea covers (Tile::coveredBySea; the sea pass computes the floor it
  /// sees through the water itself), so such a tile is split only to find land or a floor
  /// within this depth in it. One whose highest sample is deeper than this plus the rise its
  /// sample spacing could hide (kHiddenRisePerSpacing) is selected as it is (and, covered, not
  /// drawn): none of its descendants would be drawn either (start-up and every frame after:
  /// no sea-floor tiles built over the open ocean, docs/performance.md).
  double unseenFloorDepthM = std::numeric_limits<double>::infinity();
};

/// How far the relief can rise between two samples of a tile, per metre of their spacing:
/// steeper than the layer's bilinear slopes (< 0.1 for ETOPO20) and than sea-floor flanks
/// (seamounts, continental slopes: < 0.5). The coast mask can raise an island out of deep water
/// within about one of its 2′ cells (data::LandMask::constrainHeightM); tiles as fine as the
/// mask sample it, coarser ones are split on unless the water is deeper than their spacing.
inline constexpr double kHiddenRisePerSpacing = 1.0;

/// Whether a tile's descendants are all as unseen as it is (SelectionParams::unseenFloorDepthM).
bool deepSeaFloorOnly(const Tile& tile, double unseenFloorDepthM);

struct SelectionStats {
  int visited = 0;
  int culledFrustum = 0;
  int culledHorizon = 0;
  int finestLevel = 0;
  int standIns = 0;          ///< tiles drawn in place of children not built yet (wait = false)
  int deepSeaFloor = 0;      ///< tiles not split because only unseen sea floor lies under them
  std::size_t pending = 0;   ///< tiles requested or being built after this frame
};

/// Whether a sphere (ECEF centre, radius m) can be seen over the planet from `eyeEcef`: false
/// only when it lies wholly behind the horizon of an ellipsoid inside all terrain (the WGS84
/// one shrunk by 11.5 km). Exact for the occluder, conservative for the sphere. With
/// `occluderDepthM` (m below the ellipsoid, ≥ 0) the occluder is the ellipsoid shrunk by that
/// much instead, and with `topHeightM` no point of the sphere is higher than that above it
/// (default: 18 km, above all terrain).
bool aboveHorizon(const glm::dvec3& eyeEcef, const glm::dvec3& centreEcef, double radiusM,
                  double occluderDepthM = 11500.0, double topHeightM = 18000.0);

/// How far below sea level (m) the drawn surface that hides what lies beyond the horizon can
/// reach where the land mask decides the coast: the sea's wave troughs (the highest seas' are
/// ~30 m deep) with margin, since land there is never below sea level (data::LandMask's
/// constrained heights, Heightfield).
inline constexpr double kSeaOccluderDepthM = 100.0;

/// Whether any drawn point of `tile` can be seen from `eyeEcef` over the sea's horizon (the
/// ellipsoid kSeaOccluderDepthM down: the sea and the land above it hide everything lower
/// beyond it). Drawn points are at most at the tile's highest vertex, or at sea level where
/// the mask raises land out of it (terrain.frag). Only where the land mask decides the coast
/// (Heightfield::coastFromMask): elsewhere dry land may lie below the sea (a regional DEM of
/// the Dead Sea), and aboveHorizon's deep occluder holds.
bool aboveSeaHorizon(const glm::dvec3& eyeEcef, const Tile& tile);

/// The view rays that pass under the sea's lowest surface within the eye's horizon: the cone
/// from the eye tangent to a sphere inside the ellipsoid lowered by `depthM` (the osculating
/// sphere of its tightest curvature under the eye, the meridian's, lowered by depthM and by a
/// margin for how far the ellipsoid falls below it where the rays enter: 5e-17 d³ m at d m
/// along a meridian). A point in the cone beyond its tangent circle's plane lies behind that
/// sphere: where the land mask decides the coast (land never below sea level) the sea's waves
/// or the land hide it (aboveSeaHorizon's argument, at the waves' own depth).
struct SeaHorizonCone {
  glm::dvec3 axis{0.0, 0.0, -1.0};  ///< unit, ECEF axes: from the eye towards the sphere's centre
  double centreM = 1.0, radiusM = 0.0;  ///< the sphere's centre along the axis and its radius, m
  double tangentM = 1.0;                ///< the eye's tangent length to it, m
  /// The cosine and the sine of the cone's half angle (the sphere's angular radius).
  [[nodiscard]] double cosHalfAngle() const { return tangentM / centreM; }
  [[nodiscard]] double sinHalfAngle() const { return radiusM / centreM; }
  /// The tangent circle's plane, m along the axis from the eye.
  [[nodiscard]] double capM() const { return tangentM * cosHalfAngle(); }
};
/// The cone for `view` and the waves' troughs `depthM` (m, ≥ 0) below sea level.
SeaHorizonCone seaHorizonCone(const geo::CameraView& view, double depthM);
/// Negative only for points (ECEF axes, m from the eye) in the cone beyond its cap: the most of
/// the distance-like cone function and the cap's plane. Convex in the point, so its linear
/// interpolation between hidden points (a triangle's clip distance: terrain/terrain.vert, its
/// GLSL twin) is negative only where every point is hidden.
double seaHorizonClip(const SeaHorizonCone& cone, const glm::dvec3& relative);
/// Whether the cone may hide any point of a sphere (centre m from the eye, ECEF axes; radius
/// m): false when every point of it is seen over the cone's sphere, outside that sphere and
/// its distance from the eye within the two tangent lengths (the eye's, and the point's own,
/// from its least distance to the sphere's centre). A tile it may not hide is drawn without the
/// clip, which costs llvmpipe's clipper every triangle.
bool seaHorizonMayHide(const SeaHorizonCone& cone, const glm::dvec3& centreRelative, double radiusM);

/// Whether a sphere intersects the view frustum's four side planes (no far plane).
bool inFrustum(const geo::CameraView& view, int widthPx, int heightPx,
               const glm::dvec3& centreEcef, double radiusM);

/// A tile's vertex spacing in pixels seen at `distanceM` from the eye. Tiles the sea covers
/// (Tile::coveredBySea) count a quarter.
double tileSpacingPx(const geo::CameraView& view, int heightPx, const Tile& tile, double distanceM);

/// Screen-space error of a tile: tileSpacingPx at its bounding sphere's nearest distance.
double tileErrorPx(const geo::CameraView& view, int heightPx, const Tile& tile);

/// The tiles to draw, in depth-first quadtree order (children 0..3); builds missing tiles in
/// `cache` (all of them with params.wait, else only levels below minLevel).
std::vector<const Tile*> selectTiles(TileCache& cache, const geo::CameraView& view,
                                     const SelectionParams& params, SelectionStats* stats = nullptr);

}  // namespace og::terrain
