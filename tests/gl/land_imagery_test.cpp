// GL tier (issue 14): land looks like the Earth. With the default (embedded) imagery the Sahara
// reads tan and the Congo basin green from 2000 km with the Sun 60° up; a synthetic GeoTIFF
// layer (geographic and Web Mercator) appears where it belongs and nowhere else; city lights
// show on the night side only (the day side is unchanged by them). Images are written to
// OG_TEST_OUT_DIR/land_imagery for looking at.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "data/Elevation.hpp"
#include "data/Imagery.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GeoTiffWriter.hpp"

using namespace og;
namespace fs = std::filesystem;

namespace {

constexpr int kSize = 128;

fs::path outDir() {
  const fs::path d = fs::path(OG_TEST_OUT_DIR) / "land_imagery";
  fs::create_directories(d);
  return d;
}

render::FrameInput downFrom(double lat, double lon, double heightM, double sunElevationDeg) {
  render::FrameInput f;
  f.camera.position = {lat, lon, heightM};
  f.camera.pitchDeg = -90.0;
  f.camera.verticalFovDeg = 20.0;
  f.width = f.height = kSize;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, sunElevationDeg, 150.0);
  return f;
}

/// Mean sRGB colour of the display image in a (2r+1)² window around (x, y).
std::array<double, 3> meanSrgb(const io::ImageRgba8& img, int x, int y, int r = 4) {
  std::array<double, 3> sum{};
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      for (int c = 0; c < 3; ++c)
        sum[static_cast<std::size_t>(c)] +=
            img.pixels[(static_cast<std::size_t>(y + dy) * static_cast<std::size_t>(img.width) +
                        static_cast<std::size_t>(x + dx)) * 4 + static_cast<std::size_t>(c)];
  for (double& s : sum) s /= (2 * r + 1) * (2 * r + 1);
  return sum;
}

double meanLuminance(const io::ImageRgbaF& img) {
  double s = 0.0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 4)
    s += 0.2126 * double{img.pixels[i]} + 0.7152 * double{img.pixels[i + 1]} + 0.0722 * double{img.pixels[i + 2]};
  return s / static_cast<double>(img.pixels.size() / 4);
}

/// A solid-colour GeoTIFF over lon0..lon1, lat0..lat1, in EPSG:4326 or 3857.
fs::path writeSolidGeoTiff(const std::string& name, int epsg, std::array<std::uint8_t, 3> rgb,
                           double lon0, double lon1, double lat0, double lat1) {
  return test::writeGeoRaster(outDir() / name, epsg, 64, 64, {lon0, lon1, lat0, lat1},
                              [rgb](double, double) { return rgb; });
}

}  // namespace

TEST(LandImagery, SaharaIsTanAndCongoGreenFromOrbit) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.render(downFrom(23.0, 12.0, 2.0e6, 60.0));
  const io::ImageRgba8 sahara = r.display();
  io::writePng(outDir() / "sahara_2000km.png", sahara);
  r.render(downFrom(-1.0, 22.0, 2.0e6, 60.0));
  const io::ImageRgba8 congo = r.display();
  io::writePng(outDir() / "congo_2000km.png", congo);
  const auto s = meanSrgb(sahara, kSize / 2, kSize / 2);
  const auto c = meanSrgb(congo, kSize / 2, kSize / 2);
  // Tan: red over green over blue, clearly warm (measured without imagery: 137, 134, 132).
  EXPECT_GT(s[0], s[1] + 8) << s[0] << "," << s[1] << "," << s[2];
  EXPECT_GT(s[1], s[2] + 15) << s[0] << "," << s[1] << "," << s[2];
  EXPECT_GT(s[0], 140.0);
  // Green: green well over red and at least level with blue, where the stand-in's was 5 under
  // it (measured without imagery: 90, 115, 120; with it 89, 111, 111). From 2000 km the
  // atmosphere's blue path radiance is as bright as the forest's green reflectance (~0.08):
  // the top-of-atmosphere colour of a rain forest is green-cyan, not the green of
  // atmospherically corrected satellite pictures.
  EXPECT_GT(c[1], c[0] + 15) << c[0] << "," << c[1] << "," << c[2];
  EXPECT_GE(c[1], c[2] - 2.0) << c[0] << "," << c[1] << "," << c[2];
}

TEST(LandImagery, GeoTiffLayerAppearsWhereItBelongs) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  // Magenta over 20..24°E, 10..14°N (Chad: land, no sea to confuse), geographic; cyan-ish
  // over 26..30°E in Web Mercator.
  std::vector<data::GeoImage> layers;
  layers.push_back(data::loadImageryLayer(writeSolidGeoTiff("magenta4326.tif", 4326, {230, 20, 230}, 20, 24, 10, 14), 256));
  layers.push_back(data::loadImageryLayer(writeSolidGeoTiff("green3857.tif", 3857, {20, 230, 20}, 26, 30, 10, 14), 256));
  r.imagery().setLayers(layers);
  render::FrameInput f = downFrom(12.0, 25.0, 1.5e6, 60.0);
  f.camera.verticalFovDeg = 40.0;
  r.render(f);
  const io::ImageRgba8 img = r.display();
  io::writePng(outDir() / "layers_1500km.png", img);
  // The camera looks down at 25°E: 1° of longitude is ~8.5 pixels (1500 km, 40° fov, 128 px).
  const double pxPerDeg = kSize / (2.0 * 1.5e6 * std::tan(20.0 * 3.14159265358979323846 / 180.0) / 111.0e3);
  const auto at = [&](double lon, double lat) {
    return meanSrgb(img, static_cast<int>(kSize / 2 + (lon - 25.0) * pxPerDeg * std::cos(12.0 * 3.14159265358979323846 / 180.0)),
                    static_cast<int>(kSize / 2 - (lat - 12.0) * pxPerDeg), 2);
  };
  const auto magenta = at(22.0, 12.0), green = at(28.0, 12.0), between = at(25.0, 12.0);
  EXPECT_GT(magenta[0], magenta[1] + 40) << magenta[0] << "," << magenta[1] << "," << magenta[2];
  EXPECT_GT(magenta[2], magenta[1] + 40);
  EXPECT_GT(green[1], green[0] + 40) << green[0] << "," << green[1] << "," << green[2];
  EXPECT_GT(green[1], green[2] + 40);
  // Between the layers: the Blue Marble's Sahel (warm, neither magenta nor green).
  EXPECT_LT(std::abs(between[1] - between[0]), 40.0) << between[0] << "," << between[1] << "," << between[2];
}

