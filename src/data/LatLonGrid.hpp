#pragma once
// A scalar field on a regular latitude/longitude grid, normalised on load so every consumer
// sees one layout whatever the file had (descending latitude, 0..360 or -180..180 longitude,
// a duplicated seam column, packed shorts, fill values).
#include <cstddef>
#include <string>
#include <vector>

namespace og::data {

struct LatLonGrid {
  std::string name;        ///< variable name in the source, e.g. "ROSE"
  std::string units;       ///< units as found in the file, e.g. "METERS"
  int width = 0;           ///< number of longitude columns (seam duplicate removed)
  int height = 0;          ///< number of latitude rows
  double lon0Deg = 0.0;    ///< longitude of column 0 (cell centre), degrees east, in [-180, 360)
  double lat0Deg = 0.0;    ///< latitude of row 0 (cell centre), degrees north; southernmost row
  double dLonDeg = 1.0;    ///< column spacing, > 0 (longitude increases with column)
  double dLatDeg = 1.0;    ///< row spacing, > 0 (latitude increases with row)
  bool wrapsLongitude = false;  ///< true when the columns cover 360° (sampling wraps)
  std::vector<float> values;    ///< row-major [row][column], NaN where the file has no data
  /// Cells whose depth a land mask must keep rather than push down to its offshore floor, 0-1
  /// like `values` (data::correctShallowBanks marks the banks it sets; LandMask::constrainHeightM);
  /// empty = none.
  std::vector<float> keepDepth;

  [[nodiscard]] float at(int column, int row) const {
    return values[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(column)];
  }

  /// True when the first and last rows lie within about one cell of the poles: sampling then
  /// holds the polar rows' values up to the poles instead of ending half a cell beyond them.
  [[nodiscard]] bool coversPoles() const;

  /// Bilinear sample at a geodetic position (degrees). Longitude is taken modulo 360.
  /// Outside a regional grid, or where a neighbour is NaN, returns NaN.
  [[nodiscard]] float sample(double latitudeDeg, double longitudeDeg) const;
  /// keepDepth sampled the same way, 0 where it is empty.
  [[nodiscard]] float sampleKeepDepth(double latitudeDeg, double longitudeDeg) const;

 private:
  [[nodiscard]] float sampleField(const std::vector<float>& field, double latitudeDeg, double longitudeDeg) const;
};

}  // namespace og::data
