#pragma once
// The terrain's height function: the elevation layer (bilinear) plus deterministic fractal
// detail below the layer's resolution. A pure function of the geodetic position, so tiles of any
// level that share a vertex position get bit-identical heights (crack-free seams).
#include <memory>

#include "data/LatLonGrid.hpp"

namespace og::terrain {

class Heightfield {
 public:
  /// Keeps a copy of the layer. NaN (no data) reads as 1 m below sea level (sea), as the globe
  /// pass does.
  explicit Heightfield(data::LatLonGrid layer);

  /// Height above mean sea level in metres (negative = depth) at a geodetic position (degrees),
  /// detail included.
  [[nodiscard]] double heightM(double latitudeDeg, double longitudeDeg) const;
  /// The layer alone (bilinear, no detail), metres.
  [[nodiscard]] double layerHeightM(double latitudeDeg, double longitudeDeg) const;
  /// Fractal detail in [-1, 1] at a point of the unit sphere (geodetic normal); continuous and
  /// deterministic, wavelengths from `longestM` down to kDetailShortestM.
  [[nodiscard]] static double detail(double nx, double ny, double nz, double longestM);

  /// Shortest wavelength of the procedural detail, m.
  static constexpr double kDetailShortestM = 40.0;

  [[nodiscard]] const data::LatLonGrid& layer() const { return layer_; }
  /// The layer's cell size, m (north-south).
  [[nodiscard]] double cellM() const { return cellM_; }

 private:
  data::LatLonGrid layer_;
  double cellM_ = 0.0;
};

}  // namespace og::terrain
