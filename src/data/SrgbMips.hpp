#pragma once
// Mip chains of sRGB images on the CPU, averaged in linear light as a GPU's sRGB texture
// filtering does: the global day and night images' levels made in a few milliseconds each
// instead of glGenerateMipmap's ~50 ms on llvmpipe (its blits decode and encode every texel
// through the whole pipeline; docs/performance.md, start-up).
#include <cstdint>
#include <vector>

namespace og::data {

/// One mip level: sRGB-encoded RGBA bytes (alpha linear), `width` × `height`, rows as the base.
struct SrgbLevel {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

/// Levels 1 .. the last (1 × 1) of the RGBA8 sRGB image `rgba` (`width` × `height` ≥ 1), sized
/// as GL sizes them (max(1, size >> level)): each texel the mean of the 2 × 2 texels under it
/// (2 × 1 or 1 × 2 once a side is 1; an odd side's last row or column is left out, as a box
/// filter's), colour averaged as linear values (IEC 61966-2-1) and encoded back to sRGB,
/// rounded to the nearest byte (within 1 of the exact encoding), alpha averaged as it is.
std::vector<SrgbLevel> srgbMipChain(int width, int height, const std::vector<std::uint8_t>& rgba);

}  // namespace og::data
