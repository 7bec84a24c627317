// GL tier: the atmosphere tables computed on the GL device against the double-precision CPU
// reference (the same shaders/atmosphere/functions.glsl compiled as C++), and the table cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <filesystem>
#include <fstream>

#include "atmosphere/Reference.hpp"
#include "gl/Context.hpp"
#include "render/Atmosphere.hpp"
#include "support/GlFixtures.hpp"

using namespace og;
namespace fs = std::filesystem;

namespace {

atmosphere::Parameters smallEarth(int orders = 3) {
  atmosphere::Parameters p = atmosphere::earth();
  p.tables = atmosphere::TableSizes::small();
  p.scatteringOrders = orders;
  return p;
}

render::AtmosphereOptions noCache() {
  render::AtmosphereOptions o;
  o.useCache = false;
  return o;
}

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(OG_TEST_OUT_DIR) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Peak signal-to-noise ratio of `test` against `ref`, the peak being ref's largest value.
double psnr(const std::vector<double>& ref, const std::vector<double>& test) {
  double peak = 0.0, se = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    peak = std::max(peak, ref[i]);
    se += (ref[i] - test[i]) * (ref[i] - test[i]);
  }
  const double mse = se / static_cast<double>(ref.size());
  return mse == 0.0 ? 200.0 : 10.0 * std::log10(peak * peak / mse);
}

}  // namespace

// The sky maps are the GPU's sky images from sea level (stereographic, one per Sun zenith);
// the CPU renders the same directions from its own double-precision tables.
TEST(AtmospherePrecompute, GpuSkyImageMatchesCpuReference) {
  auto ctx = gl::createHeadlessContext();
  const atmosphere::Parameters p = smallEarth();
  render::Atmosphere gpu(p, noCache());
  std::printf("GPU tables: %.0f ms, sky maps %.0f ms\n", gpu.timing().tablesMs,
              gpu.timing().skyMapsMs);
  const auto t0 = std::chrono::steady_clock::now();
  const atmosphere::ReferenceTables cpu = atmosphere::precomputeReference(p);
  std::printf("CPU reference tables: %.0f ms\n",
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());

  // Transmittance tables agree closely (same integral, float vs double).
  const atmosphere::ReferenceTables gpuTables = gpu.readTables();
  double worst = 0.0;
  for (std::size_t i = 0; i < cpu.transmittance.texels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(cpu.transmittance.texels[i][c] - gpuTables.transmittance.texels[i][c]));
  EXPECT_LT(worst, 2e-3);

  const int n = p.tables.skyMapSize;
  const double extent = 1.1, maxZenith = render::Atmosphere::kSkyMapMaxZenithRad;
  EXPECT_NEAR(maxZenith, 105.0 * std::numbers::pi / 180.0, 1e-7);
  for (int layer : {0, 8, 11}) {
    const double sunZenith = layer / double(p.tables.skyMapLayers - 1) * maxZenith;
    const glm::dvec3 sun(std::sin(sunZenith), 0.0, std::cos(sunZenith));
    const std::vector<float> image = gpu.readSkyMap(layer);
    std::vector<double> ref, test;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::dvec2 u = (glm::dvec2(x + 0.5, y + 0.5) / double(n) * 2.0 - 1.0) * extent;
        const double s = glm::dot(u, u);
        if (s >= 1.0) continue;  // above the horizon only
        const glm::dvec3 dir(2.0 * u.x / (1 + s), 2.0 * u.y / (1 + s), (1 - s) / (1 + s));
        const glm::dvec3 l = atmosphere::referenceSkyRadiance(p, cpu, p.bottomRadiusM, dir.z,
                                                              sun.z, glm::dot(dir, sun));
        for (int c = 0; c < 3; ++c) {
          ref.push_back(l[c]);
          test.push_back(image[4 * static_cast<std::size_t>(y * n + x) + static_cast<std::size_t>(c)]);
        }
      }
    const double db = psnr(ref, test);
    std::printf("sky map layer %d (Sun zenith %.1f deg): PSNR %.1f dB\n", layer,
                sunZenith * 180 / std::numbers::pi, db);
    EXPECT_GT(db, 40.0) << "layer " << layer;
  }
}

