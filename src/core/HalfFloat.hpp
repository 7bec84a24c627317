#pragma once
// IEEE 754 binary16 ("half float") conversion of float arrays, for GL textures stored as
// R16F/RG16F: with the CPU's F16C instructions where it has them (8 values an instruction),
// else glm's software conversion (which rounds ties away from zero, not to even).
#include <cstddef>
#include <cstdint>

namespace og::core {

/// out[i] = binary16(in[i]) for i < n, rounded to nearest (ties to even with F16C); NaN stays
/// NaN, values beyond ±65504 become ±infinity.
void floatsToHalves(const float* in, std::uint16_t* out, std::size_t n);

/// The binary16 value of -1 (0xBC00).
inline constexpr std::uint16_t kHalfMinusOne = 0xBC00;

/// Whether the binary16 bits `h` are a NaN.
constexpr bool isHalfNan(std::uint16_t h) { return (h & 0x7C00u) == 0x7C00u && (h & 0x03FFu) != 0; }
/// Whether the binary16 bits `h` are finite (not NaN, not ±infinity).
constexpr bool isHalfFinite(std::uint16_t h) { return (h & 0x7C00u) != 0x7C00u; }

}  // namespace og::core
