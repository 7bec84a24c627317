// GL tier (issue 6, "Done when"): mountains read as relief. A Lambertian relief lit from the
// east and then from the west swaps its bright and dark slopes; a terrain without relief in
// its shading (flat normals, or normals too smooth to see) changes only as a whole. And a ridge
// casts its shadow on the plain on the side away from the Sun.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "data/Elevation.hpp"
#include "geo/Camera.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "gl/DriverProfile.hpp"
#include "render/GlobeRenderer.hpp"
#include "render/ShadowReceivers.hpp"
#include "support/GlFixtures.hpp"
#include "support/GridFixtures.hpp"

using namespace og;

namespace {

constexpr int kW = 192, kH = 108;

// The image minus its 5x5 box mean: the pixel-scale shading, not the haze or the materials'
// broad gradients.
double highPass(const std::vector<double>& y, int x, int row) {
  double sum = 0.0;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) sum += y[static_cast<std::size_t>((row + dy) * kW + x + dx)];
  return y[static_cast<std::size_t>(row * kW + x)] - sum / 25.0;
}

}  // namespace

TEST(TerrainRender, MountainShadingSwapsWhenTheSunCrossesTheSky) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  render::FrameInput f;
  f.camera.position = {27.3, 86.9, 15000.0};  // Nepal, looking north at the Himalaya
  f.camera.headingDeg = 10.0;
  f.camera.pitchDeg = -20.0;
  f.width = kW;
  f.height = kH;
  std::vector<double> y[2];
  const double azimuths[2] = {90.0, 270.0};
  for (int k = 0; k < 2; ++k) {
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 35.0, azimuths[k]);
    r.render(f);
    y[k] = test::luminance(r.radiance());
  }
  // Correlation of the two high-passed images over the ground (the lower half of the frame).
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (int row = kH / 2; row < kH - 2; ++row)
    for (int x = 2; x < kW - 2; ++x) {
      const double a = highPass(y[0], x, row), b = highPass(y[1], x, row);
      sxy += a * b;
      sxx += a * a;
      syy += b * b;
    }
  ASSERT_GT(sxx, 0.0);
  ASSERT_GT(syy, 0.0);
  const double correlation = sxy / std::sqrt(sxx * syy);
  // Measured -0.98 with the relief normals; +0.94 with flat ones.
  EXPECT_LT(correlation, -0.4) << "slopes lit from the east should be dark when lit from the west";
}

namespace {

// A dry plain at 100 m with a 5 km high north-south ridge along 5°E (0.05° cells, 0..10°E,
// 20..30°N).
data::LatLonGrid ridgeLayer() {
  return test::grid("ridge", 20.0, 0.0, 0.05, 201, 201, false, [](double, double lon) {
    return std::abs(lon - 5.0) < 0.01 ? 5000.0 : 100.0;
  });
}

}  // namespace

TEST(TerrainRender, RidgeCastsItsShadowAwayFromTheSun) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(ridgeLayer());
  render::FrameInput f;
  f.camera.position = {25.0, 5.0, 12000.0};  // straight down on the ridge, north up
  f.camera.pitchDeg = -90.0;
  f.camera.verticalFovDeg = 60.0;
  f.width = kW;
  f.height = kH;
  // Mean luminance of the plain near the frame's west and east edges (about 10 km from the
  // ridge, past its 5.5 km wide foot: inside its shadow for a Sun 15° up, which reaches 18 km).
  auto sides = [&](double sunAzimuthDeg) {
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 15.0, sunAzimuthDeg);
    r.render(f);
    const std::vector<double> y = test::luminance(r.radiance());
    double west = 0.0, east = 0.0;
    for (int row = kH / 4; row < 3 * kH / 4; ++row)
      for (int dx = -3; dx <= 3; ++dx) {
        west += y[static_cast<std::size_t>(row * kW + kW / 10 + dx)];
        east += y[static_cast<std::size_t>(row * kW + 9 * kW / 10 + dx)];
      }
    return std::pair{west, east};
  };
  const auto [westMorning, eastMorning] = sides(90.0);  // Sun in the east: the west is shaded
  const auto [westEvening, eastEvening] = sides(270.0);
  // Each side of the plain is darker when the ridge stands between it and the Sun: only the
  // sky lights it then (the haze in front of it stays). Measured 0.67 of the sunlit value with
  // shadows; without them the shaded side came out brighter (1.16).
  EXPECT_LT(westMorning, 0.8 * westEvening);
  EXPECT_LT(eastEvening, 0.8 * eastMorning);
}

// The sea at a mountain's foot lies in its shadow too: seen from straight above (no glint),
// the sea south of a ridge's end, in its shadow, is darker than the sea north of it, in the Sun.
TEST(TerrainRender, RidgeShadesTheSeaAtItsFoot) {
  // Sea west of 5°E; a 3 km ridge along the coast from 23°N to 25°N only.
  const data::LatLonGrid g = test::grid("coast", 20.0, 0.0, 0.05, 201, 201, false, [](double lat, double lon) {
    if (std::abs(lon - 5.05) < 0.01 && lat >= 23.0 - 1e-9 && lat <= 25.0 + 1e-9) return 3000.0;
    return lon < 5.0 - 1e-9 ? -200.0 : 100.0;
  });
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(g);
  render::FrameInput f;
  f.camera.position = {25.0, 4.95, 8000.0};  // over the coast at the ridge's end
  f.camera.pitchDeg = -90.0;
  f.camera.verticalFovDeg = 90.0;  // 4.81..5.09°E: the ridge (a caster only if in view) and sea
  f.width = kW;
  f.height = kH;
  // Sun 10° up in the east: the ridge's shadow reaches ~17 km west over the sea.
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 10.0, 90.0);
  r.render(f);
  const std::vector<double> y = test::luminance(r.radiance());
  double north = 0.0, south = 0.0;
  for (int row = 4; row < kH / 4; ++row)
    for (int x = kW / 4; x < 2 * kW / 5; ++x) {  // the sea, 8 to 13 km west of the ridge
      north += y[static_cast<std::size_t>(row * kW + x)];  // image rows from the top
      south += y[static_cast<std::size_t>((kH - 1 - row) * kW + x)];
    }
  // A low Sun's share of the sea's radiance seen from above is small (the sky's reflection,
  // the water's sky-lit glow and the haze make the rest): measured 0.962 with the shadow,
  // 1.000 without it.
  EXPECT_LT(south, 0.98 * north);
}

