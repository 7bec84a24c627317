// The globe's classifying draw by blocks (render/GlobeBlocks): a block the CPU classes as a
// whole holds only that class at every sample the per-pixel draw would test, and the picture
// is the per-pixel classification's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "data/Elevation.hpp"
#include "data/LandMask.hpp"
#include "data/LandFractionMips.hpp"
#include "data/LandMaskPyramid.hpp"
#include "data/WindLayers.hpp"
#include "geo/Sun.hpp"
#include "geo/Wgs84.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "ocean/WaterOptics.hpp"
#include "render/GlobeBlocks.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GlFixtures.hpp"
#include "support/ImageCompare.hpp"

using namespace og;

namespace {

struct View {
  const char* name;
  double lat, lon, h, heading, pitch;
};
// Real coasts from above the grid's ceiling: the Strait of Gibraltar from 30 km (the fine
// level decides), Portugal's coast from 100 km, the Atlantic's limb from 400 km, the Bahama
// Banks straight down from 300 km (the sea's water column over shallow floors).
constexpr std::array<View, 4> kViews{{{"gibraltar-30km", 35.6, -5.6, 3.0e4, 0, -30},
                                      {"portugal-100km", 38.3, -10.5, 1.0e5, 74, -25},
                                      {"limb-400km", 20, -40, 4.0e5, 90, -15},
                                      {"bahamas-300km", 24.5, -77.5, 3.0e5, 0, -90}}};
constexpr int kWidth = 320, kHeight = 180;
// From higher up, where pixels span several 2′ cells and the land fraction's pyramid decides
// (data::LandFractionMips): Finland's lakes from 1500 km (the B-spline still weighs at the
// nearest pixels), the Great Lakes obliquely from 4000 km (the pyramid's levels blend) and
// orbit (every pixel on the pyramid, its last level).
constexpr std::array<View, 3> kHighViews{{{"finland-1500km", 62.0, 26.0, 1.5e6, 0, -90},
                                          {"great-lakes-4000km", 40.0, -84.0, 4.0e6, 0, -60},
                                          {"orbit-20000km", 10, -30, 2.0e7, 0, -90}}};

render::FrameInput frameOf(const View& v);

// Programs that leave out code no pixel of a frame weighs keep its picture: each view rendered
// with them off and on (`set`), the frame using them (`used`), no pixel changed by over `bound`.
void expectSamePicture(render::GlobeRenderer& r, const std::vector<View>& views, const std::function<void(bool)>& set,
                       const std::function<bool()>& used, const std::string& pngPrefix, double bound = 1e-5) {
  for (const View& v : views) {
    const test::OffAndOn images = test::renderOffAndOn(r, frameOf(v), set);
    EXPECT_TRUE(used()) << v.name;
    const test::RadianceChange change = test::radianceChange(images.off, images.on, bound);
    std::printf("%s: %d pixels changed, largest relative change %.2e\n", v.name, change.over, change.worst);
    EXPECT_EQ(change.over, 0) << v.name << " (largest relative change " << change.worst << ")";
    if (change.over > 0) test::savePictureAndChange(r, images.off, images.on, bound, pngPrefix + v.name);
  }
}

render::FrameInput frameOf(const View& v) {
  render::FrameInput f;
  f.camera.position = {v.lat, v.lon, v.h};
  f.camera.headingDeg = v.heading;
  f.camera.pitchDeg = v.pitch;
  f.width = kWidth;
  f.height = kHeight;
  f.samples = 1;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 30, 120);
  return f;
}

}  // namespace

