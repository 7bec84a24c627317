// GL tier (issue 5): the sea follows the local wind. A render from orbit over a wind front
// must show the glint change across it: on the calm side a higher, narrower peak.
#include <gtest/gtest.h>

#include <cmath>

#include "data/Elevation.hpp"
#include "data/WindLayers.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "render/GlobeRenderer.hpp"

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