// The open sea between the eye and a far coast towards a low Sun lies farther from the Sun than
// every caster in the shadow maps (their depth range is the casters'): it must stay lit. The
// default flythrough's frame 330 (6.5 km over the Atlantic west of Portugal, looking at the
// glitter of a Sun 7° up behind the coast, 640x360: the terrain's coarse Iberian tiles are the
// casters) lost the upper half of its glitter: the float shadow map does not clamp the
// comparison's reference, so depths beyond 1 read as shadowed where no caster was drawn.
// Measured: the glitter below the horizon 44x the sea beside it; 1.5x with the bug.
TEST(TerrainRender, SeaBeyondTheCastersDepthRangeStaysLit) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  render::FrameInput f;
  f.camera.position = {38.04937, -11.74772, 6474.2};
  f.camera.headingDeg = 78.08;
  f.camera.pitchDeg = -20.44;
  f.camera.verticalFovDeg = 52.8;
  f.width = 640;
  f.height = 360;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 7.0, 80.0);
  r.render(f);
  test::savePng(r, "sea_beyond_casters");
  EXPECT_TRUE(r.terrain().shadows().on) << "the coast's tiles must be casters for this to test anything";
  const std::vector<double> y = test::luminance(r.radiance());
  // Rows 70-150 from the top (the horizon at ~60): the glitter's column against the sea 250 px
  // to its left.
  const auto box = [&](int x0) {
    double sum = 0.0;
    for (int row = 70; row < 150; ++row)
      for (int x = x0; x < x0 + 30; ++x) sum += y[static_cast<std::size_t>(row * f.width + x)];
    return sum;
  };
  EXPECT_GT(box(312) / box(62), 3.0) << box(312) / box(62);
}

// Tiles wholly beyond the sea's horizon are not drawn (terrain::aboveSeaHorizon): from 2 m over
// the Strait of Gibraltar looking west out of it the coarse tiles of far coasts lie beyond it
// (the selection's occluder, 11.5 km down, keeps them), and over the Great Bahama Bank nearly
// every tile the view selects does. The pictures must not change: what the sea's horizon hides was
// behind the sea's surface. Measured (256x144): the strait 15 tiles drawn of 21 without; the
// bank 1 of 14.
TEST(TerrainRender, TilesBeyondTheSeaHorizonAreLeftOutUnseen) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  struct Case {
    const char* name;
    double lat, lon, heading, pitch;
  };
  for (const Case& c : {Case{"strait", 36.0, -5.5, 270.0, 2.0}, Case{"bank", 24.2, -78.2, 270.0, -10.0}}) {
    SCOPED_TRACE(c.name);
    render::FrameInput f;
    f.camera.position = {c.lat, c.lon, 2.0};
    f.camera.headingDeg = c.heading;
    f.camera.pitchDeg = c.pitch;
    f.width = 256;
    f.height = 144;
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 30.0, 200.0);
    r.terrain().setSeaHorizonCulling(false);
    r.render(f);
    const int allDrawn = r.terrain().stats().drawnTiles;
    const io::ImageRgbaF all = r.radiance();
    r.terrain().setSeaHorizonCulling(true);
    r.render(f);
    const int drawn = r.terrain().stats().drawnTiles;
    const io::ImageRgbaF culled = r.radiance();
    test::savePng(r, std::string("sea_horizon_culled_") + c.name);
    EXPECT_LT(drawn, allDrawn);
    if (std::string(c.name) == "strait") {
      EXPECT_GT(drawn, 0) << "the strait's own coasts are in view";
    }
    ASSERT_EQ(all.pixels.size(), culled.pixels.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < all.pixels.size(); ++i)
      worst = std::max(worst, static_cast<double>(std::abs(all.pixels[i] - culled.pixels[i])));
    EXPECT_EQ(worst, 0.0) << "drawn " << drawn << " of " << allDrawn;
  }
}

// A shadow cascade draws only as many texels as the screen resolves at the nearest point it can
// shadow (TerrainRenderer::shadowCascadeTexels): from 2 m over the Great Bahama Bank, 640 x 360,
// the islands' casters lie kilometres off. The picture must be the full maps', and the lookups
// must stay inside the part drawn: the renderer drew the full maps first, so a lookup past the
// part would read that frame's depths at the wrong place. Measured: both cascades at 256 texels,
// no pixel changed by over 1 %.
TEST(TerrainRender, ShadowMapsFittedToTheScreenKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const render::FrameInput f = test::frameOf({.latDeg = 24.2, .lonDeg = -78.2, .heightM = 2.0, .headingDeg = 270.0,
                                              .pitchDeg = -10.0, .fovDeg = 45.0, .width = 640, .height = 360},
                                             20.0, 250.0);
  r.terrain().setShadowCropped(false);  // the cascades' extents, uncropped: their fitted texels
  const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.terrain().setShadowTexelsFitted(on); });
  test::savePng(r, "shadows_fitted_bahama_bank_2m");
  const render::SunShadows& s = r.terrain().shadows();
  ASSERT_TRUE(s.on);
  const float least = std::min(s.cropUv[0].z, s.cropUv[1].z);  // (texels - 1) / 2048
  EXPECT_LT(least, 0.5f) << "a cascade should draw at most half the texels the map holds";
  ASSERT_EQ(images.off.pixels.size(), images.on.pixels.size());
  const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.01);
  std::printf("shadow extents %.3f %.3f, largest change %.4f, %d pixels over 1 %%\n",
              static_cast<double>(s.cropUv[0].z), static_cast<double>(s.cropUv[1].z), change.worst, change.over);
  EXPECT_LT(change.over, static_cast<int>(images.on.pixels.size() / 4 / 100)) << "more than 1 % of the pixels changed by over 1 %";
  EXPECT_LT(change.worst, 0.05);
}

// A cascade draws only the part of its map over the receivers the screen shows in its range of
// distances (render/ShadowReceivers), on the same texels as the whole map: a caster shades
// only points across the Sun's rays from it, so the picture must not change. Views with the
// Sun ahead, behind and low, from 2 m to 30 km; the near cascade of the Himalaya from 15 km
// must come out cropped (else the test would compare a picture with itself). (The floor's
// shadows, looked up off the view rays, have a margin of their own, which no view here needs.)
namespace {

// A named 320 x 180 view with its Sun (elevation, azimuth, degrees).
struct ViewCase {
  const char* name;
  test::View view;
  double sunElevationDeg, sunAzimuthDeg;
};
const ViewCase kHimalaya15kmHorizon{"himalaya_15km_horizon", {.latDeg = 27.3, .lonDeg = 86.9, .heightM = 15000.0, .headingDeg = 10.0, .pitchDeg = -2.0, .fovDeg = 45.0, .width = 320, .height = 180}, 20.0, 250.0};
const ViewCase kGibraltar2m{"gibraltar_2m", {.latDeg = 36.0, .lonDeg = -5.5, .heightM = 2.0, .headingDeg = 270.0, .pitchDeg = 2.0, .fovDeg = 45.0, .width = 320, .height = 180}, 20.0, 250.0};
const ViewCase kTarifa2mBeach{"tarifa_2m_beach", {.latDeg = 35.995, .lonDeg = -5.595, .heightM = 2.0, .headingDeg = 300.0, .pitchDeg = -3.0, .fovDeg = 45.0, .width = 320, .height = 180}, 20.0, 250.0};
const ViewCase kBahamas2m{"bahamas_2m", {.latDeg = 24.2, .lonDeg = -78.2, .heightM = 2.0, .headingDeg = 270.0, .pitchDeg = -10.0, .fovDeg = 45.0, .width = 320, .height = 180}, 30.0, 120.0};
const ViewCase kGibraltar30km{"gibraltar_30km", {.latDeg = 35.6, .lonDeg = -5.6, .heightM = 30000.0, .headingDeg = 0.0, .pitchDeg = -30.0, .fovDeg = 45.0, .width = 320, .height = 180}, 20.0, 250.0};

}  // namespace

