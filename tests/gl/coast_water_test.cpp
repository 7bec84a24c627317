// GL tier (issue 15, "Done when"): the water volume over the sea floor (seed 001). Over a
// synthetic flat floor at a chosen depth, seen straight down from 20 m: the floor's detail shows
// through 2 m of water and is gone through 40 m; caustics move between two frames over a
// shallow floor and not over a deep one; from orbit the Great Bahama Bank (ETOPO5) reads
// turquoise against the deep Tongue of the Ocean; no NaN/Inf at the shoreline, where the floor
// rises above the surface, or with the camera under 1 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "data/Elevation.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GlFixtures.hpp"
#include "support/GridFixtures.hpp"
#include "support/ImageCompare.hpp"

using namespace og;

namespace {

constexpr int kW = 160, kH = 120;
constexpr double kLat = 24.0, kLon = -77.0;

// A flat sea floor `depthM` deep over 2° around (kLat, kLon).
data::LatLonGrid flatFloor(double depthM) {
  return test::grid("floor", kLat - 1.0, kLon - 1.0, 0.02, 101, 101, false,
                    [depthM](double, double) { return -depthM; });
}

render::FrameInput downView(double heightM, double timeS) {
  // Sun 55° up in the south: its glint lies ~35° off the vertical, outside the 30° view.
  render::FrameInput f = test::frameOf({kLat, kLon, heightM, 0.0, -90.0, 30.0, kW, kH}, 55.0, 180.0);
  f.wind.speedMs = 5.0;
  f.wind.towardsDeg = 45.0;
  f.simulationTimeS = timeS;
  return f;
}
using test::luminance;

// Fine detail: the mean |pixel - its 5x5 box mean| over the image's upper half (north, away
// from the Sun's glitter, which is the same over any depth).
double detailContrast(const std::vector<double>& y) {
  double sum = 0.0;
  int n = 0;
  for (int row = 2; row < kH / 2; ++row)
    for (int x = 2; x < kW - 2; ++x) {
      double box = 0.0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) box += y[static_cast<std::size_t>((row + dy) * kW + x + dx)];
      sum += std::abs(y[static_cast<std::size_t>(row * kW + x)] - box / 25.0);
      ++n;
    }
  return sum / n;
}

// Mean |a - b| over the upper half.
double meanAbsDiff(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size() / 2; ++i) sum += std::abs(a[i] - b[i]);
  return sum / double(a.size() / 2);
}

void save(const render::GlobeRenderer& r, const std::string& name) { test::savePng(r, name); }

}  // namespace

// Detail contrast seen from 20 m: through 2 m of water the floor's ripples and patches show;
// through 40 m the water has taken them (no more detail than over water 500 m deep).
TEST(CoastWater, FloorDetailShowsThroughTwoMetresAndIsGoneThroughForty) {
  auto ctx = gl::createHeadlessContext();
  double contrast[3];
  const double depths[3] = {2.0, 40.0, 500.0};
  for (int i = 0; i < 3; ++i) {
    render::GlobeRenderer r(flatFloor(depths[i]));
    r.render(downView(20.0, 1.0));
    contrast[i] = detailContrast(luminance(r.radiance()));
    save(r, "coast_floor_" + std::to_string(static_cast<int>(depths[i])) + "m");
  }
  std::printf("detail contrast: 2 m %.6f, 40 m %.6f, 500 m %.6f\n", contrast[0], contrast[1], contrast[2]);
  // The floor's share (above the surface's own texture, the same over any depth): through 40 m
  // under 3 % of what shows through 2 m (measured 1 %).
  EXPECT_GT(contrast[0], 3.0 * contrast[2]);
  EXPECT_LT(contrast[1] - contrast[2], 0.03 * (contrast[0] - contrast[2]));
}

// Caustics: the waves' focusing moves between frames 0.2 s apart on a floor 2 m down; over
// water 500 m deep only the surface itself changes.
TEST(CoastWater, CausticsMoveOnAShallowFloorOnly) {
  auto ctx = gl::createHeadlessContext();
  double change[2];
  const double depths[2] = {2.0, 500.0};
  for (int i = 0; i < 2; ++i) {
    render::GlobeRenderer r(flatFloor(depths[i]));
    r.render(downView(20.0, 1.0));
    const std::vector<double> a = luminance(r.radiance());
    r.render(downView(20.0, 1.2));
    change[i] = meanAbsDiff(a, luminance(r.radiance()));
  }
  std::printf("change between frames: 2 m %.6f, 500 m %.6f\n", change[0], change[1]);
  EXPECT_GT(change[0], 5.0 * change[1]);  // measured 24x
}

// The caustics' map is made only where some pixel looks it up: their lookups stop where twice
// the floor's footprint (at least the sea's) reaches the caustic patterns' tiles (6 m and
// 0.64 m). Over a floor 2 m down, 60° down at 160x120, the finest footprint is ~0.1 m from 20 m,
// ~1.4 m from 300 m and ~5.8 m from 1200 m, the switch near 880 m: the map is made from 20 and
// 300 m, not from 1200 m or 3 km, with the same picture as with the map made. Rules that
// skipped it where seen leave the floor without its caustics: never made, the 20 m view differs
// by up to 22 levels; tested against the 0.64 m tile instead of the 6 m one, the 300 m view by a
// level on 16 % of its pixels (and it reports the map unmade).
TEST(CoastWater, CausticsMapIsMadeOnlyWhereLookedUp) {
  auto ctx = gl::createHeadlessContext();
  for (const double heightM : {20.0, 300.0, 1200.0, 3000.0}) {
    SCOPED_TRACE(heightM);
    render::FrameInput f = downView(heightM, 1.0);
    f.camera.pitchDeg = -60.0;
    std::array<io::ImageRgba8, 2> shown;
    for (const bool always : {false, true}) {
      render::GlobeRenderer r(flatFloor(2.0));
      r.setCausticsAlwaysMade(always);
      r.render(f);
      EXPECT_TRUE(r.lastFrameFloorInReach());
      EXPECT_EQ(r.lastFrameCausticsSeen(), always || heightM < 880.0);
      shown.at(always ? 1 : 0) = r.display();
    }
    const test::Comparison c = test::compareRgb(shown[0], shown[1], 0);
    EXPECT_EQ(c.maxDiff, 0) << c.describe();
  }
}

// The floor seen through the waves from close by does not sparkle pixel by pixel: from 2 m,
// 30° down over a floor 5 m deep, the finest resolved waves turn the refracted rays enough to
// move the floor point by centimetres from one pixel to the next, and caustics looked up finer
// than that came out as salt-and-pepper noise (seventh session; the floor's footprint now
// carries that move, and the unresolved slopes' spread of its rays as a blur:
// water_volume.glsl). Pixel-scale contrast (|pixel - its 4 neighbours' mean| relative, over the
// lower half, the near field) against the same over water 500 m deep (the surface's own):
// measured 23x with the noise, 3.8x without (the caustics' network and the floor's patches).
TEST(CoastWater, FloorSeenThroughTheWavesDoesNotSparkle) {
  auto ctx = gl::createHeadlessContext();
  double sparkle[2];
  const double depths[2] = {5.0, 500.0};
  for (int i = 0; i < 2; ++i) {
    render::GlobeRenderer r(flatFloor(depths[i]));
    render::FrameInput f = test::frameOf({kLat, kLon, 2.0, 0.0, -30.0, 45.0, kW, kH}, 55.0, 180.0);
    f.wind.speedMs = 7.0;
    f.simulationTimeS = 1.0;
    r.render(f);
    const std::vector<double> y = luminance(r.radiance());
    double sum = 0.0;
    int n = 0;
    for (int row = kH / 2; row < kH - 1; ++row)
      for (int x = 1; x < kW - 1; ++x) {
        const auto at = [&](int yy, int xx) { return y[static_cast<std::size_t>(yy * kW + xx)]; };
        const double around = 0.25 * (at(row - 1, x) + at(row + 1, x) + at(row, x - 1) + at(row, x + 1));
        sum += std::abs(at(row, x) - around) / std::max(around, 1e-6);
        ++n;
      }
    sparkle[i] = sum / n;
    save(r, "coast_floor_sparkle_" + std::to_string(static_cast<int>(depths[i])) + "m");
  }
  std::printf("pixel-scale contrast: floor 5 m down %.4f, 500 m %.4f\n", sparkle[0], sparkle[1]);
  EXPECT_LT(sparkle[0], 8.0 * sparkle[1]);
}