TEST(GlobeBlocks, FilledBlocksHoldTheirClassAtEverySample) {
  // Every sample of every pixel of a land (sea) block is land (sea) by the CPU twin of the
  // per-pixel test (LandMask::landFraction with the pixel's footprint: globe.frag's
  // samplesSea), an open-sea block's on a floor deeper than the water's reach, and the blocks
  // fill much of each view. (The blocks' margin of a cell around
  // their footprint matters only for points within a hair of a cell's edge, which no lattice
  // of test points is likely to hit: this checks the classes, the pyramid and the fine level.)
  const data::LandMask& mask = data::defaultLandMask();
  const data::LandMaskPyramid pyramid(mask);
  const data::LandFractionMips mips(mask);
  // The renderer's open-sea map (GlobeRenderer's constructor and bindOpenSeaMap): an open-sea
  // block's samples must lie on a floor deeper than the water's reach.
  const data::LatLonGrid& layer = data::defaultElevation();
  const double reachM = ocean::waterMaxPathM(ocean::jerlovWater(ocean::kDefaultWater).attenuationPerM, ocean::kWaterEpsilon);
  std::vector<unsigned char> blocked = render::blockedByLayer(layer, 1.5 * reachM);
  render::addBlockedByMask(mask, blocked);
  const render::OpenSeaMap openSea = render::makeOpenSeaMap(std::move(blocked));
  int openBlocks = 0;
  // The high views with the pyramid, and again without it (the B-spline at every scale: frames
  // below the upload's bound, setFractionMipsOn(false)); near the pole and across the
  // antimeridian too, where the lattice's bend and the longitudes' wrap matter.
  std::vector<std::pair<View, const data::LandFractionMips*>> views;
  for (const View& v : kViews) views.emplace_back(v, &mips);
  for (const View& v : kHighViews) views.emplace_back(v, &mips);
  views.emplace_back(View{"svalbard-3000km", 79.0, 20.0, 3.0e6, 0, -90}, &mips);
  views.emplace_back(View{"fiji-1500km", -17.0, 179.8, 1.5e6, 30, -70}, &mips);
  for (const View& v : kHighViews) views.emplace_back(v, nullptr);
  for (const auto& [v, withMips] : views) {
    const std::string name = std::string(v.name) + (withMips != nullptr ? "" : " (no pyramid)");
    const geo::CameraView view = geo::makeCameraView(frameOf(v).camera, kWidth, kHeight);
    // A rect off the blocks' lattice (the globe's scissor box): the lattice stays on multiples
    // of the block's side from the frame's corner (llvmpipe's 4 x 4 blocks), widened to it.
    // (Its right column and top row partial.)
    const std::array<int, 4> asked{3, 5, kWidth - 7, kHeight - 5};
    const render::GlobeBlocks blocks =
        render::classifyGlobeBlocks(view, kWidth, kHeight, asked, pyramid, &openSea, nullptr, withMips);
    EXPECT_EQ(blocks.rect, (std::array<int, 4>{0, 0, kWidth - 4, kHeight})) << name;
    const int right = blocks.rect[0] + blocks.rect[2], top = blocks.rect[1] + blocks.rect[3];
    const double pixelRad = 2.0 * std::tan(0.5 * view.verticalFovRad) / kHeight;
    int filled = 0, onGlobe = 0, wrong = 0, shallow = 0, samples = 0, onPyramid = 0, nearHalf = 0;
    for (int by = 0; by < blocks.rows; ++by)
      for (int bx = 0; bx < blocks.columns; ++bx) {
        const render::GlobeBlockClass c = blocks.classes[static_cast<std::size_t>(by * blocks.columns + bx)];
        // (Blocks whose centre sees the globe: from orbit at this size the outline is too tight
        // for Miss blocks, and the sky's are classed per pixel.)
        const glm::dvec3 centre = view.rayDirection(2.0 * (blocks.rect[0] + (bx + 0.5) * render::kGlobeBlockPx) / kWidth - 1.0,
                                                    2.0 * (blocks.rect[1] + (by + 0.5) * render::kGlobeBlockPx) / kHeight - 1.0);
        onGlobe += geo::intersectEllipsoid(view.positionEcef, centre).has_value() ? 1 : 0;
        if (c != render::GlobeBlockClass::Land && c != render::GlobeBlockClass::Sea &&
            c != render::GlobeBlockClass::OpenSea)
          continue;
        ++filled;
        openBlocks += c == render::GlobeBlockClass::OpenSea ? 1 : 0;
        // Its pixels' four samples (globe.frag's rotated grid), their footprint the pixel's.
        constexpr std::array<std::array<double, 2>, 4> kOffsets{{{-0.125, -0.375}, {0.375, -0.125}, {0.125, 0.375}, {-0.375, 0.125}}};
        const int x0 = blocks.rect[0] + bx * render::kGlobeBlockPx, y0 = blocks.rect[1] + by * render::kGlobeBlockPx;
        for (int y = y0; y < std::min(y0 + render::kGlobeBlockPx, top); ++y)
          for (int x = x0; x < std::min(x0 + render::kGlobeBlockPx, right); ++x) {
            std::array<geo::Geodetic, 4> at{};
            double footprintDeg = 0.0;
            for (std::size_t k = 0; k < 4; ++k) {
              const glm::dvec3 dir = view.rayDirection(2.0 * (x + 0.5 + kOffsets[k][0]) / kWidth - 1.0,
                                                       2.0 * (y + 0.5 + kOffsets[k][1]) / kHeight - 1.0);
              const std::optional<double> t = geo::intersectEllipsoid(view.positionEcef, dir);
              ASSERT_TRUE(t.has_value()) << name << " pixel " << x << ", " << y;
              ++samples;
              const glm::dvec3 p = view.positionEcef + *t * dir;
              at[k] = geo::ecefToGeodetic(p);
              footprintDeg += 0.25 * data::LandMask::coastFootprintDeg(*t, pixelRad, -glm::dot(geo::ellipsoidNormalAt(p), dir));
            }
            for (const geo::Geodetic& g : at) {
              const float fraction = withMips != nullptr
                                         ? withMips->landFraction(g.latitudeDeg, g.longitudeDeg, footprintDeg)
                                         : mask.landFraction(g.latitudeDeg, g.longitudeDeg, footprintDeg);
              const bool land = fraction >= 0.5f;
              onPyramid += withMips != nullptr && mips.weight(footprintDeg) > 0.0 ? 1 : 0;
              // (within the GPU's filtering of the pyramid's bytes, blocks keep their margin)
              nearHalf += std::abs(fraction - 0.5f) < 2.0f / 255.0f ? 1 : 0;
              wrong += land != (c == render::GlobeBlockClass::Land) ? 1 : 0;
              if (c == render::GlobeBlockClass::OpenSea)
                shallow += double{layer.sample(g.latitudeDeg, g.longitudeDeg)} > -reachM ? 1 : 0;
            }
          }
      }
    EXPECT_EQ(wrong, 0) << name;
    EXPECT_EQ(nearHalf, 0) << name;
    const bool high = v.h > 1.0e6;
    if (high && withMips != nullptr) {
      EXPECT_GT(onPyramid, samples / 2) << name << ": the pyramid decides";
    }
    EXPECT_EQ(shallow, 0) << name << ": open-sea blocks over a floor the water shows";
    // (From high up at 320 x 180 a block spans hundreds of kilometres: fewer are one class.)
    // (Without the pyramid the lakes keep most inland blocks per pixel from high up.)
    EXPECT_GT(filled, onGlobe / (!high ? 4 : withMips != nullptr ? 8 : 16)) << name << ": " << filled << " of " << onGlobe << " blocks on the globe filled";
  }
  EXPECT_GT(openBlocks, 50) << "the open sea's blocks (the Atlantic's limb)";
}

