#include "io/Image.hpp"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <cstddef>
#include <exception>
#include <string>
#include <system_error>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

namespace og::io {
namespace fs = std::filesystem;

namespace {

/// Largest accepted side in pixels: far above any render target, small enough that a hostile
/// header cannot make us allocate more than 32768² × 16 bytes.
constexpr int kMaxSide = 32768;

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw InputError(file.string() + ": " + problem);
}

/// Library messages may span lines; error messages are one line by policy.
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? std::string("unknown error") : text;
}

std::size_t pixelCount(int width, int height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

/// Throws unless the size is usable; `what` says which image (the target file).
void checkSize(const fs::path& file, int width, int height) {
  if (width <= 0 || height <= 0)
    fail(file, "invalid image size " + std::to_string(width) + "x" + std::to_string(height));
  if (width > kMaxSide || height > kMaxSide)
    fail(file, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                   " exceeds the limit of " + std::to_string(kMaxSide) + " pixels per side");
}

template <typename Image>
void checkImage(const fs::path& file, const Image& image) {
  checkSize(file, image.width, image.height);
  if (image.pixels.size() != 4 * pixelCount(image.width, image.height))
    throw InternalError(file.string() + ": image buffer holds " +
                        std::to_string(image.pixels.size()) + " values, expected " +
                        std::to_string(4 * pixelCount(image.width, image.height)));
}

/// Requires an existing regular file, so "no such file" reads better than a codec's message.
void checkReadable(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) fail(file, "no such file");
  if (!fs::is_regular_file(file, ec)) fail(file, "not a regular file");
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// PNG. Reading: libpng's simplified API reports errors through png_image::message, no setjmp
// needed. Writing: the full API, for the compression level (the simplified one has only
// zlib's default, 6, or PNG_IMAGE_FLAG_FAST, which drops the row filters).

namespace {

/// zlib level of written PNGs. Level 2 with libpng's adaptive row filters writes a 1280x720
/// frame 4-5x faster than the default level 6 (sea-4m: 38 against 166 ms) for a file ~20 %
/// larger (640 against 533 KB); `render`'s start-up paid the difference (docs/performance.md).
constexpr int kPngZlibLevel = 2;

/// Where pngError leaves libpng's message before it long-jumps back into writePngFile.
struct PngWriteError {
  std::array<char, 256> message{};
};

[[noreturn]] void pngError(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngWriteError*>(png_get_error_ptr(png));
  // libpng's own writer says only "Write Error"; errno says why (a full disk, a file too large).
  const bool io = std::strcmp(message, "Write Error") == 0 && errno != 0;
  std::snprintf(error->message.data(), error->message.size(), "%s%s%s", message, io ? ": " : "",
                io ? std::strerror(errno) : "");
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

/// Writes 8-bit RGBA rows (`width` x `height`, tightly packed) as an RGB or RGBA PNG with an
/// sRGB chunk. C style on purpose: libpng's errors long-jump out of the calls below, so nothing
/// in this frame may need a destructor. Returns false with `error` filled in on failure.
bool writePngFile(const char* path, const std::uint8_t* rgba, int width, int height, bool keepAlpha,
                  PngWriteError* error) {
  std::FILE* file = std::fopen(path, "wb");
  if (file == nullptr) {
    std::snprintf(error->message.data(), error->message.size(), "%s", std::strerror(errno));
    return false;
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, pngError, pngWarning);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (png == nullptr || info == nullptr) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    std::snprintf(error->message.data(), error->message.size(), "out of memory");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {  // NOLINT(cert-err52-cpp): libpng's error protocol
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return false;
  }
  png_init_io(png, file);
  errno = 0;
  png_set_compression_level(png, kPngZlibLevel);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               keepAlpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  if (!keepAlpha) png_set_filler(png, 0, PNG_FILLER_AFTER);  // the rows' 4th byte is dropped
  const std::size_t stride = 4 * static_cast<std::size_t>(width);
  for (int y = 0; y < height; ++y) png_write_row(png, rgba + static_cast<std::size_t>(y) * stride);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  if (std::fflush(file) != 0 || std::ferror(file) != 0) {
    std::snprintf(error->message.data(), error->message.size(), "%s", errno != 0 ? std::strerror(errno) : "write error");
    std::fclose(file);
    return false;
  }
  if (std::fclose(file) != 0) {
    std::snprintf(error->message.data(), error->message.size(), "%s", std::strerror(errno));
    return false;
  }
  return true;
}

}  // namespace

void writePng(const fs::path& file, const ImageRgba8& image, bool keepAlpha) {
  checkImage(file, image);
  writeFileAtomically(file, [&](const fs::path& tmp) {
    PngWriteError error;
    if (!writePngFile(tmp.c_str(), image.pixels.data(), image.width, image.height, keepAlpha, &error))
      fail(file, "cannot write PNG: " + oneLine(error.message.data()));
  });
}

ImageRgba8 readPng(const fs::path& file) {
  checkReadable(file);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, file.c_str()) == 0) {
    const std::string message = oneLine(png.message);
    png_image_free(&png);
    fail(file, "not a readable PNG: " + message);
  }
  if (png.width == 0 || png.height == 0 || png.width > static_cast<png_uint_32>(kMaxSide) ||
      png.height > static_cast<png_uint_32>(kMaxSide)) {
    const std::string size = std::to_string(png.width) + "x" + std::to_string(png.height);
    png_image_free(&png);
    fail(file,
         "PNG size " + size + " is outside 1.." + std::to_string(kMaxSide) + " pixels per side");
  }
  // Ask for 8-bit sRGB RGBA whatever the file holds (palette, grey, 16-bit, ...).
  png.format = PNG_FORMAT_RGBA;
  ImageRgba8 image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.pixels.resize(4 * pixelCount(image.width, image.height));
  if (png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr) == 0) {
    const std::string message = oneLine(png.message);
    png_image_free(&png);
    fail(file, "cannot decode PNG: " + message);
  }
  png_image_free(&png);  // already released by finish_read; harmless and keeps this obvious
  return image;
}

