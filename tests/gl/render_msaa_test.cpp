// GL tier: multisampling of the HDR target. A ridge seen against the sky from below its top:
// with 4 samples the silhouette's pixels are partly covered (alpha and colour between sky
// and ground), with 1 sample they step from sky to ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "data/LatLonGrid.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "gl/DriverProfile.hpp"
#include "gl/Readback.hpp"
#include "gl/Shader.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/GridFixtures.hpp"
#include "support/ImageCompare.hpp"

using namespace og;

namespace {

// Global 0.25° layer: lowland at 300 m and a 5000 m ridge along 0.375° N from 2° W to 2° E
// (one row of cells: a crest, jagged by the procedural detail).
data::LatLonGrid ridge() {
  return test::globalGrid("ridge", 0.25, [](double lat, double lon) {
    return lat > 0.3 && lat < 0.45 && std::abs(lon) < 2.0 ? 5000.0 : 300.0;
  });
}

// Looking north at the crest from 2500 m, 30 km south of it; the Sun low behind it and off
// to the side, so the face towards the camera is dark against a bright sky.
render::FrameInput ridgeView(int samples) {
  render::FrameInput f;
  f.camera.position = {0.1, 0.0, 2500.0};
  f.camera.headingDeg = 0.0;
  f.camera.pitchDeg = 4.0;
  f.camera.rollDeg = 5.0;  // the skyline crosses the pixel rows: a staircase without AA
  f.camera.verticalFovDeg = 30.0;
  f.width = 192;
  f.height = 128;
  f.samples = samples;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 8.0, 40.0);
  return f;
}

struct Silhouette {
  int columns = 0;           ///< columns with sky above ground
  int partlyCovered = 0;     ///< of which the first non-sky pixel has coverage in (0, 1)
  int contrasted = 0;        ///< columns where sky and ground differ enough on screen
  int blendedOnScreen = 0;   ///< of which the silhouette pixel lies strictly between them
};

double luminance(const io::ImageRgba8& img, int x, int y) {
  const std::uint8_t* p = &img.pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) +
                                           static_cast<std::size_t>(x))];
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// Per column, top down: the first pixel with any coverage (alpha, linear resolve) is the
// silhouette; compared with the last sky pixel above it and the first fully covered below.
Silhouette measure(const io::ImageRgbaF& radiance, const io::ImageRgba8& display) {
  const int w = radiance.width, h = radiance.height;
  auto alpha = [&](int x, int y) {
    return radiance.pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                                static_cast<std::size_t>(x)) + 3];
  };
  Silhouette s;
  for (int x = 0; x < w; ++x) {
    int y = 0;
    while (y < h && alpha(x, y) <= 0.01f) ++y;
    if (y == 0 || y >= h - 6) continue;
    int ground = y;
    while (ground < y + 3 && alpha(x, ground) < 0.99f) ++ground;
    if (alpha(x, ground) < 0.99f) continue;
    ++s.columns;
    if (alpha(x, y) < 0.99f) ++s.partlyCovered;
    // The ground's value nearest the sky's among its first rows (the crest itself is hazier
    // than the face below it): an edge pixel must lie beyond it, not just inside a gradient.
    const double sky = luminance(display, x, y - 1), edge = luminance(display, x, y);
    double below = luminance(display, x, ground);
    for (int r = ground + 1; r <= ground + 2; ++r)
      if (std::abs(sky - luminance(display, x, r)) < std::abs(sky - below)) below = luminance(display, x, r);
    const double step = std::abs(sky - below);
    if (step < 20.0) continue;
    ++s.contrasted;
    const double lo = std::min(sky, below) + 0.1 * step, hi = std::max(sky, below) - 0.1 * step;
    if (edge > lo && edge < hi) ++s.blendedOnScreen;
  }
  return s;
}

}  // namespace

