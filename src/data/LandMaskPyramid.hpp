#pragma once
// What a rectangle of a LandMask's cells holds (only water, only land, or both), in constant
// time whatever its size: levels of 2^k × 2^k cells (k ≥ 3) that each record whether any cell
// under them is land and whether any is water, a refined cell (its 15″ fine cells not all one
// class) counting as both. The globe's classifying draw asks it which blocks of pixels can be
// classed as a whole (render/GlobeBlocks).
#include <cstdint>
#include <vector>

#include "data/LandMask.hpp"

namespace og::data {

class LandMaskPyramid {
 public:
  /// One pass over the mask's packed cells (~10 ms for the global 2′ mask).
  explicit LandMaskPyramid(const LandMask& mask);

  enum class Content : std::uint8_t { Water = 1, Land = 2, Both = 3 };
  /// What the cells of columns c0 ... c1 and rows r0 ... r1 may hold (c0 ≤ c1, r0 ≤ r1): never
  /// less than they do, exact up to 32 × 32 cells; larger rectangles are answered at the level
  /// where they span at most 5 × 5 cells, which may see up to that cell's size around them. Columns wrap
  /// on a global mask (c0 may be negative, c1 past the last column) and count as water outside
  /// a regional one; rows clamp to the mask.
  [[nodiscard]] Content cells(int c0, int c1, int r0, int r1) const;

  /// The same over the fine level's cells (LandMask::kFinePerCell per cell each way: columns
  /// fc0 ... fc1, rows fr0 ... fr1, wrapping and clamping likewise), exactly: a refined cell's
  /// own fine cells, another cell's class for all of its. Without a fine level: cells()'s
  /// answer for the cells holding them.
  [[nodiscard]] Content fineCells(int fc0, int fc1, int fr0, int fr1) const;

  [[nodiscard]] const LandMask& mask() const { return mask_; }

 private:
  static constexpr int kFirstLevel = 3;
  struct Level {
    int width = 0, height = 0;
    std::vector<std::uint8_t> content;  ///< Content bits per cell, row-major, rows south to north
  };
  [[nodiscard]] std::uint8_t levelContent(int level, int c0, int c1, int r0, int r1) const;
  const LandMask& mask_;
  bool global_ = false;
  std::vector<Level> levels_;  ///< levels_[i]: cells of 2^(kFirstLevel + i) mask cells
};

}  // namespace og::data