// ---------------------------------------------------------------------------------------------
// OpenEXR: one code path for half and float files; OpenEXR converts between the float frame
// buffer and the channel type it stores (rounding to nearest for half).

namespace {
constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};
constexpr std::size_t kFloatPixelBytes = 4 * sizeof(float);
}  // namespace

void writeExr(const fs::path& file, const ImageRgbaF& image, ExrPixelType type,
              const std::vector<ExrChannel>& extra) {
  checkImage(file, image);
  const std::size_t pixels = pixelCount(image.width, image.height);
  for (std::size_t i = 0; i < extra.size(); ++i) {
    const ExrChannel& c = extra[i];
    if (c.values.size() != pixels)
      fail(file, "OpenEXR channel '" + c.name + "' has " + std::to_string(c.values.size()) +
                     " values for " + std::to_string(pixels) + " pixels");
    bool taken = c.name.empty();
    for (const char* rgba : kChannelNames) taken = taken || c.name == rgba;
    for (std::size_t j = 0; j < i; ++j) taken = taken || extra[j].name == c.name;
    if (taken) fail(file, "OpenEXR channel name '" + c.name + "' is empty or already used");
  }
  // OpenEXR converts pixel types when reading but not when writing: the frame buffer must
  // hold the channel type, so half output goes through a converted copy.
  std::vector<half> halves;
  if (type == ExrPixelType::Half) halves.assign(image.pixels.begin(), image.pixels.end());
  writeFileAtomically(file, [&](const fs::path& tmp) {
    try {
      Imf::Header header(image.width, image.height);
      header.compression() = Imf::ZIP_COMPRESSION;
      const bool isHalf = type == ExrPixelType::Half;
      const Imf::PixelType pixelType = isHalf ? Imf::HALF : Imf::FLOAT;
      for (const char* name : kChannelNames)
        header.channels().insert(name, Imf::Channel(pixelType));

      // Slice takes a non-const pointer but only reads through it when writing.
      const std::size_t valueBytes = isHalf ? sizeof(half) : sizeof(float);
      const void* data = isHalf ? static_cast<const void*>(halves.data())
                                : static_cast<const void*>(image.pixels.data());
      char* base = const_cast<char*>(static_cast<const char*>(data));
      const std::size_t pixelBytes = 4 * valueBytes;
      const std::size_t rowBytes = pixelBytes * static_cast<std::size_t>(image.width);
      Imf::FrameBuffer frame;
      for (std::size_t c = 0; c < 4; ++c)
        frame.insert(kChannelNames[c],
                     Imf::Slice(pixelType, base + c * valueBytes, pixelBytes, rowBytes));
      for (const ExrChannel& c : extra) {
        header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
        char* values = const_cast<char*>(reinterpret_cast<const char*>(c.values.data()));
        frame.insert(c.name, Imf::Slice(Imf::FLOAT, values, sizeof(float),
                                        sizeof(float) * static_cast<std::size_t>(image.width)));
      }

      Imf::OutputFile out(tmp.c_str(), header);
      out.setFrameBuffer(frame);
      out.writePixels(image.height);
    } catch (const std::exception& e) {
      fail(file, "cannot write OpenEXR: " + oneLine(e.what()));
    }
  });
}