TEST(Multisampling, SilhouetteAgainstTheSkyIsBlendedWithFourSamples) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(ridge());
  Silhouette s[2];
  io::ImageRgba8 images[2];
  const int counts[2] = {1, 4};
  for (int k = 0; k < 2; ++k) {
    r.render(ridgeView(counts[k]));
    ASSERT_EQ(r.samples(), counts[k]) << "this GL device offers fewer samples";
    images[k] = r.display();
    io::writePng(std::string(OG_TEST_OUT_DIR) + "/msaa_ridge_" + std::to_string(counts[k]) + ".png",
                 images[k]);
    s[k] = measure(r.radiance(), images[k]);
    std::printf("%d sample(s): %d silhouette columns, %d partly covered; %d with contrast, %d "
                "blended on screen\n",
                counts[k], s[k].columns, s[k].partlyCovered, s[k].contrasted, s[k].blendedOnScreen);
  }
  const int w = images[0].width;
  // Both views must find the skyline across (nearly) the whole image.
  for (const Silhouette& x : s) {
    ASSERT_GE(x.columns, w * 9 / 10);
    ASSERT_GE(x.contrasted, w / 2);
  }
  // One sample: coverage is all or nothing, the colour steps from sky to ground.
  EXPECT_LE(s[0].partlyCovered, w / 20);
  EXPECT_LE(s[0].blendedOnScreen, s[0].contrasted / 10);
  // Four samples: most silhouette pixels are partly covered (an edge misses all four only
  // within a quarter of a pixel of the pixel's border), in the linear resolve and on screen.
  EXPECT_GE(s[1].partlyCovered, s[1].columns / 2);
  EXPECT_GE(s[1].blendedOnScreen, s[1].contrasted / 2);
}

namespace {

// Whether the ground seen in pixel (x, y) lies within a pixel of a geometric edge: where the
// ground hides farther ground, or folds. On a plane the inverse view distance is affine in
// screen space, so its second difference across the pixel, relative to its value, is ~0; over
// 1 % there is an edge (a step of a few hundred metres at 20-30 km, a fold) inside the pixel,
// which the 4 samples resolve and 1 sample steps over. `distance`: viewDistance() of a frame.
bool nearGeometricEdge(const std::vector<float>& distance, int w, int h, int x, int y) {
  auto inv = [&](int px, int py) { return 1.0 / double{distance[static_cast<std::size_t>(py * w + px)]}; };
  for (int py = std::max(1, y - 1); py <= std::min(h - 2, y + 1); ++py)
    for (int px = std::max(1, x - 1); px <= std::min(w - 2, x + 1); ++px) {
      const double c = inv(px, py);
      const double kink = std::max(std::abs(inv(px - 1, py) - 2.0 * c + inv(px + 1, py)),
                                   std::abs(inv(px, py - 1) - 2.0 * c + inv(px, py + 1)));
      if (kink > 0.01 * c) return true;
    }
  return false;
}

// The images and their difference (x16) as PNGs, to look at.
void writeInteriorImages(const io::ImageRgba8& one, const io::ImageRgba8& four) {
  io::ImageRgba8 diff = one;
  for (std::size_t i = 0; i < diff.pixels.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c)
      diff.pixels[i + c] = static_cast<std::uint8_t>(
          std::min(255, 16 * std::abs(int(one.pixels[i + c]) - int(four.pixels[i + c]))));
  const std::string prefix = std::string(OG_TEST_OUT_DIR) + "/msaa_interior_";
  io::writePng(prefix + "1.png", one);
  io::writePng(prefix + "4.png", four);
  io::writePng(prefix + "diff_x16.png", diff);
}

}  // namespace