TEST(GlobeRender, BlocksClassedOnTheCpuKeepThePicture) {
  // The same views rendered with the blocks and with every pixel classified on the GPU, by the
  // one classifying draw and by the draws per step (OCEANGLOBE_STENCIL_EXPORT=0: NVIDIA's
  // path): the same picture but at single pixels where the two draws' rays round differently
  // across a coast (the blocks' triangles interpolate the pixel's position in other triangles
  // than the full-screen one) or where the land/sea split (on with blocks) shades an edge
  // otherwise.
  for (int path = 0; path < 2; ++path) {
    const std::optional<test::ScopedEnv> steps =
        path == 1 ? std::optional<test::ScopedEnv>(std::in_place, "OCEANGLOBE_STENCIL_EXPORT", "0") : std::nullopt;
    auto ctx = gl::createHeadlessContext();
    render::GlobeRenderer r(data::defaultElevation());
    std::vector<View> views(kViews.begin(), kViews.end());
    // The pyramid's blocks (not orbit's: at this size its coasts' pixels are shaded otherwise by
    // the land/sea split, which the blocks turn on, with the pyramid or without).
    views.insert(views.end(), kHighViews.begin(), kHighViews.end() - 1);
    for (const View& v : views) {
      const std::string name = std::string(v.name) + (path == 1 ? " (draws per step)" : "");
      const test::DisplayOffAndOn images = test::displayOffAndOn(r, frameOf(v), [&r](bool on) { r.setGlobeBlocks(on); });
      const auto& counts = r.globeBlockCounts();
      // (From 4000 km at this size a block spans ~500 km: a third as many fill; without the
      // pyramid, whose lakes fade, a tenth.)
      const bool high = v.h > 1.0e6;
      EXPECT_GT(counts[1] + counts[2] + counts[3], high ? 80 : 100) << name << ": the blocks are in use";
      // Above the limb from 400 km: blocks in space, not drawn at all.
      if (std::string(v.name) == "limb-400km") {
        EXPECT_GT(counts[static_cast<std::size_t>(render::GlobeBlockClass::Space)], 50) << name << ": space's blocks";
      }
      const test::Comparison change = test::compareRgb(images.on, images.off, 2);
      const long over2 = std::lround(change.shareOver * kWidth * kHeight);
      EXPECT_LE(over2, 3) << name << " (largest difference " << change.maxDiff << " levels)";
      if (over2 > 3) {
        const std::string prefix = std::string(OG_TEST_OUT_DIR) + "/globe_blocks_" + v.name + (path == 1 ? "_steps" : "");
        io::writePng(prefix + "_off.png", images.off);
        io::writePng(prefix + "_on.png", images.on);
      }
    }
  }
}

