#pragma once
// A large synthetic imagery layer for the streamed-tile tests (unit: data_imagerytiles; GL:
// imagery_tiles): a checker of one-pixel cells, light and dark, in EPSG:4326 over Chad (flat
// land, no sea), its pixels exactly the texels of level-9 tiles (180° / 2^9 / 256) and its
// edges on level-9 tile edges. Its whole-layer texture (2048² over 5.625° × 2.8125°: two
// source columns per texel) averages the checker to grey; only level-9 tiles show it.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "support/GeoTiffWriter.hpp"

namespace og::test {

inline constexpr int kCheckerWidthPx = 4096;
inline constexpr int kCheckerHeightPx = 2048;
inline constexpr double kCheckerCellDeg = 180.0 / 512 / 256;
inline const GeoBox kCheckerBox{-180.0 + 568 * 256 * kCheckerCellDeg, -180.0 + 584 * 256 * kCheckerCellDeg,
                                -90.0 + 286 * 256 * kCheckerCellDeg, -90.0 + 294 * 256 * kCheckerCellDeg};
/// The centre of the box, degrees.
inline constexpr double kCheckerLatDeg = 11.953125, kCheckerLonDeg = 22.5;
inline constexpr Rgb8 kCheckerLight{230, 230, 230};
inline constexpr Rgb8 kCheckerDark{25, 25, 25};

/// Writes the checker GeoTIFF at `file` (under a temporary name, then renamed: tests running
/// in parallel may write it at once).
inline std::filesystem::path writeCheckerGeoTiff(const std::filesystem::path& file) {
  std::filesystem::path tmp = file;
  tmp += ".tmp" + std::to_string(::getpid());
  const double cellLon = (kCheckerBox.eastDeg - kCheckerBox.westDeg) / kCheckerWidthPx;
  const double cellLat = (kCheckerBox.northDeg - kCheckerBox.southDeg) / kCheckerHeightPx;
  writeGeoRaster(tmp, 4326, kCheckerWidthPx, kCheckerHeightPx, kCheckerBox, [=](double lat, double lon) {
    const auto i = static_cast<long>(std::floor((lon - kCheckerBox.westDeg) / cellLon));
    const auto j = static_cast<long>(std::floor((lat - kCheckerBox.southDeg) / cellLat));
    return ((i + j) & 1) != 0 ? kCheckerLight : kCheckerDark;
  });
  std::filesystem::rename(tmp, file);
  return file;
}

}  // namespace og::test
