#pragma once
// The land fraction filtered over a footprint of several cells: a mip pyramid of a global
// LandMask's area fraction of land (level 0: 2 × 2 cells, 4′ for the 2′ mask; each level the
// area mean of what its texels span at GL's next mip size), as bytes (255 = all land). A refined cell counts its 15″ fine cells
// (LandMask::block), so a coastal cell is the share of it the shorelines give to land.
//
// Where a pixel's footprint on the ground spans more than a cell, the B-spline of the 3 × 3
// nearest cells (LandMask::landFraction) point-samples the coast: lakes and islets a fraction of
// a pixel wide come and go from frame to frame. The pyramid's trilinear lookup at the
// footprint's level (shaders/terrain/landmask.glsl's landFractionFiltered, the GPU twin, on
// gl::kUnitLandFraction) is the area fraction around the point at that scale: features under
// the footprint fade into their surroundings' class instead of flickering. landFraction()
// blends from the B-spline at one cell to the pyramid at two.
#include <cstdint>
#include <vector>

#include "data/LandMask.hpp"
#include "data/LandMaskPyramid.hpp"

namespace og::data {

class LandFractionMips {
 public:
  /// Needs a global mask from 180° W and 90° S with an even number of columns and rows
  /// (InternalError otherwise). One pass over the packed cells and the refined blocks (~55 ms
  /// for the global 2′ mask, on one core).
  explicit LandFractionMips(const LandMask& mask);

  /// Levels: level 0 holds 2 × 2 cells a texel; each next level is GL's next mip size (both
  /// sides halved, rounded down) while both sides are 2 or more, at most kMaxLevels of them
  /// (the 2′ mask: 4′ to 64′, 5400 × 2700 down to 337 × 168).
  static constexpr int kMaxLevels = 5;
  [[nodiscard]] int levels() const { return static_cast<int>(levels_.size()); }
  [[nodiscard]] int levelWidth(int level) const { return levels_[static_cast<std::size_t>(level)].width; }
  [[nodiscard]] int levelHeight(int level) const { return levels_[static_cast<std::size_t>(level)].height; }
  /// A level's bytes, row-major, rows south to north (the GPU texture's layout).
  [[nodiscard]] const std::vector<std::uint8_t>& levelBytes(int level) const {
    return levels_[static_cast<std::size_t>(level)].bytes;
  }
  /// Texel (column, row) of `level`, 0-255: columns wrap, rows clamp (GL's REPEAT and
  /// CLAMP_TO_EDGE).
  [[nodiscard]] std::uint8_t texel(int level, int column, int row) const;

  /// The pyramid's weight against the B-spline for a footprint of `footprintDeg` (degrees of
  /// arc on the ground): 0 up to one cell, 1 from two, smooth between.
  [[nodiscard]] double weight(double footprintDeg) const;
  /// The mip level (0: 2 cells a texel) a footprint of `footprintDeg` reads: log2(footprint /
  /// 2 cells), before the lookup clamps it to [0, levels() - 1].
  [[nodiscard]] double levelOf(double footprintDeg) const;
  /// The trilinear lookup at (latitude, longitude) degrees and mip level `lod` (clamped to the
  /// levels), as GL's LINEAR_MIPMAP_LINEAR with the columns wrapping and the rows clamped
  /// (OpenGL 4.5 core, §8.14.2 and §8.14.3: texel centres at (i + ½) / size, the levels d and
  /// d + 1 around the lod blended by its fraction): [0, 1].
  [[nodiscard]] float filtered(double latitudeDeg, double longitudeDeg, double lod) const;
  /// The fraction of land as a footprint of `footprintDeg` sees it: the mask's own
  /// (LandMask::landFraction, the fine level and the B-spline) up to one cell, the pyramid's from
  /// two, blended by weight() between. landmask.glsl's landFraction(latLon, footprintRad) is its
  /// GPU twin (equal up to the GPU's filtering weights, ~1/256).
  [[nodiscard]] float landFraction(double latitudeDeg, double longitudeDeg, double footprintDeg) const;

  /// What every trilinear lookup at a level in [lodLo, lodHi] at a point of the box latLo ...
  /// latHi, lonLo ... lonHi (degrees; longitudes may run past ±180°) returns: Land where all
  /// the texels they can blend (those within a texel of the box, at every level the lookups
  /// blend) are kLandByte or more, Water where all are kWaterByte or less, else Both: 2.5 bytes
  /// of margin each side of 0.5 (127.5) for the GPU's filtering weights.
  static constexpr std::uint8_t kLandByte = 130, kWaterByte = 125;
  [[nodiscard]] LandMaskPyramid::Content boxContent(double latLoDeg, double latHiDeg, double lonLoDeg, double lonHiDeg,
                                                    double lodLo, double lodHi) const;

  [[nodiscard]] const LandMask& mask() const { return mask_; }
  /// The levels' bytes (what the GPU texture holds), without boxContent's bit planes.
  [[nodiscard]] std::size_t bytes() const;

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<std::uint8_t> bytes;
    /// boxContent's bits, 64 texels a word, wordsPerRow words a row: bytes under kLandByte
    /// (not land) and over kWaterByte (not water).
    int wordsPerRow = 0;
    std::vector<std::uint64_t> notLand, notWater;
  };
  static void setBoxBits(Level& l);
  static Level halved(const Level& fine);
  [[nodiscard]] float bilinear(int level, double latitudeDeg, double longitudeDeg) const;
  const LandMask& mask_;
  std::vector<Level> levels_;
};

}  // namespace og::data
