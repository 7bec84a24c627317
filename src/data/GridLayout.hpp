#pragma once
// Internal to og_data (exposed for unit tests): validation of a grid's shape and axes, and the
// plan that turns a file's layout into LatLonGrid's normal form. Pure functions, no I/O, so
// hostile sizes and odd axes are testable without writing files.
#include <cstddef>
#include <string>
#include <vector>

namespace og::data::detail {

/// Limits on what a reader will allocate for one field.
inline constexpr std::size_t kMinAxisLength = 2;
inline constexpr std::size_t kMaxAxisLength = 100000;
inline constexpr std::size_t kMaxCells = 400'000'000;  ///< 1.6 GB of float

/// Throws og::InputError "LABEL: problem" unless an nLat × nLon field is within the limits.
/// Checked before anything is allocated; the product is formed without overflow.
void checkGridShape(const std::string& label, std::size_t nLat, std::size_t nLon);

/// How the file's rows and columns map onto LatLonGrid (row 0 south, longitude increasing).
struct GridLayout {
  int width = 0;             ///< output columns (file columns minus a dropped seam column)
  int height = 0;            ///< output rows (= file rows)
  bool flipRows = false;     ///< file latitude is descending (north first)
  bool flipColumns = false;  ///< file longitude is descending
  bool dropSeam = false;     ///< the easternmost column repeats the westernmost one + 360°
  double lon0Deg = 0.0;      ///< westernmost column centre, degrees east, in [-180, 360)
  double dLonDeg = 0.0;      ///< column spacing, degrees, > 0 (exactly 360/width if wrapping)
  double lat0Deg = 0.0;      ///< southernmost row centre, degrees north
  double dLatDeg = 0.0;      ///< row spacing, degrees, > 0
  bool wrapsLongitude = false;

  /// File column that output column `c` comes from.
  [[nodiscard]] std::size_t fileColumn(std::size_t c, std::size_t fileWidth) const {
    return flipColumns ? fileWidth - 1 - c : c;
  }
  /// Output row that file row `r` goes to.
  [[nodiscard]] std::size_t outputRow(std::size_t r) const {
    return flipRows ? static_cast<std::size_t>(height) - 1 - r : r;
  }
};

/// Validates the axes' values (finite, strictly monotonic, regular within 1e-3 of a step,
/// latitude within ±90°, longitude spanning at most 360°) and plans the normalisation.
/// `latFloat`/`lonFloat` say the axis was stored as 32-bit float, which widens the spacing
/// tolerance by the float rounding of its values. Names are for messages.
/// Throws og::InputError "LABEL: problem".
GridLayout planGridLayout(const std::string& label, const std::vector<double>& lat,
                          const std::string& latName, bool latFloat, const std::vector<double>& lon,
                          const std::string& lonName, bool lonFloat);

}  // namespace og::data::detail