// Second construction with the same parameters loads the tables; a corrupt or foreign file is
// ignored, recomputed and replaced, never trusted.
// The frame layer (the array's last) holds the two Sun layers around a zenith angle blended as
// skymap.glsl blends them per pixel: what the sea below 50 m reads instead (SKY_FRAME_LAYER).
TEST(AtmospherePrecompute, FrameSkyLayerBlendsTheLayersAroundTheSun) {
  auto ctx = gl::createHeadlessContext();
  const atmosphere::Parameters p = smallEarth(2);
  render::Atmosphere gpu(p, noCache());
  const int layers = p.tables.skyMapLayers;
  const double layerRad = render::Atmosphere::kSkyMapMaxZenithRad / (layers - 1);
  const double zenithRad = 5.3 * layerRad;  // 30 % of the way from layer 5 to layer 6
  gpu.prepareFrameSkyLayer(zenithRad);
  const std::vector<float> frame = gpu.readSkyMap(layers);
  const std::vector<float> a = gpu.readSkyMap(5), b = gpu.readSkyMap(6);
  ASSERT_EQ(frame.size(), a.size());
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const double want = 0.7 * static_cast<double>(a[i]) + 0.3 * static_cast<double>(b[i]);
    worst = std::max(worst, std::abs(static_cast<double>(frame[i]) - want));
    largest = std::max(largest, std::abs(want));
  }
  EXPECT_LT(worst, 2e-3 * largest);  // half floats
  EXPECT_GT(largest, 0.0);
}

// The sky maps' radial sums (render/SkyRadialSums, on CPU rasterisers): each column integrates a
// layer along one radius of the map, less its radiance below the horizon (its corner texel), so
// the difference of two rows over their spacing is the layer between them, and past the
// horizon's band the sums stand still. Checked against the layer's own texels on radii towards
// the Sun, away from it and across (a turned or mirrored table fails), for the frame layer (made
// each frame) and two Sun layers (made once).
namespace {
/// An atmosphere on llvmpipe's sky filter with its radial sums made: the frame layer's (the Sun
/// at 0.6 of the maps' zenith range) and the Sun layers'.
struct RadialSums {
  std::unique_ptr<gl::Context> ctx = gl::createHeadlessContext();
  test::ScopedEnv env{"OCEANGLOBE_SKY_FILTER", "radial"};
  atmosphere::Parameters p = smallEarth(2);
  render::Atmosphere gpu{p, noCache()};
  RadialSums() {
    gpu.prepareFrameSkyLayer(0.6 * render::Atmosphere::kSkyMapMaxZenithRad);
    gpu.prepareSunLayerSums();
  }
};
}  // namespace