// Floor brightness falls with depth: the mean radiance over the floor decreases monotonically
// from 1 m to 40 m and tends to the deep sea's, red first (clear water: turquoise shallows).
TEST(CoastWater, FloorFadesWithDepthRedFirst) {
  auto ctx = gl::createHeadlessContext();
  const double depths[4] = {1.0, 5.0, 15.0, 500.0};
  glm::dvec3 mean[4];
  for (int i = 0; i < 4; ++i) {
    render::GlobeRenderer r(flatFloor(depths[i]));
    render::FrameInput f = downView(20.0, 1.0);
    f.camera.pitchDeg = -80.0;  // off the vertical: no dependence on the exact nadir
    r.render(f);
    const io::ImageRgbaF img = r.radiance();
    glm::dvec3 s(0.0);
    for (std::size_t p = 0; p < img.pixels.size(); p += 4) s += glm::dvec3(img.pixels[p], img.pixels[p + 1], img.pixels[p + 2]);
    mean[i] = s / double(img.width * img.height);
    std::printf("%5.0f m: %.4f %.4f %.4f\n", depths[i], mean[i].x, mean[i].y, mean[i].z);
  }
  for (int i = 1; i < 4; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_LT(mean[i][c], mean[i - 1][c]) << depths[i] << " m, channel " << c;
  // At 5 m red has lost far more (relative to 1 m) than green and blue.
  EXPECT_LT(mean[1].x / mean[0].x, 0.7 * (mean[1].z / mean[0].z));
}

namespace {
const char* kEtopo5 = "/usr/share/ferret-vis/data/etopo5.cdf";

// ETOPO5 (5', ~9 km) over the Bahamas, 20-28°N, 82-72°W. `bankDepthM` > 0: the banks at that
// depth instead of ETOPO5's -10 m, which is a placeholder there, not a sounding: in 80-76°W,
// 22-27°N, 485 cells hold exactly -10 m against at most 12 for any other depth from -1 to
// -60 m; charts give the Great Bahama Bank 2-7 m.
data::LatLonGrid bahamas(double bankDepthM = 0.0) {
  const data::LatLonGrid world = data::readElevationFile(kEtopo5);
  const double step = 5.0 / 60.0;
  return test::grid("bahamas", 20.0, -82.0, step, 121, 97, false, [&](double lat, double lon) {
    const double z = world.sample(lat, lon);
    return bankDepthM > 0.0 && std::abs(z + 10.0) < 1e-3 ? -bankDepthM : z;
  });
}

struct OrbitColour {
  glm::dvec3 radiance;  // linear, the central 5x5 pixels' mean
  glm::dvec3 display;   // tone-mapped sRGB, 0-255
};

// The colour of the central 5x5 pixels seen straight down from 700 km over (lat, lon).
OrbitColour orbitColour(render::GlobeRenderer& r, double lat, double lon, const std::string& name) {
  render::FrameInput f;
  f.camera.position = {lat, lon, 7.0e5};
  f.camera.pitchDeg = -90.0;
  f.camera.verticalFovDeg = 10.0;
  f.width = 96;
  f.height = 96;
  f.wind.speedMs = 5.0;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal({lat, lon, 0.0}, 60.0, 135.0);
  r.render(f);
  save(r, name);
  const io::ImageRgbaF img = r.radiance();
  const io::ImageRgba8 shown = r.display();
  OrbitColour c{glm::dvec3(0.0), glm::dvec3(0.0)};
  for (int y = 46; y < 51; ++y)
    for (int x = 46; x < 51; ++x) {
      const auto i = static_cast<std::size_t>(4 * (y * img.width + x));
      c.radiance += glm::dvec3(img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]) / 25.0;
      c.display += glm::dvec3(shown.pixels[i], shown.pixels[i + 1], shown.pixels[i + 2]) / 25.0;
    }
  return c;
}

// Hue (degrees) and saturation (HSV, 0-1) of an sRGB colour.
glm::dvec2 hueSaturation(const glm::dvec3& c) {
  const double hi = std::max({c.x, c.y, c.z}), lo = std::min({c.x, c.y, c.z}), d = hi - lo;
  if (d <= 0.0) return {0.0, 0.0};
  double h = hi == c.x ? std::fmod((c.y - c.z) / d, 6.0) : hi == c.y ? (c.z - c.x) / d + 2.0 : (c.x - c.y) / d + 4.0;
  h *= 60.0;
  return {h < 0.0 ? h + 360.0 : h, d / hi};
}

// A bank that reads turquoise from orbit against the deep Tongue of the Ocean: the light it
// adds is greener than blue, and it is displayed cyan (hue under 200°, 15° or more from the
// Tongue's blue) about as saturated. Returns the bank's displayed hue, degrees.
double expectTurquoiseAgainstTheTongue(const OrbitColour& bank, const OrbitColour& tongue) {
  const glm::dvec3 added = bank.radiance - tongue.radiance;
  EXPECT_GT(added.y / added.z, 1.05);
  const glm::dvec2 hsBank = hueSaturation(bank.display), hsDeep = hueSaturation(tongue.display);
  EXPECT_LT(hsBank.x, 200.0);
  EXPECT_GT(hsDeep.x, hsBank.x + 15.0);
  EXPECT_GT(hsBank.y, 0.8 * hsDeep.y);
  return hsBank.x;
}
}  // namespace

// From orbit the Great Bahama Bank (a few metres of clear water over sand) reads turquoise,
// green and blue both bright, against the deep blue of the Tongue of the Ocean next to it.
TEST(CoastWater, BahamaBankIsTurquoiseFromOrbit) {
  if (!std::filesystem::exists(kEtopo5)) GTEST_SKIP() << kEtopo5 << " not installed (package ferret-datasets)";
  const double bank[2] = {24.25, -78.6}, tongue[2] = {24.0, -77.25};
  auto ctx = gl::createHeadlessContext();
  OrbitColour shallow[2], deep[2];
  for (int charted = 0; charted < 2; ++charted) {
    const data::LatLonGrid layer = bahamas(charted == 1 ? 4.5 : 0.0);
    std::printf("layer: bank %.1f m, Tongue of the Ocean %.0f m\n", double{layer.sample(bank[0], bank[1])},
                double{layer.sample(tongue[0], tongue[1])});
    ASSERT_GT(layer.sample(bank[0], bank[1]), -20.0f);
    ASSERT_LT(layer.sample(tongue[0], tongue[1]), -500.0f);  // ETOPO5 has it ~800 m
    render::GlobeRenderer r(layer);
    const std::string suffix = charted == 1 ? "_charted" : "";
    shallow[charted] = orbitColour(r, bank[0], bank[1], "coast_orbit_bank" + suffix);
    deep[charted] = orbitColour(r, tongue[0], tongue[1], "coast_orbit_tongue" + suffix);
    const glm::dvec2 hsBank = hueSaturation(shallow[charted].display), hsDeep = hueSaturation(deep[charted].display);
    std::printf("bank %.4f %.4f %.4f (sRGB %.0f %.0f %.0f, hue %.0f, sat %.2f), tongue %.4f %.4f %.4f (sRGB %.0f %.0f %.0f, hue %.0f, sat %.2f)\n",
                shallow[charted].radiance.x, shallow[charted].radiance.y, shallow[charted].radiance.z,
                shallow[charted].display.x, shallow[charted].display.y, shallow[charted].display.z, hsBank.x, hsBank.y,
                deep[charted].radiance.x, deep[charted].radiance.y, deep[charted].radiance.z, deep[charted].display.x,
                deep[charted].display.y, deep[charted].display.z, hsDeep.x, hsDeep.y);
  }
  // ETOPO5's 10 m: the light the bank adds over the deep water (the air's haze is the same
  // over both) is blue-green, red absorbed; the bank brighter and greener than the Tongue.
  const glm::dvec3 added = shallow[0].radiance - deep[0].radiance;
  EXPECT_GT(added.y, 5.0 * added.x);
  EXPECT_GT(added.y / added.z, 0.6);
  EXPECT_GT(shallow[0].radiance.y, 1.4 * deep[0].radiance.y);
  // At the charted depth the light the bank adds is turquoise, greener than blue (measured
  // G/B 1.22, 2.3x ETOPO5's green), and the displayed bank is cyan against the Tongue's blue
  // (measured hue 195 against 217, both through the same 700 km of blue haze: saturation
  // 0.38 and 0.40).
  const glm::dvec3 addedCharted = shallow[1].radiance - deep[1].radiance;
  EXPECT_GT(addedCharted.y, 2.0 * added.y);
  const double bankHue = expectTurquoiseAgainstTheTongue(shallow[1], deep[1]);
  // ETOPO5's 10 m reads only slightly greener (measured hue 205).
  EXPECT_GT(hueSaturation(shallow[0].display).x, bankHue + 5.0);
}