namespace {
// The data window's width and height, refused outside 1..kMaxSide. Computed in 64 bits: a
// hostile header can hold any int32 corners.
std::pair<long long, long long> exrWindowSize(const fs::path& file, const Imath::Box2i& window) {
  const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
  const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
  if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide)
    fail(file, "OpenEXR data window " + std::to_string(w) + "x" + std::to_string(h) +
                   " is outside 1.." + std::to_string(kMaxSide) + " pixels per side");
  return {w, h};
}
}  // namespace

ImageRgbaF readExr(const fs::path& file) {
  checkReadable(file);
  try {
    Imf::InputFile in(file.c_str());
    const Imath::Box2i window = in.header().dataWindow();
    const auto [w, h] = exrWindowSize(file, window);
    const Imf::ChannelList& channels = in.header().channels();
    for (std::size_t c = 0; c < 3; ++c)
      if (channels.findChannel(kChannelNames[c]) == nullptr)
        fail(file, std::string("OpenEXR file has no '") + kChannelNames[c] + "' channel");
    for (std::size_t c = 0; c < 4; ++c) {
      const Imf::Channel* channel = channels.findChannel(kChannelNames[c]);
      if (channel != nullptr && (channel->xSampling != 1 || channel->ySampling != 1))
        fail(file, std::string("OpenEXR channel '") + kChannelNames[c] +
                       "' is subsampled, which is not supported");
    }
    if (!in.isComplete()) fail(file, "OpenEXR file is incomplete (truncated?)");

    ImageRgbaF image;
    image.width = static_cast<int>(w);
    image.height = static_cast<int>(h);
    image.pixels.resize(4 * pixelCount(image.width, image.height));
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < 4; ++c) {
      // A missing alpha channel reads as the fill value 1 (opaque).
      frame.insert(kChannelNames[c],
                   Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, window, kFloatPixelBytes,
                                    kFloatPixelBytes * static_cast<std::size_t>(w), 1, 1,
                                    c == 3 ? 1.0 : 0.0));
    }
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    fail(file, "not a readable OpenEXR file: " + oneLine(e.what()));
  }
}

std::vector<std::string> readExrChannelNames(const fs::path& file) {
  checkReadable(file);
  try {
    Imf::InputFile in(file.c_str());
    std::vector<std::string> names;
    const Imf::ChannelList& channels = in.header().channels();
    for (auto it = channels.begin(); it != channels.end(); ++it) names.emplace_back(it.name());
    return names;
  } catch (const std::exception& e) {
    fail(file, "not a readable OpenEXR file: " + oneLine(e.what()));
  }
}

std::vector<float> readExrChannel(const fs::path& file, const std::string& name) {
  checkReadable(file);
  try {
    Imf::InputFile in(file.c_str());
    const Imath::Box2i window = in.header().dataWindow();
    const auto [w, h] = exrWindowSize(file, window);
    const Imf::Channel* channel = in.header().channels().findChannel(name);
    if (channel == nullptr) fail(file, "OpenEXR file has no '" + name + "' channel");
    if (channel->xSampling != 1 || channel->ySampling != 1)
      fail(file, "OpenEXR channel '" + name + "' is subsampled, which is not supported");
    if (!in.isComplete()) fail(file, "OpenEXR file is incomplete (truncated?)");
    std::vector<float> values(pixelCount(static_cast<int>(w), static_cast<int>(h)));
    Imf::FrameBuffer frame;
    frame.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window, sizeof(float),
                                        sizeof(float) * static_cast<std::size_t>(w)));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return values;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    fail(file, "not a readable OpenEXR file: " + oneLine(e.what()));
  }
}

}  // namespace og::io
