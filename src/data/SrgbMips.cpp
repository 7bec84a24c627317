#include "data/SrgbMips.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "core/Error.hpp"

namespace og::data {
namespace {

/// Linear values are carried as 16-bit fixed point (0 .. 65535 = 0 .. 1): fine enough that
/// encoding through a table is within one byte of the exact sRGB curve (its steepest part,
/// 12.92 × 255 bytes per unit near black, moves 0.05 byte per step).
constexpr int kLinearSteps = 65536;

const std::array<std::uint16_t, 256>& decodeTable() {
  static const std::array<std::uint16_t, 256> table = [] {
    std::array<std::uint16_t, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      const double lin = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
      t[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(std::lround(lin * (kLinearSteps - 1)));
    }
    return t;
  }();
  return table;
}

const std::vector<std::uint8_t>& encodeTable() {
  static const std::vector<std::uint8_t> table = [] {
    std::vector<std::uint8_t> t(kLinearSteps);
    for (int i = 0; i < kLinearSteps; ++i) {
      const double c = static_cast<double>(i) / (kLinearSteps - 1);
      const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
      t[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0, 1.0) * 255.0));
    }
    return t;
  }();
  return table;
}

/// The level after `in` (`w` × `h`): 2 × 2 means (or 2 × 1 / 1 × 2 where a side is 1).
SrgbLevel halve(const std::uint8_t* in, int w, int h) {
  const auto& dec = decodeTable();
  const auto& enc = encodeTable();
  SrgbLevel out;
  out.width = std::max(1, w / 2);
  out.height = std::max(1, h / 2);
  out.rgba.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
  const int dx = w > 1 ? 1 : 0, dy = h > 1 ? 1 : 0;
  const auto at = [&](int x, int y) { return in + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4; };
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const int x0 = x * (dx + 1), y0 = y * (dy + 1);
      const std::uint8_t* a = at(x0, y0);
      const std::uint8_t* b = at(x0 + dx, y0);
      const std::uint8_t* c = at(x0, y0 + dy);
      const std::uint8_t* d = at(x0 + dx, y0 + dy);
      std::uint8_t* o = &out.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x)) * 4];
      for (int k = 0; k < 3; ++k) {
        const unsigned sum = 2u + dec[a[k]] + dec[b[k]] + dec[c[k]] + dec[d[k]];
        o[k] = enc[sum / 4u];
      }
      o[3] = static_cast<std::uint8_t>((2u + a[3] + b[3] + c[3] + d[3]) / 4u);
    }
  return out;
}

}  // namespace

std::vector<SrgbLevel> srgbMipChain(int width, int height, const std::vector<std::uint8_t>& rgba) {
  if (width < 1 || height < 1 || rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
    throw InternalError("srgbMipChain: " + std::to_string(rgba.size()) + " bytes for " + std::to_string(width) +
                        " x " + std::to_string(height) + " RGBA texels");
  std::vector<SrgbLevel> levels;
  levels.reserve(32);
  const std::uint8_t* in = rgba.data();
  int w = width, h = height;
  while (w > 1 || h > 1) {
    levels.push_back(halve(in, w, h));
    in = levels.back().rgba.data();
    w = levels.back().width;
    h = levels.back().height;
  }
  return levels;
}

}  // namespace og::data
