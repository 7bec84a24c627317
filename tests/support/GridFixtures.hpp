#pragma once
// Synthetic elevation layers for the GL tiers: a regular latitude/longitude grid whose values
// come from a function of each cell centre's latitude and longitude (degrees).
#include <string>
#include <utility>

#include "data/LatLonGrid.hpp"

namespace og::test {

/// `width` x `height` cells of `stepDeg` from the cell centre (lat0Deg, lon0Deg), rows south to
/// north; `wraps` when the columns go round the globe.
template <class F>
data::LatLonGrid grid(std::string name, double lat0Deg, double lon0Deg, double stepDeg, int width,
                      int height, bool wraps, F&& valueAt) {
  data::LatLonGrid g;
  g.name = std::move(name);
  g.width = width;
  g.height = height;
  g.lat0Deg = lat0Deg;
  g.lon0Deg = lon0Deg;
  g.dLatDeg = g.dLonDeg = stepDeg;
  g.wrapsLongitude = wraps;
  g.values.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col)
      g.values.push_back(static_cast<float>(valueAt(lat0Deg + row * stepDeg, lon0Deg + col * stepDeg)));
  return g;
}

/// The whole globe in cells of `stepDeg` (which must divide 180).
template <class F>
data::LatLonGrid globalGrid(std::string name, double stepDeg, F&& valueAt) {
  const int width = static_cast<int>(360.0 / stepDeg + 0.5), height = static_cast<int>(180.0 / stepDeg + 0.5);
  return grid(std::move(name), -90.0 + 0.5 * stepDeg, -180.0 + 0.5 * stepDeg, stepDeg, width, height,
              true, std::forward<F>(valueAt));
}

}  // namespace og::test