// The same with the embedded default layer (ETOPO20, ETOPO5 averaged to 20'), whose bank is
// ETOPO5's -10 m placeholder until data/ShallowBanks replaces it near land (a few metres west
// of Andros; the GSHHG mask then keeps that depth): turquoise against the Tongue of the Ocean,
// as at the charted depth above; uncorrected, cyan-blue.
TEST(CoastWater, BahamaBankIsTurquoiseFromOrbitWithTheDefaultLayer) {
  const double bank[2] = {24.0 + 1.0 / 6.0, -78.5}, tongue[2] = {24.0, -77.25};
  const data::LatLonGrid& corrected = data::defaultElevation();
  ASSERT_GT(corrected.sample(bank[0], bank[1]), -7.0f);
  auto ctx = gl::createHeadlessContext();
  OrbitColour shallow[2], deep[2];
  for (int fixed = 0; fixed < 2; ++fixed) {
    render::GlobeRenderer r(fixed == 1 ? corrected : data::uncorrectedDefaultElevation());
    const std::string suffix = fixed == 1 ? "_default" : "_default_raw";
    shallow[fixed] = orbitColour(r, bank[0], bank[1], "coast_orbit_bank" + suffix);
    deep[fixed] = orbitColour(r, tongue[0], tongue[1], "coast_orbit_tongue" + suffix);
    const glm::dvec2 hsBank = hueSaturation(shallow[fixed].display), hsDeep = hueSaturation(deep[fixed].display);
    std::printf("%s: bank sRGB %.0f %.0f %.0f (hue %.0f, sat %.2f), tongue sRGB %.0f %.0f %.0f (hue %.0f, sat %.2f)\n",
                suffix.c_str(), shallow[fixed].display.x, shallow[fixed].display.y, shallow[fixed].display.z, hsBank.x,
                hsBank.y, deep[fixed].display.x, deep[fixed].display.y, deep[fixed].display.z, hsDeep.x, hsDeep.y);
  }
  // Measured: the added light G/B 1.2, G/R 3.9; displayed hue 196 against the Tongue's 217
  // (saturation 0.39 and 0.40), as at the charted depth; uncorrected hue 205.
  const glm::dvec3 added = shallow[1].radiance - deep[1].radiance;
  EXPECT_GT(added.y, 2.5 * added.x);
  const double bankHue = expectTurquoiseAgainstTheTongue(shallow[1], deep[1]);
  // Uncorrected (the placeholder's 10 m, which the land mask keeps): bluer.
  EXPECT_GT(hueSaturation(shallow[0].display).x, bankHue + 5.0);
}

namespace {
// A shelf sloping from 5 m of land at 24.0°N down to 60 m deep 0.1° (11 km) south of the shore.
data::LatLonGrid shelf() {
  return test::grid("shelf", kLat - 1.0, kLon - 1.0, 0.005, 401, 401, false, [](double lat, double) {
    return std::clamp((lat - kLat) * 650.0, -60.0, 5.0);
  });
}
}  // namespace

// No NaN or Inf where the floor rises above the surface, at the shoreline, with the camera
// under 1 m, looking along the shore, down and up, the Sun high and set.
TEST(CoastWater, RadianceIsFiniteAtTheShore) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(shelf());
  int renders = 0;
  for (double lat : {kLat - 0.0002, kLat, kLat - 0.02})  // 2 m deep, the shoreline, 13 m deep
    for (double h : {0.3, 0.9, 20.0})
      for (double pitch : {-90.0, -20.0, 5.0})
        for (double sun : {-5.0, 70.0}) {
          render::FrameInput f;
          f.camera.position = {lat, kLon, h};
          f.camera.pitchDeg = pitch;
          f.camera.headingDeg = 10.0;  // towards the land
          f.width = 32;
          f.height = 18;
          f.wind.speedMs = 8.0;
          f.simulationTimeS = 2.3;
          f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, sun, 200.0);
          r.render(f);
          const io::ImageRgbaF img = r.radiance();
          std::size_t bad = 0;
          for (float v : img.pixels) bad += std::isfinite(v) ? 0 : 1;
          ASSERT_EQ(bad, 0u) << "at " << lat << " h " << h << " pitch " << pitch << " sun " << sun;
          ++renders;
        }
  EXPECT_EQ(renders, 54);
}

// The 20 km switch over a bank (5 m of water everywhere in view): the grid's per-pixel water
// volume (waves faded out, detail and caustics averaged out by the footprint) and the globe's
// column agree, with ocean_switch_test's tolerance for the horizon's sampling.
TEST(CoastWater, SwitchAtTwentyKilometresIsInvisibleOverABank) {
  const data::LatLonGrid bank = test::globalGrid("bank", 0.5, [](double, double) { return -5.0; });
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(bank);
  auto view = [](double heightM) {
    render::FrameInput f;
    f.camera.position = {20.0, -40.0, heightM};
    f.camera.headingDeg = 90;
    f.camera.pitchDeg = -30;
    f.camera.verticalFovDeg = 60;
    f.width = 192;
    f.height = 108;
    f.wind.speedMs = 9.0;
    f.wind.towardsDeg = 60.0;
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 30, 100);
    return f;
  };
  r.render(view(19999.0));
  const io::ImageRgba8 below = r.display();
  save(r, "coast_switch_below");
  r.render(view(20001.0));
  const io::ImageRgba8 above = r.display();
  save(r, "coast_switch_above");
  // Measured max 6, mean 0.14, 1.8 % over 2 (before the terrain stopped drawing and shadowing
  // with the floor under the water: max 119 where the floor showed through the sea's far
  // chords and shadowed its glint).
  const test::Comparison c = test::compareRgb(below, above, 2);
  if (!c.within({12, 0.2, 2, 0.03}))
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / "coast_switch.diff.png", c.diff);
  EXPECT_TRUE(c.within({12, 0.2, 2, 0.03})) << c.describe();
}

namespace {
// A shore at kLat (5 m of land north of it), a shelf falling 20 m per km to 60 m at 3 km, then
// a slope of 100 m per km beyond the water's reach (154 m, from 3.9 km out) to 400 m: every
// class of the grid's sea in one view (render/OceanRenderer's split).
data::LatLonGrid shoreShelfAndDeep() {
  return test::grid("shore-shelf-deep", kLat - 0.1, kLon - 0.1, 0.001, 201, 201, false,
                    [](double lat, double) {
                      const double offshoreKm = (kLat - lat) * 111.2;
                      if (offshoreKm <= 0.0) return 5.0;
                      return offshoreKm < 3.0 ? -20.0 * offshoreKm : std::max(-60.0 - 100.0 * (offshoreKm - 3.0), -400.0);
                    });
}
}  // namespace

