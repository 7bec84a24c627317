// The globe's open deep sea (render/OpenSeaMap, globe.frag's open-sea part): the coarse map
// never lets a pixel that could see land or a shallow floor into the part without the land's
// code, and the part paints what the surface part would have.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "data/Elevation.hpp"
#include "data/LandMask.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "gl/DriverProfile.hpp"
#include "render/GlobeRenderer.hpp"
#include "render/OpenSeaMap.hpp"
#include "support/GridFixtures.hpp"

using namespace og;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMinDepthM = 200.0;

// 2° cells: an island at 1000 m around (10° N, 30° W), a shelf 50 m deep around it, and a
// continent east of 60° E; the ocean 4000 m deep elsewhere.
data::LatLonGrid islandWorld() {
  return test::globalGrid("islands", 2.0, [](double lat, double lon) {
    const double d = std::hypot(lat - 10.0, lon + 30.0);
    if (d < 3.0) return 1000.0;
    if (d < 8.0) return -50.0;
    return lon > 60.0 ? 500.0 : -4000.0;
  });
}

// A point `angle` radians from (lat, lon) degrees in direction `bearing` radians (great circle).
std::pair<double, double> moved(double latDeg, double lonDeg, double angle, double bearing) {
  const double lat = latDeg * kDeg, lon = lonDeg * kDeg;
  const double lat2 = std::asin(std::sin(lat) * std::cos(angle) + std::cos(lat) * std::sin(angle) * std::cos(bearing));
  const double lon2 = lon + std::atan2(std::sin(bearing) * std::sin(angle) * std::cos(lat),
                                       std::cos(angle) - std::sin(lat) * std::sin(lat2));
  return {lat2 / kDeg, std::remainder(lon2 / kDeg, 360.0)};
}

constexpr double kCell = render::OpenSeaMap::kCellDeg;

// The map's index of the cell holding (lat, lon) degrees.
std::size_t cellAt(double latDeg, double lonDeg) {
  const auto row = static_cast<std::size_t>(std::floor((latDeg + 90.0) / kCell));
  const auto col = static_cast<std::size_t>(std::floor((lonDeg + 180.0) / kCell));
  return row * render::OpenSeaMap::kWidth + col;
}

// Every point within a cell's clearance of random points of that cell passes `isOpen`, for a
// random seventh of the cells with a clearance (all of them: 25 M lookups); and the map is not
// empty (at least `minOpenDeg2` square degrees of cells with a clearance).
template <class IsOpen>
void expectClearanceHolds(const render::OpenSeaMap& map, IsOpen&& isOpen, double minOpenDeg2) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int open = 0, bad = 0;
  for (int row = 0; row < render::OpenSeaMap::kHeight; ++row)
    for (int col = 0; col < render::OpenSeaMap::kWidth; ++col) {
      const double c = map.clearanceRad[static_cast<std::size_t>(row) * render::OpenSeaMap::kWidth + static_cast<std::size_t>(col)];
      if (c <= 0.0) continue;
      ++open;
      if (rng() % 7 != 0) continue;
      for (int k = 0; k < 6; ++k) {
        const double lat = -90.0 + (row + unit(rng)) * kCell, lon = -180.0 + (col + unit(rng)) * kCell;
        // Out to the clearance's edge, in any direction.
        const auto [qLat, qLon] = moved(lat, lon, c * (k < 3 ? 1.0 : unit(rng)), 2.0 * std::numbers::pi * unit(rng));
        if (!isOpen(qLat, qLon)) {
          if (++bad <= 5) ADD_FAILURE() << "cell (" << row << ", " << col << ") clearance " << c / kDeg << "°: (" << qLat << ", " << qLon << ") is not open sea";
        }
      }
    }
  EXPECT_EQ(bad, 0);
  EXPECT_GE(open * kCell * kCell, minOpenDeg2);
}
}  // namespace