// The scattered parts (the limb, the horizon, the coasts) listed and shaded by the compute
// variant of the globe's shader (GlobeRenderer::shadeScatteredParts) against the same parts'
// fragments: the same code on the same pixel centres, so the same picture (to float rounding:
// the centre's NDC computed, not interpolated, moves the rays by ~1e-7). From orbit, from
// above the ceiling, and below it (the horizon's pixels behind the grid at 4 m). A list that
// missed pixels would leave them black; one that shaded the wrong ones, another colour.
TEST(GlobeRender, ScatteredPartsShadedFromAListKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.setGlobeBlocks(true);  // (llvmpipe's default, whose blocks leave the horizon's pixels per pixel)
  std::vector<View> views(kViews.begin(), kViews.end());
  views.push_back({"orbit-20000km", 10, -30, 2.0e7, 0, -90});
  views.push_back({"sea-4m", 20, -40, 4.0, 270, -1});
  for (const View& v : views) {
    const render::FrameInput f = frameOf(v);
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.setScatteredPartsListed(on); });
    // (At sea-4m the horizon's pixels behind the grid: 58 on llvmpipe; 18 on the H200, whose sea
    // is drawn forward before the globe, hiding more of them.)
    const unsigned least = std::string(v.name) == "sea-4m" && !gl::driverProfile().software ? 10u : 50u;
    EXPECT_GT(r.listedPixelCount(), least) << v.name << ": the list is in use";
    ASSERT_EQ(images.off.pixels.size(), images.on.pixels.size());
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.01, 4);
    std::printf("%s: %u pixels listed, %d changed by over 1 %%, largest change %.2e\n", v.name, r.listedPixelCount(),
                change.over, change.worst);
    EXPECT_EQ(change.over, 0) << v.name << " (largest relative change " << change.worst << ")";
    if (change.over > 0) {
      test::savePictureAndChange(r, images.off, images.on, 0.01, std::string("globe_listed_") + v.name, 4);
    }
  }
}