// The extra samples change edges only: away from them both images agree, and sky pixels
// (one value in every sample) are identical after the per-sample tone mapping. Edges are the
// sky's and the ground's own (a nearer slope over a farther one, a fold): with the calibrated
// relief detail (docs/terrain.md) the distant ridge is full of them. Measured: of 11352
// interior ground pixels 493 differ by > 2 levels, 426 of them within a pixel of a geometric
// edge; elsewhere 66-67 of 9142 (0.7 %; 50 without the per-pixel detail, 93 with its crests
// point-sampled, 1050 with its octaves unfaded, i.e. aliasing).
TEST(Multisampling, InteriorsMatchOneSampleAndDepthReadsBack) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(ridge());
  r.render(ridgeView(1));
  const io::ImageRgba8 one = r.display();
  const io::ImageRgbaF oneRadiance = r.radiance();
  const std::vector<float> oneDistance = r.viewDistance();
  r.render(ridgeView(4));
  const io::ImageRgba8 four = r.display();
  const io::ImageRgbaF fourRadiance = r.radiance();
  const std::vector<float> depth = r.depth();
  const int w = one.width, h = one.height;
  ASSERT_EQ(depth.size(), static_cast<std::size_t>(w * h));

  auto alphaAt = [&](const io::ImageRgbaF& img, int x, int y) {
    return img.pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                           static_cast<std::size_t>(x)) + 3];
  };
  int sky = 0, ground = 0, skyDiffer = 0, groundOver2 = 0, smooth = 0, smoothOver2 = 0;
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      // Interior: the 3x3 neighbourhood wholly sky or wholly covered in both renders.
      float lo = 1.0f, hi = 0.0f;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          for (const io::ImageRgbaF* img : {&oneRadiance, &fourRadiance}) {
            lo = std::min(lo, alphaAt(*img, x + dx, y + dy));
            hi = std::max(hi, alphaAt(*img, x + dx, y + dy));
          }
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                            static_cast<std::size_t>(x);
      int diff = 0;
      for (std::size_t c = 0; c < 3; ++c)
        diff = std::max(diff, std::abs(int(one.pixels[4 * i + c]) - int(four.pixels[4 * i + c])));
      if (hi == 0.0f) {
        ++sky;
        skyDiffer += diff > 0 ? 1 : 0;
        EXPECT_EQ(depth[i], 0.0f) << x << "," << y;
      } else if (lo == 1.0f) {
        ++ground;
        EXPECT_GT(depth[i], 0.0f) << x << "," << y;
        groundOver2 += diff > 2 ? 1 : 0;
        if (nearGeometricEdge(oneDistance, w, h, x, y)) continue;
        ++smooth;
        smoothOver2 += diff > 2 ? 1 : 0;
      }
    }
  std::printf("interior ground %d (%d differ by > 2 levels), away from its edges %d (%d differ)\n", ground,
              groundOver2, smooth, smoothOver2);
  if (smoothOver2 > smooth / 100) writeInteriorImages(one, four);
  ASSERT_GT(sky, w * h / 10);
  ASSERT_GT(ground, w * h / 10);
  ASSERT_GT(smooth, ground * 3 / 4) << "the edge test should leave most of the ground";
  EXPECT_EQ(skyDiffer, 0);
  // Away from edges, triangle edges between tiles and skirts may still shift a little; the
  // detail, filtered to the pixel, must not (aliasing detail fails this by ten times).
  EXPECT_LE(smoothOver2, smooth / 100) << smoothOver2 << " of " << smooth;
}

