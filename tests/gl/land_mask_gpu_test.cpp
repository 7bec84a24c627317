// GL tier: the land mask's GPU twin (shaders/terrain/landmask.glsl on render::LandMaskTexture's
// 16-bit texels) gives the CPU's data::LandMask::landFraction: along coasts, across the
// antimeridian (where the texels wrap) and at the poles.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/vec2.hpp>

#include "data/LandMask.hpp"
#include "gl/Context.hpp"
#include "render/LandMaskTexture.hpp"

using namespace og;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(LandMaskGpu, LandFractionMatchesTheCpuTwin) {
  const auto context = gl::createHeadlessContext();
  const data::LandMask& mask = data::defaultLandMask();
  const render::LandMaskTexture texture(&mask);
  ASSERT_TRUE(texture.active());
  std::vector<glm::dvec2> points;
  // A fine grid over the Strait of Gibraltar (coasts in every direction), a strip across the
  // antimeridian through Fiji's Taveuni and Wrangel Island (columns 0 and 10799 side by
  // side), and rows at the poles.
  for (double lat = 35.7; lat < 36.3; lat += 0.0123)
    for (double lon = -6.0; lon < -5.0; lon += 0.0171) points.emplace_back(lat, lon);
  for (double lat : {-16.8, -16.2, 71.2})
    for (double lon = 179.5; lon < 180.5; lon += 0.0137) points.emplace_back(lat, lon > 180.0 ? lon - 360.0 : lon);
  for (double lon = -180.0; lon < 180.0; lon += 7.3) {
    points.emplace_back(89.99, lon);
    points.emplace_back(-89.99, lon);
  }
  std::vector<glm::vec2> radians;
  for (const glm::dvec2& p : points) radians.emplace_back(static_cast<float>(p.x * kDeg), static_cast<float>(p.y * kDeg));
  const std::vector<float> gpu = texture.probeLandFraction(radians);
  ASSERT_EQ(gpu.size(), points.size());
  int coastal = 0, worstIndex = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // The CPU at the GPU's float position (what the shader was given).
    const double lat = static_cast<double>(radians[i].x) / kDeg, lon = static_cast<double>(radians[i].y) / kDeg;
    const double cpu = static_cast<double>(mask.landFraction(lat, lon));
    if (cpu > 0.0 && cpu < 1.0) ++coastal;
    const double diff = std::abs(static_cast<double>(gpu[i]) - cpu);
    if (diff > worst) {
      worst = diff;
      worstIndex = static_cast<int>(i);
    }
  }
  // Float cell coordinates on the GPU (10800 columns): ~1e-3 of a cell.
  EXPECT_LT(worst, 5e-3) << "at " << points[static_cast<std::size_t>(worstIndex)].x << ", "
                         << points[static_cast<std::size_t>(worstIndex)].y;
  EXPECT_GT(coastal, 300);  // the points do cross coasts
}

}  // namespace