// West of Portugal, where the demo flight comes down (150 km and 40 km up), the deep sea lies
// within a degree of the shelf and of seamounts: with the open-sea map's 7.5′ cells (1° cells
// gave it no radius there) most of the frame's sea goes to the open sea's part, without the
// water column, and the picture is the same as with every sea pixel in the sea's part.
TEST(GlobeRender, OpenSeaOffTheShelfKeepsThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.setCountPartSamples(true);
  // (each with the least share of its pixels the open sea's part must take: 75 % and 38 % here)
  const std::vector<std::pair<View, double>> views{{{"demo-flight-40km", 38.0, -12.0, 4.0e4, 74, -30}, 0.6},
                                                   {{"demo-flight-150km", 37.8, -13.2, 1.5e5, 70, -22}, 0.25}};
  for (const auto& [v, share] : views) {
    r.setSeaLattice(false);  // (every open-sea pixel shaded: SeaLatticeKeepsThePicture)
    const test::OffAndOn images = test::renderOffAndOn(r, frameOf(v), [&r](bool on) { r.setOpenSeaPart(on); });
    std::uint64_t open = 0;
    for (const auto& [name, samples] : r.partSamples()) open += name == "open sea" ? samples : 0;
    std::printf("%s: %.0f %% of the pixels in the open sea's part\n", v.name, 100.0 * static_cast<double>(open) / (kWidth * kHeight));
    EXPECT_GT(static_cast<double>(open), share * kWidth * kHeight) << v.name;
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 1e-5);
    EXPECT_EQ(change.over, 0) << v.name << " (largest relative change " << change.worst << ")";
    if (change.over > 0) test::savePng(r, std::string("globe_open_sea_") + v.name);
  }
}

// Above the grid's ceiling the sea's and the open sea's blocks are shaded at a lattice every
// 4 pixels and interpolated where the lattice shows that holds (render/SeaLattice): the
// displayed picture within a level of 255 of the per-pixel one at the demo flight's poses with
// the constant wind and the embedded month of winds (one frame 326 pixels wide: a last block
// of 6, whose points lie past the frame's edge), the Bahamas' banks (also at 160 x 90 from 300
// and 600 km, where the layer's 5′ cells are narrower than two lattice spacings), Portugal's
// coast and the limb; the radiance within 2 %. Most blocks are interpolated there, and their
// pixels are drawn from the lattice (the interpolating draw's samples); over a calm sea (0.3 m/s, the glint a few pixels wide) the
// lattice's points mark the narrow lobe and its blocks stay per pixel. (At 320 x 180 a block
// spans 4 times the angle it does at 1280 x 720, where more pass.)
TEST(GlobeRender, SeaLatticeKeepsThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.setGlobeBlocks(true);  // (the lattice is the blocks': llvmpipe's default)
  r.setCountPartSamples(true);
  struct Case {
    View view;
    double windMs;
    bool layers;
    double interpolatedShare;  // of the listed blocks, at least (at most, for the calm sea)
    int width = kWidth, height = kHeight;
  };
  const std::vector<Case> cases{{{"demo-flight-40km", 38.0, -12.0, 4.0e4, 74, -30}, 7.0, false, 0.85},
                                {{"demo-flight-40km-326px", 38.0, -12.0, 4.0e4, 74, -30}, 7.0, false, 0.85, 326},
                                {{"demo-flight-40km-winds", 38.0, -12.0, 4.0e4, 74, -30}, 7.0, true, 0.8},
                                {{"demo-flight-150km-winds", 37.8, -13.2, 1.5e5, 70, -22}, 7.0, true, 0.8},
                                {{"limb-400km", 20, -40, 4.0e5, 90, -15}, 7.0, false, 0.55},
                                {{"bahamas-300km", 24.5, -77.5, 3.0e5, 0, -90}, 7.0, false, 0.6},
                                {{"bahamas-300km-160px", 24.5, -77.5, 3.0e5, 0, -90}, 7.0, false, 0.3, 160, 90},
                                {{"bahamas-600km-160px", 24.5, -77.5, 6.0e5, 0, -90}, 7.0, false, 0.3, 160, 90},
                                {{"portugal-100km", 38.3, -10.5, 1.0e5, 74, -25}, 7.0, true, 0.4},
                                {{"calm-40km-towards-sun", 38.0, -12.0, 4.0e4, 120, -20}, 0.3, false, 0.6}};
  for (const Case& c : cases) {
    render::FrameInput f = frameOf(c.view);
    f.width = c.width;
    f.height = c.height;
    f.wind = geo::Wind::blowingTowards(c.windMs, 60.0);
    r.setWindLayers(c.layers ? std::make_shared<data::WindLayers>(data::WindLayers::load({"default"}, {}, std::nullopt))
                             : nullptr);
    const test::DisplayOffAndOn images = test::displayOffAndOn(r, f, [&r](bool on) { r.setSeaLattice(on); });
    const auto [listed, interpolated] = r.seaLatticeBlocks();
    std::uint64_t drawn = 0;  // pixels the interpolating draws wrote
    for (const auto& [name, samples] : r.partSamples()) drawn += name.find("lattice") != std::string::npos ? samples : 0;
    const test::Comparison change = test::compareRgb(images.on, images.off, 0);
    const double share = listed > 0 ? static_cast<double>(interpolated) / static_cast<double>(listed) : 0.0;
    std::printf("%s: %zu of %zu blocks interpolated, %llu pixels drawn from the lattice; %.2f %% of the pixels "
                "changed, by at most %d levels\n", c.view.name, interpolated, listed,
                static_cast<unsigned long long>(drawn), 100.0 * change.shareOver, change.maxDiff);
    EXPECT_GT(listed, 50u) << c.view.name;
    if (c.windMs >= 1.0) EXPECT_GE(share, c.interpolatedShare) << c.view.name;
    else EXPECT_LE(share, c.interpolatedShare) << c.view.name << ": the calm sea's narrow glint";
    // Every pixel of an interpolated block but those the terrain covers, or past the frame's
    // edge (90 rows end with a row of blocks 2 pixels tall).
    EXPECT_GE(static_cast<double>(drawn), 0.85 * 64.0 * static_cast<double>(interpolated)) << c.view.name;
    EXPECT_LE(drawn, 64u * interpolated) << c.view.name;
    EXPECT_LE(change.maxDiff, 1) << c.view.name;
    if (change.maxDiff > 1) test::savePng(r, std::string("globe_sea_lattice_") + c.view.name);
    // The radiance itself (an EXR's values): within the check's 2 % (its bound between a
    // block's corners and its other points; the lattice's own spacing is half that: up to
    // 0.6 % here, but 1.9 % over the Bahamas' banks).
    const test::OffAndOn radiance = test::renderOffAndOn(r, f, [&r](bool on) { r.setSeaLattice(on); });
    const test::RadianceChange relative = test::radianceChange(radiance.off, radiance.on, 0.02);
    std::printf("  radiance: %d pixels changed by over 2 %%, largest relative change %.2e\n", relative.over, relative.worst);
    EXPECT_EQ(relative.over, 0) << c.view.name << " (largest relative change " << relative.worst << ")";
  }
}

