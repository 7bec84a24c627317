#pragma once
// Image files: 8-bit sRGB PNG through libpng, linear HDR OpenEXR through OpenEXR.
// Every writer goes through og::writeFileAtomically: a file appears complete or not at all.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace og::io {

/// 8-bit RGBA pixels, rows top to bottom, 4 bytes per pixel (sRGB-encoded colour).
struct ImageRgba8 {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // size 4 * width * height
};

/// Linear float RGBA pixels, rows top to bottom (radiance; alpha is coverage).
struct ImageRgbaF {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;  // size 4 * width * height
};

enum class ExrPixelType { Half, Float };

/// Writes an 8-bit PNG (RGB, or RGBA when `keepAlpha`), tagged sRGB. Throws og::InputError
/// naming the file when it cannot be written; never leaves a partial file.
void writePng(const std::filesystem::path& file, const ImageRgba8& image, bool keepAlpha = false);

/// Reads any PNG as 8-bit RGBA. Throws og::InputError "FILE: problem" on a bad file.
ImageRgba8 readPng(const std::filesystem::path& file);

/// An extra named channel of an EXR (an AOV, e.g. "whitecap", "depth"): one value per pixel,
/// rows top to bottom, the image's size. Always stored as 32-bit float (depths in metres
/// overflow half's 65504).
struct ExrChannel {
  std::string name;
  std::vector<float> values;
};

/// Writes a scanline OpenEXR with R, G, B, A channels (`type`) and the `extra` channels
/// (float), ZIP compressed. Throws og::InputError naming the file for a bad size or name (empty,
/// duplicate, or one of R, G, B, A).
void writeExr(const std::filesystem::path& file, const ImageRgbaF& image,
              ExrPixelType type = ExrPixelType::Half, const std::vector<ExrChannel>& extra = {});

/// The names of an OpenEXR's channels, in the file's (alphabetical) order.
std::vector<std::string> readExrChannelNames(const std::filesystem::path& file);

/// Reads one channel of an OpenEXR as float, rows top to bottom. Throws og::InputError
/// "FILE: problem" on a bad file or a missing channel.
std::vector<float> readExrChannel(const std::filesystem::path& file, const std::string& name);

/// Reads an OpenEXR's R, G, B, A channels as float (missing A = 1).
/// Throws og::InputError "FILE: problem" on a bad file.
ImageRgbaF readExr(const std::filesystem::path& file);

}  // namespace og::io
