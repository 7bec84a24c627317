#pragma once
// The GL tier's shared set-up: one headless context and one GlobeRenderer over the default
// elevation per test suite (GlobeSuite), frames built from a camera and a Sun given in the
// camera's horizon (frameOf), and the luminance and PNG helpers the image checks use.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
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

/// The renderer's display image as OG_TEST_OUT_DIR/<name>.png, to look at.
inline void savePng(const render::GlobeRenderer& r, const std::string& name) {
  io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".png"), r.display());
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
