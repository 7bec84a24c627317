#include "data/LatLonGrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace og::data {

namespace {
/// Slack on "the first/last row is within one cell of the pole", in cells: axes written as
/// text or float rarely hit ±90 exactly.
constexpr double kPoleSlackCells = 1e-3;
}  // namespace

bool LatLonGrid::coversPoles() const {
  const double topDeg = lat0Deg + static_cast<double>(height - 1) * dLatDeg;
  return lat0Deg - dLatDeg * (1.0 + kPoleSlackCells) <= -90.0 &&
         topDeg + dLatDeg * (1.0 + kPoleSlackCells) >= 90.0;
}

float LatLonGrid::sample(double latitudeDeg, double longitudeDeg) const {
  return sampleField(values, latitudeDeg, longitudeDeg);
}

float LatLonGrid::sampleKeepDepth(double latitudeDeg, double longitudeDeg) const {
  if (keepDepth.empty()) return 0.0f;
  const float k = sampleField(keepDepth, latitudeDeg, longitudeDeg);
  return std::isfinite(k) ? k : 0.0f;
}

float LatLonGrid::sampleField(const std::vector<float>& field, double latitudeDeg, double longitudeDeg) const {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  if (width <= 0 || height <= 0 || !(dLonDeg > 0.0) || !(dLatDeg > 0.0) ||
      field.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    return kNaN;
  if (!std::isfinite(latitudeDeg) || !std::isfinite(longitudeDeg)) return kNaN;

  // Rows: cell centres sit at integer row coordinates.
  const double lastRow = static_cast<double>(height - 1);
  double y = (latitudeDeg - lat0Deg) / dLatDeg;
  const bool global = coversPoles();
  // A regional grid's cells reach half a cell beyond its outer centres; a global grid has no
  // centres nearer the poles than its first/last row, so it holds those rows' values.
  if (!global && (y < -0.5 || y > lastRow + 0.5)) return kNaN;
  y = std::clamp(y, 0.0, lastRow);

  // Columns: longitude relative to column 0, modulo 360.
  double dx = std::fmod(longitudeDeg - lon0Deg, 360.0);
  if (dx < 0.0) dx += 360.0;
  double x = dx / dLonDeg;
  const double lastColumn = static_cast<double>(width - 1);
  int c0 = 0;
  int c1 = 0;
  double fx = 0.0;
  if (wrapsLongitude) {
    const double cell = std::floor(x);
    fx = x - cell;
    c0 = static_cast<int>(cell) % width;  // x may round up to exactly `width`
    c1 = (c0 + 1) % width;
  } else {
    // A point just west of column 0 comes out of the modulo near 360°: bring it back.
    if (x > lastColumn + 0.5) x -= 360.0 / dLonDeg;
    if (x < -0.5 || x > lastColumn + 0.5) return kNaN;
    x = std::clamp(x, 0.0, lastColumn);
    c0 = std::min(static_cast<int>(x), std::max(width - 2, 0));
    c1 = std::min(c0 + 1, width - 1);
    fx = x - static_cast<double>(c0);
  }
  const int r0 = std::min(static_cast<int>(y), std::max(height - 2, 0));
  const int r1 = std::min(r0 + 1, height - 1);
  const double fy = y - static_cast<double>(r0);

  auto at = [&](int column, int row) {
    return static_cast<double>(field[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                                     static_cast<std::size_t>(column)]);
  };
  const double v00 = at(c0, r0);
  const double v10 = at(c1, r0);
  const double v01 = at(c0, r1);
  const double v11 = at(c1, r1);
  // Any NaN neighbour makes the sum NaN, even one with zero weight: no-data is never blended.
  const double south = v00 * (1.0 - fx) + v10 * fx;
  const double north = v01 * (1.0 - fx) + v11 * fx;
  return static_cast<float>(south * (1.0 - fy) + north * fy);
}

}  // namespace og::data