TEST(OpenSeaMap, ClearanceHoldsNoLandNoShallowFloor) {
  const data::LatLonGrid layer = islandWorld();
  const render::OpenSeaMap map = render::makeOpenSeaMap(render::blockedByLayer(layer, kMinDepthM));
  expectClearanceHolds(map, [&](double lat, double lon) { return static_cast<double>(layer.sample(lat, lon)) <= -kMinDepthM; },
                       20000);
  // The island and its shelf are blocked, and the sea 20° west of it is open by more than 5°.
  EXPECT_EQ(map.blocked[cellAt(10.5, -29.5)], 1);
  EXPECT_EQ(map.blocked[cellAt(10.5, -24.5)], 1);  // on the shelf
  EXPECT_GT(map.clearanceRad[cellAt(10.5, -59.5)], 5.0 * kDeg);
}

TEST(OpenSeaMap, ClearanceHoldsAgainstTheLandMask) {
  // A layer all deep: only the GSHHG mask blocks. Every point within a clearance has a land
  // fraction of 0 (so elevationAt keeps the layer's depth there), and the open ocean is open.
  const data::LatLonGrid deep = test::globalGrid("deep", 2.0, [](double, double) { return -4000.0; });
  std::vector<unsigned char> blocked = render::blockedByLayer(deep, kMinDepthM);
  const data::LandMask& mask = data::defaultLandMask();
  render::addBlockedByMask(mask, blocked);
  const render::OpenSeaMap map = render::makeOpenSeaMap(std::move(blocked));
  expectClearanceHolds(map, [&](double lat, double lon) { return mask.landFraction(lat, lon) == 0.0f; }, 20000);
  EXPECT_EQ(map.blocked[cellAt(51.5, -0.1)], 1);  // London
  EXPECT_GT(map.clearanceRad[cellAt(0.5, -139.5)], 5.0 * kDeg);
}

// The land clearance (the projected grid's sea classes): around land alone, the mask's fine
// cells included, so that no islet or spit only the 15" level holds is ever within a cell's
// radius (the coast test keeps the sea off it there). Some cells are blocked for such land
// alone.
TEST(OpenSeaMap, LandClearanceHoldsAgainstTheMasksFineCells) {
  const data::LandMask& mask = data::defaultLandMask();
  ASSERT_TRUE(mask.hasFineLevel());
  std::vector<unsigned char> coarse(static_cast<std::size_t>(render::OpenSeaMap::kWidth) * render::OpenSeaMap::kHeight, 0);
  std::vector<unsigned char> fine = coarse;
  render::addBlockedByMask(mask, coarse);
  render::addBlockedByMask(mask, fine, true);
  int fineOnly = 0;
  for (std::size_t i = 0; i < fine.size(); ++i) {
    EXPECT_TRUE(fine[i] || !coarse[i]) << i;
    fineOnly += fine[i] && !coarse[i] ? 1 : 0;
  }
  EXPECT_GT(fineOnly, 0) << "no cell blocked for its fine land alone";
  const render::OpenSeaMap map = render::makeOpenSeaMap(std::move(fine));
  expectClearanceHolds(map, [&](double lat, double lon) { return mask.landFraction(lat, lon, 0.0) == 0.0f; }, 20000);
}