TEST(ShadowReceivers, RaysStopAtTheGroundUnderTheSlab) {
  // From 2 m over Gibraltar's strait towards a Sun 20° up, the slab of the tiles' heights
  // (-1100 m to 1600 m): a ray below the horizon meets the slab's floor, under which all is
  // ground. Its stretch past the floor's far crossing lies behind the planet, 12 700 km on:
  // projected across the Sun's rays it stretched the rectangle to 3700 km, and the padding
  // between rays (the farthest end's angle) with it. Every point the view can show within
  // the slab lies within ~300 km of the eye (the far end of a ray grazing the floor).
  const render::FrameInput f = test::frameOf(kGibraltar2m.view, kGibraltar2m.sunElevationDeg, kGibraltar2m.sunAzimuthDeg);
  const geo::CameraView view = geo::makeCameraView(f.camera, f.width, f.height);
  const glm::dvec3 s = glm::normalize(f.sunDirectionEcef);
  const glm::dvec3 lx = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), s)), ly = glm::cross(s, lx);
  const render::LightRect rect = render::shadowReceiverRect(view, lx, ly, 0.0, 1e9, -1100.0, 1600.0);
  ASSERT_FALSE(rect.empty());
  for (const double v : {rect.lo.x, rect.lo.y, rect.hi.x, rect.hi.y}) EXPECT_LT(std::abs(v), 4.0e5);
  // The far cascade's reach (render::TerrainRenderer, 20 km at 2 m) and the view's half
  // across it: the rectangle holds the near receivers.
  EXPECT_LT(rect.lo.x, -1.0e4);
  EXPECT_GT(rect.hi.x - rect.lo.x, 2.0e4);
}

namespace {
// shadowReceiverRect's stretches by brute force, on n + 1 rays a side and without padding.
render::LightRect denseReceivers(const geo::CameraView& view, const glm::dvec3& lx, const glm::dvec3& ly,
                                 double lowM, double highM, int n) {
  render::LightRect rect;
  const auto add = [&](const glm::dvec3& dir, double t) { rect.add({glm::dot(t * dir, lx), glm::dot(t * dir, ly)}); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const glm::dvec3 dir = view.rayDirection(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n);
      const auto below = geo::ellipsoidCrossings(view.positionEcef, dir, highM);
      if (!below || below->second < 0.0) continue;
      const double enter = std::max(below->first, 0.0);
      const auto under = geo::ellipsoidCrossings(view.positionEcef, dir, lowM);
      const double leave = under && under->first > enter && under->first < below->second ? under->first : below->second;
      add(dir, enter);
      add(dir, leave);
    }
  return rect;
}
}  // namespace

TEST(ShadowReceivers, HoldTheRaysBetweenTheirRaysThatPassOverTheFloor) {
  // Near the horizon a ray between one that meets the slab's floor and one that misses it may
  // pass just over the floor and see the slab's far side, beyond the floor's horizon: the
  // rectangle must hold it (against 201² rays). Views from 2 m to 30 km, the Sun ahead,
  // beside and behind.
  struct Case { test::View view; double sunElevationDeg, sunAzimuthDeg, lowM, highM; };
  const std::vector<Case> cases{
      {kGibraltar2m.view, 20.0, 250.0, -1100.0, 1600.0},
      {{.latDeg = 27.3, .lonDeg = 86.9, .heightM = 15000.0, .headingDeg = 10.0, .pitchDeg = -2.0, .fovDeg = 45.0, .width = 320, .height = 180}, 60.0, 250.0, 0.0, 8800.0},
      {{.latDeg = 27.3, .lonDeg = 86.9, .heightM = 15000.0, .headingDeg = 10.0, .pitchDeg = -5.0, .fovDeg = 45.0, .width = 320, .height = 180}, 45.0, 90.0, 0.0, 8800.0},
      {{.latDeg = 35.6, .lonDeg = -5.6, .heightM = 30000.0, .headingDeg = 0.0, .pitchDeg = -3.0, .fovDeg = 45.0, .width = 320, .height = 180}, 20.0, 250.0, -1100.0, 3400.0},
      {{.latDeg = 35.6, .lonDeg = -5.6, .heightM = 5000.0, .headingDeg = 180.0, .pitchDeg = -1.0, .fovDeg = 45.0, .width = 320, .height = 180}, 10.0, 0.0, -1100.0, 3400.0},
  };
  for (const Case& c : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    const geo::CameraView view = geo::makeCameraView(f.camera, f.width, f.height);
    const glm::dvec3 s = glm::normalize(f.sunDirectionEcef);
    const glm::dvec3 lx = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), s)), ly = glm::cross(s, lx);
    const render::LightRect rect = render::shadowReceiverRect(view, lx, ly, 0.0, 1e9, c.lowM, c.highM);
    const render::LightRect dense = denseReceivers(view, lx, ly, c.lowM, c.highM, 200);
    ASSERT_FALSE(dense.empty());
    std::printf("%.0f m: rect %.0f %.0f %.0f %.0f dense %.0f %.0f %.0f %.0f\n", c.view.heightM, rect.lo.x, rect.lo.y,
                rect.hi.x, rect.hi.y, dense.lo.x, dense.lo.y, dense.hi.x, dense.hi.y);
    EXPECT_LE(rect.lo.x, dense.lo.x) << c.view.heightM << " m";
    EXPECT_LE(rect.lo.y, dense.lo.y) << c.view.heightM << " m";
    EXPECT_GE(rect.hi.x, dense.hi.x) << c.view.heightM << " m";
    EXPECT_GE(rect.hi.y, dense.hi.y) << c.view.heightM << " m";
  }
}

