#pragma once
// Reading rendered pixels back to the CPU, rows flipped to top-first (image order).
#include <glad/gl.h>

#include <cstdint>
#include <vector>

namespace og::gl {

/// RGBA float pixels of the colour attachment of `fbo`, top row first.
std::vector<float> readRgbaF(GLuint fbo, int width, int height);
/// RGBA 8-bit pixels of the colour attachment of `fbo`, top row first.
std::vector<std::uint8_t> readRgba8(GLuint fbo, int width, int height);
/// Single-channel float pixels of colour attachment `attachment` (0, 1, ...), top row first.
std::vector<float> readRedF(GLuint fbo, int width, int height, int attachment);
/// Depth values (reversed-Z: 1 near, 0 at infinity), top row first.
std::vector<float> readDepth(GLuint fbo, int width, int height);

}  // namespace og::gl