// With the constant wind (no wind layers) the globe's sea reads the wind, its direction's sine
// and cosine and the whole sea's slope and Jacobian variances from uniforms the CPU computed
// from the same tables (PATTERN_CONSTANT_WIND) instead of the one-cell wind texture and the
// tables per pixel: the same picture within float rounding, from orbit, the limb, and over the
// coasts (the water column's sea part) at 30 to 400 km. A wind layer keeps the per-pixel path.
TEST(GlobeRender, ConstantWindUniformsKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  std::vector<View> views{{"orbit-20000km", 10, -30, 2.0e7, 0, -90}, {"limb-400km-atlantic", 0, -30, 4.0e5, 90, -10}};
  views.insert(views.end(), kViews.begin(), kViews.end());
  for (const View& v : views) {
    render::FrameInput f = frameOf(v);
    f.wind.speedMs = 11.37;  // (between the tables' columns: their mixing is tested too)
    f.wind.towardsDeg = 60.0;
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.setConstantWindVariants(on); });
    EXPECT_TRUE(r.lastFrameConstantWind()) << v.name;
    // (Exact on llvmpipe; a GPU's compiler contracts each program's arithmetic its own way.)
    const double bound = gl::driverProfile().software ? 1e-4 : 2e-3;
    const test::RadianceChange change = test::radianceChange(images.off, images.on, bound);
    std::printf("%s: %d pixels changed by over %.0e, largest relative change %.2e\n", v.name, change.over, bound,
                change.worst);
    EXPECT_EQ(change.over, 0) << v.name << " (largest relative change " << change.worst << ")";
    if (change.over > 0) {
      test::savePictureAndChange(r, images.off, images.on, bound, std::string("globe_constant_wind_") + v.name);
    }
  }
}

