#pragma once
// A large synthetic imagery layer for the streamed-tile tests (unit: data_imagerytiles; GL:
// imagery_tiles): a checker of one-pixel cells, light and dark, in EPSG:4326 over Chad (flat
// land, no sea), its pixels exactly the texels of level-9 tiles (180° / 2^9 / 256) and its
// edges on level-9 tile edges. Its whole-layer texture (2048² over 5.625° × 2.8125°: two
// source columns per texel) averages the checker to grey; only level-9 tiles show it. A grey
// ramp on the same grid tests the tiles' borders (no seam where tiles meet).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
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

/// Grey level per source pixel eastwards of the ramp layer (writeRampGeoTiff).
inline constexpr double kRampLevelsPerPx = 12.0;

/// Writes at `file` a layer on the checker's grid and box whose grey rises eastwards by
/// kRampLevelsPerPx a pixel, 128 at kCheckerLonDeg (an edge of tiles of every level 3..9, in
/// the box's middle), clamped to 16..240: magnified, a tile edge there must not show a step.
inline std::filesystem::path writeRampGeoTiff(const std::filesystem::path& file) {
  std::filesystem::path tmp = file;
  tmp += ".tmp" + std::to_string(::getpid());
  writeGeoRaster(tmp, 4326, kCheckerWidthPx, kCheckerHeightPx, kCheckerBox, [](double, double lon) {
    const double v = std::clamp(128.0 + kRampLevelsPerPx * (lon - kCheckerLonDeg) / kCheckerCellDeg, 16.0, 240.0);
    const auto g = static_cast<std::uint8_t>(std::lround(v));
    return Rgb8{g, g, g};
  });
  std::filesystem::rename(tmp, file);
  return file;
}

}  // namespace og::test
