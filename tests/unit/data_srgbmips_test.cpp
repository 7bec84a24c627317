// Mip chains of sRGB images on the CPU (data/SrgbMips), made for the global day and night
// textures instead of glGenerateMipmap: the levels are sized as GL sizes them down to 1 x 1,
// each texel the linear-light mean of the 2 x 2 under it encoded back within one byte of the
// exact sRGB curve, alpha a plain mean; a black/white checker averages to sRGB 188 (linear
// 0.5), not 128; bad sizes throw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/Error.hpp"
#include "data/SrgbMips.hpp"

using og::data::srgbMipChain;

namespace {
double toLinear(int byte) {
  const double c = byte / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double toSrgbByte(double lin) {
  const double s = lin <= 0.0031308 ? 12.92 * lin : 1.055 * std::pow(lin, 1.0 / 2.4) - 0.055;
  return s * 255.0;
}
}  // namespace

TEST(SrgbMips, LevelsAreLinearLightMeansOfTheLevelAbove) {
  constexpr int kW = 64, kH = 16;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<std::uint8_t> base(kW * kH * 4);
  for (auto& b : base) b = static_cast<std::uint8_t>(byte(rng));
  const auto levels = srgbMipChain(kW, kH, base);
  ASSERT_EQ(levels.size(), 6u);  // 32x8, 16x4, 8x2, 4x1, 2x1, 1x1
  EXPECT_EQ(levels[0].width, 32);
  EXPECT_EQ(levels[0].height, 8);
  EXPECT_EQ(levels[3].width, 4);
  EXPECT_EQ(levels[3].height, 1);
  EXPECT_EQ(levels.back().width, 1);
  EXPECT_EQ(levels.back().height, 1);
  const std::vector<std::uint8_t>* above = &base;
  int w = kW, h = kH;
  double worst = 0.0;
  for (const auto& level : levels) {
    ASSERT_EQ(level.rgba.size(), static_cast<std::size_t>(level.width * level.height * 4));
    const int dx = w > 1 ? 1 : 0, dy = h > 1 ? 1 : 0;
    for (int y = 0; y < level.height; ++y)
      for (int x = 0; x < level.width; ++x)
        for (int c = 0; c < 4; ++c) {
          double sum = 0.0;
          for (int j = 0; j <= 1; ++j)
            for (int i = 0; i <= 1; ++i) {
              const int v = (*above)[static_cast<std::size_t>(((y * (dy + 1) + j * dy) * w + x * (dx + 1) + i * dx) * 4 + c)];
              sum += c < 3 ? toLinear(v) : v;
            }
          const double exact = c < 3 ? toSrgbByte(sum / 4.0) : sum / 4.0;
          const double got = level.rgba[static_cast<std::size_t>((y * level.width + x) * 4 + c)];
          worst = std::max(worst, std::abs(got - exact));
        }
    above = &level.rgba;
    w = level.width;
    h = level.height;
  }
  EXPECT_LT(worst, 1.0) << "bytes from the exact linear-light mean";
}

TEST(SrgbMips, CheckerAveragesInLinearLight) {
  std::vector<std::uint8_t> checker(4 * 4 * 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 4; ++c) checker[static_cast<std::size_t>((y * 4 + x) * 4 + c)] = c == 3 || (x + y) % 2 == 0 ? 255 : 0;
  const auto levels = srgbMipChain(4, 4, checker);
  ASSERT_EQ(levels.size(), 2u);
  for (const auto& level : levels)
    for (std::size_t i = 0; i < level.rgba.size(); ++i) EXPECT_EQ(level.rgba[i], i % 4 == 3 ? 255 : 188) << i;
}

TEST(SrgbMips, WrongSizesThrow) {
  EXPECT_THROW(srgbMipChain(4, 4, std::vector<std::uint8_t>(10)), og::InternalError);
  EXPECT_THROW(srgbMipChain(0, 4, {}), og::InternalError);
}
