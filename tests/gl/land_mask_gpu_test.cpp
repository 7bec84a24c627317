// GL tier: the land mask's GPU twin (shaders/terrain/landmask.glsl on render::LandMaskTexture's
// 16-bit texels and its fine level's rank index and blocks) gives the CPU's
// data::LandMask::landFraction: along coasts, at the fine level, the coarse one and blended
// between, across the antimeridian (where the texels wrap) and at the poles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "data/LandFractionMips.hpp"
#include "data/LandMask.hpp"
#include "geo/Camera.hpp"
#include "geo/Wgs84.hpp"
#include "gl/Context.hpp"
#include "gl/Probe.hpp"
#include "gl/Shader.hpp"
#include "render/LandMaskTexture.hpp"

using namespace og;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The probe's inputs: each point (latitude, longitude degrees) with the footprints in turn, in
// radians as the shader takes them.
std::vector<glm::vec3> probeInputs(const std::vector<glm::dvec2>& points, const std::vector<double>& footprintsDeg) {
  std::vector<glm::vec3> radians;
  for (std::size_t i = 0; i < points.size(); ++i)
    radians.emplace_back(static_cast<float>(points[i].x * kDeg), static_cast<float>(points[i].y * kDeg),
                         static_cast<float>(footprintsDeg[i % footprintsDeg.size()] * kDeg));
  return radians;
}

// A probe input back in degrees, as the shader was given it (floats).
struct ProbedDegrees {
  double lat, lon, footprint;
};
ProbedDegrees probedDegrees(const glm::vec3& radians) {
  return {static_cast<double>(radians.x) / kDeg, static_cast<double>(radians.y) / kDeg, static_cast<double>(radians.z) / kDeg};
}

// Rows across the antimeridian at `latitudes` (longitudes lonLo ... lonHi degrees, stepDeg
// apart, those past 180° wrapped), then rows 0.01° from both poles, 7.3° apart.
void appendSeamAndPoles(std::vector<glm::dvec2>& points, std::initializer_list<double> latitudes, double lonLo,
                        double lonHi, double stepDeg) {
  for (double lat : latitudes)
    for (double lon = lonLo; lon < lonHi; lon += stepDeg) points.emplace_back(lat, lon > 180.0 ? lon - 360.0 : lon);
  for (double lon = -180.0; lon < 180.0; lon += 7.3) {
    points.emplace_back(89.99, lon);
    points.emplace_back(-89.99, lon);
  }
}

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
  appendSeamAndPoles(points, {-16.8, -16.2, 71.2}, 179.5, 180.5, 0.0137);
  // Footprints in turn: the fine level, blended (two fine cells), the coarse level.
  const double fineCellDeg = mask.cellDeg() / data::LandMask::kFinePerCell;
  const std::vector<glm::vec3> radians = probeInputs(points, {0.0, 2.0 * fineCellDeg, 1.0});
  const std::vector<float> gpu = texture.probeLandFraction(radians);
  ASSERT_EQ(gpu.size(), points.size());
  int coastal = 0, fineDiffers = 0, worstIndex = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // The CPU at the GPU's float position (what the shader was given).
    const auto [lat, lon, footprint] = probedDegrees(radians[i]);
    const double cpu = static_cast<double>(mask.landFraction(lat, lon, footprint));
    if (cpu > 0.0 && cpu < 1.0) ++coastal;
    if (i % 3 == 0 && std::abs(cpu - static_cast<double>(mask.landFraction(lat, lon))) > 0.1) ++fineDiffers;
    const double diff = std::abs(static_cast<double>(gpu[i]) - cpu);
    if (diff > worst) {
      worst = diff;
      worstIndex = static_cast<int>(i);
    }
  }
  // Float cell coordinates on the GPU (86 400 fine columns): ~5e-3 of a fine cell.
  EXPECT_LT(worst, 1e-2) << "at " << points[static_cast<std::size_t>(worstIndex)].x << ", "
                         << points[static_cast<std::size_t>(worstIndex)].y;
  EXPECT_GT(coastal, 300);     // the points do cross coasts
  EXPECT_GT(fineDiffers, 20);  // and the fine level's own coast
}