// Where the land mask decides the coast the globe's four samples a pixel are classed by its
// fraction alone (GLOBE_MASK_COAST), without the layer's heights: constrainByLandFraction's
// height is above 0 exactly where the fraction is 0.5 or more but at 0.5 itself, so only
// samples within rounding of the contour may change (8 coast pixels at coast-30km, 1280 x 720).
// From orbit, the limb and the coasts at 30-400 km (land and sea parts, the coasts' samples).
TEST(GlobeRender, SamplesByTheMaskAloneKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  std::vector<View> views{{"orbit-20000km", 10, -30, 2.0e7, 0, -90}};
  views.insert(views.end(), kViews.begin(), kViews.end());
  for (const View& v : views) {
    const render::FrameInput f = frameOf(v);
    const test::OffAndOn images = test::renderOffAndOn(r, f, [&r](bool on) { r.setMaskCoastVariants(on); });
    const test::RadianceChange change = test::radianceChange(images.off, images.on, 0.02);
    std::printf("%s: %d pixels changed by over 2 %%, largest relative change %.2e\n", v.name, change.over, change.worst);
    EXPECT_LE(change.over, kWidth * kHeight / 2000) << v.name << " (largest relative change " << change.worst << ")";
    // (From orbit 0 pixels on llvmpipe; on the H200 28 single coast pixels scattered over
    // Europe and Africa, mean 1.5e-4: its arithmetic and filtering round otherwise at the contour.)
    const double meanBound = gl::driverProfile().software ? 1e-4 : 2.5e-4;
    EXPECT_LT(change.mean, meanBound) << v.name;
    if (change.over > kWidth * kHeight / 2000 || change.mean >= meanBound) {
      test::savePictureAndChange(r, images.off, images.on, 0.02, std::string("globe_mask_coast_") + v.name);
    }
  }
}

// From high up no pixel resolves the land mask's fine level (LandMaskTexture::fineLevelUnresolved)
// and the globe's and the terrain's programs leave its code out (LANDMASK_COARSE_ONLY): the same
// picture as with it (its weight is 0 at every pixel there), from orbit and from just above the
// threshold over coasts whose fine cells decide them from lower down. Lower, the frame keeps it.
TEST(GlobeRender, FineCoastLeftOutFromHighUpKeepsThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::array<View, 3> high{{{"orbit-20000km", 10, -30, 2.0e7, 0, -90},
                                  {"gibraltar-700km", 33.0, -5.5, 7.0e5, 0, -60},
                                  {"norway-1500km", 55.0, 5.0, 1.5e6, 20, -50}}};
  expectSamePicture(r, {high.begin(), high.end()}, [&r](bool on) { r.setCoarseMaskVariants(on); },
                    [&r] { return r.lastFrameCoarseMask(); }, "globe_coarse_mask_");
  for (const View& v : kViews) {  // 30-400 km
    r.render(frameOf(v));
    EXPECT_FALSE(r.lastFrameCoarseMask()) << v.name;
  }
}

// From high up every pixel's footprint spans two 2′ cells or more and the programs read only the
// land fraction's pyramid (LANDMASK_FILTERED_ONLY): the same picture as the programs that weigh
// the B-spline too (its weight is 0 at every pixel there), from orbit and from just above the
// threshold (~2900 km at 180 rows) over coasts and lakes. Lower, the frame keeps the B-spline.
TEST(GlobeRender, PyramidAloneFromHighUpKeepsThePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::array<View, 2> high{{{"orbit-20000km", 10, -30, 2.0e7, 0, -90},
                                  {"finland-3000km", 62.0, 26.0, 3.0e6, 0, -80}}};
  expectSamePicture(r, {high.begin(), high.end()}, [&r](bool on) { r.setFilteredMaskVariants(on); },
                    [&r] { return r.lastFrameFilteredMask(); }, "globe_filtered_mask_");
  r.render(frameOf(kHighViews[0]));  // Finland from 1500 km: the nearest pixels weigh the B-spline
  EXPECT_FALSE(r.lastFrameFilteredMask());
  EXPECT_TRUE(r.lastFrameFractionMips());
  // At sea level at 1280 x 720 no pixel can (at 320 x 180 the horizon's may, beyond which the
  // highest ground could stand): the programs leave the pyramid out (LANDMASK_PYRAMID).
  render::FrameInput sea = frameOf({"gibraltar-2m", 36.0, -5.6, 2.0, 200, 0});
  sea.width = 1280;
  sea.height = 720;
  r.render(sea);
  EXPECT_FALSE(r.lastFrameFractionMips());
}

