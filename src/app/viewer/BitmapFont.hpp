#pragma once
// A 5x7 bitmap font defined in code (no font files are shipped), and a rasteriser that turns
// lines of text into an RGBA8 overlay image: white glyphs with a dark outline on a
// translucent backdrop, readable over both sea and sky.
#include <string>
#include <vector>

#include "io/Image.hpp"

namespace og::app::viewer {

inline constexpr int kGlyphWidth = 5;   ///< pixels
inline constexpr int kGlyphHeight = 7;  ///< pixels
inline constexpr int kCellWidth = 6;    ///< glyph plus one column of spacing
inline constexpr int kCellHeight = 9;   ///< glyph plus two rows of line spacing

/// The rows of a character's glyph, top first; bit 4 is the leftmost column. Lower-case
/// letters use the capitals; "°" is written as the UTF-8 pair C2 B0 and looked up as 0xB0.
/// Characters without a glyph draw as a hollow box.
const unsigned char* glyphRows(unsigned char c);

/// True when the character has its own glyph (not the fallback box).
bool hasGlyph(unsigned char c);

/// Renders `lines` at `scale` (integer pixel multiple, >= 1) into a non-premultiplied RGBA8
/// image, rows top to bottom, with `padding` pixels of backdrop around the text.
io::ImageRgba8 rasterizeText(const std::vector<std::string>& lines, int scale, int padding = 3);

}  // namespace og::app::viewer