// Where a footprint spans more than a 2′ cell the GPU reads the land fraction's pyramid
// (landmask.glsl's landFractionFiltered, R8 mip levels, hardware trilinear filtering): it gives
// the CPU's data::LandFractionMips::landFraction to the filter's 8-bit weights, blended (1.5
// cells), on the first level (3 cells), between levels (6 and 20 cells) and past the last (60),
// across the antimeridian and at the poles. Before the upload the GPU keeps the B-spline.
TEST(LandMaskGpu, LandFractionThroughThePyramidMatchesTheCpuTwin) {
  const auto context = gl::createHeadlessContext();
  const data::LandMask& mask = data::defaultLandMask();
  const data::LandFractionMips mips(mask);
  render::LandMaskTexture texture(&mask);
  std::vector<glm::dvec2> points;
  for (double lat = 59.0; lat < 66.0; lat += 0.0731)  // Finland's lakes and coasts
    for (double lon = 21.0; lon < 31.0; lon += 0.1337) points.emplace_back(lat, lon);
  appendSeamAndPoles(points, {-16.8, 65.3, 71.2}, 179.0, 181.0, 0.0437);
  const double cellDeg = mask.cellDeg();
  const std::vector<glm::vec3> radians =
      probeInputs(points, {1.5 * cellDeg, 3.0 * cellDeg, 6.0 * cellDeg, 20.0 * cellDeg, 60.0 * cellDeg});
  const std::vector<float> before = texture.probeLandFraction(radians);
  texture.uploadFractionMips(mips);
  ASSERT_TRUE(texture.fractionMipsUploaded());
  const std::vector<float> gpu = texture.probeLandFraction(radians);
  ASSERT_EQ(gpu.size(), points.size());
  int between = 0, changed = 0, splineWorse = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [lat, lon, footprint] = probedDegrees(radians[i]);
    const double cpu = static_cast<double>(mips.landFraction(lat, lon, footprint));
    between += cpu > 0.05 && cpu < 0.95 ? 1 : 0;
    worst = std::max(worst, std::abs(static_cast<double>(gpu[i]) - cpu));
    changed += std::abs(static_cast<double>(before[i]) - cpu) > 0.1 ? 1 : 0;
    splineWorse += std::abs(static_cast<double>(before[i]) - static_cast<double>(mask.landFraction(lat, lon, footprint))) > 1e-2 ? 1 : 0;
  }
  // llvmpipe's filter weighs texels and levels in 1/256ths (1.35 bytes here at worst).
  std::printf("worst difference %.5f (%.2f bytes)\n", worst, 255.0 * worst);
  EXPECT_LT(worst, 3.0 / 255.0);
  EXPECT_GT(between, 1000);  // the points do cross coasts and lakes
  EXPECT_GT(changed, 300);   // and the pyramid is not the B-spline there
  EXPECT_EQ(splineWorse, 0);  // (before the upload: the B-spline)
}