// The terrain draws the land below the globe's switch with a program variant chosen per frame
// (TerrainRenderer: city lights compiled out where the Sun is up everywhere in view): the Ruhr
// from 60 km, at night and with the Sun just set (lights, twilight), and by day (none).
TEST(LandImagery, TerrainCityLightsFollowTheSunInEveryVariant) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  for (double sunDeg : {-20.0, -2.0}) {
    r.imagery().setNightLights(1.0f);
    r.render(downFrom(51.45, 7.0, 6.0e4, sunDeg));
    const double on = meanLuminance(r.radiance());
    r.imagery().setNightLights(0.0f);
    r.render(downFrom(51.45, 7.0, 6.0e4, sunDeg));
    const double off = meanLuminance(r.radiance());
    EXPECT_GT(on, off * 1.2 + 1e-6) << "Sun " << sunDeg << " deg: " << on << " vs " << off;
  }
  r.imagery().setNightLights(1.0f);
  r.render(downFrom(51.45, 7.0, 6.0e4, 30.0));
  const io::ImageRgbaF dayOn = r.radiance();
  r.imagery().setNightLights(0.0f);
  r.render(downFrom(51.45, 7.0, 6.0e4, 30.0));
  const io::ImageRgbaF dayOff = r.radiance();
  double maxDiff = 0.0;
  for (std::size_t i = 0; i < dayOn.pixels.size(); ++i)
    maxDiff = std::max(maxDiff, static_cast<double>(std::abs(dayOn.pixels[i] - dayOff.pixels[i])));
  EXPECT_LT(maxDiff, 1e-6) << "no lights by day";
}

// From orbit with the terminator across the view the tiles with the Sun up on all of them are
// shaded without the city lights' lookup (TerrainRenderer::tileBits: a tenth of orbit's terrain
// pass on llvmpipe), the others with it: the same picture as all with it, lights and all.
TEST(LandImagery, DayTilesLeaveOutTheLightsAndKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  render::FrameInput f = downFrom(20.0, 10.0, 2.0e7, 0.0);
  f.camera.verticalFovDeg = 40.0;
  r.render(f);  // (the tiles' first frame)
  r.imagery().setNightLights(0.0f);
  r.render(f);
  const io::ImageRgbaF unlit = r.radiance();
  r.imagery().setNightLights(1.0f);
  r.terrain().setDayTiles(false);
  r.render(f);
  const io::ImageRgbaF reference = r.radiance();
  EXPECT_EQ(r.terrain().stats().dayTiles, 0);
  r.terrain().setDayTiles(true);
  r.render(f);
  const int dayTiles = r.terrain().stats().dayTiles;
  std::printf("day tiles %d of %d\n", dayTiles, r.terrain().stats().drawnTiles);
  EXPECT_GT(dayTiles, 0);
  EXPECT_LT(dayTiles, r.terrain().stats().drawnTiles) << "the night's tiles too";
  double maxDiff = 0.0, maxValue = 0.0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    maxDiff = std::max(maxDiff, static_cast<double>(std::abs(reference.pixels[i] - r.radiance().pixels[i])));
    maxValue = std::max(maxValue, static_cast<double>(reference.pixels[i]));
  }
  EXPECT_LE(maxDiff, 1e-6 * maxValue);
  int lights = 0;  // pixels the city lights brighten: the night's tiles kept them
  for (std::size_t i = 0; i < reference.pixels.size(); i += 4)
    lights += reference.pixels[i] > unlit.pixels[i] + 1e-4f ? 1 : 0;
  EXPECT_GT(lights, 100) << "city lights in view";
}

TEST(LandImagery, CityLightsOnlyOnTheNightSide) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  // The Low Countries and the Ruhr from 2000 km.
  const render::FrameInput night = downFrom(51.0, 6.0, 2.0e6, -25.0);
  const render::FrameInput day = downFrom(51.0, 6.0, 2.0e6, 60.0);
  r.render(night);
  const io::ImageRgbaF nightOn = r.radiance();
  io::writePng(outDir() / "europe_night.png", r.display());
  r.render(day);
  const io::ImageRgbaF dayOn = r.radiance();
  r.imagery().setNightLights(0.0f);
  r.render(night);
  const io::ImageRgbaF nightOff = r.radiance();
  r.render(day);
  const io::ImageRgbaF dayOff = r.radiance();
  EXPECT_GT(meanLuminance(nightOn), 3.0 * meanLuminance(nightOff) + 1e-5)
      << meanLuminance(nightOn) << " vs " << meanLuminance(nightOff);
  double maxDiff = 0.0;
  for (std::size_t i = 0; i < dayOn.pixels.size(); ++i)
    maxDiff = std::max(maxDiff, static_cast<double>(std::abs(dayOn.pixels[i] - dayOff.pixels[i])));
  EXPECT_LT(maxDiff, 1e-6) << "the lights must not change the day side";
}
