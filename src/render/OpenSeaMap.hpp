#pragma once
// Where the globe's sea is open and deep (render/globe.frag's open-sea part): a map of 7.5′
// cells, each holding a great-circle radius around any point of the cell within which every
// point is sea deeper than the water's reach (no land, no floor seen through the water). The
// globe's classifying draw reads it once per pixel (one fetch, no elevation lookup) and routes
// pixels whose four samples all lie within that radius to a part compiled without the land's
// code, the coast test and the water column: what those samples would get anyway.
// Conservative by construction: a cell is blocked wherever the elevation layer's bilinear
// filter or the land mask's B-spline could give land or a shallower floor. The cells are an
// eighth of a degree because a cell next to a blocked one gets no radius: with 1° cells the
// deep sea within a degree of any shelf or seamount (the demo flight's, west of Portugal) was
// shaded with the water column it does not need (docs/performance.md, thirtieth session).
#include <cstdint>
#include <memory>
#include <vector>

#include "data/LandMask.hpp"
#include "data/LatLonGrid.hpp"
#include "gl/Objects.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {

struct OpenSeaMap {
  static constexpr int kCellsPerDeg = static_cast<int>(gl::kOpenSeaCellsPerDeg);
  static constexpr double kCellDeg = 1.0 / kCellsPerDeg;  ///< 7.5′
  static constexpr int kWidth = 360 * kCellsPerDeg;   ///< columns from 180° W, eastwards
  static constexpr int kHeight = 180 * kCellsPerDeg;  ///< rows from 90° S, northwards
  /// The largest radius measured: 30° of arc (from orbit a block of pixels spans degrees).
  static constexpr int kMaxRings = 30 * kCellsPerDeg;
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
/// kMaxRings, turned into a great-circle radius that holds for every point of the cell).
OpenSeaMap makeOpenSeaMap(std::vector<unsigned char> blocked);
/// Chebyshev distance in cells from every cell to the nearest blocked one (kWidth × kHeight,
/// columns wrapping, rows ending at the poles), at most `cap` (0..255): two raster passes
/// (Rosenfeld & Pfaltz 1966, all eight neighbours at distance 1), each row swept on past the
/// seam while it changes.
std::vector<std::uint8_t> chessboardDistances(const std::vector<unsigned char>& blocked, int cap);
/// The renderer's map (GlobeRenderer, on a helper thread): the cells `layerBlocked`
/// (blockedByLayer) and, with a mask, those its land can reach; the land clearance from the
/// mask's cells with its fine ones (left empty without a mask).
OpenSeaMap makeRendererOpenSeaMap(std::vector<unsigned char> layerBlocked, const data::LandMask* mask);

/// The map's texels for OpenSeaTexture: (clearance, land clearance) as half floats rounded
/// down (never a radius larger than the map's), 0 where there is none.
std::vector<std::uint16_t> openSeaTexels(const OpenSeaMap& map);

/// The map on the GPU: an RG16F texture (kWidth × kHeight, nearest, 16 MiB) on
/// gl::kUnitOpenSea, the clearance in .r and the land clearance in .g (0 where there is none).
class OpenSeaTexture {
 public:
  /// Needs a current GL context.
  explicit OpenSeaTexture(const std::vector<std::uint16_t>& texels);
  void bind() const;

 private:
  gl::Texture texture_;
};

}  // namespace og::render