// From orbit the globe's sea hides the bathymetry. With 4 samples llvmpipe's per-sample depth
// could not tell a sea floor kilometres down from the surface 20 000 km away, and whole tiles
// of sea floor showed through in lighter blocks; the terrain now leaves sub-sea fragments to
// the globe from up there. The open sea must look the same with 1 and 4 samples.
TEST(Multisampling, OrbitSeaIsTheSameWithFourSamples) {
  auto ctx = gl::createHeadlessContext();
  // Sea 4000 m deep with one land block (so that its tiles, partly sea, are drawn).
  const data::LatLonGrid g = test::globalGrid("sea", 5.0, [](double lat, double lon) {
    return lat > 20.0 && lat < 25.0 && lon > 20.0 && lon < 25.0 ? 800.0 : -4000.0;
  });
  render::GlobeRenderer r(g);
  render::FrameInput f;
  f.camera.position = {20.0, 15.0, 2.0e7};
  f.camera.pitchDeg = -90.0;
  f.width = 96;
  f.height = 96;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 60.0, 180.0);
  f.samples = 1;
  r.render(f);
  const io::ImageRgba8 one = r.display();
  f.samples = 4;
  r.render(f);
  const io::ImageRgba8 four = r.display();
  int sea = 0, differ = 0;
  for (int y = 30; y < 66; ++y)
    for (int x = 30; x < 66; ++x) {
      const std::size_t i = 4 * (static_cast<std::size_t>(y) * 96 + static_cast<std::size_t>(x));
      // Skip the land block and its edges: where the 1-sample image is not sea-blue.
      if (one.pixels[i + 2] <= one.pixels[i]) continue;
      ++sea;
      int diff = 0;
      for (std::size_t c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(one.pixels[i + c]) - int(four.pixels[i + c])));
      differ += diff > 3 ? 1 : 0;
    }
  ASSERT_GT(sea, 600);
  EXPECT_LE(differ, sea / 50) << differ << " of " << sea << " sea pixels differ";
}

TEST(Multisampling, UnavailableCountsAreClampedAndInvalidOnesRefused) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(ridge());
  render::FrameInput f = ridgeView(8);
  f.width = 32;
  f.height = 16;
  r.render(f);  // 8 may exceed the device's limit: clamped with a warning, never an error
  EXPECT_GE(r.samples(), 1);
  EXPECT_LE(r.samples(), 8);
  EXPECT_EQ(r.radiance().pixels.size(), 4u * 32u * 16u);
  f.samples = 3;
  EXPECT_THROW(r.render(f), InternalError);
}

