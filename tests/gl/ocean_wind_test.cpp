// GL tier (issue 5): the sea follows the local wind. A render from orbit over a wind front
// must show the glint change across it: on the calm side a higher, narrower peak.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "data/Elevation.hpp"
#include "data/WindLayers.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GlFixtures.hpp"

using namespace og;

namespace {
// A global 1° wind field blowing east: 3 m/s west of 30°W, 14 m/s east of it.
std::shared_ptr<const data::WindLayers> windFront() {
  data::WindGrid g;
  g.label = "front";
  for (data::LatLonGrid* c : {&g.u, &g.v}) {
    c->width = 360;
    c->height = 181;
    c->lon0Deg = -180.0;
    c->lat0Deg = -90.0;
    c->dLonDeg = c->dLatDeg = 1.0;
    c->wrapsLongitude = true;
    c->values.assign(360 * 181, 0.0f);
  }
  for (int r = 0; r < 181; ++r)
    for (int c = 0; c < 360; ++c)
      g.u.values[static_cast<std::size_t>(r * 360 + c)] = (-180.0 + c) < -30.0 ? 3.0f : 14.0f;
  auto layers = std::make_shared<data::WindLayers>();
  layers->push(std::move(g));
  return layers;
}
}  // namespace

TEST(OceanWind, GlintIsHigherAndNarrowerOnTheCalmSideOfAFront) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.setWindLayers(windFront());
  render::FrameInput f;
  f.camera.position = {0.0, -30.0, 2.0e6};  // over the open Atlantic, the front below us
  f.camera.pitchDeg = -90;
  f.camera.verticalFovDeg = 40;
  f.width = 161;
  f.height = 81;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal({0.0, -30.0, 0.0}, 90.0, 0.0);  // glint at nadir
  r.render(f);
  EXPECT_FALSE(r.lastFrameConstantWind()) << "a wind layer's sea reads the wind per pixel";
  const io::ImageRgbaF img = r.radiance();
  // Luminance along the middle row, west (calm) half and east (windy) half from the centre.
  auto lum = [&](int x) {
    const float* p = &img.pixels[static_cast<std::size_t>(4 * (40 * img.width + x))];
    return 0.2126 * double(p[0]) + 0.7152 * double(p[1]) + 0.0722 * double(p[2]);
  };
  const int centre = 80;
  double peakCalm = 0, peakWindy = 0;
  for (int d = 2; d < 20; ++d) {
    peakCalm = std::max(peakCalm, lum(centre - d));
    peakWindy = std::max(peakWindy, lum(centre + d));
  }
  // Half width: first distance where the side falls below half its peak.
  auto halfWidth = [&](int sign, double peak) {
    for (int d = 2; d < 80; ++d)
      if (lum(centre + sign * d) < 0.5 * peak) return d;
    return 80;
  };
  const int widthCalm = halfWidth(-1, peakCalm), widthWindy = halfWidth(+1, peakWindy);
  std::printf("glint peak calm %.4f windy %.4f; half width calm %d px windy %d px\n", peakCalm,
              peakWindy, widthCalm, widthWindy);
  EXPECT_GT(peakCalm, 1.5 * peakWindy);
  EXPECT_LT(widthCalm, widthWindy);
}

// A constant wind along one of the patterns' direction bins reads that bin's patterns alone
// (OceanRenderer::windAlongOneBin, PATTERN_ONE_BIN) and the per-wind tables' values the CPU
// computed once (PATTERN_CONSTANT_WIND, OceanPatterns::setConstantWind): the other bin's
// weight is under 1e-3, so the sea is the two bins' sea. Along bin 0 (the default westerly, towards 90°), just past it
// (float rounding can put it just below bin 0: the shader takes the nearest bin), along bin 5
// (towards 225°, a diagonal) and bin 2 (towards 0°); and the decision itself.
TEST(OceanWind, AWindAlongOneBinReadsOneBinsPatterns) {
  using render::OceanRenderer;
  constexpr double kDeg = 0.017453292519943295;
  EXPECT_TRUE(OceanRenderer::windAlongOneBin(90.0 * kDeg, 0.0));
  EXPECT_TRUE(OceanRenderer::windAlongOneBin(90.00001 * kDeg, 0.0));
  EXPECT_TRUE(OceanRenderer::windAlongOneBin(225.0 * kDeg, 0.0));
  EXPECT_TRUE(OceanRenderer::windAlongOneBin(100.0 * kDeg, -10.0 * kDeg));  // a field turned with it
  EXPECT_FALSE(OceanRenderer::windAlongOneBin(100.0 * kDeg, 0.0));
  EXPECT_FALSE(OceanRenderer::windAlongOneBin(90.1 * kDeg, 0.0));  // the other bin at 2.7e-3

  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  for (const double towardsDeg : {90.0, 90.00001, 225.0, 0.0}) {
    render::FrameInput f;
    f.camera.position = {20.0, -40.0, 4.0};
    f.camera.headingDeg = 250.0;
    f.camera.pitchDeg = -20.0;
    f.width = 320;
    f.height = 180;
    f.samples = 1;
    f.wind = geo::Wind::blowingTowards(12.0, towardsDeg);
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 20.0, 250.0);
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.ocean().setOneBinAllowed(on); });
    EXPECT_TRUE(r.ocean().lastDrawOneBin()) << "towards " << towardsDeg << " deg";
    // Along an even bin the other's weight is exactly 0: the same picture. Along an odd one
    // (45° in float) it is ~1e-7, whose rounding can tip a pixel at a threshold (the
    // back-facing fix): a handful of pixels.
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.01);
    std::printf("towards %g deg: one bin against two, mean change %.3g, worst %.3g, %d pixels over 1 %%\n", towardsDeg,
                change.mean, change.worst, change.over);
    // (Within 1e-5 on llvmpipe; a GPU's compiler contracts each program's arithmetic its own way.)
    EXPECT_LT(change.mean, gl::driverProfile().software ? 1e-5 : 1e-4) << "towards " << towardsDeg << " deg";
    EXPECT_LE(change.over, 20) << "towards " << towardsDeg << " deg";
  }
}