namespace {
// A cliff coast: 300 m of land north of kLat, the floor falling 10 m per km from the foot of
// the cliff (the floor within reach over 15 km): with the Sun low behind the cliff its shadow
// falls ~2 km out over the sea and the floor seen through it.
data::LatLonGrid cliffCoast() {
  return test::grid("cliff", kLat - 0.1, kLon - 0.1, 0.001, 201, 201, false, [](double lat, double) {
    const double offshoreKm = (kLat - lat) * 111.2;
    return offshoreKm <= 0.0 ? 300.0 : -1.0 - 10.0 * offshoreKm;
  });
}

// A round island 600 m high at (kLat, kLon), its flanks falling 100 m per km (the layer's
// steepest slope 0.1, so that the coast class stays near the island) to a bank 30 m deep
// (`shelving`: the floor within reach everywhere) or to 400 m (beyond reach), over ±40 km.
data::LatLonGrid shadowingIsland(bool shelving) {
  return test::grid("island", kLat - 0.36, kLon - 0.4, 0.004, 181, 201, false, [shelving](double lat, double lon) {
    const double northKm = (lat - kLat) * 110.8, eastKm = (lon - kLon) * 111.3 * std::cos(kLat * M_PI / 180.0);
    const double height = 600.0 - 100.0 * std::hypot(northKm, eastKm);
    return std::max(height, shelving ? -30.0 : -400.0);
  });
}

// Bit k of OceanRenderer::classesDrawn: class k + 1 of ocean/sea_classify.frag.
constexpr unsigned kClassOpenSea = 1, kClassShadows = 2, kClassFloor = 4, kClassFloorShadows = 8, kClassCoast = 16;

// Samples per class (open sea, shadows, floor, floor with shadows, coast) as "n n n n n", for
// failure messages.
std::string classCounts(const std::array<std::uint64_t, render::OceanRenderer::kSeaClasses>& n) {
  std::string s;
  for (const std::uint64_t k : n) {
    if (!s.empty()) s += ' ';
    s += std::to_string(k);
  }
  return s;
}

// A 192 x 108 view from `position` (50° tall, one sample a pixel), wind 6 m/s at t = 1.5 s, the Sun
// `sunElevationDeg` up at `sunAzimuthDeg`.
render::FrameInput classView(const geo::Geodetic& position, double headingDeg, double pitchDeg,
                             double sunElevationDeg, double sunAzimuthDeg) {
  render::FrameInput f;
  f.camera.position = position;
  f.camera.headingDeg = headingDeg;
  f.camera.pitchDeg = pitchDeg;
  f.camera.verticalFovDeg = 50.0;
  f.width = 192;
  f.height = 108;
  f.samples = 1;  // the classes and the deferred surface are the single-sample path ("auto" is 4 on a GPU)
  f.wind.speedMs = 6.0;
  f.simulationTimeS = 1.5;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, sunElevationDeg, sunAzimuthDeg);
  return f;
}

// The display image of `f` by a fresh context and renderer over `grid` with OCEANGLOBE_SEA set
// to `path`; `check` looks at the renderer after the frame (which path it took).
io::ImageRgba8 drawnWithSea(const data::LatLonGrid& grid, const render::FrameInput& f, const char* path,
                            const std::function<void(const render::GlobeRenderer&)>& check) {
  const test::ScopedEnv sea("OCEANGLOBE_SEA", path);
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(grid);
  r.render(f);
  check(r);
  return r.display();
}

// `a` against `b`: at most `maxLevels` apart (the picture and a diff image on failure).
void expectWithinLevels(const io::ImageRgba8& a, const io::ImageRgba8& b, int maxLevels, const std::string& name) {
  const test::Comparison c = test::compareRgb(a, b, maxLevels);
  std::printf("%s: at most %d levels apart\n", name.c_str(), c.maxDiff);
  if (c.maxDiff > maxLevels) {
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".png"), a);
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".diff.png"), c.diff);
  }
  EXPECT_LE(c.maxDiff, maxLevels) << name << ": " << c.describe();
}

// `f` drawn deferred (render/OceanRenderer::drawDeferred), then by the grid's own fragments,
// compared as the classes are below.
// Returns the classes the deferred frame drew (OceanRenderer::classesDrawn).
unsigned expectDeferredMatchesForward(render::GlobeRenderer& r, const render::FrameInput& f, const std::string& name) {
  r.ocean().setDeferred(true);
  r.render(f);
  EXPECT_TRUE(r.ocean().lastDrawDeferred()) << name;
  const unsigned classesDrawn = r.ocean().classesDrawn();
  const io::ImageRgba8 deferred = r.display();
  save(r, name);
  r.ocean().setDeferred(false);
  r.render(f);
  r.ocean().setDeferred(true);
  EXPECT_FALSE(r.ocean().lastDrawDeferred()) << name;
  const io::ImageRgba8 forward = r.display();
  save(r, name + "_forward");
  const test::Comparison c = test::compareRgb(deferred, forward, 1);
  if (!c.within({2, 0.01, 1, 0.001}))
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".diff.png"), c.diff);
  EXPECT_TRUE(c.within({2, 0.01, 1, 0.001})) << name << ": " << c.describe();
  return classesDrawn;
}

// `f` drawn with the sea in classes, then by one program (saved as `name` and `name`_single),
// compared: at most 2 levels, 1 % of the pixels over 1 level (a diff image on failure).
void expectClassesMatchTheSingleProgram(render::GlobeRenderer& r, render::FrameInput f, const std::string& name) {
  f.oceanClasses = true;
  r.render(f);
  const io::ImageRgba8 classes = r.display();
  save(r, name);
  f.oceanClasses = false;
  r.render(f);
  const io::ImageRgba8 single = r.display();
  save(r, name + "_single");
  const test::Comparison c = test::compareRgb(classes, single, 1);
  if (!c.within({2, 0.01, 1, 0.001}))
    io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".diff.png"), c.diff);
  EXPECT_TRUE(c.within({2, 0.01, 1, 0.001})) << name << ": " << c.describe();
}
}  // namespace

// The terrain's shadows routed to their own class (render/OceanRenderer::shadowReachM): the
// classes without them (open sea, floor) must lie beyond every shadow the cliff casts. Looking
// at the cliff 2.5 km offshore from 100 m, the Sun 8° up behind it: its shadow covers the sea
// (and the Sun's glitter) from the cliff's foot to ~2.1 km out, the lower half of the picture
// but its bottom rows, so a shadow reach too short leaves a lit band where the single program
// has the shadow (the glitter: hundreds of levels). Measured: identical. (The cliff's slope,
// 3 m/m at the layer's cells, makes all this sea the coast class: see the next test.)
TEST(CoastWater, ShadowClassCoversEveryShadowOnTheSea) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(cliffCoast());
  expectClassesMatchTheSingleProgram(r, classView({kLat - 2.5 / 111.2, kLon, 100.0}, 0.0, -12.0, 8.0, 0.0),
                                     "coast_classes_cliff");
  // The comparison means something only with the cliff in the shadow maps (the routing's
  // reach comes from the casters' height: 300 m / tan 8° = 2.1 km).
  EXPECT_TRUE(r.terrain().shadows().on);
  EXPECT_GT(r.terrain().shadows().casterMaxHeightM, 250.0);
}

// The floor and the shadows combine independently in the sea's classes: an island's shadow
// under a low Sun (3° up in the west-south-west: 11 km long) falls over open sea far from its
// coast. Over 400 m of water that sea is the shadows' own class, without the water volume (the
// open sea in a mountain's shadow must not pay for it: sea-2m-horizon's regression,
// docs/performance.md); over a 30 m bank, the floor with shadows. Seen from 200 m, 8 km east
// of the island looking south-south-west across the shadow's southern edge (the lit sea
// beyond it has the Sun's glitter on its right): the picture is the single program's.
TEST(CoastWater, FloorAndShadowClassesCombineIndependently) {
  const test::ScopedEnv deferred("OCEANGLOBE_SEA", "deferred");  // also without stencil export (NVIDIA)
  auto ctx = gl::createHeadlessContext();
  for (const bool shelving : {true, false}) {
    SCOPED_TRACE(shelving ? "bank" : "deep water");
    render::GlobeRenderer r(shadowingIsland(shelving));
    const render::FrameInput f =
        classView({kLat - 1.0 / 110.8, kLon + 8.0 / (111.3 * std::cos(kLat * M_PI / 180.0)), 200.0}, 200.0, -25.0, 3.0, 250.0);
    r.ocean().setCountClassSamples(true);
    r.render(f);
    const unsigned drawn = r.ocean().classesDrawn();
    const auto n = r.ocean().classSamples();
    expectClassesMatchTheSingleProgram(r, f, shelving ? "coast_classes_island_bank" : "coast_classes_island_deep");
    EXPECT_TRUE(r.terrain().shadows().on);
    const std::string counts = classCounts(n);  // open sea, shadows, floor, floor with shadows, coast
    const std::uint64_t shadowed = shelving ? n[3] : n[1], volume = n[2] + n[3];
    EXPECT_GT(shadowed, 192u * 108u / 2u) << counts;
    // Over deep water the volume stays on the island's flanks (measured: 699 of 20 736 samples,
    // against 16 185 for the shadows' class; 82 before the GPU's latitudes were corrected, when
    // the flanks' lookups fell 1.3 km off the island drawn, geo/ellipsoid.glsl).
    if (!shelving) {
      EXPECT_LT(volume, 192u * 108u / 20u) << "the deep sea drawn with the water volume: " << counts;
    }
    EXPECT_NE(drawn & (shelving ? kClassFloorShadows : kClassShadows), 0u) << "classes drawn " << drawn;
  }
}