TEST(TerrainRender, ShadowMapsCroppedToTheReceiversKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::vector<ViewCase> cases{
      kHimalaya15kmHorizon,
      {"himalaya_6km_sun_behind", {.latDeg = 28.0, .lonDeg = 86.5, .heightM = 6000.0, .headingDeg = 70.0, .pitchDeg = -40.0, .fovDeg = 45.0, .width = 320, .height = 180}, 10.0, 250.0},
      {"himalaya_9km_low_sun_ahead", {.latDeg = 27.8, .lonDeg = 87.2, .heightM = 9000.0, .headingDeg = 240.0, .pitchDeg = -10.0, .fovDeg = 45.0, .width = 320, .height = 180}, 5.0, 250.0},
      kGibraltar2m,
      kGibraltar30km,
      // A coast's sea from 300 m with the Sun low over the land beyond it (Gibraltar's bay).
      {"gibraltar_bay_300m_low_sun", {.latDeg = 36.14, .lonDeg = -5.40, .heightM = 300.0, .headingDeg = 90.0, .pitchDeg = -12.0, .fovDeg = 45.0, .width = 320, .height = 180}, 8.0, 100.0},
  };
  for (const ViewCase& c : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    // Cropped first: over the maps the last case left (another view's) or fresh ones, so a crop
    // that missed a receiver, or a lookup past the part drawn, reads wrong depths.
    r.terrain().setShadowCropped(true);
    r.render(f);
    const io::ImageRgbaF cropped = r.radiance();
    const std::array<glm::vec4, 2> crops = r.terrain().shadows().cropUv;
    r.terrain().setShadowCropped(false);
    r.render(f);
    const io::ImageRgbaF whole = r.radiance();
    const render::SunShadows& s = r.terrain().shadows();
    ASSERT_TRUE(s.on) << c.name;
    auto area = [](const glm::vec4& uv) { return std::max(uv.z - uv.x, 0.0f) * std::max(uv.w - uv.y, 0.0f); };
    if (std::string(c.name) == "himalaya_15km_horizon") {
      EXPECT_LT(area(crops[0]), 0.5f * area(s.cropUv[0])) << "the near cascade should draw under half its texels";
    }
    ASSERT_EQ(whole.pixels.size(), cropped.pixels.size());
    const double worst = test::radianceChange(whole, cropped, 1e-4).worst;
    std::printf("%s: the crops draw %.3f and %.3f of the cascades' texels; largest change %.2e\n", c.name,
                static_cast<double>(area(crops[0]) / std::max(area(s.cropUv[0]), 1e-9f)),
                static_cast<double>(area(crops[1]) / std::max(area(s.cropUv[1]), 1e-9f)), worst);
    if (worst > 1e-4) test::savePng(r, std::string("shadows_cropped_") + c.name);
    EXPECT_LT(worst, 1e-4) << c.name;
  }
}

// A tile is drawn into a shadow cascade from every 2nd vertex where that mesh's part above the
// sea lies within half a texel of the full grid's (less at a low Sun: TerrainRenderer::
// shadowStride): the casters' outlines move by under half a texel, within the lookups' own
// 2 x 2 filter. Views where the maps draw many tiles: the strait from 2 m (the bench's
// sea-2m-horizon, whose maps were a fifth of its frame), its beach with the hills behind, the
// bay from 300 m under a low Sun and the Himalaya from 6 km with the Sun behind. The maps
// themselves are compared texel by texel (what the casters cover, and their depth where both
// cover, in metres along the Sun's rays), so a coarser draw that left a caster out, or drew
// the wrong triangles, fails even where no pixel in view shows it (drawn from the index
// buffer's start: 62 000 texels fewer in the strait); and the pictures. Measured: the same
// texels covered, no depth moved by 0.1 texel, no pixel changed by over 1 %.
namespace {

// What a cascade's map holds within its crop (SunShadows::cropUv, uv of kShadowMapSize²).
struct CascadeMap {
  std::vector<float> depths;
  glm::ivec4 crop{0};  // texels x0, y0, x1, y1
};
CascadeMap cascadeMap(const render::TerrainRenderer& t, int c) {
  const glm::vec4 uv = t.shadows().cropUv[static_cast<std::size_t>(c)];
  const float n = static_cast<float>(render::TerrainRenderer::kShadowMapSize);
  return {t.shadowMapDepths(c), glm::ivec4(glm::round(glm::vec4(uv.x, uv.y, uv.z, uv.w) * n))};
}

}  // namespace

TEST(TerrainRender, ShadowMapsFromCoarserCastersKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::vector<ViewCase> cases{
      {"gibraltar_2m_640", {.latDeg = 36.0, .lonDeg = -5.5, .heightM = 2.0, .headingDeg = 270.0, .pitchDeg = 2.0, .fovDeg = 45.0, .width = 640, .height = 360}, 20.0, 250.0},
      kTarifa2mBeach,
      {"gibraltar_bay_300m_low_sun", {.latDeg = 36.14, .lonDeg = -5.40, .heightM = 300.0, .headingDeg = 90.0, .pitchDeg = -12.0, .fovDeg = 45.0, .width = 320, .height = 180}, 8.0, 100.0},
      {"himalaya_6km_sun_behind", {.latDeg = 28.0, .lonDeg = 86.5, .heightM = 6000.0, .headingDeg = 70.0, .pitchDeg = -40.0, .fovDeg = 45.0, .width = 320, .height = 180}, 10.0, 250.0},
  };
  int coarseDraws = 0;
  for (const ViewCase& c : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    std::array<std::array<CascadeMap, 2>, 2> maps;  // [strides on][cascade]
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&](bool on) {
      // (called before each render: the maps of the one before are read here)
      if (on)
        for (int k = 0; k < 2; ++k) maps[0][static_cast<std::size_t>(k)] = cascadeMap(r.terrain(), k);
      r.terrain().setShadowStrides(on);
    });
    for (int k = 0; k < 2; ++k) maps[1][static_cast<std::size_t>(k)] = cascadeMap(r.terrain(), k);
    const render::TerrainStats& ts = r.terrain().stats();
    const render::SunShadows& s = r.terrain().shadows();
    ASSERT_TRUE(s.on) << c.name;
    coarseDraws += ts.shadowCoarseTileDraws;
    for (std::size_t k = 0; k < 2; ++k) {
      const CascadeMap &full = maps[0][k], &coarse = maps[1][k];
      ASSERT_EQ(full.crop, coarse.crop) << c.name << " cascade " << k;
      // Metres along the Sun's rays per unit of depth: the matrix's depth row is -s / (zHi - zLo).
      const glm::mat4& m = s.matrices[k];
      const double depthM = 1.0 / glm::length(glm::dvec3(m[0][2], m[1][2], m[2][2]));
      const double texelM = static_cast<double>(s.texelM[k]);
      long coveredFull = 0, coveredCoarse = 0, both = 0, far = 0;
      for (int y = full.crop.y; y < full.crop.w; ++y)
        for (int x = full.crop.x; x < full.crop.z; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * render::TerrainRenderer::kShadowMapSize + static_cast<std::size_t>(x);
          const bool a = full.depths[i] < 1.0f, b = coarse.depths[i] < 1.0f;
          coveredFull += a ? 1 : 0;
          coveredCoarse += b ? 1 : 0;
          if (!a || !b) continue;
          ++both;
          far += std::abs(static_cast<double>(full.depths[i] - coarse.depths[i])) * depthM > 0.1 * texelM ? 1 : 0;
        }
      std::printf("%s cascade %zu: %ld texels covered by the full grid's casters, %ld by the coarser ones; %ld of %ld "
                  "depths over 0.1 texel apart\n",
                  c.name, k, coveredFull, coveredCoarse, far, both);
      EXPECT_LE(std::abs(coveredCoarse - coveredFull), coveredFull / 200 + 16) << c.name << " cascade " << k;
      EXPECT_LE(far, both / 50) << c.name << " cascade " << k << ": over 2 % of the depths moved by over 0.1 texel";
    }
    ASSERT_EQ(images.off.pixels.size(), images.on.pixels.size());
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.01);
    const auto pixels = static_cast<int>(images.on.pixels.size() / 4);
    std::printf("%s: %d of %d tile draws into the maps from every 2nd vertex; largest change %.4f, %d of %d pixels over 1 %%\n",
                c.name, ts.shadowCoarseTileDraws, ts.shadowTileDraws, change.worst, change.over, pixels);
    if (change.over > pixels / 2000) {
      test::savePng(r, std::string("shadow_strides_") + c.name);
      test::saveChangePng(images.off, images.on, 0.01, std::string("shadow_strides_change_") + c.name);
    }
    EXPECT_LE(change.over, pixels / 2000) << c.name << ": more than 0.05 % of the pixels changed by over 1 %";
  }
  EXPECT_GT(coarseDraws, 0) << "no tile was drawn from the coarser mesh: the test compared a picture with itself";
}

