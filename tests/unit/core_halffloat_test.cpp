// core::floatsToHalves (the elevation texture's RG16F texels): binary16 bit patterns of known
// values, round to nearest (ties to even on CPUs with F16C), overflow to infinity, NaN kept, the same whatever the array's
// length (the 8-wide path and its tail).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/HalfFloat.hpp"

using og::core::floatsToHalves;

TEST(HalfFloat, KnownBitPatterns) {
  const std::vector<float> in{1.0f, -1.0f, 0.0f, -0.0f, 65504.0f, 1e5f, -1e5f, 0.1f, 8848.0f, -10.5f, 1.0f + 1.0f / 2048.0f,
                              std::numeric_limits<float>::quiet_NaN()};
  std::vector<std::uint16_t> out(in.size());
  floatsToHalves(in.data(), out.data(), in.size());
  EXPECT_EQ(out[0], 0x3C00);
  EXPECT_EQ(out[1], og::core::kHalfMinusOne);
  EXPECT_EQ(out[2], 0x0000);
  EXPECT_EQ(out[3], 0x8000);
  EXPECT_EQ(out[4], 0x7BFF);  // the largest finite half
  EXPECT_EQ(out[5], 0x7C00);  // +infinity
  EXPECT_EQ(out[6], 0xFC00);
  EXPECT_EQ(out[7], 0x2E66);  // 0.0999755859375
  EXPECT_EQ(out[8], 0x7052);  // 8848 exactly (8 m steps there)
  EXPECT_EQ(out[9], 0xC940);
#if defined(__x86_64__) || defined(__i386__)
  if (__builtin_cpu_supports("f16c")) {
    EXPECT_EQ(out[10], 0x3C00);  // halfway between 1 and 1 + 2^-10: to even
  }
#endif
  EXPECT_TRUE(og::core::isHalfNan(out[11]));
  EXPECT_FALSE(og::core::isHalfNan(out[5]));
}

TEST(HalfFloat, LengthDoesNotChangeTheResult) {
  std::vector<float> in(37);
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = std::ldexp(static_cast<float>(i) - 18.3f, static_cast<int>(i % 7) - 3);
  std::vector<std::uint16_t> all(in.size());
  floatsToHalves(in.data(), all.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    std::uint16_t one = 0;
    floatsToHalves(&in[i], &one, 1);  // the scalar tail alone
    EXPECT_EQ(one, all[i]) << i;
  }
}