// A caster shades only the sea on its far side from the Sun (ocean/water_volume_vertex.glsl):
// the island under a Sun 10° up in the west-south-west (its shadow 3.8 km long, to the
// east-north-east) seen from 200 m 10 km west-south-west of it, the Sun behind the eye: the sea
// between the eye and the island is lit, so it is the open sea's class, though the island is
// within the shadows' reach of all of it. Measured: 9 600 open sea samples, none in the
// shadows' classes (2 953 the coast's); with the disc round each point that this replaced, or
// with the disc moved away from the Sun instead of towards it, 0 and 9 600 (sea-2m-horizon's
// sea was all in the shadows' class, Morocco's coast within their reach at Gibraltar:
// docs/performance.md). The picture must be the single program's, which has the shadows
// everywhere.
TEST(CoastWater, ShadowClassOnlyWhereACasterStandsTowardsTheSun) {
  const test::ScopedEnv deferred("OCEANGLOBE_SEA", "deferred");  // also without stencil export (NVIDIA)
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(shadowingIsland(false));
  const double az = 250.0 * M_PI / 180.0;
  const render::FrameInput f = classView({kLat + 10.0 * std::cos(az) / 110.8,
                                          kLon + 10.0 * std::sin(az) / (111.3 * std::cos(kLat * M_PI / 180.0)), 200.0},
                                         70.0, -8.0, 10.0, 250.0);
  r.ocean().setCountClassSamples(true);
  r.render(f);
  const auto n = r.ocean().classSamples();
  const std::string counts = classCounts(n);  // open sea, shadows, floor, floor with shadows, coast
  std::printf("samples per class (open sea, shadows, floor, floor with shadows, coast): %s\n", counts.c_str());
  EXPECT_TRUE(r.terrain().shadows().on) << "the island must be a caster for this to test anything";
  EXPECT_GT(r.terrain().shadows().casterMaxHeightM, 500.0);
  EXPECT_GT(n[0], 192u * 108u / 3u) << counts;
  EXPECT_LT(n[1] + n[3], n[0] / 4u) << counts;
  expectClassesMatchTheSingleProgram(r, f, "coast_classes_island_sunny_side");
}

// Far from land the sea's classes do without the coast test and the terrain's shadows even where
// the grid's triangles are kilometres wide (render/OpenSeaMap's land clearance): the default
// flythrough's 6.5 km frame, 195 km off Portugal looking at its coast under a Sun 7° up behind
// it, had 27 % of its pixels in the coast's class and 55 % in the shadows' at 1280x720 (the
// grid's far triangles are wider than the 2′ mask's cells, which the test alone flagged as
// near land); 6 % and 0 % with the clearance. Here (192x108) all 17 411 sea samples were the
// coast's before, 2 983 (and 220 the shadows') with it. The picture must be the single program's.
TEST(CoastWater, SeaFarFromLandNeedsNoCoastOrShadowClass) {
  const test::ScopedEnv deferred("OCEANGLOBE_SEA", "deferred");  // also without stencil export (NVIDIA)
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  render::FrameInput f = classView({38.04937, -11.74772, 6474.2}, 78.08, -20.44, 7.0, 80.0);
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal({38.0652, -11.6769, 3.0}, 7.0, 80.0);
  r.ocean().setCountClassSamples(true);
  r.render(f);
  const auto n = r.ocean().classSamples();
  const std::string counts = classCounts(n);
  EXPECT_TRUE(r.terrain().shadows().on) << "the coast's tiles must be casters for this to test anything";
  EXPECT_GT(n[0], 192u * 108u / 2u) << counts;                     // open sea
  EXPECT_LT(n[1] + n[3] + n[4], 192u * 108u / 4u) << counts;       // shadows, floor shadows, coast
  expectClassesMatchTheSingleProgram(r, f, "coast_classes_far_coast");
}

// The sea in classes (open sea, floor within reach, land near; each drawn by a program with
// only its code) against the one program of all the frame's features, looking at the shore
// with the Sun's glitter: over the shelf and deep layer 4.2 km offshore (180 m of water), 100 m
// up (the open sea's and the land's classes), and over shelf() 2.2 km offshore (14 m), 20 m up
// (the floor's and the land's). A pixel sent to the wrong class shows the deep sea where the
// floor is (tens of levels), or the sea over the beach. Measured: identical (max 0). The
// surface pass draws the grid in three (ocean/grid_near_land.comp): without its draw of the
// triangles neither near land nor over a floor in reach (the compact layout's), the 20 m view
// differs by 95 levels.
TEST(CoastWater, SeaClassesMatchTheSingleProgram) {
  const test::ScopedEnv deferred("OCEANGLOBE_SEA", "deferred");  // also without stencil export (NVIDIA)
  auto ctx = gl::createHeadlessContext();
  for (const auto& [deep, offshoreKm, heightM, pitch] :
       {std::tuple{true, 4.2, 100.0, -20.0}, std::tuple{false, 2.2, 20.0, -15.0}}) {
    render::GlobeRenderer r(deep ? shoreShelfAndDeep() : shelf());
    const render::FrameInput f = classView({kLat - offshoreKm / 111.2, kLon, heightM}, 10.0, pitch, 40.0, 20.0);
    r.render(f);
    EXPECT_NE(r.ocean().classesDrawn() & (deep ? kClassOpenSea : kClassFloor), 0u) << r.ocean().classesDrawn();
    expectClassesMatchTheSingleProgram(r, f, "coast_classes_" + std::to_string(int(-pitch)));
  }
}

// The sea deferred (the grid's nearest fragment per pixel into the surface buffer, then one
// full-screen shading per class) against the grid's own fragments shading it: the open sea
// with the Sun's glitter, the floor and the coast from 20 m over the shelf, the island's shadow
// on a bank (the floor with shadows). The buffer carries the grid's values as floats, the
// smooth ones (aerial perspective, pattern shares, the water's irradiance) as half floats:
// measured within 1 level. A pixel shaded with a wrong fragment's values, or of a wrong class,
// differs by tens of levels.
TEST(CoastWater, DeferredSeaMatchesTheGridsOwnFragments) {
  const test::ScopedEnv surfaceBuffer("OCEANGLOBE_SEA_SURFACE", "buffer");  // (the visibility buffer: its own tests)
  const test::ScopedEnv deferred("OCEANGLOBE_SEA", "deferred");  // also without stencil export (NVIDIA)
  auto ctx = gl::createHeadlessContext();
  {
    render::GlobeRenderer r(shoreShelfAndDeep());
    expectDeferredMatchesForward(r, classView({kLat - 30.0 / 111.2, kLon, 4.0}, 10.0, -10.0, 30.0, 10.0),
                                 "deferred_open_sea");
  }
  {
    // The open Atlantic (no floor within reach): the surface buffer's compact layout, its
    // layers 0-3 only (ocean/sea_surface.glsl), with stencil export or without.
    render::GlobeRenderer r(data::defaultElevation());
    expectDeferredMatchesForward(r, classView({20.0, -40.0, 4.0}, 270.0, -10.0, 30.0, 250.0), "deferred_open_atlantic");
    r.render(classView({20.0, -40.0, 4.0}, 270.0, -10.0, 30.0, 250.0));
    EXPECT_TRUE(r.ocean().lastSurfaceCompact());
  }
  {
    render::GlobeRenderer r(shelf());
    const unsigned drawn = expectDeferredMatchesForward(
        r, classView({kLat - 2.2 / 111.2, kLon, 20.0}, 10.0, -15.0, 40.0, 20.0), "deferred_shelf");
    EXPECT_NE(drawn & kClassFloor, 0u) << drawn;
  }
  {
    render::GlobeRenderer r(shadowingIsland(true));
    const unsigned drawn = expectDeferredMatchesForward(
        r, classView({kLat - 1.0 / 110.8, kLon + 8.0 / (111.3 * std::cos(kLat * M_PI / 180.0)), 200.0}, 200.0, -25.0, 3.0, 250.0),
        "deferred_island_bank");
    EXPECT_NE(drawn & kClassFloorShadows, 0u) << drawn;
  }
}

