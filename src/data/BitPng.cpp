#include "data/BitPng.hpp"

#include <png.h>

#include <array>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "core/Error.hpp"

namespace og::data {
namespace {

// libpng reports errors by longjmp: the functions that call setjmp below hold no C++ objects
// with destructors, and everything they allocate belongs to the caller.
struct Reader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  const unsigned char* data = nullptr;
  std::size_t size = 0, pos = 0;
  std::array<char, 256> message{};
};

void readCallback(png_structp png, png_bytep out, png_size_t count) {
  auto* r = static_cast<Reader*>(png_get_io_ptr(png));
  if (count > r->size - r->pos) png_error(png, "the file is truncated");
  std::memcpy(out, r->data + r->pos, count);
  r->pos += count;
}

void errorCallback(png_structp png, png_const_charp text) {
  auto* r = static_cast<Reader*>(png_get_error_ptr(png));
  std::snprintf(r->message.data(), r->message.size(), "%s", text);
  png_longjmp(png, 1);
}

void warningCallback(png_structp, png_const_charp) {}

/// Reads the header; false with r.message on a bad file. Width/height out.
bool readHeader(Reader& r, png_uint_32& width, png_uint_32& height) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_set_read_fn(r.png, &r, readCallback);
  png_read_info(r.png, r.info);
  int depth = 0, colour = 0, interlace = 0;
  png_get_IHDR(r.png, r.info, &width, &height, &depth, &colour, &interlace, nullptr, nullptr);
  if (depth != 1 || colour != PNG_COLOR_TYPE_GRAY || interlace != PNG_INTERLACE_NONE) {
    std::snprintf(r.message.data(), r.message.size(),
                  "a land mask PNG must be 1-bit greyscale, not interlaced (got %d-bit, colour type %d%s)",
                  depth, colour, interlace != PNG_INTERLACE_NONE ? ", interlaced" : "");
    return false;
  }
  png_set_packswap(r.png);  // PNG packs the first pixel in the high bit; ours is bit 0
  png_read_update_info(r.png, r.info);
  return true;
}

/// Reads the rows, last first, into `bits` (height × stride bytes).
bool readRows(Reader& r, std::uint8_t* bits, png_uint_32 height, std::size_t stride) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  for (png_uint_32 row = 0; row < height; ++row) png_read_row(r.png, bits + (height - 1 - row) * stride, nullptr);
  png_read_end(r.png, nullptr);
  return true;
}

}  // namespace

PackedBitImage decodeBitPng(std::string_view png, const std::string& label) {
  Reader r;
  r.data = reinterpret_cast<const unsigned char*>(png.data());
  r.size = png.size();
  if (r.size < 8 || png_sig_cmp(r.data, 0, 8) != 0) throw InputError(label + ": not a PNG file");
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r, errorCallback, warningCallback);
  if (r.png != nullptr) r.info = png_create_info_struct(r.png);
  if (r.png == nullptr || r.info == nullptr) {
    png_destroy_read_struct(&r.png, nullptr, nullptr);
    throw InternalError("libpng: cannot create a reader");
  }
  png_uint_32 width = 0, height = 0;
  PackedBitImage image;
  bool ok = readHeader(r, width, height);
  if (ok && (width == 0 || height == 0 || width > 1u << 20 || height > 1u << 20)) {
    std::snprintf(r.message.data(), r.message.size(), "unsupported size %ux%u", width, height);
    ok = false;
  }
  if (ok) {
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.bits.assign(static_cast<std::size_t>(image.bytesPerRow()) * height, 0);
    ok = readRows(r, image.bits.data(), height, static_cast<std::size_t>(image.bytesPerRow()));
  }
  png_destroy_read_struct(&r.png, &r.info, nullptr);
  if (!ok) throw InputError(label + ": " + r.message.data());
  return image;
}

WorldFileGrid parseWorldFile(std::string_view text, const std::string& label) {
  std::istringstream in{std::string(text)};
  std::array<double, 6> v{};
  for (double& x : v)
    if (!(in >> x)) throw InputError(label + ": a world file needs six numbers");
  if (v[1] != 0.0 || v[2] != 0.0 || v[0] <= 0.0 || v[3] >= 0.0)
    throw InputError(label + ": the world file must describe a north-up grid (no rotation)");
  // The world file gives the centre of the top-left cell.
  return {v[4] - 0.5 * v[0], v[5] - 0.5 * v[3], v[0], -v[3]};
}

}  // namespace og::data