// The two-pass chessboard distances (render::chessboardDistances) against their definition
// taken the long way: per row the distance along it (wrapping), then the smallest over the
// rows within the cap of the larger of that and the rows between. Scattered cells, a band
// across the antimeridian, cells at both poles.
TEST(OpenSeaMap, ChessboardDistancesMatchTheirDefinition) {
  constexpr int kW = render::OpenSeaMap::kWidth, kH = render::OpenSeaMap::kHeight, kCap = 9;
  std::vector<unsigned char> blocked(static_cast<std::size_t>(kW) * kH, 0);
  std::mt19937 rng(11);
  for (int k = 0; k < 20000; ++k) blocked[rng() % blocked.size()] = 1;
  for (int r = 700; r < 720; ++r) blocked[static_cast<std::size_t>(r) * kW + kW - 1] = 1;  // at the seam
  blocked[5] = blocked[blocked.size() - 9] = 1;
  const std::vector<std::uint8_t> d = render::chessboardDistances(blocked, kCap);
  std::vector<int> along(blocked.size(), kCap);
  for (int r = 0; r < kH; ++r)
    for (int c = 0; c < kW; ++c)
      for (int dc = 0; dc <= kCap; ++dc)
        if (blocked[static_cast<std::size_t>(r) * kW + static_cast<std::size_t>((c + dc) % kW)] ||
            blocked[static_cast<std::size_t>(r) * kW + static_cast<std::size_t>((c - dc + kW) % kW)]) {
          along[static_cast<std::size_t>(r) * kW + static_cast<std::size_t>(c)] = dc;
          break;
        }
  int bad = 0, atCap = 0;
  for (int r = 0; r < kH; ++r)
    for (int c = 0; c < kW; ++c) {
      int expected = kCap;
      for (int rr = std::max(0, r - kCap); rr <= std::min(kH - 1, r + kCap); ++rr)
        expected = std::min(expected, std::max(along[static_cast<std::size_t>(rr) * kW + static_cast<std::size_t>(c)], std::abs(rr - r)));
      const int got = d[static_cast<std::size_t>(r) * kW + static_cast<std::size_t>(c)];
      atCap += expected == kCap ? 1 : 0;
      if (got != expected && ++bad <= 5) ADD_FAILURE() << "cell (" << r << ", " << c << "): " << got << ", expected " << expected;
    }
  EXPECT_EQ(bad, 0);
  EXPECT_GT(atCap, 1000);  // the cap is reached too
  // The renderer's cap (kMaxRings + 1, near a byte's end): one cell blocked near the seam, the
  // distances max(rows, columns round the shorter way) up to it.
  std::fill(blocked.begin(), blocked.end(), 0);
  constexpr int kRow = 900, kColumn = 3, kBigCap = render::OpenSeaMap::kMaxRings + 1;
  blocked[static_cast<std::size_t>(kRow) * kW + kColumn] = 1;
  const std::vector<std::uint8_t> far = render::chessboardDistances(blocked, kBigCap);
  bad = 0;
  for (int r = 0; r < kH; ++r)
    for (int c = 0; c < kW; ++c) {
      const int dc = std::abs(c - kColumn), expected = std::min(kBigCap, std::max(std::abs(r - kRow), std::min(dc, kW - dc)));
      const int got = far[static_cast<std::size_t>(r) * kW + static_cast<std::size_t>(c)];
      if (got != expected && ++bad <= 5) ADD_FAILURE() << "one cell: (" << r << ", " << c << "): " << got << ", expected " << expected;
    }
  EXPECT_EQ(bad, 0);
}

// The texture's half floats never widen a clearance, and keep it within 0.1 % (or a
// subnormal half's step, 6e-8 rad).
TEST(OpenSeaMap, TexelsRoundTheClearanceDown) {
  // The renderer's map (the island world with the GSHHG mask): both radii in the texels.
  const render::OpenSeaMap map =
      render::makeRendererOpenSeaMap(render::blockedByLayer(islandWorld(), kMinDepthM), &data::defaultLandMask());
  const std::vector<std::uint16_t> texels = render::openSeaTexels(map);
  ASSERT_EQ(texels.size(), 2 * map.clearanceRad.size());
  ASSERT_EQ(map.landClearanceRad.size(), map.clearanceRad.size());
  std::array<int, 2> open{0, 0};
  for (std::size_t i = 0; i < map.clearanceRad.size(); ++i)
    for (std::size_t k = 0; k < 2; ++k) {
      const float c = (k == 0 ? map.clearanceRad : map.landClearanceRad)[i], t = glm::unpackHalf1x16(texels[2 * i + k]);
      ASSERT_LE(t, c) << i << " " << k;
      ASSERT_GE(t, 0.999f * c - 6e-8f) << i << " " << k;  // (radii of 1e-19 rad: cells whose box reaches a pole)
      open[k] += c > 0.0f ? 1 : 0;
    }
  EXPECT_GT(open[0], 1000000);
  EXPECT_GT(open[1], open[0]) << "the land clearance ignores the shelves";
}

TEST(OpenSeaMap, ARegionalLayerHasNoOpenSea) {
  // elevationAt reads -1 m (a shallow sea) outside a regional layer: nothing may be open.
  const data::LatLonGrid regional = test::grid("regional", 0.0, 0.0, 1.0, 10, 10, false,
                                               [](double, double) { return -4000.0; });
  const render::OpenSeaMap map = render::makeOpenSeaMap(render::blockedByLayer(regional, kMinDepthM));
  for (float c : map.clearanceRad) ASSERT_EQ(c, 0.0f);
}

