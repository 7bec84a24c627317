#pragma once
// One-bit grey PNGs (the embedded land mask's format) decoded straight into packed bits with
// libpng, with no byte-per-cell pass: the 10800 × 5400 GSHHG mask decodes in tens of
// milliseconds instead of the ~1.7 s of GDAL's general raster path (issue #16's start-up goal).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace og::data {

/// A 1-bit image as packed bits: bit k of byte b of a row = column 8b + k (least significant
/// bit first), rows SOUTH TO NORTH (the PNG's last row first), (width + 7) / 8 bytes a row.
struct PackedBitImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> bits;
  [[nodiscard]] int bytesPerRow() const { return (width + 7) / 8; }
};

/// Decodes `png` (bytes of a non-interlaced 1-bit greyscale PNG; 1 = white = set). Anything
/// else, or a damaged file, throws og::InputError "LABEL: problem".
PackedBitImage decodeBitPng(std::string_view png, const std::string& label);

/// The outer edges and cell size (degrees) of a north-up raster from its world file text
/// (six numbers: x cell, two rotations, −y cell, centre of the top-left cell x and y).
struct WorldFileGrid {
  double westDeg = 0.0, northDeg = 0.0, cellLonDeg = 0.0, cellLatDeg = 0.0;
};
/// Throws og::InputError "LABEL: problem" for text that is not a north-up world file.
WorldFileGrid parseWorldFile(std::string_view text, const std::string& label);

}  // namespace og::data
