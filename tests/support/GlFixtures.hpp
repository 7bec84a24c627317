#pragma once
// The GL tier's shared set-up: one headless context and one GlobeRenderer over the default
// elevation per test suite (GlobeSuite), frames built from a camera and a Sun given in the
// camera's horizon (frameOf), and the luminance and PNG helpers the image checks use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "data/Elevation.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"

namespace og::test {

/// Fixture: the context and the renderer are made once for the suite (an atmosphere and the FFT
/// patterns cost seconds) and shared by its tests through context_ and renderer_.
class GlobeSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = gl::createHeadlessContext();
    renderer_ = std::make_unique<render::GlobeRenderer>(data::defaultElevation());
  }
  static void TearDownTestSuite() {
    renderer_.reset();
    context_.reset();
  }
  static inline std::unique_ptr<gl::Context> context_;
  static inline std::unique_ptr<render::GlobeRenderer> renderer_;
};

/// A camera (degrees, metres above the ellipsoid) and the image size, px.
struct View {
  double latDeg = 0.0;
  double lonDeg = 0.0;
  double heightM = 2.0;
  double headingDeg = 0.0;  ///< clockwise from north
  double pitchDeg = 0.0;    ///< up positive, [-90, 90]
  double fovDeg = 60.0;     ///< vertical field of view
  int width = 64;
  int height = 48;
};

/// The frame of `view` lit by the Sun at `sunElevationDeg` above the camera's horizon and
/// `sunAzimuthDeg` clockwise from north; everything else FrameInput's defaults.
inline render::FrameInput frameOf(const View& view, double sunElevationDeg, double sunAzimuthDeg) {
  render::FrameInput f;
  f.camera.position = {view.latDeg, view.lonDeg, view.heightM};
  f.camera.headingDeg = view.headingDeg;
  f.camera.pitchDeg = view.pitchDeg;
  f.camera.verticalFovDeg = view.fovDeg;
  f.width = view.width;
  f.height = view.height;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, sunElevationDeg, sunAzimuthDeg);
  return f;
}

/// Rec. 709 luminance of pixel (x, y) of a linear image.
inline double luminance(const io::ImageRgbaF& im, int x, int y) {
  const float* p = &im.pixels[4 * static_cast<std::size_t>(y * im.width + x)];
  return 0.2126 * double{p[0]} + 0.7152 * double{p[1]} + 0.0722 * double{p[2]};
}

/// Rec. 709 luminance of every pixel, row by row.
inline std::vector<double> luminance(const io::ImageRgbaF& im) {
  std::vector<double> y;
  y.reserve(static_cast<std::size_t>(im.width * im.height));
  for (int row = 0; row < im.height; ++row)
    for (int x = 0; x < im.width; ++x) y.push_back(luminance(im, x, row));
  return y;
}

/// Frame `f` rendered with a feature off, then on (`set` switches it), each read back by
/// `read(r)`: for tests that a speed-up keeps the picture.
template <class Image>
struct OffAndOnImages {
  Image off, on;
};
template <class Read>
auto renderedOffAndOn(render::GlobeRenderer& r, const render::FrameInput& f, const std::function<void(bool)>& set,
                      Read read) {
  OffAndOnImages<decltype(read(r))> images;
  for (const bool on : {false, true}) {
    set(on);
    r.render(f);
    (on ? images.on : images.off) = read(r);
  }
  return images;
}
/// The radiance (linear floats).
using OffAndOn = OffAndOnImages<io::ImageRgbaF>;
inline OffAndOn renderOffAndOn(render::GlobeRenderer& r, const render::FrameInput& f,
                               const std::function<void(bool)>& set) {
  return renderedOffAndOn(r, f, set, [](const render::GlobeRenderer& g) { return g.radiance(); });
}
/// The display image (8-bit sRGB).
using DisplayOffAndOn = OffAndOnImages<io::ImageRgba8>;
inline DisplayOffAndOn displayOffAndOn(render::GlobeRenderer& r, const render::FrameInput& f,
                                       const std::function<void(bool)>& set) {
  return renderedOffAndOn(r, f, set, [](const render::GlobeRenderer& g) { return g.display(); });
}

/// How two radiance images of the same size differ per pixel: the largest relative change of
/// its first `channels` channels, |a - b| / max(|a|, floor), the worst and mean over the image
/// and how many pixels change by more than `bound`.
struct RadianceChange {
  double worst = 0.0, mean = 0.0;
  int over = 0;
};
/// Pixel i's largest relative change over its first `channels` channels (radianceChange's).
inline double relativeChange(const io::ImageRgbaF& a, const io::ImageRgbaF& b, std::size_t i, std::size_t channels,
                             float floor) {
  double d = 0.0;
  for (std::size_t k = 0; k < channels; ++k) {
    const float x = a.pixels[4 * i + k], y = b.pixels[4 * i + k];
    d = std::max(d, static_cast<double>(std::abs(x - y) / std::max(std::abs(x), floor)));
  }
  return d;
}
inline RadianceChange radianceChange(const io::ImageRgbaF& a, const io::ImageRgbaF& b, double bound,
                                     std::size_t channels = 3, float floor = 1e-3f) {
  RadianceChange c;
  const std::size_t n = std::min(a.pixels.size(), b.pixels.size()) / 4;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = relativeChange(a, b, i, channels, floor);
    c.worst = std::max(c.worst, d);
    c.mean += d / static_cast<double>(n);
    c.over += d > bound ? 1 : 0;
  }
  return c;
}

/// The renderer's display image as OG_TEST_OUT_DIR/<name>.png, to look at.
inline void savePng(const render::GlobeRenderer& r, const std::string& name) {
  io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".png"), r.display());
}

/// Where two radiance images differ, as OG_TEST_OUT_DIR/<name>_change.png: pixels changed by
/// over `bound` (radianceChange's measure) red, the others grey by their change (white at
/// `bound`), black where nothing changed; beside savePng's picture, to see which pixels moved.
inline void saveChangePng(const io::ImageRgbaF& a, const io::ImageRgbaF& b, double bound, const std::string& name,
                          std::size_t channels = 3) {
  io::ImageRgba8 out{a.width, a.height, std::vector<std::uint8_t>(4 * static_cast<std::size_t>(a.width) * a.height, 255)};
  const std::size_t n = std::min(a.pixels.size(), b.pixels.size()) / 4;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = relativeChange(a, b, i, channels, 1e-3f);
    const auto grey = static_cast<std::uint8_t>(std::lround(255.0 * std::min(1.0, d / bound)));
    out.pixels[4 * i] = d > bound ? 255 : grey;
    out.pixels[4 * i + 1] = d > bound ? 0 : grey;
    out.pixels[4 * i + 2] = d > bound ? 0 : grey;
  }
  io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + "_change.png"), out);
}

/// savePng's picture and saveChangePng's map of the change from `before` to `after`.
inline void savePictureAndChange(const render::GlobeRenderer& r, const io::ImageRgbaF& before,
                                 const io::ImageRgbaF& after, double bound, const std::string& name,
                                 std::size_t channels = 3) {
  savePng(r, name);
  saveChangePng(before, after, bound, name, channels);
}

/// Sets an environment variable for the scope's lifetime, then restores what it was.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* before = std::getenv(name)) before_ = before;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (before_) setenv(name_, before_->c_str(), 1);
    else unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> before_;  ///< the value it had, restored (a run of many tests in one process)
};

}  // namespace og::test
