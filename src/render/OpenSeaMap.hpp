#pragma once
// Where the globe's sea from orbit is open and deep (render/globe.frag's open-sea part): a
// coarse map of 1° cells, each holding a great-circle radius around any point of the cell within
// which every point is sea deeper than the water's reach (no land, no floor seen through the
// water). The globe's classifying draw reads it once per pixel (one fetch, no elevation lookup)
// and routes pixels whose four samples all lie within that radius to a part compiled without
// the land's code, the coast test and the water column: what those samples would get anyway.
// Conservative by construction: a cell is blocked wherever the elevation layer's bilinear
// filter or the land mask's B-spline could give land or a shallower floor.
#include <memory>
#include <vector>

#include "data/LandMask.hpp"
#include "data/LatLonGrid.hpp"
#include "gl/Objects.hpp"

namespace og::render {

struct OpenSeaMap {
  static constexpr int kWidth = 360;   ///< 1° columns from 180° W, eastwards
  static constexpr int kHeight = 180;  ///< 1° rows from 90° S, northwards
  static constexpr double kCellDeg = 1.0;
  /// Per cell, row-major, rows south to north: radius (radians of arc, ≥ 0) of the disc around
  /// any point of the cell holding only open deep sea; 0 where the cell itself is blocked.
  std::vector<float> clearanceRad;
  /// The blocked cells (1) that clearanceRad was measured from, same layout.
  std::vector<unsigned char> blocked;
  /// The same radius around land alone (the mask's fine cells included; empty without a mask):
  /// the projected grid's sea classes (ocean/water_volume_vertex.glsl's seaClassLandWithin)
  /// leave the coast test and the terrain's shadows out of triangles that far from land.
  std::vector<float> landClearanceRad;
  /// clearanceRad of the cell holding (latitude, longitude) degrees (clamped to the map).
  [[nodiscard]] float clearanceAt(double latitudeDeg, double longitudeDeg) const;
};

/// Cells where `layer` (heights m; NaN = unknown) has a bilinear neighbourhood above
/// -minDepthM, or that lie outside a layer that does not wrap in longitude (elevationAt reads
/// -1 m there: shallow). Cheap (one pass over the layer's texels).
std::vector<unsigned char> blockedByLayer(const data::LatLonGrid& layer, double minDepthM);
/// Adds the cells where `mask`'s land fraction can be above 0 (its B-spline's reach around
/// every land cell) to `blocked`; with `fineCells`, also around the cells its fine level refines
/// (an islet or a bay the 2′ cells do not hold).
void addBlockedByMask(const data::LandMask& mask, std::vector<unsigned char>& blocked, bool fineCells = false);
/// The clearance radii of the cells around the blocked ones (Chebyshev distance in cells up to
/// 30, turned into a great-circle radius that holds for every point of the cell).
OpenSeaMap makeOpenSeaMap(std::vector<unsigned char> blocked);

/// The map on the GPU: an RG32F texture (kWidth × kHeight, nearest) on gl::kUnitOpenSea, the
/// clearance in .r and the land clearance in .g (0 where there is none).
class OpenSeaTexture {
 public:
  /// Needs a current GL context.
  explicit OpenSeaTexture(const OpenSeaMap& map);
  void bind() const;

 private:
  gl::Texture texture_;
};

}  // namespace og::render