// The display resolve tone-maps each sample, then averages: an edge between a very bright and
// a dark surface gets intermediate pixels. Averaging the linear radiance first would saturate
// every partly bright pixel to white (the second render below shows it).
TEST(Multisampling, ToneMappingIsPerSampleBeforeAveraging) {
  auto ctx = gl::createHeadlessContext();
  constexpr int kSize = 32;
  gl::RenderTarget hdr = gl::createRenderTarget(kSize, kSize, GL_RGBA32F, true, 4);
  ASSERT_EQ(hdr.samples, 4);
  gl::RenderTarget linear = gl::createRenderTarget(kSize, kSize, GL_RGBA32F, true);
  // The display target as GlobeRenderer has it: sRGB bytes the store encodes, read through a view.
  gl::RenderTarget ldr = gl::createRenderTarget(kSize, kSize, GL_SRGB8_ALPHA8, false);
  const gl::RenderTarget ldrBytes = gl::createViewTarget(ldr, GL_RGBA8);
  gl::Program solid({{GL_VERTEX_SHADER, "render/solid.vert"}, {GL_FRAGMENT_SHADER, "render/solid.frag"}});
  gl::Program perSample({{GL_VERTEX_SHADER, "render/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "render/tonemap.frag"}},
                        {"TONEMAP_MULTISAMPLE"});
  gl::Program single({{GL_VERTEX_SHADER, "render/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "render/tonemap.frag"}});
  gl::VertexArray vao = gl::createVertexArray();
  glBindVertexArray(vao.id());
  glViewport(0, 0, kSize, kSize);
  glDisable(GL_DEPTH_TEST);

  // Dark ground, then a bright triangle whose long edge crosses the image at a slant.
  const float dark[] = {0.0005f, 0.0005f, 0.0005f, 1.0f};
  glClearNamedFramebufferfv(hdr.fbo.id(), GL_COLOR, 0, dark);
  glBindFramebuffer(GL_FRAMEBUFFER, hdr.fbo.id());
  // solid.vert's triangle at distance 0.5 spans (-1,-1), (3,-1), (-1,3); squeeze and shift it.
  glm::mat4 m(1.0f);
  m[0][0] = 0.7f;
  m[3] = glm::vec4(-0.55f, -0.8f, 0.0f, 1.0f);
  m[2][2] = 0.0f;
  solid.set("uViewProjection", m);
  solid.set("uDistance", 0.5f);
  solid.set("uColor", glm::vec4(50.0f, 50.0f, 50.0f, 1.0f));
  solid.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);

  auto intermediate = [&](GLuint texture, const gl::Program& tonemap) {
    glBindFramebuffer(GL_FRAMEBUFFER, ldr.fbo.id());
    tonemap.set("uExposure", 10.0f);
    glBindTextureUnit(0, texture);
    tonemap.use();
    glEnable(GL_FRAMEBUFFER_SRGB);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_FRAMEBUFFER_SRGB);
    const std::vector<std::uint8_t> px = gl::readRgba8(ldrBytes.fbo.id(), kSize, kSize);
    int n = 0, bright = 0;
    for (std::size_t i = 0; i < px.size(); i += 4) {
      n += px[i] > 40 && px[i] < 240 ? 1 : 0;
      bright += px[i] >= 240 ? 1 : 0;
    }
    EXPECT_GT(bright, kSize * kSize / 4);
    return n;
  };
  const int perSampleEdge = intermediate(hdr.color.id(), perSample);
  glBlitNamedFramebuffer(hdr.fbo.id(), linear.fbo.id(), 0, 0, kSize, kSize, 0, 0, kSize, kSize,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  const int linearEdge = intermediate(linear.color.id(), single);
  gl::checkErrors("tone mapping test");
  std::printf("edge pixels between dark and white: %d per sample, %d linear resolve\n", perSampleEdge, linearEdge);
  // The edge crosses ~32 pixel columns; three in four of its pixels are partly covered.
  EXPECT_GE(perSampleEdge, kSize / 2);
  EXPECT_LE(linearEdge, 2);
}

namespace {
// A 160 x 90 view with 4 samples a pixel from (lat, lon, height), the Sun 20° up in the
// west-south-west.
render::FrameInput multisampledView(double lat, double lon, double heightM, double headingDeg, double pitchDeg) {
  render::FrameInput f;
  f.camera.position = {lat, lon, heightM};
  f.camera.headingDeg = headingDeg;
  f.camera.pitchDeg = pitchDeg;
  f.width = 160;
  f.height = 90;
  f.samples = 4;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 20.0, 250.0);
  return f;
}
}  // namespace

// Below 20 km with several samples a pixel each of the globe's parts is drawn only where an
// occlusion query of a lean draw found samples of it (GlobeRenderer::drawPartGated): llvmpipe's
// early tests skip no block of a multisampled draw, so a part without samples shaded the whole
// screen (sea-4m at 640x360, 4 samples: 250 -> 74 ms, the edge's and the surface's empty parts
// 88 and 78 ms). The same pictures with the gate and without, bit for bit: the sea from 4 m and
// the Strait of Gibraltar from 2 m (the globe's sky only: its edge and surface parts gated
// out), and the sea straight down from 1 km (no part left). A gate that let every part
// through, or none, fails the counts (the time a skipped draw saves is bench's to show).
TEST(Multisampling, GlobePartsWithoutSamplesAreNotDrawn) {
  auto ctx = gl::createHeadlessContext();
  struct Case {
    std::string name;
    data::LatLonGrid grid;
    render::FrameInput frame;
    int minDrawn, minSkipped;  // parts the gate lets through, parts it leaves out
  };
  const data::LatLonGrid& relief = data::defaultElevation();
  const std::vector<Case> cases{{"sea_4m", relief, multisampledView(20.0, -40.0, 4.0, 270.0, -10.0), 1, 2},
                                {"gibraltar_2m", relief, multisampledView(36.0, -5.5, 2.0, 270.0, 2.0), 1, 2},
                                {"sea_1km_down", relief, multisampledView(20.0, -40.0, 1000.0, 0.0, -90.0), 0, 3}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    render::GlobeRenderer r(c.grid);
    r.setPartGate(false);
    r.render(c.frame);
    const io::ImageRgba8 ungated = r.display();
    r.setPartGate(true);
    r.setRecordPartGate(true);
    r.render(c.frame);
    const io::ImageRgba8 gated = r.display();
    const std::vector<bool>& parts = r.partsGated();
    const auto drawn = static_cast<int>(std::count(parts.begin(), parts.end(), true));
    const int skipped = static_cast<int>(parts.size()) - drawn;
    std::printf("%s: %d parts drawn, %d left out\n", c.name.c_str(), drawn, skipped);
    EXPECT_GE(drawn, c.minDrawn);
    EXPECT_GE(skipped, c.minSkipped);
    ASSERT_EQ(gated.pixels.size(), ungated.pixels.size());
    std::size_t differ = 0;
    for (std::size_t k = 0; k < gated.pixels.size(); ++k) differ += gated.pixels[k] != ungated.pixels[k] ? 1 : 0;
    EXPECT_EQ(differ, 0u) << "channels differ";
  }
}

// With several samples a pixel each of the globe's parts is drawn over the blocks of pixels that
// may hold it instead of a triangle over the frame, which llvmpipe shaded whole for a few edge
// pixels: above 20 km GlobeRenderer::drawPartOverBlocks (the per-pixel blocks, the sky's and
// the fills of its stencil count; limb-400km at 1280x720, 4 samples: 876 -> 196 ms), below it
// the edge's and the surface's parts over the blocks the grid and the terrain left
// (render/UncoveredPixels; sea-1km 1669 -> 472 ms of one thread). The same pictures either
// way, from orbit, over the limb from 400 km, over the Strait of Gibraltar from 30 km and 2 m,
// over the sea from 1 km (its edge's part holds the grid's horizon gaps) and 4 m: the parts'
// rays come from vNdc interpolated over other triangles, an ulp apart; at most 1 level
// (measured: 1 at orbit, else identical). Mutations: the sky's blocks left out, 129 levels at
// the limb; the fills', 102 and 142; below 20 km no block drawn, 216 at 1 km.
TEST(Multisampling, GlobePartsOverTheirBlocksDrawTheSamePicture) {
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(data::defaultElevation());
  r.setRecordPartGate(true);
  r.setPartGate(true);  // (on by default on software renderers only: sea_1km's check reads its record)
  for (const auto& [name, f] : {std::pair{"orbit", multisampledView(20.0, -40.0, 2.0e7, 0.0, -90.0)},
                                std::pair{"limb_400km", multisampledView(38.0, -12.0, 4.0e5, 90.0, -15.0)},
                                std::pair{"gibraltar_30km", multisampledView(35.5, -6.5, 3.0e4, 60.0, -30.0)},
                                std::pair{"sea_1km", multisampledView(20.0, -40.0, 1000.0, 270.0, -20.0)},
                                std::pair{"sea_4m", multisampledView(20.0, -40.0, 4.0, 270.0, -10.0)},
                                std::pair{"gibraltar_2m", multisampledView(36.0, -5.5, 2.0, 270.0, 2.0)}}) {
    SCOPED_TRACE(name);
    r.setPartsOverBlocks(false);
    r.render(f);
    const io::ImageRgba8 whole = r.display();
    r.setPartsOverBlocks(true);
    r.render(f);
    const io::ImageRgba8 blocks = r.display();
    ASSERT_GT(r.samples(), 1);
    if (f.camera.position.heightM > 2.0e4 && gl::driverProfile().software) {  // (blocks: software renderers)
      const auto& n = r.globeBlockCounts();
      EXPECT_GT(n[static_cast<std::size_t>(render::GlobeBlockClass::PerPixel)], 0) << "no blocks drawn over";
    }
    if (std::string(name) == "sea_1km") {  // below 20 km: the edge's part over the grid's gaps
      ASSERT_EQ(r.partsGated().size(), 3u);
      EXPECT_TRUE(r.partsGated()[1]) << "no edge: the blocks' draw below 20 km is not tested";
    }
    ASSERT_EQ(blocks.pixels.size(), whole.pixels.size());
    int maxDiff = 0;
    for (std::size_t k = 0; k < blocks.pixels.size(); ++k)
      maxDiff = std::max(maxDiff, std::abs(int(blocks.pixels[k]) - int(whole.pixels[k])));
    std::printf("%s: at most %d levels apart\n", name, maxDiff);
    EXPECT_LE(maxDiff, 1);
  }
}

// A viewer's window is resized and its sample count may change between frames of one renderer:
// every target made for one size or count (the HDR target, the sea's surface and visibility
// buffers, the radiance image of multisampled frames, the grid) must be remade for the next,
// and nothing of a former frame's may show. One renderer through 320 x 180 with 1 sample,
// 256 x 144 with 4, 320 x 180 with 4, 192 x 108 with 1 and 320 x 180 with 1 again, each frame
// against a renderer that only ever drew at that size and count, over the open sea from 4 m
// (its sea deferred through a visibility buffer on llvmpipe, at 1 and at 4 samples) and the
// Strait of Gibraltar from 2 m (the sea in classes: coast, open sea, the far coasts). Measured:
// the same bytes. Mutated, the visibility buffer kept at its former size when only the size
// changes: 65-67 % of the open sea's pixels off, by up to 255 levels (38 % at the coast).
TEST(Multisampling, SizesAndSampleCountsChangingBetweenFramesKeepThePicture) {
  auto ctx = gl::createHeadlessContext();
  struct Setting {
    int width, height, samples;
  };
  const std::vector<Setting> settings{{320, 180, 1}, {256, 144, 4}, {320, 180, 4}, {192, 108, 1}, {320, 180, 1}};
  const auto frame = [](const Setting& s, bool coast) {
    render::FrameInput f;
    f.camera.position = coast ? geo::Geodetic{36.0, -5.5, 2.0} : geo::Geodetic{20.0, -40.0, 4.0};
    f.camera.headingDeg = 270.0;
    f.camera.pitchDeg = coast ? 2.0 : -10.0;
    f.camera.verticalFovDeg = 45.0;
    f.width = s.width;
    f.height = s.height;
    f.samples = s.samples;
    f.simulationTimeS = 3.0;
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 20.0, 250.0);
    return f;
  };
  render::GlobeRenderer changing(data::defaultElevation());
  for (std::size_t k = 0; k < settings.size(); ++k) {
    const Setting& s = settings[k];
    render::GlobeRenderer fixed(data::defaultElevation());
    for (const bool coast : {false, true}) {
      const render::FrameInput f = frame(s, coast);
      fixed.render(f);
      changing.render(f);
      const io::ImageRgba8 expected = fixed.display(), actual = changing.display();
      if (!coast && gl::driverProfile().seaByVisibility) {
        EXPECT_TRUE(changing.ocean().lastSurfaceByVisibility()) << k;
      }
      ASSERT_EQ(actual.width, s.width);
      ASSERT_EQ(actual.height, s.height);
      const test::Comparison c = test::compareRgb(actual, expected, 1);
      const std::string name = std::to_string(k) + "_" + std::to_string(s.width) + "x" + std::to_string(s.height) + "_" +
                               std::to_string(s.samples) + (coast ? "_coast" : "_open");
      std::printf("%s: %s\n", name.c_str(), c.describe().c_str());
      if (!c.within({1, 0.01, 1, 0.0})) {
        io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / ("size_change_" + name + ".png"), actual);
        io::writePng(std::filesystem::path(OG_TEST_OUT_DIR) / ("size_change_" + name + ".diff.png"), c.diff);
      }
      EXPECT_TRUE(c.within({1, 0.01, 1, 0.0})) << name << ": " << c.describe();
    }
  }
}