// Lakes and islets under a pixel: with the B-spline of the 2′ cells they stand in a pixel at
// full strength wherever its centre falls on them, and a camera moved by half a pixel makes
// them blink; the pyramid's fraction fades them into their surroundings. Over Finland's lakes
// from 3000 km, two frames half a pixel apart differ in fewer pixels with the pyramid than
// without, and the blocks the CPU can class as land are many more.
TEST(GlobeRender, LakesUnderAPixelBlinkLessThroughThePyramid) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.setGlobeBlocks(true);  // (the land blocks counted below: llvmpipe's default)
  render::FrameInput a = frameOf({"finland-3000km", 62.0, 26.0, 3.0e6, 0, -90});
  const geo::CameraView view = geo::makeCameraView(a.camera, kWidth, kHeight);
  // Half a pixel of ground below the eye, eastwards.
  const double halfPixelM = 0.5 * 3.0e6 * 2.0 * std::tan(0.5 * view.verticalFovRad) / kHeight;
  render::FrameInput b = a;
  b.camera.position.longitudeDeg += halfPixelM / (geo::kWgs84SemiMajorM * std::cos(62.0 * 3.14159265358979 / 180.0)) * 180.0 / 3.14159265358979;
  std::array<double, 2> blink{}, land{};
  for (int on = 0; on < 2; ++on) {
    r.setFractionMipsOn(on == 1);
    r.render(a);
    EXPECT_EQ(r.lastFrameFractionMips(), on == 1);
    const io::ImageRgbaF first = r.radiance();
    r.render(b);
    const io::ImageRgbaF second = r.radiance();
    blink[static_cast<std::size_t>(on)] = test::radianceChange(first, second, 0.25).over;
    const auto& counts = r.globeBlockCounts();
    land[static_cast<std::size_t>(on)] = counts[static_cast<std::size_t>(render::GlobeBlockClass::Land)];
  }
  std::printf("pixels changed by over 25 %%: %g with the B-spline, %g with the pyramid; land blocks %g, %g\n", blink[0],
              blink[1], land[0], land[1]);
  // (1444 and 1057 pixels: the imagery's own half-pixel shift stays in both.)
  EXPECT_LT(blink[1], 0.8 * blink[0]);
  EXPECT_GT(land[1], 2.0 * land[0]);  // blocks of land the lakes had made mixed (66 and 260)
}

// Below the grid's ceiling, from ~7 km up, the terrain's coast test reads the pyramid too: in
// its coverage pass (the discards alone) as in the one-pass draw. The same picture both ways
// over Spain's coast from 18 km and the Aegean's islands from 15 km, whose far coasts' pixels
// span 2′ cells at 320 x 180: within 1 % (the two draws' shading differs by up to 1e-3 at a few
// pixels); the coverage pass with the B-spline's coast put 4 and 10 pixels 8-18 % off.
TEST(GlobeRender, TerrainCoveragePassTakesThePyramidsCoast) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  const std::vector<View> views{{"spain-east-18km", 36.5, -5.0, 1.8e4, 70, -2},
                                {"aegean-15km", 37.0, 24.0, 1.5e4, 0, -3}};
  expectSamePicture(r, views, [&r](bool on) { r.terrain().setCoveragePass(on); },
                    [&r] { return r.lastFrameFractionMips(); }, "terrain_coverage_pyramid_", 1e-2);
}
