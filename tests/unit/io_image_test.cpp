// PNG and OpenEXR codecs: exact round trips, precision, and the error policy (InputError
// "FILE: problem", no partial or temporary files left behind).
#include <Imath/half.h>
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/Error.hpp"
#include "io/Image.hpp"

namespace fs = std::filesystem;
using og::io::ExrPixelType;
using og::io::ImageRgba8;
using og::io::ImageRgbaF;

namespace {

/// A fresh, empty directory per test so "no temp files left" can list it.
fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(OG_TEST_OUT_DIR) / "io_image" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

ImageRgba8 noiseRgba8(int width, int height, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  ImageRgba8 image{width, height, {}};
  image.pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (auto& p : image.pixels) p = static_cast<std::uint8_t>(byte(rng));
  return image;
}

ImageRgbaF rampRgbaF(int width, int height) {
  ImageRgbaF image{width, height, {}};
  image.pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> radiance(0.0f, 1000.0f);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = (i % 4 == 3) ? static_cast<float>(i % 17) / 16.0f : radiance(rng);
  image.pixels[0] = 1e-5f;  // a half subnormal
  image.pixels[1] = 65000.0f;
  return image;
}

std::string readAll(const fs::path& file) {
  std::string bytes(static_cast<std::size_t>(fs::file_size(file)), '\0');
  std::ifstream in(file, std::ios::binary);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bytes;
}

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << bytes;
}

/// Runs `f`, expecting InputError whose message starts with "FILE: ".
template <typename F>
void expectInputError(const fs::path& file, F&& f) {
  try {
    f();
    ADD_FAILURE() << "expected og::InputError for " << file;
  } catch (const og::InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

std::size_t countEntries(const fs::path& dir) {
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

/// Makes writes beyond `bytes` fail with EFBIG (instead of SIGXFSZ) while alive.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*previous_)(int) = nullptr;
};

}  // namespace

TEST(IoPng, RoundTripRgbaIsExact) {
  const fs::path file = freshDir("png_rgba") / "noise.png";
  const ImageRgba8 image = noiseRgba8(37, 23, 1);
  og::io::writePng(file, image, /*keepAlpha=*/true);
  const ImageRgba8 back = og::io::readPng(file);
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.pixels, image.pixels);
}

