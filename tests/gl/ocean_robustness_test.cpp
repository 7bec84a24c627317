// GL tier (issue 4, "Done when"): no NaN or Inf anywhere in the radiance for any Sun elevation,
// wind, pitch, at the poles and 0.5 m above the sea; and the orbit glint's response to wind.
#include <gtest/gtest.h>

#include <cmath>

#include "data/Elevation.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "render/GlobeRenderer.hpp"

using namespace og;

TEST(OceanRobustness, RadianceIsFiniteEverywhere) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const geo::Geodetic places[] = {{90.0, 0.0, 0.5}, {-90.0, 45.0, 0.5}, {0.0, -140.0, 0.5},
                                  {45.0, -30.0, 19999.0}, {10.0, -30.0, 2.0e6}};
  // The extremes of each range (Sun -10° and 90°, wind 0 and 40 m/s, pitch -90° to +10°):
  // the places outermost so the terrain tiles are built once per place.
  int renders = 0;
  for (const geo::Geodetic& where : places)
    for (double wind : {0.0, 40.0})
      for (double pitch : {-90.0, 0.0, 10.0})
        for (double sunElevation : {-10.0, 90.0}) {
          render::FrameInput f;
          f.camera.position = where;
          f.camera.pitchDeg = pitch;
          f.camera.headingDeg = 30.0;
          f.width = 32;
          f.height = 18;
          f.wind.speedMs = wind;
          f.simulationTimeS = 3.7;
          f.sunDirectionEcef = geo::sunDirectionFromHorizontal(where, sunElevation, 40.0);
          r.render(f);
          const io::ImageRgbaF img = r.radiance();
          std::size_t bad = 0;
          for (float v : img.pixels) bad += std::isfinite(v) ? 0 : 1;
          ASSERT_EQ(bad, 0u) << "wind " << wind << " at " << where.latitudeDeg << "," << where.longitudeDeg
                             << " h " << where.heightM << " pitch " << pitch << " sun " << sunElevation;
          ++renders;
        }
  EXPECT_EQ(renders, 5 * 2 * 3 * 2);
}

// From orbit the glint of a calm sea (2 m/s) is brighter and tighter than at 12 m/s.
TEST(OceanRobustness, OrbitGlintIsBrighterAndTighterInLightWind) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  double peak[2], width[2];
  const double winds[2] = {2.0, 12.0};
  for (int k = 0; k < 2; ++k) {
    render::FrameInput f;
    f.camera.position = {0.0, -30.0, 2.0e6};
    f.camera.pitchDeg = -90;
    f.camera.verticalFovDeg = 40;
    f.width = 121;
    f.height = 61;
    f.wind.speedMs = winds[k];
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal({0.0, -30.0, 0.0}, 90.0, 0.0);
    r.render(f);
    const io::ImageRgbaF img = r.radiance();
    auto lum = [&](int x) {
      const float* p = &img.pixels[static_cast<std::size_t>(4 * (30 * img.width + x))];
      return 0.2126 * double(p[0]) + 0.7152 * double(p[1]) + 0.0722 * double(p[2]);
    };
    peak[k] = lum(60);
    int d = 1;
    while (d < 60 && lum(60 + d) > 0.5 * peak[k]) ++d;
    width[k] = d;
  }
  std::printf("orbit glint peak 2 m/s %.4f, 12 m/s %.4f; half width %g px, %g px\n", peak[0],
              peak[1], width[0], width[1]);
  EXPECT_GT(peak[0], 2.0 * peak[1]);
  EXPECT_LT(width[0], width[1]);
}