// Up to 500 km the vertices' aerial perspective comes from a table made each frame of path
// length, end altitude and angle to the Sun (render/aerial.glsl's TERRAIN_AERIAL_TABLE) instead
// of ten lookups into the atmosphere's 4D tables per vertex: the picture must stay the exact
// path's. Views at the sea's horizon (the far coasts of the strait from 2 m: grazing paths), of
// the Himalaya at the horizon from 15 km, at a Sun 2° up from 9 km, of a coast from 30 km and
// straight down from 300 km. The pixels that may change are single ones along the sea's horizon
// where a triangle's far vertex lies beyond it, unseen, whose path either way is a convention.
TEST(TerrainRender, AerialTableKeepsThePerVertexPicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::vector<ViewCase> cases{
      kGibraltar2m,
      kHimalaya15kmHorizon,
      {"himalaya_9km_sun_2deg", {.latDeg = 27.8, .lonDeg = 87.2, .heightM = 9000.0, .headingDeg = 240.0, .pitchDeg = -10.0, .fovDeg = 45.0, .width = 320, .height = 180}, 2.0, 250.0},
      kGibraltar30km,
      {"gibraltar_300km_down", {.latDeg = 36.0, .lonDeg = -5.5, .heightM = 3.0e5, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 30.0, .width = 320, .height = 180}, 45.0, 160.0},
  };
  for (const ViewCase& c : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.terrain().setAerialTable(on); });
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.02);
    std::printf("%s: largest change %.4f, mean %.5f, %d pixels over 2 %%\n", c.name, change.worst, change.mean, change.over);
    EXPECT_LE(change.over, 320 * 180 / 200) << c.name << ": over 0.5 % of the pixels changed by over 2 %";
    EXPECT_LT(change.mean, 0.002) << c.name;
    EXPECT_GT(change.worst, 0.0) << c.name << ": the table is not in use";
  }
}

namespace {
// Frame `f` with a terrain feature off, then on (TerrainRenderer's `set`), and the second
// frame's statistics: the first drew no tile with the feature (`count`), the second some.
std::pair<test::OffAndOn, render::TerrainStats> terrainOffAndOn(render::GlobeRenderer& r, const render::FrameInput& f,
                                                                 const char* name, void (render::TerrainRenderer::*set)(bool),
                                                                 int render::TerrainStats::*count) {
  const test::OffAndOn images = test::renderOffAndOn(r, f, [&](bool on) {
    if (on) {  // (of the frame without)
      EXPECT_EQ(r.terrain().stats().*count, 0) << name;
    }
    (r.terrain().*set)(on);
  });
  EXPECT_GT(r.terrain().stats().*count, 0) << name << ": no tile drawn with the feature";
  return {images, r.terrain().stats()};
}
}  // namespace

// Above 500 km (no table) the vertices' aerial perspective is the exact path's, computed for
// the vertices of the frame's tiles the eye may see by a compute pass
// (terrain/tile_aerial.comp) instead of the vertex shader: the same code on the same inputs,
// so the same picture. From orbit over
// the Atlantic (tiles with water: nearly all of them), at 2000 km over the terminator (night
// and day) and at 800 km over the Alps.
TEST(TerrainRender, TileAerialBufferKeepsThePerVertexPicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::vector<ViewCase> cases{
      {"orbit_20000km", {.latDeg = 10.0, .lonDeg = -30.0, .heightM = 2.0e7, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 45.0, .width = 320, .height = 180}, 40.0, 120.0},
      {"terminator_2000km", {.latDeg = 30.0, .lonDeg = 10.0, .heightM = 2.0e6, .headingDeg = 90.0, .pitchDeg = -60.0, .fovDeg = 45.0, .width = 320, .height = 180}, 2.0, 270.0},
      {"alps_800km", {.latDeg = 46.0, .lonDeg = 8.0, .heightM = 8.0e5, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 30.0, .width = 320, .height = 180}, 30.0, 180.0},
  };
  r.terrain().setCoarseStrides(false);  // (which need the buffer: their own test below)
  for (const ViewCase& c : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    const auto [images, stats] = terrainOffAndOn(r, f, c.name, &render::TerrainRenderer::setTileAerialBuffer,
                                                 &render::TerrainStats::aerialBufferTiles);
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 1e-4);
    std::printf("%s: %d tiles, %d of their vertices listed, largest change %.2e\n", c.name, stats.drawnTiles,
                stats.aerialVertices, change.worst);
    // Only the vertices the eye may see (TerrainRenderer::listTileAerialVertices): from orbit
    // and from 2000 km some of the tiles' lie beyond the horizon (measured: 62 % and 81 % of
    // them listed), from 800 km straight down none. A vertex left out that a fragment reads
    // would change its pixels here by far more than the bound.
    const double listedShare = static_cast<double>(stats.aerialVertices) / (stats.aerialBufferTiles * terrain::kTileVertices);
    EXPECT_GT(listedShare, 0.0) << c.name;
    EXPECT_LE(listedShare, c.name == std::string("orbit_20000km") ? 0.7 : c.name == std::string("terminator_2000km") ? 0.9 : 1.0)
        << c.name;
    if (change.worst > 1e-4) test::savePng(r, std::string("tile_aerial_buffer_") + c.name);
    EXPECT_LT(change.worst, 1e-4) << c.name;
  }
  r.terrain().setCoarseStrides(true);
}