// Where the driver cannot export stencil values from a fragment shader (NVIDIA's drivers), the
// deferred sea's surface pass leaves each pixel's class in the surface buffer and three passes
// copy its bits into the stencil (OceanRenderer::classesIntoStencil; asked with
// OCEANGLOBE_SEA=deferred): the same classes, the same picture as with the exported stencil,
// over the shelf (floor 3 = 011, coast 5 = 101) and the island's bank in its shadow (floor with
// shadows 4 = 100), so every bit is copied; and over the open Atlantic, in the surface buffer's
// compact layout (the class in the low bits of layer 0's footprint, as in the full one).
TEST(CoastWater, DeferredSeaWithoutStencilExportDrawsTheSameClasses) {
  const test::ScopedEnv surfaceBuffer("OCEANGLOBE_SEA_SURFACE", "buffer");  // (the visibility buffer: its own tests)
  if (!gl::createHeadlessContext()->info().profile.stencilExport)
    GTEST_SKIP() << "this driver cannot export stencil values: no exported classes to compare with";
  const std::vector<std::tuple<std::string, data::LatLonGrid, render::FrameInput, unsigned>> views{
      {"deferred_no_export_shelf", shelf(), classView({kLat - 2.2 / 111.2, kLon, 20.0}, 10.0, -15.0, 40.0, 20.0),
       kClassFloor},
      {"deferred_no_export_island_bank", shadowingIsland(true),
       classView({kLat - 1.0 / 110.8, kLon + 8.0 / (111.3 * std::cos(kLat * M_PI / 180.0)), 200.0}, 200.0, -25.0, 3.0,
                 250.0),
       kClassFloorShadows},
      {"deferred_no_export_open_atlantic", data::defaultElevation(), classView({20.0, -40.0, 4.0}, 270.0, -10.0, 30.0, 250.0),
       0u}};
  for (const auto& [name, grid, f, mustDraw] : views) {
    SCOPED_TRACE(name);
    auto drawn = [&](bool exportStencil) {
      const std::optional<test::ScopedEnv> noExport =
          exportStencil ? std::nullopt : std::optional<test::ScopedEnv>(std::in_place, "OCEANGLOBE_STENCIL_EXPORT", "0");
      const test::ScopedEnv deferred("OCEANGLOBE_SEA", "deferred");
      auto ctx = gl::createHeadlessContext();
      EXPECT_EQ(gl::driverProfile().stencilExport, exportStencil);
      render::GlobeRenderer r(grid);
      r.render(f);
      EXPECT_TRUE(r.ocean().lastDrawDeferred());
      if (mustDraw != 0) {
        EXPECT_NE(r.ocean().classesDrawn() & mustDraw, 0u) << r.ocean().classesDrawn();
      } else {
        EXPECT_TRUE(r.ocean().lastSurfaceCompact());  // (no floor in reach)
      }
      if (!exportStencil) save(r, name);
      return r.display();
    };
    const io::ImageRgba8 exported = drawn(true), copied = drawn(false);
    const test::Comparison c = test::compareRgb(copied, exported, 0);
    if (c.maxDiff != 0) io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".diff.png"), c.diff);
    EXPECT_EQ(c.maxDiff, 0) << name << ": " << c.describe();
  }
}

// OCEANGLOBE_SEA=compute: the deferred classes shaded by compute shaders (for GPUs whose pixel
// shaders are few), the water volume's slope derivatives exchanged in the work group's shared
// memory, the classes read from the stencil or, without stencil export, from the surface
// buffer: the picture of the full-screen passes. Over the shelf (floor and coast classes), the
// island's bank in its shadow and the open Atlantic; on llvmpipe bit-identical (a GPU may
// contract its arithmetic differently in the two stages: 1 level allowed). Mutations: the
// derivatives set to 0 change the shelf by up to 7 levels, taken from the next quad by 5; the
// classes unread leave the sea black (255).
TEST(CoastWater, DeferredSeaByComputeDrawsTheSamePicture) {
  const test::ScopedEnv surfaceBuffer("OCEANGLOBE_SEA_SURFACE", "buffer");  // (the visibility buffer: its own tests)
  const bool exports = gl::createHeadlessContext()->info().profile.stencilExport;
  const std::vector<std::tuple<std::string, data::LatLonGrid, render::FrameInput, unsigned>> views{
      {"compute_shelf", shelf(), classView({kLat - 2.2 / 111.2, kLon, 20.0}, 10.0, -15.0, 40.0, 20.0),
       kClassFloor | kClassCoast},
      {"compute_island_bank", shadowingIsland(true),
       classView({kLat - 1.0 / 110.8, kLon + 8.0 / (111.3 * std::cos(kLat * M_PI / 180.0)), 200.0}, 200.0, -25.0, 3.0,
                 250.0),
       kClassFloorShadows},
      {"compute_open_atlantic", data::defaultElevation(), classView({20.0, -40.0, 4.0}, 270.0, -10.0, 30.0, 250.0),
       0u}};  // (one class, unrecorded: no floor or coast in the frame)
  for (const bool exportStencil : {true, false}) {
    if (exportStencil && !exports) continue;
    const std::optional<test::ScopedEnv> noExport =
        exportStencil ? std::nullopt : std::optional<test::ScopedEnv>(std::in_place, "OCEANGLOBE_STENCIL_EXPORT", "0");
    for (const auto& [name, grid, f, mustDraw] : views) {
      SCOPED_TRACE(name + (exportStencil ? " (stencil exported)" : " (classes in the surface buffer)"));
      auto drawn = [&](const char* path) {
        return drawnWithSea(grid, f, path, [&](const render::GlobeRenderer& r) {
          EXPECT_TRUE(r.ocean().lastDrawDeferred());
          EXPECT_EQ(r.ocean().lastClassesByCompute(), std::string(path) == "compute");
          EXPECT_EQ(r.ocean().classesDrawn() & mustDraw, mustDraw) << r.ocean().classesDrawn();
        });
      };
      const io::ImageRgba8 fragments = drawn("deferred"), computed = drawn("compute");
      expectWithinLevels(computed, fragments, 1, name);
    }
  }
}

// OCEANGLOBE_SEA_SURFACE=visibility: where the frame's sea has one class the surface pass
// writes each pixel's grid triangle alone and the shading interpolates its three vertices at
// the pixel's centre (ocean/sea_visibility.glsl): the picture of the surface buffer's, which
// keeps some terms as half floats and takes llvmpipe's own derivatives, by full-screen
// fragments and by compute shaders (without stencil export, by compute shaders). The open
// Atlantic from 4 m, from 2 m along the horizon (the grid's folds) and from 300 m. In a frame
// in classes (a floor or a coast) with stencil export and full-screen passes, the deep
// triangles (no floor in reach, no land near) go through it as classes of their own: the Strait
// of Gibraltar from 2 m (the coast's classes, open sea through the visibility buffer) and the
// shelf (the floor's; it has none). Mutations: the barycentrics a pixel off change the picture by
// 122-172 levels, the footprint doubled by 45-144.
TEST(CoastWater, VisibilityBufferDrawsTheSamePicture) {
  const bool exports = gl::createHeadlessContext()->info().profile.stencilExport;
  const std::vector<std::tuple<std::string, data::LatLonGrid, render::FrameInput, bool>> views{
      {"visibility_open_4m", data::defaultElevation(), classView({20.0, -40.0, 4.0}, 270.0, -10.0, 30.0, 250.0), true},
      {"visibility_open_2m_horizon", data::defaultElevation(), classView({20.0, -40.0, 2.0}, 200.0, -1.0, 12.0, 190.0),
       true},
      {"visibility_open_300m", data::defaultElevation(), classView({20.0, -40.0, 300.0}, 270.0, -20.0, 50.0, 120.0),
       true},
      {"visibility_shelf", shelf(), classView({kLat - 2.2 / 111.2, kLon, 20.0}, 10.0, -15.0, 40.0, 20.0), false},
      {"visibility_gibraltar_2m", data::defaultElevation(), classView({36.0, -5.5, 2.0}, 250.0, -2.0, 15.0, 240.0),
       false}};
  for (const bool exportStencil : {true, false}) {
    if (exportStencil && !exports) continue;
    const std::optional<test::ScopedEnv> noExport =
        exportStencil ? std::nullopt : std::optional<test::ScopedEnv>(std::in_place, "OCEANGLOBE_STENCIL_EXPORT", "0");
    // (Without export, as on NVIDIA, the path its GPU would take.)
    for (const char* path : exportStencil ? std::vector<const char*>{"deferred", "compute"} : std::vector<const char*>{"compute"}) {
      for (const auto& [name, grid, f, oneClass] : views) {
        if (!exportStencil && name == "visibility_open_300m") continue;  // (the suite's time)
        SCOPED_TRACE(name + " " + path + (exportStencil ? " (stencil exported)" : " (no stencil export)"));
        auto drawn = [&](const char* surface) {
          const test::ScopedEnv env("OCEANGLOBE_SEA_SURFACE", surface);
          return drawnWithSea(grid, f, path, [&](const render::GlobeRenderer& r) {
            EXPECT_TRUE(r.ocean().lastDrawDeferred());
            EXPECT_EQ(r.ocean().lastClassesByCompute(), std::string(path) == "compute");
            const bool asked = std::string(surface) == "visibility";
            const bool deepByVisibility = exportStencil && std::string(path) == "deferred";  // (in classes)
            if (name != "visibility_shelf") {  // (no deep triangle there)
              EXPECT_EQ(r.ocean().lastSurfaceByVisibility(), asked && (oneClass || deepByVisibility));
            }
          });
        };
        const io::ImageRgba8 buffer = drawn("buffer"), visibility = drawn("visibility");
        expectWithinLevels(visibility, buffer, 2, name + "_" + path);
      }
    }
  }
}

