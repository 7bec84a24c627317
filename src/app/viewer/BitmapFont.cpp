#include "app/viewer/BitmapFont.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

namespace og::app::viewer {
namespace {

// Glyphs drawn as text so they can be read and edited: '#' is ink, '.' is background.
struct GlyphArt {
  unsigned char c;
  std::array<const char*, kGlyphHeight> rows;
};

constexpr GlyphArt kArt[] = {
    {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
    {'!', {"..#..", "..#..", "..#..", "..#..", "..#..", ".....", "..#.."}},
    {'"', {".#.#.", ".#.#.", ".....", ".....", ".....", ".....", "....."}},
    {'#', {".#.#.", ".#.#.", "#####", ".#.#.", "#####", ".#.#.", ".#.#."}},
    {'%', {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"}},
    {'\'', {"..#..", "..#..", ".....", ".....", ".....", ".....", "....."}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {'*', {".....", "..#..", "#.#.#", ".###.", "#.#.#", "..#..", "....."}},
    {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
    {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {'/', {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."}},
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
    {';', {".....", ".##..", ".##..", ".....", ".##..", "..#..", ".#..."}},
    {'<', {"...#.", "..#..", ".#...", "#....", ".#...", "..#..", "...#."}},
    {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
    {'>', {".#...", "..#..", "...#.", "....#", "...#.", "..#..", ".#..."}},
    {'?', {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."}},
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
    {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
    {'D', {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
    {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
    {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
    {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
    {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
    {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
    {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
    {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
    {'[', {".###.", ".#...", ".#...", ".#...", ".#...", ".#...", ".###."}},
    {'\\', {".....", "#....", ".#...", "..#..", "...#.", "....#", "....."}},
    {']', {".###.", "...#.", "...#.", "...#.", "...#.", "...#.", ".###."}},
    {'^', {"..#..", ".#.#.", "#...#", ".....", ".....", ".....", "....."}},
    {'_', {".....", ".....", ".....", ".....", ".....", ".....", "#####"}},
    {'|', {"..#..", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {0xB0, {".##..", "#..#.", "#..#.", ".##..", ".....", ".....", "....."}},  // degree sign
};
constexpr std::array<const char*, kGlyphHeight> kBox = {"#####", "#...#", "#...#", "#...#",
                                                        "#...#", "#...#", "#####"};

struct Table {
  std::array<std::array<unsigned char, kGlyphHeight>, 256> rows{};
  std::array<bool, 256> defined{};
  Table() {
    auto encode = [](const std::array<const char*, kGlyphHeight>& art) {
      std::array<unsigned char, kGlyphHeight> bits{};
      for (int r = 0; r < kGlyphHeight; ++r)
        for (int c = 0; c < kGlyphWidth; ++c)
          if (art[static_cast<std::size_t>(r)][c] == '#')
            bits[static_cast<std::size_t>(r)] |= static_cast<unsigned char>(1u << (kGlyphWidth - 1 - c));
      return bits;
    };
    rows.fill(encode(kBox));
    for (const GlyphArt& g : kArt) {
      rows[g.c] = encode(g.rows);
      defined[g.c] = true;
    }
    for (unsigned char c = 'a'; c <= 'z'; ++c) {
      rows[c] = rows[c - 'a' + 'A'];
      defined[c] = true;
    }
  }
};

const Table& table() {
  static const Table t;
  return t;
}

// Bytes to glyph codes: UTF-8 "°" (C2 B0) becomes 0xB0, other multi-byte sequences one box.
std::vector<unsigned char> glyphCodes(const std::string& line) {
  std::vector<unsigned char> codes;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const auto b = static_cast<unsigned char>(line[i]);
    if (b < 0x80) {
      codes.push_back(b);
      continue;
    }
    if (b == 0xC2 && i + 1 < line.size() && static_cast<unsigned char>(line[i + 1]) == 0xB0) {
      codes.push_back(0xB0);
      ++i;
      continue;
    }
    codes.push_back(0x7F);  // no glyph: the box; skip the sequence's continuation bytes
    while (i + 1 < line.size() && (static_cast<unsigned char>(line[i + 1]) & 0xC0) == 0x80) ++i;
  }
  return codes;
}

}  // namespace

const unsigned char* glyphRows(unsigned char c) { return table().rows[c].data(); }
bool hasGlyph(unsigned char c) { return table().defined[c]; }

io::ImageRgba8 rasterizeText(const std::vector<std::string>& lines, int scale, int padding) {
  scale = std::max(scale, 1);
  padding = std::max(padding, 1);  // room for the outline
  std::vector<std::vector<unsigned char>> codes;
  std::size_t columns = 0;
  for (const std::string& line : lines) {
    codes.push_back(glyphCodes(line));
    columns = std::max(columns, codes.back().size());
  }
  io::ImageRgba8 image;
  image.width = (static_cast<int>(columns) * kCellWidth + 2 * padding) * scale;
  image.height = (static_cast<int>(lines.size()) * kCellHeight + 2 * padding) * scale;
  image.pixels.assign(4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height), 0);
  if (lines.empty()) return image;

  // Ink mask in unscaled pixels, then outline = ink dilated by one pixel.
  const int w = image.width / scale, h = image.height / scale;
  std::vector<std::uint8_t> ink(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (std::size_t l = 0; l < codes.size(); ++l)
    for (std::size_t k = 0; k < codes[l].size(); ++k) {
      const unsigned char* rows = glyphRows(codes[l][k]);
      const int x0 = padding + static_cast<int>(k) * kCellWidth;
      const int y0 = padding + static_cast<int>(l) * kCellHeight + 1;
      for (int r = 0; r < kGlyphHeight; ++r)
        for (int c = 0; c < kGlyphWidth; ++c)
          if (rows[r] & (1u << (kGlyphWidth - 1 - c)))
            ink[static_cast<std::size_t>((y0 + r) * w + x0 + c)] = 1;
    }
  auto at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && ink[static_cast<std::size_t>(y * w + x)] != 0;
  };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const int sx = x / scale, sy = y / scale;
      std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                           static_cast<std::size_t>(x))];
      if (at(sx, sy)) {
        p[0] = p[1] = p[2] = p[3] = 255;
        continue;
      }
      bool outline = false;
      for (int dy = -1; dy <= 1 && !outline; ++dy)
        for (int dx = -1; dx <= 1 && !outline; ++dx) outline = at(sx + dx, sy + dy);
      p[0] = p[1] = p[2] = 0;
      p[3] = outline ? 230 : 110;  // outline nearly opaque, backdrop translucent
    }
  return image;
}

}  // namespace og::app::viewer