namespace {
// 96 x 96 straight down from (lat, lon, h), the Sun 60° up in the south-south-east.
render::FrameInput straightDown(double latDeg, double lonDeg, double heightM) {
  render::FrameInput f;
  f.camera.position = {latDeg, lonDeg, heightM};
  f.camera.pitchDeg = -90;
  f.width = f.height = 96;
  f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 60, 150);
  return f;
}

// A globe split into parts against the unsplit render: every channel within 1e-5 of the
// reference's largest value (the parts run the same code; rounding only).
void expectSamePicture(const io::ImageRgbaF& reference, const io::ImageRgbaF& split, double heightM) {
  ASSERT_EQ(reference.pixels.size(), split.pixels.size());
  double maxDiff = 0.0, maxValue = 0.0;
  for (std::size_t k = 0; k < split.pixels.size(); ++k) {
    maxDiff = std::max(maxDiff, static_cast<double>(std::abs(split.pixels[k] - reference.pixels[k])));
    maxValue = std::max(maxValue, static_cast<double>(std::abs(reference.pixels[k])));
  }
  EXPECT_LE(maxDiff, 1e-5 * maxValue + 1e-7) << "camera at " << heightM << " m";
}

// `f` rendered with a split of the globe's pixels off and on (`setSplit`): the same picture.
template <class SetSplit>
void expectSplitKeepsThePicture(render::GlobeRenderer& r, const render::FrameInput& f, SetSplit setSplit) {
  // The surface part's pixels by fragments either way: listed, the compute shader's pixel
  // centres round apart from the fragments' by an ulp, over this test's bound (the listing's
  // own test: GlobeRender.ScatteredPartsShadedFromAListKeepThePicture).
  r.setScatteredPartsListed(false);
  // The terrain from its full grids: drawn from the coarser meshes (every 2nd vertex, a few km
  // under the full grid's chords from orbit), two pixels at the limb of the 8000 km view take
  // the split's and the unsplit surface part's colours 5 levels apart (the twenty-first
  // session's note).
  r.terrain().setCoarseStrides(false);
  // The tiles with water over every class, with their own coast test: over the land's class
  // alone they would follow each split's classes (their own test:
  // TerrainRender.TilesOverTheGlobesLandClassKeepThePicture).
  r.setTilesOverLandClass(false);
  setSplit(false);
  r.render(f);
  const io::ImageRgbaF reference = r.radiance();
  setSplit(true);
  r.render(f);
  expectSamePicture(reference, r.radiance(), f.camera.position.heightM);
}
}  // namespace

TEST(GlobeRender, OpenSeaPartMatchesTheSurfacePart) {
  // Orbit views over the island world: the open sea shaded by its own part against the
  // unsplit surface part. A pixel misrouted to the open sea (land, the shelf, a coast) would be
  // shaded as deep sea: far outside this bound.
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(islandWorld());
  for (const auto& [lat, lon, h] : {std::tuple{10.0, -30.0, 2.0e7}, std::tuple{10.0, -30.0, 3.0e6},
                                    std::tuple{20.0, 40.0, 8.0e6}}) {
    expectSplitKeepsThePicture(r, straightDown(lat, lon, h), [&r](bool on) { r.setOpenSeaPart(on); });
  }
  ASSERT_NE(r.openSeaMap(), nullptr);
  int open = 0;
  for (float c : r.openSeaMap()->clearanceRad) open += c > 0.0f ? 1 : 0;
  EXPECT_GT(open * kCell * kCell, 10000.0);  // square degrees: the part is in use
}

