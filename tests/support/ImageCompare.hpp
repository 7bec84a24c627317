#pragma once
// Image comparison with explicit tolerances, shared by GL and golden tests.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/Image.hpp"

namespace og::test {

struct Tolerance {
  int maxDiff = 8;             ///< largest allowed per-channel difference (0..255)
  double meanDiff = 0.5;       ///< largest allowed mean absolute difference over RGB
  int bound = 2;               ///< a pixel "differs" when any channel is off by more than this
  double maxShareOver = 0.01;  ///< largest allowed share of pixels that differ
};

struct Comparison {
  int maxDiff = 0;
  double meanDiff = 0.0;
  double shareOver = 0.0;
  io::ImageRgba8 diff;  ///< |a - b| * 8, for looking at
  [[nodiscard]] bool within(const Tolerance& t) const {
    return maxDiff <= t.maxDiff && meanDiff <= t.meanDiff && shareOver <= t.maxShareOver;
  }
  [[nodiscard]] std::string describe() const {
    return "max " + std::to_string(maxDiff) + ", mean " + std::to_string(meanDiff) +
           ", share over bound " + std::to_string(shareOver);
  }
};

/// Compares RGB (alpha ignored); sizes must match (checked by the caller).
inline Comparison compareRgb(const io::ImageRgba8& a, const io::ImageRgba8& b, int bound) {
  Comparison c;
  c.diff = {a.width, a.height, std::vector<std::uint8_t>(a.pixels.size(), 255)};
  const std::size_t n = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
  double sum = 0.0;
  std::size_t over = 0;
  for (std::size_t i = 0; i < n; ++i) {
    int pixelMax = 0;
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const int d = std::abs(int(a.pixels[4 * i + ch]) - int(b.pixels[4 * i + ch]));
      pixelMax = std::max(pixelMax, d);
      sum += d;
      c.diff.pixels[4 * i + ch] = static_cast<std::uint8_t>(std::min(255, d * 8));
    }
    c.maxDiff = std::max(c.maxDiff, pixelMax);
    if (pixelMax > bound) ++over;
  }
  c.meanDiff = n ? sum / double(3 * n) : 0.0;
  c.shareOver = n ? double(over) / double(n) : 0.0;
  return c;
}

}  // namespace og::test