// Multisampled (4 samples, the GPU default), where the sea is otherwise drawn forward: with the
// visibility buffer each pixel is shaded once by a compute shader from its first sample with
// sea, its radiance written to its samples with sea (ocean/sea_radiance_copy.frag). Against the
// forward draw, whose every triangle in a pixel shades it at the pixel's centre, each for its
// own samples: the pixels on the grid's triangles' edges in the Sun's glitter differ (one
// triangle's shading against two triangles' mean; up to ~50 levels at 1.3 % of the pixels, the
// mean under 0.2 levels), the rest within 2 levels. The same views as above. Mutation: the
// copy read a pixel off fails it by 122-255 levels on 17-53 % of the pixels.
TEST(CoastWater, MultisampledVisibilityBufferDrawsTheForwardPicture) {
  const std::vector<std::tuple<std::string, data::LatLonGrid, render::FrameInput, bool>> views{
      {"visibility4_open_4m", data::defaultElevation(), classView({20.0, -40.0, 4.0}, 270.0, -10.0, 30.0, 250.0), true},
      {"visibility4_open_2m_horizon", data::defaultElevation(),
       classView({20.0, -40.0, 2.0}, 200.0, -1.0, 12.0, 190.0), true},
      {"visibility4_open_300m", data::defaultElevation(), classView({20.0, -40.0, 300.0}, 270.0, -20.0, 50.0, 120.0),
       true},
      {"visibility4_shelf", shelf(), classView({kLat - 2.2 / 111.2, kLon, 20.0}, 10.0, -15.0, 40.0, 20.0), false}};
  for (const auto& [name, grid, fOneSample, oneClass] : views) {
    SCOPED_TRACE(name);
    render::FrameInput f = fOneSample;
    f.samples = 4;
    auto drawn = [&](const char* surface) {
      const test::ScopedEnv asked("OCEANGLOBE_SEA_SURFACE", surface);
      auto ctx = gl::createHeadlessContext();
      render::GlobeRenderer r(grid);
      r.render(f);
      const bool byVisibility = std::string(surface) == "visibility" && oneClass;
      EXPECT_EQ(r.ocean().lastDrawDeferred(), byVisibility);
      EXPECT_EQ(r.ocean().lastSurfaceByVisibility(), byVisibility);
      EXPECT_EQ(r.ocean().lastClassesByCompute(), byVisibility);
      return r.display();
    };
    const io::ImageRgba8 forward = drawn("buffer"), visibility = drawn("visibility");
    const test::Comparison c = test::compareRgb(visibility, forward, 2);
    std::printf("%s: %s\n", name.c_str(), c.describe().c_str());
    if (!c.within({255, 0.25, 2, 0.02})) {
      io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".png"), visibility);
      io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / (name + ".diff.png"), c.diff);
    }
    EXPECT_TRUE(c.within({255, 0.25, 2, 0.02})) << c.describe();
  }
}

// On a GPU without stencil export (NVIDIA's) the frames with a floor within reach are drawn
// deferred with their classes shaded by compute shaders, the others forward (the H200's
// numbers: docs/performance.md, "Thirty-third session"): the rule played on llvmpipe with its
// export turned off, over the shelf (floor and coast), the island's bank and the open Atlantic.
TEST(CoastWater, GpuWithoutExportShadesFloorsByCompute) {
  const test::ScopedEnv noExport("OCEANGLOBE_STENCIL_EXPORT", "0");
  const test::ScopedEnv gpuSurface("OCEANGLOBE_SEA_SURFACE", "buffer");  // (a GPU's profile: no visibility buffer)
  const std::vector<std::tuple<std::string, data::LatLonGrid, render::FrameInput, bool>> views{
      {"shelf", shelf(), classView({kLat - 2.2 / 111.2, kLon, 20.0}, 10.0, -15.0, 40.0, 20.0), true},
      {"island_bank", shadowingIsland(true),
       classView({kLat - 1.0 / 110.8, kLon + 8.0 / (111.3 * std::cos(kLat * M_PI / 180.0)), 200.0}, 200.0, -25.0, 3.0,
                 250.0),
       true},
      {"open_atlantic", data::defaultElevation(), classView({20.0, -40.0, 4.0}, 270.0, -10.0, 30.0, 250.0), false}};
  auto ctx = gl::createHeadlessContext();
  for (const auto& [name, grid, f, floor] : views) {
    render::GlobeRenderer r(grid);
    r.ocean().setComputeForFloors(true);
    r.render(f);
    EXPECT_EQ(r.ocean().lastDrawDeferred(), floor) << name;
    EXPECT_EQ(r.ocean().lastClassesByCompute(), floor) << name;
    if (floor) {
      EXPECT_NE(r.ocean().classesDrawn() & (kClassFloor | kClassFloorShadows), 0u) << name;
    }
    r.ocean().setComputeForFloors(false);  // llvmpipe's own choice without export: forward,
    r.render(f);                            // its triangles in classes
    EXPECT_FALSE(r.ocean().lastDrawDeferred()) << name;
    EXPECT_EQ(r.ocean().lastDrawForwardSplit(), floor) << name;
  }
}

// OCEANGLOBE_SEA=split: a forward frame (here without stencil export, as on NVIDIA; with one
// sample and with four, the GPU default) draws the grid's triangles in three classes, near
// land, over a floor within reach and the rest, each with only what it needs: the picture of
// the one program with every feature (its pattern bands per pixel instead of per vertex):
// within 1 level here, 2 allowed. Over the shelf (floor and coast), the island's bank in its
// shadow, and the Strait of Gibraltar from 2 m (the coast test alone). Measured on llvmpipe at
// 1280x720 without export: sea-2m-horizon 208 -> 157 ms, coast-2m-bank 432 -> 344 (docs/
// performance.md, "Thirty-third session"). Mutation: the near-land list drawn without the
// coast test changes the island's bank with 4 samples by up to 17 levels (14 pixels).
TEST(CoastWater, ForwardSplitDrawsTheSamePicture) {
  const test::ScopedEnv noExport("OCEANGLOBE_STENCIL_EXPORT", "0");
  const std::vector<std::tuple<std::string, data::LatLonGrid, render::FrameInput>> views{
      {"split_shelf", shelf(), classView({kLat - 2.2 / 111.2, kLon, 20.0}, 10.0, -15.0, 40.0, 20.0)},
      {"split_island_bank", shadowingIsland(true),
       classView({kLat - 1.0 / 110.8, kLon + 8.0 / (111.3 * std::cos(kLat * M_PI / 180.0)), 200.0}, 200.0, -25.0, 3.0,
                 250.0)},
      {"split_gibraltar_2m", data::defaultElevation(), classView({36.0, -5.5, 2.0}, 270.0, 2.0, 20.0, 250.0)}};
  for (const int samples : {1, 4}) {
    for (const auto& [name, grid, frame] : views) {
      SCOPED_TRACE(name + ", " + std::to_string(samples) + " samples");
      render::FrameInput f = frame;
      f.samples = samples;
      auto drawn = [&](const char* path) {
        return drawnWithSea(grid, f, path, [&](const render::GlobeRenderer& r) {
          EXPECT_FALSE(r.ocean().lastDrawDeferred());
          EXPECT_EQ(r.ocean().lastDrawForwardSplit(), std::string(path) == "split");
        });
      };
      const io::ImageRgba8 single = drawn("forward"), split = drawn("split");
      expectWithinLevels(split, single, 2, name + "_" + std::to_string(samples) + "_samples");
    }
  }
}