TEST(IoPng, RgbDropsAlphaAndIsTaggedSrgb) {
  const fs::path file = freshDir("png_rgb") / "noise.png";
  const ImageRgba8 image = noiseRgba8(16, 9, 2);
  og::io::writePng(file, image);
  const ImageRgba8 back = og::io::readPng(file);
  ASSERT_EQ(back.pixels.size(), image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    ASSERT_EQ(back.pixels[i], i % 4 == 3 ? 255 : image.pixels[i]) << "byte " << i;
  const std::string bytes = readAll(file);
  EXPECT_NE(bytes.find("sRGB"), std::string::npos) << "no sRGB chunk";
  EXPECT_EQ(bytes[25], 2) << "colour type should be RGB";  // IHDR colour type byte
}

TEST(IoExr, HalfRoundTripWithinHalfPrecision) {
  const fs::path file = freshDir("exr_half") / "ramp.exr";
  const ImageRgbaF image = rampRgbaF(31, 17);
  og::io::writeExr(file, image, ExrPixelType::Half);
  const ImageRgbaF back = og::io::readExr(file);
  ASSERT_EQ(back.width, 31);
  ASSERT_EQ(back.height, 17);
  ASSERT_EQ(back.pixels.size(), image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    // Exactly what half rounding gives; and within half's 2^-11 relative precision.
    EXPECT_EQ(back.pixels[i], static_cast<float>(Imath::half(image.pixels[i]))) << "value " << i;
    EXPECT_NEAR(back.pixels[i], image.pixels[i], std::abs(image.pixels[i]) / 2048.0f + 1e-7f);
  }
}

TEST(IoExr, FloatRoundTripIsExact) {
  const fs::path file = freshDir("exr_float") / "ramp.exr";
  const ImageRgbaF image = rampRgbaF(20, 11);
  og::io::writeExr(file, image, ExrPixelType::Float);
  const ImageRgbaF back = og::io::readExr(file);
  EXPECT_EQ(back.width, 20);
  EXPECT_EQ(back.height, 11);
  EXPECT_EQ(back.pixels, image.pixels);
}

TEST(IoPng, TruncatedFileIsInputError) {
  const fs::path dir = freshDir("png_truncated");
  const fs::path good = dir / "good.png";
  og::io::writePng(good, noiseRgba8(64, 64, 3), true);
  const std::string bytes = readAll(good);
  const fs::path bad = dir / "truncated.png";
  writeBytes(bad, bytes.substr(0, bytes.size() / 2));
  expectInputError(bad, [&] { (void)og::io::readPng(bad); });
  const fs::path header = dir / "header_only.png";
  writeBytes(header, bytes.substr(0, 20));
  expectInputError(header, [&] { (void)og::io::readPng(header); });
}

TEST(IoPng, TextFileNamedPngIsInputError) {
  const fs::path file = freshDir("png_text") / "notes.png";
  writeBytes(file, "this is not an image\n");
  expectInputError(file, [&] { (void)og::io::readPng(file); });
}

TEST(IoPng, MissingFileIsInputError) {
  const fs::path file = freshDir("png_missing") / "absent.png";
  expectInputError(file, [&] { (void)og::io::readPng(file); });
}

TEST(IoExr, TruncatedFileIsInputError) {
  const fs::path dir = freshDir("exr_truncated");
  const fs::path good = dir / "good.exr";
  og::io::writeExr(good, rampRgbaF(64, 64), ExrPixelType::Float);
  const std::string bytes = readAll(good);
  for (const std::size_t keep : {bytes.size() / 2, bytes.size() - 10, std::size_t{40}}) {
    const fs::path bad = dir / ("truncated_" + std::to_string(keep) + ".exr");
    writeBytes(bad, bytes.substr(0, keep));
    expectInputError(bad, [&] { (void)og::io::readExr(bad); });
  }
}

TEST(IoExr, TextFileNamedExrIsInputError) {
  const fs::path file = freshDir("exr_text") / "notes.exr";
  writeBytes(file, "this is not an image either\n");
  expectInputError(file, [&] { (void)og::io::readExr(file); });
}

TEST(IoWrite, NonexistentDirectoryIsInputErrorAndWritesNothing) {
  const fs::path dir = freshDir("no_dir") / "missing";
  const fs::path png = dir / "out.png";
  const fs::path exr = dir / "out.exr";
  expectInputError(png, [&] { og::io::writePng(png, noiseRgba8(4, 4, 4)); });
  expectInputError(exr, [&] { og::io::writeExr(exr, rampRgbaF(4, 4)); });
  EXPECT_FALSE(fs::exists(dir));
}

TEST(IoWrite, FailedWriteKeepsExistingTargetAndLeavesNoTemporary) {
  const fs::path dir = freshDir("failed_write");
  const fs::path png = dir / "image.png";
  const fs::path exr = dir / "image.exr";
  og::io::writePng(png, noiseRgba8(8, 8, 5), true);
  og::io::writeExr(exr, rampRgbaF(8, 8));
  const std::string pngBefore = readAll(png);
  const std::string exrBefore = readAll(exr);
  ASSERT_EQ(countEntries(dir), 2u);
  {
    // Incompressible images far above the limit: the codecs fail part-way through writing.
    const FileSizeLimit limit(4096);
    expectInputError(png, [&] { og::io::writePng(png, noiseRgba8(256, 256, 6), true); });
    try {
      og::io::writePng(png, noiseRgba8(256, 256, 6), true);
      ADD_FAILURE() << "the PNG over the size limit was written";
    } catch (const og::InputError& e) {  // libpng's "Write Error" with the system's reason
      const std::string reason = std::string("Write Error: ") + std::strerror(EFBIG);
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
    expectInputError(exr, [&] { og::io::writeExr(exr, rampRgbaF(256, 256), ExrPixelType::Float); });
  }
  EXPECT_EQ(readAll(png), pngBefore);
  EXPECT_EQ(readAll(exr), exrBefore);
  EXPECT_EQ(countEntries(dir), 2u) << "a temporary file was left behind";
}

TEST(IoWrite, WrongSizesAreRejected) {
  const fs::path dir = freshDir("bad_sizes");
  ImageRgba8 empty;
  EXPECT_THROW(og::io::writePng(dir / "empty.png", empty), og::InputError);
  ImageRgba8 huge{40000, 1, {}};
  huge.pixels.resize(4 * 40000);
  EXPECT_THROW(og::io::writePng(dir / "huge.png", huge), og::InputError);
  ImageRgbaF mismatched{4, 4, std::vector<float>(10)};
  EXPECT_THROW(og::io::writeExr(dir / "short.exr", mismatched), og::InternalError);
  EXPECT_EQ(countEntries(dir), 0u);
}