TEST(AtmospherePrecompute, SkyRadialSumsIntegrateTheLayersAlongTheirRadii) {
  RadialSums f;
  const atmosphere::Parameters& p = f.p;
  render::Atmosphere& gpu = f.gpu;
  const int layers = p.tables.skyMapLayers;
  const render::SkyRadialSums& sums = gpu.skyRadialSums();
  constexpr int kAz = render::SkyRadialSums::kAzimuths, kRho = render::SkyRadialSums::kRadii;
  const int n = p.tables.skyMapSize;
  const double maxRho = 1.6, step = maxRho / kRho, extent = 1.1;
  for (const int layer : {layers, 0, layers / 2}) {  // the frame layer, the Sun at the zenith, at 52°
    const std::vector<float> map = gpu.readSkyMap(layer);
    const std::vector<float> table = sums.read(layer);
    ASSERT_EQ(table.size(), static_cast<std::size_t>(4 * kAz * kRho));
    const glm::vec3 below = sums.belowHorizon(layer);
    EXPECT_NEAR(below.g, map[1], 1e-6) << "layer " << layer;  // the corner texel
    EXPECT_GT(below.g, 0.0f);
    auto sum = [&](int column, int row) { return static_cast<double>(table[4 * static_cast<std::size_t>(row * kAz + column) + 1]); };
    auto skyAt = [&](double rho, double phi) {  // the layer bilinear (clamped to its edge), green
      const double x = std::clamp((0.5 + 0.5 * rho * std::cos(phi) / extent) * n - 0.5, 0.0, n - 1.0);
      const double y = std::clamp((0.5 + 0.5 * rho * std::sin(phi) / extent) * n - 0.5, 0.0, n - 1.0);
      const int x0 = std::min(static_cast<int>(x), n - 2), y0 = std::min(static_cast<int>(y), n - 2);
      auto at = [&](int i, int j) { return static_cast<double>(map[4 * static_cast<std::size_t>(j * n + i) + 1]); };
      const double fx = x - x0, fy = y - y0;
      return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
    };
    double worst = 0.0, largest = 0.0, beyond = 0.0, sunward = 0.0, away = 0.0;
    for (const int column : {0, kAz / 4, kAz / 2}) {  // towards the Sun (+x), across, away
      const double phi = (column + 0.5) / kAz * 2.0 * std::numbers::pi;
      for (int row = 0; row + 1 < kRho; ++row) {
        const double rho = (row + 1.0) * step;  // between the two rows' centres
        const double slope = (sum(column, row + 1) - sum(column, row)) / step + static_cast<double>(below.g);
        if (rho > 1.01 + 1.5 * 2.0 * extent / n) beyond = std::max(beyond, std::abs(sum(column, row + 1) - sum(column, row)) / step);
        if (rho < 0.95) {
          worst = std::max(worst, std::abs(slope - skyAt(rho, phi)));
          largest = std::max(largest, skyAt(rho, phi));
        }
      }
      if (column == 0) sunward = sum(column, static_cast<int>(0.9 / step)) - sum(column, static_cast<int>(0.5 / step));
      if (column == kAz / 2) away = sum(column, static_cast<int>(0.9 / step)) - sum(column, static_cast<int>(0.5 / step));
    }
    std::printf("layer %d: radial sums against the map: worst %.3g of %.3g; past the horizon %.3g; "
                "sunward %.4g, away %.4g\n", layer, worst, largest, beyond, sunward, away);
    EXPECT_LT(worst, 1e-3 * largest) << "layer " << layer;  // the same bilinear samples (midpoints), summed in float
    EXPECT_LT(beyond, 1e-3 * largest) << "layer " << layer;  // the value below the horizon taken out
    if (layer != 0) {
      EXPECT_GT(sunward, 1.2 * away) << "layer " << layer;  // the Sun's side is brighter: not turned
    }
  }
}

// The radial sums' mip levels (skymap_radial_mip.comp, the frame layer's and the Sun layers'):
// each texel the mean of the 2 x 2 below it, a 2 x 1 pair where the level below has one row.
TEST(AtmospherePrecompute, SkyRadialSumsMipLevelsAreBoxesOfTheLevelBelow) {
  const RadialSums f;
  const int layers = f.p.tables.skyMapLayers;
  const render::SkyRadialSums& sums = f.gpu.skyRadialSums();
  constexpr int kAz = render::SkyRadialSums::kAzimuths, kRho = render::SkyRadialSums::kRadii;
  for (const int layer : {layers, layers / 2}) {  // the frame layer, a Sun layer
    for (const int level : {1, 4, 8}) {  // 256 x 64, 32 x 8, 2 x 1 (from 4 x 1: one row below)
      const std::vector<float> finer = sums.read(layer, level - 1), coarser = sums.read(layer, level);
      const int fw = std::max(kAz >> (level - 1), 1), fh = std::max(kRho >> (level - 1), 1);
      const int w = std::max(kAz >> level, 1), h = std::max(kRho >> level, 1);
      ASSERT_EQ(coarser.size(), static_cast<std::size_t>(4 * w * h));
      double worst = 0.0, largest = 0.0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          auto at = [&](int i, int j) {
            return static_cast<double>(finer[4 * static_cast<std::size_t>(std::min(j, fh - 1) * fw + std::min(i, fw - 1)) + 1]);
          };
          const double box = 0.25 * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
          const double got = static_cast<double>(coarser[4 * static_cast<std::size_t>(y * w + x) + 1]);
          worst = std::max(worst, std::abs(got - box));
          largest = std::max(largest, std::abs(box));
        }
      EXPECT_GT(largest, 0.0) << "layer " << layer << " level " << level;
      EXPECT_LE(worst, 1e-5 * largest) << "layer " << layer << " level " << level;
    }
  }
}