TEST(GlobeRender, LandAndSeaPartsMatchTheSurfacePart) {
  // Above 20 km the pixels whose four samples are all on land go to a part without the sea's
  // code, those all on the sea to one without the land's (render/globe.frag's GLOBE_PART_LAND
  // and GLOBE_PART_SEA): straight down on the island world's coast (its shelf 50 m deep: the
  // water column shows) from 300 km and 30 km, and from orbit, against the unsplit surface
  // part. A pixel misrouted to the other part would be shaded as land or as sea: far outside
  // this bound.
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(islandWorld());
  r.setCountPartSamples(true);
  r.setLandAfterTiles(false);  // the land's part over all its class (its own test below)
  std::uint64_t seaSamples = 0, landSamples = 0;
  for (const auto& [lat, lon, h] : {std::tuple{10.0, -27.0, 3.0e5}, std::tuple{10.0, -27.0, 3.0e4},
                                    std::tuple{10.0, -30.0, 3.0e6}}) {
    expectSplitKeepsThePicture(r, straightDown(lat, lon, h), [&r](bool on) { r.setLandSeaParts(on); });
    for (const auto& [name, samples] : r.partSamples()) {  // (of the split frame, rendered last)
      if (name == "sea") seaSamples += samples;
      if (name == "land") landSamples += samples;
    }
  }
  EXPECT_GT(seaSamples, 96u * 96u);  // the parts are in use
  EXPECT_GT(landSamples, 96u * 96u / 4u) << "land";
}

TEST(GlobeRender, LandAfterTheTilesShadesOnlyWhatTheyLeft) {
  // Above 20 km the land's part can come after the terrain's tiles with water, over only the
  // pixels they left (its class keeps the far plane's depth), instead of before them, where the
  // tiles drew over it: the same picture (views of LandAndSeaPartsMatchTheSurfacePart), with
  // the land's part shading a fraction of the samples. Where one classifying draw writes the
  // count (stencil export); elsewhere the land comes first either way.
  auto ctx = gl::createHeadlessContext();
  if (!gl::driverProfile().stencilExport) GTEST_SKIP() << "needs GL_ARB_shader_stencil_export";
  render::GlobeRenderer r(islandWorld());
  r.setCountPartSamples(true);
  std::array<std::uint64_t, 2> landSamples{0, 0};  // before, after the tiles
  for (const auto& [lat, lon, h] : {std::tuple{10.0, -27.0, 3.0e5}, std::tuple{10.0, -27.0, 3.0e4},
                                    std::tuple{10.0, -30.0, 3.0e6}}) {
    const auto countLand = [&r](std::uint64_t& total) {
      for (const auto& [name, samples] : r.partSamples())
        if (name == "land") total += samples;
    };
    expectSplitKeepsThePicture(r, straightDown(lat, lon, h), [&r](bool on) { r.setLandAfterTiles(on); });
    countLand(landSamples[1]);  // (of the frame rendered last, after)
    r.setLandAfterTiles(false);
    r.render(straightDown(lat, lon, h));
    countLand(landSamples[0]);
  }
  EXPECT_GT(landSamples[0], 96u * 96u / 4u);
  EXPECT_LT(landSamples[1] * 10, landSamples[0]) << "the land's part shaded what the tiles drew over";
}

TEST(GlobeRender, ScissorToTheGlobeLeavesThePictureUnchanged) {
  // Above the atmosphere the globe pass is scissored to the box around the globe, its sky and
  // the Sun's disc: the pictures with and without must be the same, pixel for pixel, from far
  // (a small globe, the box a fraction of the screen), with the Sun in view beside the globe,
  // and from low orbit (the box the whole screen).
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer r(islandWorld());
  std::vector<render::FrameInput> frames;
  for (const auto& [h, pitch] : {std::pair{3.0e7, -90.0}, std::pair{2.0e7, -75.0}, std::pair{4.0e5, -15.0}}) {
    render::FrameInput f;
    f.camera.position = {10.0, -30.0, h};
    f.camera.pitchDeg = pitch;
    f.width = 128;
    f.height = 72;
    f.sunDirectionEcef = geo::sunDirectionFromHorizontal(f.camera.position, 60, 150);
    if (pitch == -75.0) {  // the Sun in view, above the globe in the picture
      const geo::CameraView v = geo::makeCameraView(f.camera, f.width, f.height);
      f.sunDirectionEcef = glm::normalize(v.forward + 0.25 * v.up + 0.3 * v.right);
    }
    frames.push_back(f);
  }
  const geo::CameraView far = geo::makeCameraView(frames[0].camera, 128, 72);
  const std::array<int, 4> box = render::globeScissor(far, 128, 72, r.atmosphere().parameters(), frames[0].sunDirectionEcef);
  EXPECT_LT(box[2] * box[3], 128 * 72 / 2) << "the far globe's box is most of the screen";
  EXPECT_GT(box[2] * box[3], 0);
  for (const render::FrameInput& f : frames) {
    r.setGlobeScissor(false);
    r.render(f);
    const io::ImageRgbaF whole = r.radiance();
    const io::ImageRgba8 wholeShown = r.display();
    r.setGlobeScissor(true);
    r.render(frames.back());  // the screen full of the globe, left in the display's target
    r.render(f);
    const io::ImageRgbaF scissored = r.radiance();
    // The tone map too runs only in the box (the rest cleared to black): the same display.
    EXPECT_TRUE(wholeShown.pixels == r.display().pixels) << "camera at " << f.camera.position.heightM << " m";
    std::size_t differ = 0, sunlit = 0;
    for (std::size_t k = 0; k < whole.pixels.size(); ++k) {
      differ += whole.pixels[k] != scissored.pixels[k] ? 1 : 0;
      sunlit += whole.pixels[k] > 1.0f ? 1 : 0;
    }
    EXPECT_EQ(differ, 0u) << "camera at " << f.camera.position.heightM << " m, pitch " << f.camera.pitchDeg;
    if (f.camera.pitchDeg == -75.0) {
      EXPECT_GT(sunlit, 0u) << "the Sun's disc is not in the picture";
    }
  }
}