// Above 20 km the tiles with water come after the globe's parts; where their relief moves a
// point on screen by at most half a pixel off the ellipsoid's point behind it
// (TerrainRenderer::reliefShiftPx), they draw only over the pixels the globe's classifying
// draw found land at all four samples (GlobeRenderer::setTilesOverLandClass), with no coast
// test of their own: the globe's classes decide the coast, whose mixed pixels keep the globe's
// surface part (anti-aliased by its four samples), and a tile's mesh above sea level beyond
// the coast stays under the sea's classes. Against the tiles' own test over every class: the
// same picture but at the coast's pixels from orbit over the Atlantic and from 3000 km over the
// Aegean (islands, lakes; measured 315 and 260 pixels, the bounds ~1.3 times that: with the
// wrong class the tiles draw nowhere and the globe's flat land changes most of the land's
// pixels). From 300 km straight down on Gibraltar's strait and from 30 km over it the relief
// moves points by pixels (the Rif, the Betics): the tiles test the mask themselves, the same
// picture to the bit (a coastal ridge would otherwise be cut where it stands over the sea).
// TerrainStats::globeLandTiles says which path each frame's tiles took.
TEST(TerrainRender, TilesOverTheGlobesLandClassKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  if (!gl::driverProfile().stencilExport) GTEST_SKIP() << "needs GL_ARB_shader_stencil_export";
  render::GlobeRenderer r(data::defaultElevation());
  struct Case {
    ViewCase view;
    int maxOver;  // pixels (of 320 x 180) changed by over 2 %; 0: none may change at all
  };
  const std::vector<Case> cases{
      {{"atlantic_20000km", {.latDeg = 10.0, .lonDeg = -30.0, .heightM = 2.0e7, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 45.0, .width = 320, .height = 180}, 40.0, 120.0}, 420},
      {{"aegean_3000km", {.latDeg = 38.0, .lonDeg = 25.0, .heightM = 3.0e6, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 45.0, .width = 320, .height = 180}, 35.0, 200.0}, 340},
      {{"gibraltar_300km_down", {.latDeg = 36.0, .lonDeg = -5.5, .heightM = 3.0e5, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 30.0, .width = 320, .height = 180}, 45.0, 160.0}, 0},
      {kGibraltar30km, 0},
  };
  for (const auto& [c, maxOver] : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.setTilesOverLandClass(on); });
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.02);
    const int overLand = r.terrain().stats().globeLandTiles;  // (of the frame with it on)
    std::printf("%s: %d tiles over the land class, %d pixels over 2 %%, largest change %.4f, mean %.5f\n", c.name,
                overLand, change.over, change.worst, change.mean);
    if (change.over > maxOver) test::savePng(r, std::string("tiles_over_land_class_") + c.name);
    if (maxOver == 0) {
      EXPECT_EQ(overLand, 0) << c.name << ": tiles whose relief moves points by pixels over the land class alone";
      EXPECT_EQ(change.worst, 0.0) << c.name;
      continue;
    }
    EXPECT_GT(overLand, 0) << c.name;
    EXPECT_GT(change.over, 0) << c.name << ": the coast's pixels unchanged (the tiles' own test still in use?)";
    EXPECT_LE(change.over, maxOver) << c.name;
  }
}

namespace {
// The mean of each k x k block of pixels.
io::ImageRgbaF blockMeans(const io::ImageRgbaF& image, int k) {
  io::ImageRgbaF out{image.width / k, image.height / k, {}};
  out.pixels.assign(static_cast<std::size_t>(4 * out.width * out.height), 0.0f);
  for (int y = 0; y < out.height * k; ++y)
    for (int x = 0; x < out.width * k; ++x)
      for (int c = 0; c < 4; ++c)
        out.pixels[static_cast<std::size_t>(4 * ((y / k) * out.width + x / k) + c)] +=
            image.pixels[static_cast<std::size_t>(4 * (y * image.width + x) + c)] / static_cast<float>(k * k);
  return out;
}
}  // namespace

// Far tiles are drawn from a coarser mesh (every 2nd vertex) where it lies within half a
// pixel of the full grid (TerrainRenderer::tileStrideIndex), their fragments still shaded from
// the full grid's normals, heights, detail amplitudes and aerial perspective (TERRAIN_COARSE):
// only their place on screen moves, by under half a pixel. That changes single pixels where the
// land's colours or the coast change from one pixel to the next, but hardly the picture over a
// few pixels: compared in blocks of 4 x 4 pixels. From 20 000 km over the Andes with the Sun
// 8° up (the tiles' vertex normals carry the relief; all 18 tiles coarser) and at 8000 km
// looking obliquely at the Himalaya towards the limb (the vertical offsets seen side on; 8 of
// 10 tiles coarser, the others not: the frame's mix of programs). Each case's bound is a few
// blocks over what it changes. Shaded from the coarse mesh's own vertices instead, 155 of the
// Andes' blocks change by over 1 %; with the coarse vertices' aerial perspective, 276 of them
// and 28 of the Himalaya's. (Not seen here: the skirts' heights, seen, if at all, for a pixel at
// a tile's edge; the detail amplitude, which these views' pixels leave out: TERRAIN_NO_DETAIL.
// TileGridGpu probes both.)
TEST(TerrainRender, CoarserMeshesKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  struct Case {
    ViewCase view;
    int blocksOver1Percent;  // of 80 x 45
  };
  const std::vector<Case> cases{
      {{"andes_20000km_sun_8deg", {.latDeg = -20.0, .lonDeg = -68.0, .heightM = 2.0e7, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 15.0, .width = 320, .height = 180}, 8.0, 90.0}, 30},
      {{"himalaya_8000km_oblique", {.latDeg = 10.0, .lonDeg = 85.0, .heightM = 8.0e6, .headingDeg = 0.0, .pitchDeg = -45.0, .fovDeg = 45.0, .width = 320, .height = 180}, 30.0, 150.0}, 14},
  };
  for (const auto& [c, bound] : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    const auto [images, stats] =
        terrainOffAndOn(r, f, c.name, &render::TerrainRenderer::setCoarseStrides, &render::TerrainStats::coarseTiles);
    const test::RadianceChange pixels = test::radianceChange(images.off, images.on, 0.01);
    const test::RadianceChange blocks = test::radianceChange(blockMeans(images.off, 4), blockMeans(images.on, 4), 0.01);
    std::printf("%s: %d of %d tiles coarser; pixels over 1 %%: %d, blocks of 4 x 4 over 1 %%: %d (mean %.5f)\n",
                c.name, stats.coarseTiles, stats.drawnTiles, pixels.over, blocks.over, blocks.mean);
    if (blocks.over > bound) test::savePng(r, std::string("coarse_meshes_") + c.name);
    EXPECT_LE(blocks.over, bound) << c.name;
  }
}