// The pyramid is uploaded for a view only where some pixel may weigh it (a footprint over a
// cell, at the farthest ground a ray can meet and the grazing floor of 0.2) and read alone
// (LANDMASK_FILTERED_ONLY) only where every pixel's footprint spans two cells: at the nearest
// ground, the passes' pixel angle. Checked against every pixel's footprint over whole views
// just past each threshold, looking down and obliquely.
TEST(LandMaskGpu, PyramidUploadedAndReadAloneOnlyWhereTheFootprintsSaySo) {
  const auto context = gl::createHeadlessContext();
  const data::LandMask& mask = data::defaultLandMask();
  render::LandMaskTexture texture(&mask);
  const double cellRad = mask.cellDeg() * kDeg;
  const int width = 1280, height = 720;
  auto viewAt = [&](double h, double pitch) {
    geo::CameraPose pose;
    pose.position = {36.0, -5.5, h};
    pose.pitchDeg = pitch;
    return geo::makeCameraView(pose, width, height);
  };
  auto threshold = [&](double pitch, auto&& predicate) {
    double lo = 1.0, hi = 1e8;
    while (hi - lo > 0.001 * lo) {
      const double mid = std::sqrt(lo * hi);
      (predicate(viewAt(mid, pitch)) ? hi : lo) = mid;
    }
    return hi;
  };
  // The footprints in cells of every fourth pixel each way and the frame's corners: the least
  // at the highest ground with the pixel's own angle (the terrain's, from its neighbours' rays),
  // the most at the ellipsoid with the grazing floor and the passes' largest angle (the globe's,
  // the centre pixel's).
  auto footprints = [&](const geo::CameraView& view) {
    const double pixelRad = 2.0 * std::tan(0.5 * view.verticalFovRad) / height;
    double least = 1e9, most = 0.0;
    for (int y = 0; y <= height; y += 4)
      for (int x = 0; x <= width; x += 4) {
        auto ray = [&](int i, int j) { return view.rayDirection(2.0 * i / width - 1.0, 2.0 * j / height - 1.0); };
        const glm::dvec3 dir = ray(x, y);
        const double ownRad = std::max(std::acos(std::min(glm::dot(dir, ray(x + 1, y)), 1.0)),
                                       std::acos(std::min(glm::dot(dir, ray(x, y + 1)), 1.0)));
        if (const std::optional<double> t = geo::intersectEllipsoid(view.positionEcef, dir, geo::kHighestGroundM))
          least = std::min(least, *t * ownRad / geo::kWgs84SemiMajorM / cellRad);
        if (const std::optional<double> t = geo::intersectEllipsoid(view.positionEcef, dir)) {
          const double cosIncidence = -glm::dot(geo::ellipsoidNormalAt(view.positionEcef + *t * dir), dir);
          most = std::max(most, *t * pixelRad / (geo::kWgs84SemiMajorM * std::max(cosIncidence, 0.2)) / cellRad);
        }
      }
    return std::pair{least, most};
  };
  // The upload's bound (mountains beyond the sea's horizon) does not depend on the pitch:
  // ~7 km at 720 rows; the horizon's pixels there are half a cell wide.
  const double weighed = threshold(-5.0, [&](const geo::CameraView& v) { return texture.fractionMipsWeighed(v, height); });
  EXPECT_GT(weighed, 3000.0);
  for (double pitch : {-90.0, -5.0, 5.0}) {
    EXPECT_FALSE(texture.fractionMipsWeighed(viewAt(0.99 * weighed, pitch), height)) << pitch;
    EXPECT_LT(footprints(viewAt(0.99 * weighed, pitch)).second, 1.0) << pitch;
    EXPECT_TRUE(texture.fractionMipsWeighed(viewAt(1.01 * weighed, pitch), height)) << pitch;
  }
  EXPECT_GT(footprints(viewAt(1.01 * weighed, -5.0)).second, 0.3) << "not needlessly early";
  EXPECT_FALSE(texture.fractionMipsOnly(viewAt(2.0e7, -90.0), height));  // (not before the upload)
  texture.uploadFractionMips(data::LandFractionMips(mask));
  for (double pitch : {-90.0, -60.0}) {
    const double alone = threshold(pitch, [&](const geo::CameraView& v) { return texture.fractionMipsOnly(v, height); });
    // 45° field, 720 rows: ~9000 km (the nearest ground's pixel: 2 cells, 7.4 km).
    const auto [least, most] = footprints(viewAt(1.001 * alone, pitch));
    EXPECT_GE(least, 2.0) << pitch;
    EXPECT_LT(least, 4.0) << pitch << ": not needlessly strict";
    EXPECT_FALSE(texture.fractionMipsOnly(viewAt(0.99 * alone, pitch), height)) << pitch;
  }
}

// Every pass finds the place under a pixel through latLonOfNormal (geo/ellipsoid.glsl). Its
// latitude must hold to metres: llvmpipe's asin, which it used, is a polynomial off by up to
// ~2e-4 rad (1.3 km south at 36° N), which put the sea's 15″ coast cells away from the
// terrain's, whose latitudes come from the CPU. Its atan is good to ~1.5e-6 rad (10 m).
TEST(LandMaskGpu, LatitudeOfANormalHoldsToTensOfMetres) {
  const auto context = gl::createHeadlessContext();
  std::vector<glm::vec4> values;
  std::vector<glm::dvec2> truth;
  for (double lat = -89.0; lat <= 89.0; lat += 0.77)
    for (double lon : {-179.3, -5.43, 0.0, 37.1, 121.9}) {
      const double phi = lat * kDeg, lambda = lon * kDeg;
      values.emplace_back(static_cast<float>(std::cos(phi) * std::cos(lambda)),
                          static_cast<float>(std::cos(phi) * std::sin(lambda)), static_cast<float>(std::sin(phi)), 0.0f);
      truth.emplace_back(phi, lambda);
    }
  const gl::Program probe({{GL_COMPUTE_SHADER, "geo/ellipsoid_probe.comp"}});
  gl::runProbe(probe, values, static_cast<int>(values.size()), "latLonOfNormal probe");
  double worstLat = 0.0, worstLon = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    worstLat = std::max(worstLat, std::abs(static_cast<double>(values[i].x) - truth[i].x));
    if (std::abs(truth[i].x) < 80.0 * kDeg)  // longitude: ill-conditioned at the poles
      worstLon = std::max(worstLon, std::abs(static_cast<double>(values[i].y) - truth[i].y) * std::cos(truth[i].x));
  }
  EXPECT_LT(worstLat, 5e-6);  // 32 m, a fifteenth of a 15″ cell
  EXPECT_LT(worstLon, 5e-6);
}