// blockedByLayer marks one box per run of shallow texels in a row (start-up: 103 -> ~10 ms on
// the default 5' layer); the cells must be those of one box per texel, from each texel's own
// wrapped longitude, on the default layer and on a 2-degree world whose runs cross the
// antimeridian.
TEST(OpenSeaMap, BlockedCellsAreThoseOfOneBoxPerTexel) {
  const auto perTexel = [](const data::LatLonGrid& layer, double minDepthM) {
    constexpr int kW = render::OpenSeaMap::kWidth, kH = render::OpenSeaMap::kHeight;
    constexpr double kPerDeg = render::OpenSeaMap::kCellsPerDeg;
    std::vector<unsigned char> blocked(static_cast<std::size_t>(kW) * kH, 0);
    for (int r = 0; r < layer.height; ++r) {
      const double lat = layer.lat0Deg + r * layer.dLatDeg;
      const double latLo = r == 0 ? -90.0 : lat - layer.dLatDeg;
      const double latHi = r == layer.height - 1 ? 90.0 : lat + layer.dLatDeg;
      for (int c = 0; c < layer.width; ++c) {
        if (static_cast<double>(layer.at(c, r)) <= -minDepthM) continue;
        double lon = std::fmod(layer.lon0Deg + c * layer.dLonDeg + 180.0, 360.0);
        lon = (lon < 0.0 ? lon + 360.0 : lon) - 180.0;
        const int r0 = std::clamp(static_cast<int>(std::floor((latLo + 90.0) * kPerDeg)), 0, kH - 1);
        const int r1 = std::clamp(static_cast<int>(std::floor((latHi + 90.0) * kPerDeg)), 0, kH - 1);
        const int c0 = static_cast<int>(std::floor((lon - layer.dLonDeg + 180.0) * kPerDeg));
        const int c1 = std::min(static_cast<int>(std::floor((lon + layer.dLonDeg + 180.0) * kPerDeg)), c0 + kW - 1);
        for (int rr = r0; rr <= r1; ++rr)
          for (int cc = c0; cc <= c1; ++cc) blocked[static_cast<std::size_t>(rr) * kW + static_cast<std::size_t>((cc % kW + kW) % kW)] = 1;
      }
    }
    return blocked;
  };
  const data::LatLonGrid seam = test::globalGrid("seam", 2.0, [](double lat, double lon) {
    return std::abs(lon) > 175.0 && std::abs(lat) < 30.0 ? -10.0 : -4000.0;
  });
  for (const data::LatLonGrid* layer : {&data::defaultElevation(), &seam}) {
    const std::vector<unsigned char> runs = render::blockedByLayer(*layer, kMinDepthM);
    const std::vector<unsigned char> reference = perTexel(*layer, kMinDepthM);
    EXPECT_EQ(runs, reference) << layer->name;
    EXPECT_GT(std::count(runs.begin(), runs.end(), 1), 100) << layer->name;
  }
}