namespace {
// A bank drowned 8 m deep within 1° of (20° N, 40° W), 4000 m deep beyond (the layer's
// bilinear step crosses the water's reach within 0.5 km of the bank's last cell), on a global
// layer (a regional one reads -1 m outside, which its terrain tiles take for land): the open
// Atlantic, no land within 1500 km.
data::LatLonGrid drownedBank() {
  return test::globalGrid("drowned-bank", 0.1, [](double lat, double lon) {
    return std::hypot(lat - 20.0, (lon + 40.0) * std::cos(20.0 * M_PI / 180.0)) < 1.0 ? -8.0 : -4000.0;
  });
}
}  // namespace

// A frame with the water volume and without the coast test (no land in view: every terrain
// tile under the sea), which the coasts' views never draw: the drowned bank from 20 m, 5.5 km
// inside its edge, looking south over its teal water to the deep beyond it (a dark band under
// the horizon) with the Sun's glitter. Each path draws the bank with a program that has the
// water volume and no coast test, the deep water without either: the sea in classes against
// the one program of the frame's features, the deferred sea against the grid's own fragments,
// and without stencil export (NVIDIA's) the forward split against the one program and the
// classes by compute against the fragments. Measured: identical but for the split's 1 level;
// the picture 7.3 levels from the deep sea's on average (its sky and glitter alike). Mutation:
// the grid's vertices never flagged over a floor in reach (ocean/grid_vertex_buffer.glsl) draw
// the bank's triangles without the water volume, 45 levels off in every path that splits.
TEST(CoastWater, DrownedBankFarFromLandDrawsItsFloorWithoutTheCoastTest) {
  const data::LatLonGrid bank = drownedBank();
  const render::FrameInput f = classView({19.1, -40.0, 20.0}, 180.0, -10.0, 40.0, 200.0);
  {
    auto ctx = gl::createHeadlessContext();
    render::GlobeRenderer r(bank);
    r.render(f);
    ASSERT_TRUE(r.lastFrameFloorInReach());
    ASSERT_FALSE(r.lastFrameLandInView()) << "the coast test is on: the test's case is not drawn";
    EXPECT_EQ(r.ocean().classesDrawn() & (kClassOpenSea | kClassFloor), kClassOpenSea | kClassFloor)
        << r.ocean().classesDrawn();
    expectClassesMatchTheSingleProgram(r, f, "drowned_bank_classes");
    expectDeferredMatchesForward(r, f, "drowned_bank_deferred");
    // The bank shows (else every path could agree on the deep sea's colour).
    render::GlobeRenderer deep(test::globalGrid("deep", 0.1, [](double, double) { return -4000.0; }));
    deep.render(f);
    EXPECT_GT(test::compareRgb(r.display(), deep.display(), 8).meanDiff, 4.0);
  }
  const test::ScopedEnv noExport("OCEANGLOBE_STENCIL_EXPORT", "0");
  auto drawn = [&](const char* path) {
    return drawnWithSea(bank, f, path, [&](const render::GlobeRenderer& r) {
      EXPECT_EQ(r.ocean().lastDrawForwardSplit(), std::string(path) == "split") << path;
      EXPECT_EQ(r.ocean().lastClassesByCompute(), std::string(path) == "compute") << path;
    });
  };
  expectWithinLevels(drawn("split"), drawn("forward"), 2, "drowned_bank_split");
  expectWithinLevels(drawn("compute"), drawn("deferred"), 1, "drowned_bank_compute");
}

// Where a grid cell's vertices (a few hundred metres apart from 3 km) fall on the land mask's
// fine land but its pixels are sea at their own footprint (the coast test keeps them), the
// floor search started from the vertices' floor at the surface and never left it: whole cells
// shaded as a floor at the surface, pale triangles and squares along every fjord of western
// Norway from 3 km (and a square off Ceuta from 1 km). It now starts from each pixel's own
// floor. Sea pixels are those whose depth AOV lies on the sea surface; the floor at the
// surface shows grey, the water blue. Measured (320x180): 4 grey of 2262 sea pixels; 814
// from the vertices' floor.
TEST(CoastWater, FjordShoresShowNoCellsOfFloorAtTheSurface) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  render::FrameInput f;
  f.camera.position = {61.0, 5.0, 3000.0};
  f.camera.headingDeg = 90.0;
  f.camera.pitchDeg = -5.0;
  f.width = 320;
  f.height = 180;
  f.samples = 1;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 30.0, 200.0);
  r.render(f);
  save(r, "fjords_3km");
  const geo::CameraView v = geo::makeCameraView(f.camera, f.width, f.height);
  const std::vector<float> distance = r.viewDistance();
  const io::ImageRgba8 img = r.display();
  int seaPixels = 0, grey = 0;
  for (int row = 0; row < f.height; ++row)
    for (int x = 0; x < f.width; ++x) {
      const glm::dvec3 dir = v.rayDirection((x + 0.5) / f.width * 2.0 - 1.0, 1.0 - (row + 0.5) / f.height * 2.0);
      const std::optional<double> t = geo::intersectEllipsoid(v.positionEcef, dir);
      const auto i = static_cast<std::size_t>(row * f.width + x);
      if (!t || std::abs(static_cast<double>(distance[i]) - *t) > 30.0) continue;
      const std::uint8_t* p = &img.pixels[4 * i];
      ++seaPixels;
      grey += p[2] - p[0] < 25 ? 1 : 0;  // the water is blue: blue over red by 40-60 levels
    }
  std::printf("fjords from 3 km: %d sea pixels, %d grey\n", seaPixels, grey);
  ASSERT_GT(seaPixels, 1500) << "the fjords' sea in view";
  EXPECT_LT(grey, seaPixels / 100) << "cells of floor at the surface along the shores";
}

// Below 20 km the sea is drawn with its water volume only where a floor within the water's reach
// lies under sea the eye sees a pixel or more below the horizon, in the view's frustum
// (TerrainRenderer's seaSeenMaxHeightM). From 2 m over the deep water east of Gran Canaria,
// looking at the island 60 km off, its shelf lies beyond the sea's horizon. The volume is left
// out there, with the picture the same to the last bit as with it; over the Great Bahama Bank
// it stays.
TEST(CoastWater, WaterVolumeOnlyWhereAFloorInReachIsSeen) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  render::FrameInput island = classView({28.0, -15.0, 2.0}, 270.0, 1.0, 20.0, 250.0);
  island.width = 320;
  island.height = 180;
  const test::OffAndOn images = test::renderOffAndOn(r, island, [&r](bool on) { r.terrain().setSeaSightTest(on); });
  EXPECT_FALSE(r.lastFrameFloorInReach()) << "no floor within reach seen off Gran Canaria";
  EXPECT_GT(r.terrain().stats().maxHeightM, 1000.0) << "the island is among the tiles";
  r.terrain().setSeaSightTest(false);
  r.render(island);
  EXPECT_TRUE(r.lastFrameFloorInReach()) << "every tile's highest point: the coasts' shallows";
  r.terrain().setSeaSightTest(true);
  ASSERT_EQ(images.off.pixels.size(), images.on.pixels.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < images.off.pixels.size(); ++i)
    worst = std::max(worst, static_cast<double>(std::abs(images.off.pixels[i] - images.on.pixels[i])));
  EXPECT_EQ(worst, 0.0);
  r.render(classView({24.2, -78.2, 2.0}, 270.0, -10.0, 20.0, 250.0));
  EXPECT_TRUE(r.lastFrameFloorInReach()) << "the bank's floor, 2-10 m under the eye";
}

// A floor 60 m down (within half the water's reach, whence its light comes back) under the eye,
// 2 m over a flat sea with no land: the water volume stays, though the floor's vertices lie
// far under the occluder below the sea's horizon (the sea's surface over them is what must be
// seen).
TEST(CoastWater, WaterVolumeKeptOverADeepShelfUnderTheEye) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(test::grid("shelf_60m", 20.0, -10.0, 0.05, 201, 201, false,
                                     [](double, double) { return -60.0; }));
  r.render(classView({25.0, -5.0, 2.0}, 0.0, -10.0, 30.0, 180.0));
  EXPECT_TRUE(r.lastFrameFloorInReach());
}