// Where no pixel of the frame's tiles resolves a detail octave their vertex normals leave out
// (TerrainRenderer::detailUnresolved), terrain.frag is compiled without the octaves' loop: the
// same picture. From orbit, from 6000 km straight down on the Alps (near the lowest height at
// which it applies; the detail adds nothing from 2500 km) and from 8000 km looking obliquely
// at the Himalaya towards the limb (the frame's corners, grazing footprints), it applies; from
// 1300 km it must not, where the detail changes a third of the pixels by over 0.1 %.
TEST(TerrainRender, UnresolvedDetailLeftOutKeepsThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  using Skip = render::TerrainRenderer::DetailSkip;
  const auto alps = [](const char* name, double heightM) {
    return ViewCase{name, {.latDeg = 46.0, .lonDeg = 8.0, .heightM = heightM, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 45.0, .width = 320, .height = 180}, 30.0, 180.0};
  };
  const ViewCase orbit{"orbit_20000km", {.latDeg = 10.0, .lonDeg = -30.0, .heightM = 2.0e7, .headingDeg = 0.0, .pitchDeg = -90.0, .fovDeg = 45.0, .width = 320, .height = 180}, 40.0, 120.0};
  const ViewCase himalaya{"himalaya_8000km_oblique", {.latDeg = 10.0, .lonDeg = 85.0, .heightM = 8.0e6, .headingDeg = 0.0, .pitchDeg = -45.0, .fovDeg = 45.0, .width = 320, .height = 180}, 30.0, 150.0};
  for (const ViewCase& c : {orbit, alps("alps_6000km", 6.0e6), himalaya, alps("alps_1300km", 1.3e6)}) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    r.terrain().setDetailSkip(Skip::never);
    r.render(f);
    const io::ImageRgbaF never = r.radiance();
    r.terrain().setDetailSkip(Skip::always);
    r.render(f);
    const test::RadianceChange detail = test::radianceChange(never, r.radiance(), 1e-3);
    r.terrain().setDetailSkip(Skip::whereUnresolved);
    r.render(f);
    const bool resolved = std::string(c.name) == "alps_1300km";
    EXPECT_EQ(r.terrain().stats().pixelDetail, resolved) << c.name;
    const test::RadianceChange change = test::radianceChange(never, r.radiance(), 1e-4);
    if (change.worst >= 1e-4) {
      test::savePictureAndChange(r, never, r.radiance(), 1e-4, std::string("unresolved_detail_") + c.name);
    }
    std::printf("%s: detail per pixel %d, its share: %d pixels over 0.1 %%; largest change %.2e\n", c.name,
                resolved ? 1 : 0, detail.over, change.worst);
    EXPECT_LT(change.worst, 1e-4) << c.name;
    if (resolved) {
      EXPECT_GT(detail.over, 320 * 180 / 4) << c.name << ": the detail should show here";
    }
  }
}

// Below the grid's ceiling the floor deeper than a metre whose view rays cross sea level where
// the land mask holds no land is clipped before its fragments (TerrainRenderer::floorClip,
// terrain.vert) instead of discarded by terrain.frag's coast test: the same picture. From 2 m
// in the Strait of Gibraltar (the bench's sea-2m-horizon: land 3 km off), from 2 m and 150 m
// off Tarifa's beach looking at it (the mesh dips under the sea where the mask holds land, so
// the shader keeps some floor), and over the Great Bahama Bank (no land for kilometres).
TEST(TerrainRender, FloorClippedAroundTheEyeKeepsThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::vector<ViewCase> cases{
      kGibraltar2m,
      kTarifa2mBeach,
      {"tarifa_150m_beach", {.latDeg = 35.99, .lonDeg = -5.59, .heightM = 150.0, .headingDeg = 300.0, .pitchDeg = -25.0, .fovDeg = 45.0, .width = 320, .height = 180}, 40.0, 200.0},
      kBahamas2m,
  };
  double clipped = 0.0;
  for (const ViewCase& c : cases) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    const geo::CameraView view = geo::makeCameraView(f.camera, f.width, f.height);
    const double clipM = r.terrain().floorClip(view, f.height).clipM;
    clipped = std::max(clipped, clipM);
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.terrain().setFloorClip(on); });
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.02);
    std::printf("%s: floor clipped within %.0f m; largest change %.4f, %d pixels over 2 %%\n", c.name, clipM,
                change.worst, change.over);
    EXPECT_LE(change.over, 2) << c.name;
    EXPECT_LT(change.mean, 1e-4) << c.name;
    if (change.over > 2) test::savePng(r, std::string("floor_clip_") + c.name);
  }
  EXPECT_GT(clipped, 2000.0) << "the clip is in use";
  r.terrain().setFloorClip(false);
  EXPECT_EQ(r.terrain().floorClip(geo::makeCameraView(test::frameOf(kGibraltar2m.view, 20.0, 250.0).camera, 320, 180), 180).clipM, 0.0);
}

// Climbing from the sea to above the grid's ceiling, where the terrain is drawn without the
// sea's horizon clip: the former frame's cone must not cut it (llvmpipe cut by it though the
// clip distance was off). The Strait of Gibraltar from 30 km after a frame at 2 m: the picture
// of a renderer that never went low, with 1 and 4 samples.
TEST(TerrainRender, NoFormerHorizonClipAfterClimbing) {
  auto ctx = gl::createHeadlessContext();
  const ViewCase high{"strait_30km", {.latDeg = 36.0, .lonDeg = -5.5, .heightM = 3.0e4, .headingDeg = 90.0, .pitchDeg = -20.0, .fovDeg = 45.0, .width = 320, .height = 180}, 30.0, 120.0};
  for (const int pixelSamples : {1, 4}) {
    render::FrameInput low = test::frameOf(kGibraltar2m.view, kGibraltar2m.sunElevationDeg, kGibraltar2m.sunAzimuthDeg);
    render::FrameInput f = test::frameOf(high.view, high.sunElevationDeg, high.sunAzimuthDeg);
    low.samples = f.samples = pixelSamples;
    std::array<io::ImageRgbaF, 2> images;
    for (const bool climbed : {false, true}) {
      render::GlobeRenderer r(data::defaultElevation());
      if (climbed) r.render(low);
      r.render(f);  // (the tiles built and uploaded: the second frame counts)
      r.render(f);
      images.at(climbed ? 1 : 0) = r.radiance();
      if (climbed) {
        const test::RadianceChange change = test::radianceChange(images[0], images[1], 1e-3);
        std::printf("%d samples: %d pixels changed by over 0.1 %%, largest change %.2e\n", pixelSamples, change.over,
                    change.worst);
        EXPECT_EQ(change.over, 0) << pixelSamples << " samples";
        if (change.over > 0) test::savePictureAndChange(r, images[0], images[1], 1e-3, "former_horizon_clip");
      }
    }
  }
}

