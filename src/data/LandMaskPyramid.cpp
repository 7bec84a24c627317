#include "data/LandMaskPyramid.hpp"

#include <algorithm>

namespace og::data {
namespace {
constexpr std::uint8_t kWater = static_cast<std::uint8_t>(LandMaskPyramid::Content::Water);
constexpr std::uint8_t kLand = static_cast<std::uint8_t>(LandMaskPyramid::Content::Land);
constexpr std::uint8_t kBoth = static_cast<std::uint8_t>(LandMaskPyramid::Content::Both);
static_assert(kWater == LandMask::kFineWater && kLand == LandMask::kFineLand, "LandMask::fineClasses' bits");
}  // namespace

LandMaskPyramid::LandMaskPyramid(const LandMask& mask)
    : mask_(mask), global_(mask.global()) {
  // The first level from the packed bytes: a byte is 8 cells of a row, one level-3 column.
  const int stride = mask.bytesPerRow();
  const std::vector<std::uint8_t>& land = mask.packedBits();
  const std::vector<std::uint8_t>& refined = mask.refinedBits();
  Level first{stride, (mask.height() + 7) / 8, {}};
  first.content.assign(static_cast<std::size_t>(first.width) * static_cast<std::size_t>(first.height), 0);
  for (int row = 0; row < mask.height(); ++row)
    for (int b = 0; b < stride; ++b) {
      const int valid = std::min(8, mask.width() - 8 * b);
      const auto used = static_cast<std::uint8_t>((1u << valid) - 1u);
      const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(b);
      const std::uint8_t l = land[i] & used, f = refined.empty() ? std::uint8_t{0} : refined[i] & used;
      std::uint8_t c = (l | f) != 0 ? kLand : 0;
      c |= ((static_cast<std::uint8_t>(~l) & used) | f) != 0 ? kWater : 0;
      first.content[static_cast<std::size_t>(row / 8) * static_cast<std::size_t>(first.width) + static_cast<std::size_t>(b)] |= c;
    }
  levels_.push_back(std::move(first));
  // Coarser levels: each cell ORs the 2 x 2 under it, up to a single cell.
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& fine = levels_.back();
    Level coarse{(fine.width + 1) / 2, (fine.height + 1) / 2, {}};
    coarse.content.assign(static_cast<std::size_t>(coarse.width) * static_cast<std::size_t>(coarse.height), 0);
    for (int y = 0; y < fine.height; ++y)
      for (int x = 0; x < fine.width; ++x)
        coarse.content[static_cast<std::size_t>(y / 2) * static_cast<std::size_t>(coarse.width) + static_cast<std::size_t>(x / 2)] |=
            fine.content[static_cast<std::size_t>(y) * static_cast<std::size_t>(fine.width) + static_cast<std::size_t>(x)];
    levels_.push_back(std::move(coarse));
  }
}

// Columns c0 ... c1 within [0, mask width), rows within [0, height).
std::uint8_t LandMaskPyramid::levelContent(int level, int c0, int c1, int r0, int r1) const {
  std::uint8_t c = 0;
  if (level < kFirstLevel) {  // the cells themselves, a byte (8 cells) of a row at a time
    const int stride = mask_.bytesPerRow();
    const std::vector<std::uint8_t>& land = mask_.packedBits();
    const std::vector<std::uint8_t>& refined = mask_.refinedBits();
    for (int row = r0; row <= r1 && c != kBoth; ++row)
      for (int b = c0 >> 3; b <= c1 >> 3; ++b) {
        const int lo = std::max(c0 - 8 * b, 0), hi = std::min(c1 - 8 * b, 7);
        const auto used = static_cast<std::uint8_t>(((1u << (hi + 1)) - 1u) & ~((1u << lo) - 1u));
        const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(b);
        const std::uint8_t l = land[i] & used, f = refined.empty() ? std::uint8_t{0} : refined[i] & used;
        c |= (l | f) != 0 ? kLand : 0;
        c |= ((static_cast<std::uint8_t>(~l) & used) | f) != 0 ? kWater : 0;
      }
    return c;
  }
  const Level& l = levels_[static_cast<std::size_t>(level - kFirstLevel)];
  for (int y = r0 >> level; y <= r1 >> level; ++y)
    for (int x = c0 >> level; x <= c1 >> level; ++x)
      c |= l.content[static_cast<std::size_t>(y) * static_cast<std::size_t>(l.width) + static_cast<std::size_t>(x)];
  return c;
}

LandMaskPyramid::Content LandMaskPyramid::cells(int c0, int c1, int r0, int r1) const {
  const int width = mask_.width();
  r0 = std::clamp(r0, 0, mask_.height() - 1);
  r1 = std::clamp(r1, 0, mask_.height() - 1);
  const int span = std::max(c1 - c0, r1 - r0) + 1;
  int level = 0;
  while ((1 << level) < span) ++level;
  // Up to 32 x 32 cells: the cells themselves (32 rows of at most 5 bytes); else the level at
  // which it spans at most 5 x 5 cells (a finer one would answer exactly more often, a coarser
  // one sooner).
  level = level <= 5 ? 0 : std::min(level - 2, kFirstLevel + static_cast<int>(levels_.size()) - 1);
  std::uint8_t c = 0;
  if (global_) {
    if (c1 - c0 + 1 >= width) {
      c = levelContent(level, 0, width - 1, r0, r1);
    } else {
      const int w0 = ((c0 % width) + width) % width, w1 = w0 + (c1 - c0);
      c = levelContent(level, w0, std::min(w1, width - 1), r0, r1);
      if (w1 >= width) c |= levelContent(level, 0, w1 - width, r0, r1);
    }
  } else {
    if (c0 < 0 || c1 >= width) c |= kWater;
    if (c1 >= 0 && c0 < width) c |= levelContent(level, std::max(c0, 0), std::min(c1, width - 1), r0, r1);
  }
  return static_cast<Content>(c);
}

LandMaskPyramid::Content LandMaskPyramid::fineCells(int fc0, int fc1, int fr0, int fr1) const {
  constexpr int n = LandMask::kFinePerCell;
  const auto cellOf = [](int fine) { return fine >= 0 ? fine / n : -((-fine + n - 1) / n); };
  if (!mask_.hasFineLevel()) return cells(cellOf(fc0), cellOf(fc1), cellOf(fr0), cellOf(fr1));
  const int rows = mask_.height() * n;
  return static_cast<Content>(mask_.fineClasses(fc0, fc1, std::clamp(fr0, 0, rows - 1), std::clamp(fr1, 0, rows - 1)));
}

}  // namespace og::data
