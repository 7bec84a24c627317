#include "data/GridLayout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.hpp"

namespace og::data::detail {

namespace {

[[noreturn]] void fail(const std::string& label, const std::string& problem) {
  throw InputError(label + ": " + problem);
}

std::string number(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

/// Regularity tolerance relative to the step: catches Gaussian grids and gaps, accepts the
/// rounding that text-derived or float-stored axes carry.
constexpr double kRegularTolerance = 1e-3;

struct AxisFacts {
  bool descending = false;
  double first = 0.0;  ///< smallest value
  double last = 0.0;   ///< largest value
  double step = 0.0;   ///< mean spacing, > 0
  double slack = 0.0;  ///< absolute rounding allowance of the stored values
};

AxisFacts analyseAxis(const std::string& label, const std::vector<double>& v,
                      const std::string& what, const std::string& name, bool isFloat) {
  const std::string axis = what + " axis '" + name + "'";
  if (v.size() < kMinAxisLength) fail(label, axis + " has fewer than 2 values");
  double maxAbs = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i]))
      fail(label, axis + " has a non-finite value at index " + std::to_string(i));
    maxAbs = std::max(maxAbs, std::abs(v[i]));
  }
  AxisFacts facts;
  facts.descending = v[1] < v[0];
  const double sign = facts.descending ? -1.0 : 1.0;
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(sign * (v[i] - v[i - 1]) > 0.0))
      fail(label, axis + " is not strictly monotonic (index " + std::to_string(i - 1) + ": " +
                      number(v[i - 1]) + ", index " + std::to_string(i) + ": " + number(v[i]) +
                      ")");
  const std::size_t n = v.size();
  facts.first = facts.descending ? v[n - 1] : v[0];
  facts.last = facts.descending ? v[0] : v[n - 1];
  facts.step = (facts.last - facts.first) / static_cast<double>(n - 1);
  // A float holds about 7 digits: allow two units in the last place of the largest value.
  facts.slack =
      isFloat ? 2.0 * maxAbs * static_cast<double>(std::numeric_limits<float>::epsilon()) : 0.0;
  const double tolerance = kRegularTolerance * facts.step + 2.0 * facts.slack;
  for (std::size_t i = 1; i < n; ++i) {
    const double step = sign * (v[i] - v[i - 1]);
    if (std::abs(step - facts.step) > tolerance)
      fail(label, axis + " is not regularly spaced (step " + number(step) + " at index " +
                      std::to_string(i - 1) + ", mean step " + number(facts.step) +
                      "); only regular latitude/longitude grids are supported");
  }
  return facts;
}

}  // namespace

void checkGridShape(const std::string& label, std::size_t nLat, std::size_t nLon) {
  const auto checkAxis = [&](std::size_t n, const char* what) {
    if (n < kMinAxisLength || n > kMaxAxisLength)
      fail(label, std::string(what) + " axis has " + std::to_string(n) + " values; expected " +
                      std::to_string(kMinAxisLength) + " to " + std::to_string(kMaxAxisLength));
  };
  checkAxis(nLat, "latitude");
  checkAxis(nLon, "longitude");
  // Division instead of multiplication so the test itself cannot overflow.
  if (nLat > kMaxCells / nLon)
    fail(label, "grid of " + std::to_string(nLat) + " x " + std::to_string(nLon) +
                    " cells exceeds the limit of " + std::to_string(kMaxCells) + " cells");
}

GridLayout planGridLayout(const std::string& label, const std::vector<double>& lat,
                          const std::string& latName, bool latFloat, const std::vector<double>& lon,
                          const std::string& lonName, bool lonFloat) {
  checkGridShape(label, lat.size(), lon.size());
  const AxisFacts la = analyseAxis(label, lat, "latitude", latName, latFloat);
  const AxisFacts lo = analyseAxis(label, lon, "longitude", lonName, lonFloat);

  GridLayout layout;
  // Latitude: cell centres must lie on the sphere (a small allowance for float-stored poles).
  const double poleSlack = 1e-6 + la.slack;
  if (la.first < -90.0 - poleSlack || la.last > 90.0 + poleSlack)
    fail(label, "latitude axis '" + latName + "' runs from " + number(la.first) + " to " +
                    number(la.last) + ", outside [-90, 90]");
  layout.height = static_cast<int>(lat.size());
  layout.flipRows = la.descending;
  layout.lat0Deg = std::max(la.first, -90.0);
  layout.dLatDeg = la.step;

  // Longitude: a last column equal to the first + 360° duplicates it (a "seam" column).
  layout.flipColumns = lo.descending;
  std::size_t width = lon.size();
  const double seamTolerance = 1e-2 * lo.step + 2.0 * lo.slack;
  if (std::abs(lo.last - lo.first - 360.0) <= seamTolerance) {
    layout.dropSeam = true;
    --width;
  }
  const double span = static_cast<double>(width) * lo.step;  // coverage of the cells, degrees
  if (span > 360.0 + 0.5 * lo.step)
    fail(label, "longitude axis '" + lonName + "' covers " + number(span) +
                    " degrees, more than 360 (overlapping columns)");
  layout.width = static_cast<int>(width);
  layout.wrapsLongitude = std::abs(span - 360.0) <= 0.5 * lo.step;
  // A wrapping grid gets the exact spacing, so column `width` lands exactly on column 0.
  layout.dLonDeg = layout.wrapsLongitude ? 360.0 / static_cast<double>(width) : lo.step;
  double lon0 = lo.first;
  if (lon0 < -180.0 || lon0 >= 360.0) {
    lon0 = std::fmod(lon0, 360.0);
    if (lon0 < 0.0) lon0 += 360.0;
    if (lon0 >= 360.0) lon0 = 0.0;  // fmod of a value a hair below a multiple of 360
  }
  layout.lon0Deg = lon0;
  return layout;
}

}  // namespace og::data::detail