// From near the sea, the tiles its horizon may hide (their draws clip at the horizon's cone)
// are drawn in one pass after the others, without the coverage pass's depth-only draw first
// (TerrainRenderer::drawCovered): the cone leaves them a strip of pixels, and the first draw
// cost their vertices and triangles twice. The same picture as with the coverage pass: the
// strait from 2 m (the far coasts), the beach at Tarifa (its coast near) and the Bahamas' bank
// from 2 m (the floor in reach). Measured: the same radiances (largest change 0); 16, 13 and 1
// tiles in one pass at 320 x 180 (those tiles left out: 201 and 356 pixels changed, by up to
// 760 %). sea-2m-horizon's terrain pass 22.5-24.1 -> 21.2-21.8 ms of one thread at 1280 x 720.
TEST(TerrainRender, TilesBeyondTheSeaHorizonInOnePassKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  for (const ViewCase& c : {kGibraltar2m, kTarifa2mBeach, kBahamas2m}) {
    const render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    r.render(f);  // (the tiles built and uploaded)
    // on: the tiles beyond the horizon in one pass (the default, restored by the last call)
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.terrain().setCoverageBeyondHorizon(!on); });
    const int onePass = r.terrain().stats().onePassBeyondHorizon;
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 1e-4);
    std::printf("%s: %d tiles in one pass; %d pixels changed by over 0.01 %%, largest change %.2e\n", c.name, onePass,
                change.over, change.worst);
    EXPECT_EQ(change.over, 0) << c.name;
    if (change.over > 0) test::savePictureAndChange(r, images.off, images.on, 1e-4, std::string("one_pass_") + c.name);
    if (std::string(c.name) == "gibraltar_2m") {
      EXPECT_GE(onePass, 10) << "the far coasts' tiles";
    }
  }
}

// The points beyond the sea's horizon at the waves' depth are clipped before any fragment
// (terrain::seaHorizonCone, terrain.vert's second clip distance): from near the sea, most of
// the far coasts' hills, which the terrain pass shaded and the sea then covered. The picture
// must stay (the sea or the land before them hides every clipped point; the pixels along the
// clip's edge are rasterised from the clipped triangles' pieces, which may move an edge pixel
// by a fraction of a percent), and the tile draws must pass fewer samples. Measured at
// 320 x 180 (samples the terrain's two draws passed, off -> on): gibraltar_2m 1069 -> 844,
// gibraltar_300m 1588 -> 1038, tarifa_2m_beach (its coast near) 1702 -> 1700. From 0.3 m in an
// 18 m/s swell the grid's top row, pulled onto the ellipsoid's horizon, is displaced the most
// against the cone (861 -> 670, the picture the same). With 4 samples a pixel too (a GPU's
// default). Each case's frames without the clip come right after the former case's with it:
// llvmpipe cut them by the former frame's cone though GL_CLIP_DISTANCE1 was off (with 4
// samples the far coasts gone at gibraltar_300m, 0 samples passed; the H200 failed the same
// case), until the frames without the clip set a cone that cuts nothing.
TEST(TerrainRender, SeaHorizonClipKeepsThePictureAndShadesLess) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::vector<ViewCase> cases{
      kGibraltar2m,
      kTarifa2mBeach,
      {"gibraltar_300m", {.latDeg = 36.0, .lonDeg = -5.5, .heightM = 300.0, .headingDeg = 250.0, .pitchDeg = -2.0, .fovDeg = 45.0, .width = 320, .height = 180}, 8.0, 260.0},
      kBahamas2m,
      {"gibraltar_0.3m_swell", {.latDeg = 36.0, .lonDeg = -5.5, .heightM = 0.3, .headingDeg = 270.0, .pitchDeg = 1.0, .fovDeg = 45.0, .width = 320, .height = 180}, 20.0, 250.0},
  };
  r.terrain().setCountSamples(true);
  for (const int pixelSamples : {1, 4})
  for (const ViewCase& c : cases) {
    SCOPED_TRACE(std::string(c.name) + ", " + std::to_string(pixelSamples) + " samples");
    render::FrameInput f = test::frameOf(c.view, c.sunElevationDeg, c.sunAzimuthDeg);
    f.samples = pixelSamples;
    if (std::string(c.name).find("swell") != std::string::npos) f.wind.speedMs = 18.0;
    std::array<std::uint64_t, 2> samples{};
    std::array<io::ImageRgbaF, 2> images;
    for (const bool on : {false, true}) {
      r.terrain().setSeaHorizonClip(on);
      r.render(f);  // (the tiles this state draws built and uploaded: the second frame counts)
      r.render(f);
      samples.at(on ? 1 : 0) = r.terrain().stats().samplesPassed;
      images.at(on ? 1 : 0) = r.radiance();
    }
    const test::RadianceChange change = test::radianceChange(images[0], images[1], 0.01);
    std::printf("%s, %d samples: terrain samples %llu -> %llu; largest change %.5f, %d pixels over 1 %%, mean %.2e\n",
                c.name, pixelSamples, static_cast<unsigned long long>(samples[0]),
                static_cast<unsigned long long>(samples[1]), change.worst, change.over, change.mean);
    // (With 4 samples the samples along the clip's edge: 2 pixels by up to 20 % at gibraltar_300m.)
    EXPECT_LE(change.over, pixelSamples == 1 ? 0 : 3);
    EXPECT_LT(change.mean, 1e-5);
    if (change.over > 0) {
      test::savePictureAndChange(r, images[0], images[1], 0.01, std::string("sea_horizon_clip_") + c.name);
    }
    EXPECT_LE(samples[1], samples[0]);
    const std::string name = c.name;
    if (name == "gibraltar_2m" || name == "gibraltar_300m") {
      EXPECT_LT(samples[1], samples[0] * 17 / 20) << "the far hills' hidden feet are clipped";
    }
  }
  r.terrain().setCountSamples(false);
}