// A frame is drawn without the fine level's code (LANDMASK_COARSE_ONLY) only where no pixel
// would weigh it: at every pixel of such a view, the footprint the terrain's coast test takes
// (coastFootprintRad from the angle between neighbouring pixels' rays, the smallest of the
// globe's and the terrain's, at the ground's distance along the ray) spans three fine cells or
// more. Checked over whole views that just pass (a fraction above the threshold, looking
// straight down and obliquely), and the threshold is neither far above nor below them.
TEST(LandMaskGpu, FineLevelLeftOutOnlyWhereNoPixelResolvesIt) {
  const auto context = gl::createHeadlessContext();
  const data::LandMask& mask = data::defaultLandMask();
  const render::LandMaskTexture texture(&mask);
  ASSERT_TRUE(mask.hasFineLevel());
  const double fineCellRad = mask.cellDeg() / data::LandMask::kFinePerCell * kDeg;
  const int width = 320, height = 180;
  auto viewAt = [&](double h, double pitch) {
    geo::CameraPose pose;
    pose.position = {36.0, -5.5, h};
    pose.pitchDeg = pitch;
    return geo::makeCameraView(pose, width, height);
  };
  // The lowest height at which the frame leaves the fine level out, by bisection.
  auto threshold = [&](double pitch) {
    double lo = 1e4, hi = 1e8;
    while (hi - lo > 100.0) {
      const double mid = 0.5 * (lo + hi);
      (texture.fineLevelUnresolved(viewAt(mid, pitch), height) ? hi : lo) = mid;
    }
    return hi;
  };
  for (double pitch : {-90.0, -70.0, -30.0}) {
    const double h = threshold(pitch);
    // 45° field, 180 rows: ~540 km (the pixel's angle at the corners, 9 km of ground below the eye).
    EXPECT_GT(h, 4.0e5) << pitch;
    EXPECT_LT(h, 7.0e5) << pitch;
    const geo::CameraView view = viewAt(h * 1.001, pitch);
    ASSERT_TRUE(texture.fineLevelUnresolved(view, height));
    double least = 1e9;
    for (int y = 0; y + 1 < height; ++y)
      for (int x = 0; x + 1 < width; ++x) {
        auto ray = [&](int i, int j) {
          return view.rayDirection((i + 0.5) / width * 2.0 - 1.0, (j + 0.5) / height * 2.0 - 1.0);
        };
        const glm::dvec3 dir = ray(x, y);
        // The highest ground (Everest) lies nearer than the ellipsoid along the ray.
        const std::optional<double> t = geo::intersectEllipsoid(view.positionEcef, dir,
                                                                geo::kHighestGroundM);
        if (!t) continue;
        const double pixelRad = std::max(std::acos(std::min(glm::dot(dir, ray(x + 1, y)), 1.0)),
                                         std::acos(std::min(glm::dot(dir, ray(x, y + 1)), 1.0)));
        least = std::min(least, *t * pixelRad / geo::kWgs84SemiMajorM / fineCellRad);
      }
    EXPECT_GE(least, render::LandMaskTexture::kFineCellsUnweighted) << pitch;
    EXPECT_LT(least, 2.0 * render::LandMaskTexture::kFineCellsUnweighted) << pitch << ": not needlessly strict";
    EXPECT_FALSE(texture.fineLevelUnresolved(viewAt(0.9 * h, pitch), height)) << pitch;
  }
  // Without a fine level there is nothing to leave out, at any height.
  const render::LandMaskTexture coarse(nullptr);
  EXPECT_TRUE(coarse.fineLevelUnresolved(viewAt(4.0, -10.0), height));
}

}  // namespace