// Each Sun layer's value below the horizon, which the radial sums' lookups add back, comes from
// the sky maps' cache on a cached start (no read-back): it must be the layer's corner texel, as
// on a cold start; the frame layer's, their blend at a fractional weight rounded to a half float
// as the layer's texels are.
TEST(AtmospherePrecompute, SkyRadialSumsBelowHorizonFromTheCache) {
  auto ctx = gl::createHeadlessContext();
  const test::ScopedEnv env("OCEANGLOBE_SKY_FILTER", "radial");
  const atmosphere::Parameters p = smallEarth(2);
  render::AtmosphereOptions o;
  o.cacheDirectory = freshDir("atmosphere-cache-radial-test");
  { render::Atmosphere cold(p, o); }
  render::Atmosphere cached(p, o);
  ASSERT_TRUE(cached.timing().fromCache);
  cached.prepareSunLayerSums();
  const int layers = p.tables.skyMapLayers;
  for (const int k : {0, layers / 2, layers - 1}) {
    const std::vector<float> map = cached.readSkyMap(k);
    const glm::vec3 below = cached.skyRadialSums().belowHorizon(k);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(below[c], map[static_cast<std::size_t>(c)]) << "layer " << k << " channel " << c;
  }
  cached.prepareFrameSkyLayer(0.63 * render::Atmosphere::kSkyMapMaxZenithRad);  // a fractional weight
  const std::vector<float> frame = cached.readSkyMap(layers);
  const glm::vec3 below = cached.skyRadialSums().belowHorizon(layers);
  for (int c = 0; c < 3; ++c)  // within a half float's step (the GPU's blend may round the other way)
    EXPECT_NEAR(below[c], frame[static_cast<std::size_t>(c)], 1e-3f * frame[static_cast<std::size_t>(c)]) << "frame channel " << c;
}

TEST(AtmospherePrecompute, CacheIsHitAndCorruptCacheIsRebuilt) {
  auto ctx = gl::createHeadlessContext();
  atmosphere::Parameters p = smallEarth(2);
  render::AtmosphereOptions o;
  // Its own directory: every other test shares atmosphere-cache (OCEANGLOBE_CACHE_DIR) and
  // may write or read it while this one corrupts and removes files there.
  o.cacheDirectory = freshDir("atmosphere-cache-precompute-test");
  render::Atmosphere first(p, o);
  EXPECT_FALSE(first.timing().fromCache);
  const fs::path file = first.timing().cacheFile;
  ASSERT_TRUE(fs::exists(file)) << file;
  const atmosphere::ReferenceTables reference = first.readTables();

  render::Atmosphere second(p, o);
  EXPECT_TRUE(second.timing().fromCache);
  EXPECT_EQ(second.timing().cacheFile, file);
  const atmosphere::ReferenceTables loaded = second.readTables();
  EXPECT_EQ(loaded.scattering.texels, reference.scattering.texels);
  EXPECT_EQ(loaded.transmittance.texels, reference.transmittance.texels);

  // Flip bytes in the middle of the payload: the checksum rejects it.
  const auto size = fs::file_size(file);
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(size / 2));
    const char junk[8] = {'\x7f', 'j', 'u', 'n', 'k', '!', '\x01', '\x02'};
    f.write(junk, sizeof junk);
  }
  render::Atmosphere third(p, o);
  EXPECT_FALSE(third.timing().fromCache);
  EXPECT_EQ(third.readTables().scattering.texels, reference.scattering.texels);
  render::Atmosphere fourth(p, o);  // the rebuilt file is good again
  EXPECT_TRUE(fourth.timing().fromCache);

  // Truncated and empty files are rebuilt as well.
  fs::resize_file(file, size / 3);
  EXPECT_FALSE(render::Atmosphere(p, o).timing().fromCache);
  std::ofstream(file, std::ios::trunc).close();
  EXPECT_FALSE(render::Atmosphere(p, o).timing().fromCache);
  EXPECT_EQ(fs::file_size(file), size);

  // Other parameters use another file.
  p.groundAlbedo = glm::dvec3(0.3);
  render::Atmosphere other(p, o);
  EXPECT_FALSE(other.timing().fromCache);
  EXPECT_NE(other.timing().cacheFile, file);
}
