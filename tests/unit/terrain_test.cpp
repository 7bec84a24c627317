// Terrain LOD on the CPU: tile selection, crack-free seams, the cache's memory bound, the
// procedural detail's continuity and the tile builders (parallel, progressive).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "data/Elevation.hpp"
#include "geo/Camera.hpp"
#include "geo/Wgs84.hpp"
#include "terrain/Heightfield.hpp"
#include "terrain/Selection.hpp"
#include "terrain/Tile.hpp"
#include "terrain/TileBuilder.hpp"
#include "terrain/TileCache.hpp"

namespace og::terrain {
namespace {

std::shared_ptr<const Heightfield> heights() {
  static const auto h = std::make_shared<const Heightfield>(data::defaultElevation());
  return h;
}

geo::CameraView viewAt(double lat, double lon, double h, double heading, double pitch, int w = 640,
                       int hPx = 360) {
  geo::CameraPose p;
  p.position = {lat, lon, h};
  p.headingDeg = heading;
  p.pitchDeg = pitch;
  return geo::makeCameraView(p, w, hPx);
}

TEST(TerrainTile, VertexLatLonIsExactAtSharedPositions) {
  // The east edge of a level-5 tile and the west edge of its level-7 neighbour: every fourth
  // fine vertex is a coarse one, with identical coordinates.
  const TileKey coarse{5, 40, 20};
  const TileKey fine{7, 4 * 41, 4 * 20 + 1};  // east neighbour, second row of fine tiles
  for (int j = 0; j <= kTileQuads; j += 4) {
    double la = 0, lo = 0, lb = 0, lob = 0;
    tileVertexLatLon(fine, 0, j, la, lo);
    tileVertexLatLon(coarse, kTileQuads, kTileQuads / 4 + j / 4, lb, lob);
    EXPECT_EQ(la, lb);
    EXPECT_EQ(lo, lob);
  }
}

TEST(TerrainTile, SharedEdgeVerticesIdenticalAcrossLevels) {
  // Himalaya: rugged, so detail and data both vary along the seam.
  const TileKey coarse{9, 0, 0};
  // Tile containing 28N 87E at level 9, and the one east of it at level 11.
  const double size9 = 180.0 / 512.0;
  const TileKey c{9, static_cast<int>((87.0 + 180.0) / size9), static_cast<int>((28.0 + 90.0) / size9)};
  (void)coarse;
  const Tile a = buildTile(*heights(), c);
  for (int row = 0; row < 4; ++row) {
    const TileKey f{11, 4 * (c.x + 1), 4 * c.y + row};
    const Tile b = buildTile(*heights(), f);
    for (int j = 0; j <= kTileQuads; j += 4) {
      const int ja = row * kTileQuads / 4 + j / 4;
      const auto ia = static_cast<std::size_t>(ja * (kTileQuads + 1) + kTileQuads);
      const auto ib = static_cast<std::size_t>(j * (kTileQuads + 1));
      const glm::dvec3 pa = a.centreEcef + a.positions[ia];
      const glm::dvec3 pb = b.centreEcef + b.positions[ib];
      EXPECT_LT(glm::length(pa - pb), 1e-6) << "row " << row << " j " << j;
      EXPECT_EQ(a.vertices[ia].heightM, b.vertices[ib].heightM);
    }
  }
  // Same level, north-south neighbours: the whole shared edge.
  const Tile n = buildTile(*heights(), TileKey{9, c.x, c.y + 1});
  for (int i = 0; i <= kTileQuads; ++i) {
    const auto ia = static_cast<std::size_t>(kTileQuads * (kTileQuads + 1) + i);
    const auto ib = static_cast<std::size_t>(i);
    EXPECT_EQ(a.vertices[ia].heightM, n.vertices[ib].heightM);
    EXPECT_LT(glm::length(a.centreEcef + a.positions[ia] - n.centreEcef - n.positions[ib]), 1e-6);
  }
}

TEST(TerrainTile, VerticesAreTheHeightfieldsSamplesAndTheSeaCoveredOnesTakeTheVertical) {
  // buildTile takes a vertex's height and its normal in two halves (Heightfield::sampleHeight,
  // normalAt) and skips the normals of a tile the sea covers: a drawable tile's vertices must
  // be sample()'s exactly, a covered one's heights too with the vertical for normals.
  const double size = 180.0 / 512.0;
  const TileKey land{9, static_cast<int>((87.0 + 180.0) / size), static_cast<int>((28.0 + 90.0) / size)};  // the Himalaya
  const TileKey sea{9, static_cast<int>((-40.0 + 180.0) / size), static_cast<int>((20.0 + 90.0) / size)};  // mid-Atlantic
  for (const TileKey& key : {land, sea}) {
    const Tile t = buildTile(*heights(), key);
    EXPECT_EQ(t.coveredBySea(), key == sea);
    const double stepDeg = 0.5 * std::max(key.sizeDeg() / kTileQuads, heights()->layer().dLatDeg);
    for (int j = 0; j <= kTileQuads; j += 7)
      for (int i = 0; i <= kTileQuads; i += 5) {
        double lat = 0.0, lon = 0.0;
        tileVertexLatLon(key, i, j, lat, lon);
        const HeightSample s = heights()->sample(lat, lon, t.normalOctaves, stepDeg);
        const TileVertex& v = t.vertices[static_cast<std::size_t>(j * (kTileQuads + 1) + i)];
        EXPECT_EQ(v.heightM, static_cast<float>(s.heightM));
        EXPECT_EQ(v.detailAmplitudeM, static_cast<float>(s.shadingAmplitudeM));
        const glm::vec3 expected = t.coveredBySea() ? glm::vec3(geodeticUpFast(lat, lon)) : glm::vec3(s.normal);
        EXPECT_EQ(v.normal, expected) << "vertex " << i << ", " << j << " of level " << key.level << " x " << key.x;
      }
  }
}

TEST(TerrainTile, SkirtsHangBelowTheEdges) {
  const Tile t = buildTile(*heights(), TileKey{8, 2 * 267 / 2, 168});
  ASSERT_EQ(t.vertices.size(), static_cast<std::size_t>(kTileVertices));
  for (int s = 0; s <= kTileQuads; ++s) {
    const auto top = static_cast<std::size_t>(s);  // south edge
    const auto low = static_cast<std::size_t>(kTileGridVertices + s);
    EXPECT_LT(t.vertices[low].heightM, t.vertices[top].heightM - 19.0f);
  }
  const auto& idx = tileIndices();
  EXPECT_EQ(idx.size() % 3, 0u);
  for (auto i : idx) EXPECT_LT(i, static_cast<std::uint32_t>(kTileVertices));
}

// The coarser mesh (render/TerrainRenderer::tileStrideIndex) joins only every 2nd vertex of the grid
// and of the skirts, covers the tile with 16² quads, and knows how far it lies from the full
// grid: it is the parent's mesh, so its deviation is the longest morph offset
// (terrain/tile_vertex.glsl), split along and across the vertical.
TEST(TerrainTile, CoarserMeshesJoinEveryStrideVertexAndKnowTheirDeviation) {
  constexpr int n = kTileQuads + 1;
  for (const int stride : {2}) {
    const auto& idx = tileIndices(stride);
    const int grid = tileGridIndexCount(stride);
    EXPECT_EQ(grid, 6 * (kTileQuads / stride) * (kTileQuads / stride));
    EXPECT_EQ(static_cast<int>(idx.size()), grid + 4 * 6 * (kTileQuads / stride));
    for (std::size_t k = 0; k < idx.size(); ++k) {
      const int v = static_cast<int>(idx[k]);
      ASSERT_LT(v, kTileVertices);
      // A skirt's lowered vertex only after the grid's triangles; every vertex a multiple of
      // the stride along its edge (skirt) or in both directions (grid).
      if (v >= kTileGridVertices) {
        EXPECT_GE(static_cast<int>(k), grid);
        EXPECT_EQ((v - kTileGridVertices) % n % stride, 0) << stride << ": " << v;
      } else {
        EXPECT_TRUE(v % n % stride == 0 && v / n % stride == 0) << stride << ": " << v;
      }
    }
  }
  EXPECT_EQ(tileIndices(1), tileIndices());
  EXPECT_THROW((void)tileIndices(3), std::invalid_argument);
  EXPECT_THROW((void)tileIndices(4), std::invalid_argument);

  const Tile t = buildTile(*heights(), TileKey{9, 759, 335});  // the Himalaya
  double longestMorph = 0.0;
  for (int k = 0; k < kTileGridVertices; ++k)
    longestMorph = std::max(longestMorph, static_cast<double>(glm::length(t.vertices[static_cast<std::size_t>(k)].morph)));
  const Tile::StrideDeviation& two = t.strideDeviation[0];
  EXPECT_GT(longestMorph, 100.0);
  EXPECT_GE(std::hypot(two.verticalM, two.horizontalM), longestMorph - 0.01);
  EXPECT_LE(std::max(two.verticalM, two.horizontalM), longestMorph + 0.01);
  // Above the sea (the shadow maps' casters, TerrainRenderer::setShadowStrides): on land all of
  // it; under the open sea none; at a coast some, at most the whole tile's.
  EXPECT_DOUBLE_EQ(two.aboveSeaVerticalM, two.verticalM);
  EXPECT_DOUBLE_EQ(two.aboveSeaHorizontalM, two.horizontalM);
  const Tile open = buildTile(*heights(), TileKey{9, 398, 312});  // 20°N 40°W, the mid-Atlantic
  EXPECT_LT(open.maxHeightM, 0.0);
  EXPECT_GT(open.strideDeviation[0].verticalM, 0.0);
  EXPECT_EQ(open.strideDeviation[0].aboveSeaVerticalM, 0.0);
  EXPECT_EQ(open.strideDeviation[0].aboveSeaHorizontalM, 0.0);
  const Tile coast = buildTile(*heights(), TileKey{9, 496, 358});  // Tarifa and the strait
  ASSERT_TRUE(coast.minHeightM < 0.0 && coast.maxHeightM > 0.0);
  EXPECT_GT(coast.strideDeviation[0].aboveSeaVerticalM, 0.0);
  EXPECT_LE(coast.strideDeviation[0].aboveSeaVerticalM, coast.strideDeviation[0].verticalM);
  std::printf("coast tile's every 2nd vertex: %.1f m off vertically, %.1f m above the sea\n",
              coast.strideDeviation[0].verticalM, coast.strideDeviation[0].aboveSeaVerticalM);
}

TEST(TerrainTile, MorphTargetsLieOnTheParentsMesh) {
  // A child's vertices morph onto its parent's triangles: the parent's own vertices stay, the
  // others go to the midpoint of the parent's edge or diagonal through them (the parent's quads
  // are split from (i, j) to (i+1, j+1), as the children's).
  const TileKey parentKey{9, 759, 335};  // 27.8°N 86.9°E, the Himalaya: rugged detail
  const Tile parent = buildTile(*heights(), parentKey);
  const TileKey childKey = parentKey.child(3);       // the north-east quarter
  const Tile child = buildTile(*heights(), childKey);
  constexpr int n = kTileQuads + 1;
  auto parentPoint = [&](int pi, int pj) {  // parent grid vertex, ECEF
    return parent.positions[static_cast<std::size_t>(pj * n + pi)] + parent.centreEcef;
  };
  double maxMorph = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(j * n + i);
      const glm::dvec3 target = child.positions[k] + child.centreEcef + glm::dvec3(child.vertices[k].morph);
      // Child (i, j) is parent (16 + i/2, 16 + j/2) in the north-east quarter.
      const int pi0 = kTileQuads / 2 + i / 2, pj0 = kTileQuads / 2 + j / 2;
      glm::dvec3 expected;
      if (i % 2 == 0 && j % 2 == 0) expected = parentPoint(pi0, pj0);
      else if (i % 2 == 1 && j % 2 == 1) expected = 0.5 * (parentPoint(pi0, pj0) + parentPoint(pi0 + 1, pj0 + 1));
      else if (i % 2 == 1) expected = 0.5 * (parentPoint(pi0, pj0) + parentPoint(pi0 + 1, pj0));
      else expected = 0.5 * (parentPoint(pi0, pj0) + parentPoint(pi0, pj0 + 1));
      // Float morph offsets of up to a few hundred metres: millimetres.
      EXPECT_LT(glm::length(target - expected), 0.01) << i << "," << j;
      maxMorph = std::max(maxMorph, static_cast<double>(glm::length(child.vertices[k].morph)));
    }
  EXPECT_GT(maxMorph, 5.0);  // the detail the child adds is really there to morph away
}

TEST(TerrainHeight, DetailIsDeterministicContinuousAndScaledToRelief) {
  const Heightfield& h = *heights();
  EXPECT_EQ(h.heightM(28.0, 87.0), h.heightM(28.0, 87.0));
  // Continuity: a metre apart, heights differ by little (relative to the relief).
  const double step = 1.0 / 111000.0;
  double maxJump = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double lat = 27.5 + i * 0.005, lon = 86.5 + i * 0.004;
    maxJump = std::max(maxJump, std::abs(h.heightM(lat + step, lon) - h.heightM(lat, lon)));
  }
  EXPECT_LT(maxJump, 20.0);
  // Across the antimeridian the detail (on the sphere) has no seam.
  EXPECT_NEAR(h.heightM(-17.0, 180.0 - 1e-9), h.heightM(-17.0, -180.0 + 1e-9), 1e-3);
  // Rugged ground gets detail; the deep sea floor keeps its sign; sea level never turns land.
  double rough = 0.0;
  for (int i = 0; i < 50; ++i)
    rough = std::max(rough, std::abs(h.heightM(28.0 + i * 1e-3, 87.0) - h.layerHeightM(28.0 + i * 1e-3, 87.0)));
  EXPECT_GT(rough, 10.0);
  for (int i = 0; i < 200; ++i) {
    const double lat = 35.5 + i * 0.004, lon = -6.5 + i * 0.01;  // across the Strait of Gibraltar
    const double layer = h.layerHeightM(lat, lon);
    EXPECT_EQ(h.heightM(lat, lon) > 0.0, layer > 0.0) << lat << " " << lon;
  }
}

TEST(TerrainHeight, DetailGradientMatchesFiniteDifferences) {
  // The analytic gradient (terrain/detail.glsl, the same code the fragment shader runs for
  // the finer octaves) against central differences of the sum, on the unit sphere.
  const DetailOctaves& o = heights()->octaves();
  ASSERT_GE(o.normalCount, o.heightCount);
  ASSERT_GE(o.heightCount, 8);  // ETOPO20: 74 km down to 40 m
  for (int i = 0; i < 20; ++i) {
    const double lat = (27.0 + 0.37 * i) * std::numbers::pi / 180.0, lon = (86.0 + 0.91 * i) * std::numbers::pi / 180.0;
    const glm::dvec3 up{std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
    glm::dvec3 grad;
    const int count = o.heightCount;
    detailSum(o, up, count, count, &grad);
    // A step far inside the finest octave's lattice cell (40 m / a on the sphere).
    const double h = 0.02 / 6378137.0;
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 d(0.0);
      d[axis] = h;
      const double fd = (detailSum(o, up + d, count, 0, nullptr) - detailSum(o, up - d, count, 0, nullptr)) / (2.0 * h);
      EXPECT_NEAR(grad[axis], fd, 2e-3 * std::max(1.0, std::abs(fd)) + 0.02 * glm::length(grad))
          << "point " << i << " axis " << axis;
    }
  }
}

TEST(TerrainHeight, SampleNormalIsTiltedByTheDetailAndHeightMatches) {
  const Heightfield& h = *heights();
  // Rugged ground: the detail's octaves tilt the normal away from the layer's; the height is
  // heightM()'s bit for bit (vertex positions and seams depend on it).
  double maxTilt = 0.0;
  for (int i = 0; i < 50; ++i) {
    const double lat = 27.8 + i * 0.003, lon = 86.9;
    const HeightSample flat = h.sample(lat, lon, 0, 0.05);
    const HeightSample tilted = h.sample(lat, lon, h.octaves().normalCount, 0.05);
    EXPECT_EQ(tilted.heightM, h.heightM(lat, lon));
    EXPECT_EQ(flat.heightM, tilted.heightM);
    EXPECT_NEAR(glm::length(tilted.normal), 1.0, 1e-12);
    maxTilt = std::max(maxTilt, std::acos(std::min(1.0, glm::dot(flat.normal, tilted.normal))));
  }
  EXPECT_GT(maxTilt, 10.0 * std::numbers::pi / 180.0);  // mountain slopes, not a blur
}

TEST(TerrainSelection, FinerNearTheCameraAndNoneBehind) {
  TileCache cache(heights());
  const geo::CameraView view = viewAt(28.0, 87.0, 15000.0, 0.0, -10.0);
  SelectionStats stats;
  const auto tiles = selectTiles(cache, view, SelectionParams{}, &stats);
  ASSERT_FALSE(tiles.empty());
  EXPECT_GT(stats.culledFrustum, 0);
  EXPECT_GT(stats.culledHorizon + stats.culledFrustum, 0);
  // Tiles near the camera are finer than far ones.
  int nearLevel = 0, farLevel = 99;
  for (const Tile* t : tiles) {
    const double d = glm::length(t->boundCentreEcef - view.positionEcef);
    if (d < 40000.0) nearLevel = std::max(nearLevel, t->key.level);
    if (d > 300000.0) farLevel = std::min(farLevel, t->key.level);
    // Nothing wholly behind the camera.
    EXPECT_GT(glm::dot(t->boundCentreEcef - view.positionEcef, view.forward), -t->boundRadiusM);
    // Each drawn tile meets the error bound (or is at the finest level).
    EXPECT_TRUE(tileErrorPx(view, 360, *t) <= SelectionParams{}.maxSpacingPx || t->key.level == kMaxLevel);
  }
  EXPECT_GT(nearLevel, farLevel + 2);
  EXPECT_GE(nearLevel, 10);
  // No two drawn tiles overlap (one is never the ancestor of another).
  std::set<std::tuple<int, int, int>> keys;
  for (const Tile* t : tiles) keys.insert({t->key.level, t->key.x, t->key.y});
  for (const Tile* t : tiles)
    for (TileKey k = t->key; k.level > 0;) {
      k = TileKey{k.level - 1, k.x / 2, k.y / 2};
      EXPECT_EQ(keys.count({k.level, k.x, k.y}), 0u);
    }
}

TEST(TerrainSelection, HorizonAndFrustumCulling) {
  // From 2 km looking at the horizon: nothing on the far side of the planet, nothing below
  // the horizon of a sphere well inside the terrain.
  TileCache cache(heights());
  const geo::CameraView view = viewAt(0.0, 0.0, 2000.0, 90.0, 0.0);
  const auto tiles = selectTiles(cache, view, SelectionParams{});
  ASSERT_FALSE(tiles.empty());
  for (const Tile* t : tiles) {
    const double d = glm::length(t->boundCentreEcef - view.positionEcef) - t->boundRadiusM;
    EXPECT_LT(d, 1.2e6) << t->key.level << " " << t->key.x << " " << t->key.y;
  }
  // The direct tests.
  const glm::dvec3 eye = view.positionEcef;
  EXPECT_FALSE(aboveHorizon(eye, -eye, 1000.0));                       // antipode
  EXPECT_TRUE(aboveHorizon(eye, eye * 0.99999 + view.forward * 5e4, 1000.0));  // just ahead
  EXPECT_FALSE(inFrustum(view, 640, 360, eye - view.forward * 1e5, 1000.0));   // behind
  EXPECT_TRUE(inFrustum(view, 640, 360, eye + view.forward * 1e5, 1000.0));
}

// The sea's horizon (TerrainRenderer draws no tile beyond it where the land mask decides the
// coast): from 2 m a point 11 m up is seen over an occluder 100 m down out to the two tangent
// lengths, sqrt(2 N (2 + 100)) + sqrt(2 N (11 + 100)) = 73.7 km along the equator (N = a
// there); the deep occluder sees it from 380 km more. An eye below the occluder sees all.
TEST(TerrainSelection, SeaHorizonHidesWhatTheDeepOccluderDoesNot) {
  auto onEquator = [](double distanceM, double heightM) {
    return geo::geodeticToEcef({0.0, glm::degrees(distanceM / geo::kWgs84SemiMajorM), heightM});
  };
  const glm::dvec3 eye = onEquator(0.0, 2.0);
  const double reachM = std::sqrt(2.0 * geo::kWgs84SemiMajorM * 102.0) + std::sqrt(2.0 * geo::kWgs84SemiMajorM * 111.0);
  EXPECT_NEAR(reachM, 73.7e3, 0.1e3);
  for (const double d : {0.95 * reachM, 1.05 * reachM, 4.0 * reachM}) {
    const glm::dvec3 c = onEquator(d, 10.0);
    EXPECT_EQ(aboveHorizon(eye, c, 1.0, kSeaOccluderDepthM, 11.0), d < reachM) << d;
    EXPECT_TRUE(aboveHorizon(eye, c, 1.0)) << d;  // the default, deep occluder
  }
  EXPECT_TRUE(aboveHorizon(onEquator(0.0, -150.0), onEquator(4.0 * reachM, 10.0), 1.0, kSeaOccluderDepthM, 11.0));

  // A tile's drawn points reach its highest vertex, or sea level where the mask raises land
  // out of the water: a shallow tile counts as reaching sea level.
  Tile t;
  t.boundRadiusM = 1.0;
  t.boundCentreEcef = onEquator(1.05 * std::sqrt(2.0 * geo::kWgs84SemiMajorM * 102.0) * 2.0, 0.0);  // beyond a 0 m top
  t.maxHeightM = -0.5;
  EXPECT_FALSE(aboveSeaHorizon(eye, t));
  t.boundCentreEcef = onEquator(0.95 * std::sqrt(2.0 * geo::kWgs84SemiMajorM * 102.0) * 2.0, 0.0);
  EXPECT_TRUE(aboveSeaHorizon(eye, t));
  t.boundCentreEcef = onEquator(1.5 * reachM, 0.0);
  t.boundRadiusM = 1000.0;
  t.maxHeightM = 1000.0;  // a hill that far shows over it
  EXPECT_TRUE(aboveSeaHorizon(eye, t));
}

// The clip of what lies beyond the sea's horizon at the waves' depth (terrain::seaHorizonCone,
// terrain.vert's clip distance): a point it clips lies behind the ellipsoid lowered by that
// depth, seen from eyes 0.5 m to 20 km up at latitudes 0-80° (the exact crossing,
// geo::intersectEllipsoid), it clips most of what lies 20 m or more under that horizon, and
// its function is convex (its interpolation along a segment never falls below the midpoint's).
TEST(TerrainSelection, SeaHorizonClipKeepsWhatTheLoweredSeaDoesNotHide) {
  const double depthM = 3.0;
  int clipped = 0, deepUnder = 0, deepClipped = 0;
  for (const double lat : {0.0, 30.0, 45.0, 60.0, 80.0})
    for (const double eyeM : {0.5, 2.0, 30.0, 1000.0, 20000.0})
      for (const double azimuth : {0.0, 45.0, 90.0, 170.0}) {
        const geo::CameraView view = viewAt(lat, -20.0, eyeM, azimuth, 0.0);
        const SeaHorizonCone cone = seaHorizonCone(view, depthM);
        const double tangentM = std::sqrt(2.0 * geo::kWgs84SemiMajorM * (eyeM + depthM));
        for (int i = 1; i <= 40; ++i) {
          const double distanceM = tangentM * 0.1 * i;  // out to four tangent lengths
          for (const double aboveM : {-50.0, -5.0, 0.0, 20.0, 200.0, 2000.0}) {
            // The point `distanceM` along the ground in the azimuth, `aboveM` over the ellipsoid.
            const double arcDeg = glm::degrees(distanceM / geo::kWgs84SemiMajorM);
            const glm::dvec3 p =
                geo::geodeticToEcef({lat + arcDeg * std::cos(glm::radians(azimuth)),
                                     -20.0 + arcDeg * std::sin(glm::radians(azimuth)) / std::cos(glm::radians(lat)),
                                     aboveM}) -
                view.positionEcef;
            const double length = glm::length(p);
            const auto crossing = geo::intersectEllipsoid(view.positionEcef, p / length, -depthM);
            const bool hidden = crossing.has_value() && *crossing < length;
            const bool clip = seaHorizonClip(cone, p) < 0.0;
            if (clip) ++clipped;
            EXPECT_TRUE(!clip || hidden) << lat << " " << eyeM << " " << azimuth << " " << distanceM << " " << aboveM;
            // 20 m under the lowered sea's horizon there, beyond the tangent point.
            const auto deeper = geo::intersectEllipsoid(view.positionEcef, p / length, -depthM - 20.0);
            if (distanceM > 1.2 * tangentM && deeper.has_value() && *deeper < length) {
              ++deepUnder;
              if (clip) ++deepClipped;
            }
          }
        }
        // Convex: along segments between points around the horizon.
        const glm::dvec3 a = view.forward * tangentM * 1.5 - view.up * 1.0, b = view.right * tangentM * 2.0 + view.forward * tangentM;
        for (const double t : {0.25, 0.5, 0.75})
          EXPECT_LE(seaHorizonClip(cone, a + t * (b - a)),
                    (1.0 - t) * seaHorizonClip(cone, a) + t * seaHorizonClip(cone, b) + 1e-6);
      }
  std::printf("clipped %d points; %d of %d points 20 m under the lowered horizon\n", clipped, deepClipped, deepUnder);
  EXPECT_GT(clipped, 1000);
  EXPECT_GT(deepClipped, 0.99 * deepUnder);
  // Along the cone's very edge, where the margins matter: every point just inside it and past
  // the tangent circle is behind the lowered ellipsoid (fails without the cubic margin).
  int edgeMisses = 0;
  for (const double lat : {0.0, 30.0, 45.0, 60.0, 80.0, 89.5})
    for (const double eyeM : {2.0, 30.0, 1000.0, 20000.0}) {
      const geo::CameraView view = viewAt(lat, -20.0, eyeM, 0.0, 0.0);
      const SeaHorizonCone cone = seaHorizonCone(view, depthM);
      const glm::dvec3 side = glm::normalize(glm::cross(cone.axis, glm::dvec3(0.3, 0.5, 0.8)));
      const double angle = std::asin(cone.sinHalfAngle()) - 1e-9;
      for (int k = 0; k < 36; ++k) {
        const double azimuth = k * std::numbers::pi / 18.0;
        const glm::dvec3 across = std::cos(azimuth) * side + std::sin(azimuth) * glm::cross(cone.axis, side);
        const glm::dvec3 dir = std::cos(angle) * cone.axis + std::sin(angle) * across;
        for (const double f : {1.0001, 1.01, 1.1, 1.5}) {
          const double length = f * cone.tangentM;
          if (seaHorizonClip(cone, length * dir) >= 0.0) continue;
          const auto crossing = geo::intersectEllipsoid(view.positionEcef, dir, -depthM);
          edgeMisses += crossing.has_value() && *crossing < length ? 0 : 1;
        }
      }
    }
  EXPECT_EQ(edgeMisses, 0);
}

// A tile drawn without the horizon's clip (terrain::seaHorizonMayHide false) holds no point the
// clip would cut: spheres around the horizon from 2 m, 300 m and 15 km up, each sampled on its
// surface and inside. From 15 km a tile of ridges 100 km off is drawn without it.
TEST(TerrainSelection, SeaHorizonMayHideHoldsEveryClippedPoint) {
  int hidingSpheres = 0, visibleSpheres = 0;
  for (const double eyeM : {2.0, 300.0, 15000.0}) {
    const geo::CameraView view = viewAt(36.0, -5.5, eyeM, 270.0, 0.0);
    const SeaHorizonCone cone = seaHorizonCone(view, 3.0);
    for (const double distanceM : {0.5, 0.9, 1.0, 1.1, 1.5, 2.0, 4.0})
      for (const double radiusM : {0.01, 0.1, 0.5})
        for (const double aboveM : {-0.2, 0.0, 0.05, 0.3}) {
          const double d = distanceM * cone.tangentM, r = radiusM * cone.tangentM;
          const glm::dvec3 ahead = glm::normalize(view.forward - glm::dot(view.forward, view.enu.up) * view.enu.up);
          const double drop = d * d / (2.0 * geo::kWgs84SemiMajorM);
          const glm::dvec3 centre = d * ahead + (aboveM * r - drop) * view.enu.up;
          const bool mayHide = seaHorizonMayHide(cone, centre, r);
          (mayHide ? hidingSpheres : visibleSpheres) += 1;
          if (mayHide) continue;
          for (int k = 0; k < 200; ++k) {
            const double u = std::sin(k * 12.9898) * 0.5 + 0.5, v = std::sin(k * 78.233) * 0.5 + 0.5;
            const double theta = 2.0 * std::numbers::pi * u, phi = std::acos(2.0 * v - 1.0);
            const glm::dvec3 dir(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi));
            for (const double s : {0.5, 1.0})
              EXPECT_GE(seaHorizonClip(cone, centre + s * r * dir), 0.0) << eyeM << " " << distanceM << " " << radiusM;
          }
        }
  }
  EXPECT_GT(hidingSpheres, 20);
  EXPECT_GE(visibleSpheres, 20);
  // A 6 km tile of ridges 5 km up, 100 km off, from 15 km; not one that reaches under the sea.
  const geo::CameraView high = viewAt(27.3, 86.9, 15000.0, 10.0, 0.0);
  const SeaHorizonCone cone = seaHorizonCone(high, 3.0);
  EXPECT_FALSE(seaHorizonMayHide(cone, 1.0e5 * high.forward - 10000.0 * high.enu.up, 3000.0));
  EXPECT_TRUE(seaHorizonMayHide(cone, 1.0e5 * high.forward - 15000.0 * high.enu.up, 3000.0));
}

TEST(TerrainSelection, OrbitViewIsCoarse) {
  TileCache cache(heights());
  const geo::CameraView view = viewAt(10.0, -30.0, 6.0e6, 0.0, -90.0, 256, 256);
  SelectionStats stats;
  const auto tiles = selectTiles(cache, view, SelectionParams{}, &stats);
  EXPECT_LE(stats.finestLevel, 5);
  EXPECT_LT(tiles.size(), 100u);
  EXPECT_GT(stats.culledHorizon, 0);  // the far side of the Earth
}

TEST(TerrainCache, StaysWithinItsBudget) {
  const std::size_t tileBytes = buildTile(*heights(), TileKey{6, 10, 10}).bytes();
  TileCache cache(heights(), 20 * tileBytes);
  for (int frame = 0; frame < 5; ++frame) {
    cache.beginFrame();
    for (int i = 0; i < 12; ++i) (void)cache.get(TileKey{6, 12 * frame + i, 20});
    EXPECT_LE(cache.bytes(), cache.budgetBytes());
  }
  EXPECT_LE(cache.size(), 20u);
  const auto evicted = cache.takeEvicted();
  EXPECT_EQ(evicted.size() + cache.size(), 60u);
  // Tiles of the current frame are kept even over budget, and dropped on a later frame.
  cache.beginFrame();
  for (int i = 0; i < 30; ++i) (void)cache.get(TileKey{7, i, 40});
  EXPECT_EQ(cache.size(), 30u);
  cache.beginFrame();
  (void)cache.get(TileKey{7, 100, 40});
  EXPECT_LE(cache.bytes(), cache.budgetBytes());
  // A re-fetched tile is the same tile (cached, not rebuilt).
  const auto built = cache.builtCount();
  (void)cache.get(TileKey{7, 100, 40});
  EXPECT_EQ(cache.builtCount(), built);
}

using KeyList = std::vector<std::tuple<int, int, int>>;

KeyList keysOf(const std::vector<const Tile*>& tiles) {
  KeyList keys;
  for (const Tile* t : tiles) keys.emplace_back(t->key.level, t->key.x, t->key.y);
  return keys;
}

bool isAncestor(const TileKey& a, const TileKey& b) {  // a strictly contains b
  return a.level < b.level && (b.x >> (b.level - a.level)) == a.x && (b.y >> (b.level - a.level)) == a.y;
}

// The depth-first walk the selection did before it was breadth-first and parallel (one tile at
// a time through TileCache::get): the reference for "the same tiles, in the same order".
void referenceWalk(TileCache& cache, const geo::CameraView& view, const SelectionParams& p,
                   const TileKey& key, KeyList& out, KeyList* split = nullptr) {
  const Tile& t = cache.get(key);
  if (!inFrustum(view, p.widthPx, p.heightPx, t.boundCentreEcef, t.boundRadiusM)) return;
  if (!aboveHorizon(view.positionEcef, t.boundCentreEcef, t.boundRadiusM)) return;
  const bool polar = key.southDeg() <= -90.0 + 1e-9 || key.southDeg() + key.sizeDeg() >= 90.0 - 1e-9;
  const int maxLevel = polar ? std::min(p.maxLevel, 7) : p.maxLevel;
  if (key.level < maxLevel &&
      (key.level < p.minLevel || tileErrorPx(view, p.heightPx, t) > p.maxSpacingPx)) {
    if (split != nullptr) split->emplace_back(key.level, key.x, key.y);
    for (int i = 0; i < 4; ++i) referenceWalk(cache, view, p, key.child(i), out, split);
  } else {
    out.emplace_back(key.level, key.x, key.y);
  }
}

struct NamedView {
  const char* name;
  geo::CameraView view;
};

SelectionParams smallParams(bool wait = true) {
  SelectionParams p;
  p.widthPx = 320;
  p.heightPx = 180;
  p.wait = wait;
  return p;
}

std::vector<NamedView> parallelTestViews() {
  // Small images: fewer, coarser tiles keep the tests fast.
  return {{"mountain-15km", viewAt(27.9, 86.9, 15000.0, 10.0, -6.0, 320, 180)},
          {"orbit", viewAt(10.0, -30.0, 2.0e7, 0.0, -90.0, 320, 180)},
          {"sea-level-coast", viewAt(36.0, -5.5, 2.0, 270.0, 2.0, 320, 180)}};
}

TEST(TerrainSelection, ParallelBuildsSelectTheSameTilesAsOneWorker) {
  for (const auto& [name, view] : parallelTestViews()) {
    const SelectionParams params = smallParams();
    TileCache one(heights(), std::size_t{96} << 20, 1);
    TileCache many(heights(), std::size_t{96} << 20, 4);  // more threads than cores: interleaving
    ASSERT_EQ(one.workerCount(), 1);
    SelectionStats s1, s4;
    const KeyList k1 = keysOf(selectTiles(one, view, params, &s1));
    const KeyList k4 = keysOf(selectTiles(many, view, params, &s4));
    ASSERT_FALSE(k1.empty()) << name;
    EXPECT_EQ(k1, k4) << name;  // same tiles, same order
    EXPECT_EQ(s1.visited, s4.visited) << name;
    EXPECT_EQ(s1.culledFrustum, s4.culledFrustum) << name;
    EXPECT_EQ(s1.culledHorizon, s4.culledHorizon) << name;
    EXPECT_EQ(s4.standIns, 0) << name;
    EXPECT_EQ(s4.pending, 0u) << name;
    // Every visited tile built exactly once, none more.
    EXPECT_EQ(many.builtCount(), static_cast<std::uint64_t>(s4.visited)) << name;
    EXPECT_EQ(many.size(), many.builtCount()) << name;
    // The recursive walk of old (on the warm cache: nothing to build) agrees, order included.
    KeyList reference;
    for (int x = 0; x < 2; ++x) referenceWalk(many, view, params, TileKey{0, x, 0}, reference);
    EXPECT_EQ(reference, k4) << name;
    EXPECT_EQ(many.size(), many.builtCount()) << name;
  }
}

// Progressive selection: each tile drawn is either one the complete selection draws or one it
// splits (standing in for children not built yet); together they cover what the complete
// selection draws, each of its tiles exactly once.
void expectCovers(const std::vector<const Tile*>& progressive, const KeyList& complete,
                  const KeyList& completeSplits) {
  for (const auto& [l, x, y] : complete) {
    const TileKey k{l, x, y};
    int covering = 0;
    for (const Tile* t : progressive) covering += t->key == k || isAncestor(t->key, k);
    EXPECT_EQ(covering, 1) << "tile " << l << " " << x << " " << y;
  }
  for (const Tile* t : progressive) {
    const auto k = std::make_tuple(t->key.level, t->key.x, t->key.y);
    EXPECT_TRUE(std::find(complete.begin(), complete.end(), k) != complete.end() ||
                std::find(completeSplits.begin(), completeSplits.end(), k) != completeSplits.end())
        << "stray tile " << t->key.level << " " << t->key.x << " " << t->key.y;
  }
}

TEST(TerrainSelection, ProgressiveDrawsAncestorsThenConvergesToTheCompleteSelection) {
  const geo::CameraView view = parallelTestViews()[0].view;
  TileCache blockingCache(heights());
  SelectionStats complete;
  const KeyList target = keysOf(selectTiles(blockingCache, view, smallParams(), &complete));
  KeyList reference, splits;
  for (int x = 0; x < 2; ++x)
    referenceWalk(blockingCache, view, smallParams(), TileKey{0, x, 0}, reference, &splits);
  ASSERT_EQ(reference, target);

  const SelectionParams params = smallParams(false);
  TileCache cache(heights());
  SelectionStats s;
  auto tiles = selectTiles(cache, view, params, &s);
  // The first frame builds only the levels below minLevel (2 + 8 tiles) and draws those.
  EXPECT_LE(cache.builtCount(), 10u);
  ASSERT_FALSE(tiles.empty());
  for (const Tile* t : tiles) EXPECT_LT(t->key.level, params.minLevel);
  EXPECT_EQ(s.standIns, static_cast<int>(tiles.size()));
  EXPECT_GT(s.pending, 0u);
  expectCovers(tiles, target, splits);

  int frames = 1;
  while (s.pending > 0 && frames < 40) {
    cache.waitIdle();
    tiles = selectTiles(cache, view, params, &s);
    ++frames;
    expectCovers(tiles, target, splits);
  }
  EXPECT_GT(frames, 5);  // refined level by level
  EXPECT_EQ(s.pending, 0u);
  EXPECT_EQ(s.standIns, 0);
  EXPECT_EQ(keysOf(tiles), target);
  EXPECT_EQ(s.visited, complete.visited);
  // Nothing was built that the complete selection does not visit, nothing twice.
  EXPECT_EQ(cache.builtCount(), static_cast<std::uint64_t>(complete.visited));
  EXPECT_EQ(cache.size(), cache.builtCount());
}

TEST(TerrainCache, ProgressiveFramesNeverRequestATileTwice) {
  // Frames in quick succession ask for the same tiles while they are queued or being built.
  const geo::CameraView view = parallelTestViews()[2].view;
  const SelectionParams params = smallParams(false);
  TileCache cache(heights());
  SelectionStats s;
  for (int round = 0; round < 40; ++round) {
    for (int i = 0; i < 4; ++i) (void)selectTiles(cache, view, params, &s);
    cache.waitIdle();
    (void)selectTiles(cache, view, params, &s);
    if (s.pending == 0) break;
  }
  EXPECT_EQ(s.pending, 0u);
  EXPECT_EQ(s.standIns, 0);
  EXPECT_EQ(cache.size(), cache.builtCount());
  EXPECT_EQ(cache.builtCount(), static_cast<std::uint64_t>(s.visited));
}

// A build function that records what it built and can be held back.
struct ScriptedBuilds {
  std::mutex mutex;
  std::map<std::uint64_t, int> count;
  std::vector<TileKey> order;
  std::atomic<bool> open{true};

  TileBuilder::BuildFn fn() {
    return [this](const TileKey& key) {
      while (!open.load()) std::this_thread::sleep_for(std::chrono::microseconds(200));
      if (key.level == 3 && key.x == 7) throw std::runtime_error("bad tile");
      {
        std::lock_guard lock(mutex);
        ++count[key.packed()];
        order.push_back(key);
      }
      Tile t;
      t.key = key;
      return t;
    };
  }
};

std::vector<TileKey> row(int level, int y, int from, int n) {
  std::vector<TileKey> keys;
  for (int x = from; x < from + n; ++x) keys.push_back({level, x, y});
  return keys;
}

TEST(TerrainBuilder, DropsStaleRequestsKeepsOrderAndBuildsEachKeyOnce) {
  ScriptedBuilds script;
  script.open = false;
  TileBuilder builder(script.fn(), 1);
  const auto stale = row(8, 1, 0, 20), fresh = row(8, 2, 0, 20);
  builder.request(stale);
  builder.request(fresh);  // the latest frame: the stale ones still queued are dropped
  builder.request(fresh);  // asked again while queued: not queued twice
  EXPECT_LE(builder.pending(), fresh.size() + 1);
  script.open = true;
  builder.build(std::vector<TileKey>{fresh[7], fresh[7], TileKey{8, 9, 9}});  // queued or new
  builder.waitIdle();
  builder.request(fresh);  // finished but not taken: not built again
  builder.waitIdle();
  const TileBuilder::Finished f = builder.takeFinished();
  EXPECT_FALSE(f.error);
  EXPECT_EQ(builder.pending(), 0u);

  int staleBuilt = 0;
  for (const TileKey& k : stale) staleBuilt += static_cast<int>(script.count.count(k.packed()));
  EXPECT_LE(staleBuilt, 1);  // at most the one the worker had started
  for (const auto& [key, n] : script.count) EXPECT_EQ(n, 1) << key;
  EXPECT_EQ(f.tiles.size(), script.count.size());
  // One worker: background requests are built in the order given.
  std::vector<TileKey> freshOrder;
  for (const TileKey& k : script.order)
    if (k.y == 2 && !(k == fresh[7])) freshOrder.push_back(k);
  std::vector<TileKey> expected = fresh;
  expected.erase(expected.begin() + 7);
  EXPECT_EQ(freshOrder, expected);
}

TEST(TerrainBuilder, WorkerExceptionsReachTheCallerAndTheBuilderGoesOn) {
  ScriptedBuilds script;
  TileBuilder builder(script.fn(), 2);
  builder.build(std::vector<TileKey>{{3, 6, 0}, {3, 7, 0}, {3, 8, 0}});
  TileBuilder::Finished f = builder.takeFinished();
  ASSERT_TRUE(f.error);
  EXPECT_THROW(std::rethrow_exception(f.error), std::runtime_error);
  EXPECT_EQ(f.tiles.size(), 2u);
  EXPECT_EQ(builder.pending(), 0u);
  builder.request(std::vector<TileKey>{{4, 1, 1}});
  builder.waitIdle();
  f = builder.takeFinished();
  EXPECT_FALSE(f.error);
  EXPECT_EQ(f.tiles.size(), 1u);
}

TEST(TerrainBuilder, DestroyedWithWorkInFlight) {
  // Joins its workers; tiles in flight are finished and dropped, queued ones never started.
  ScriptedBuilds script;
  {
    TileBuilder builder(
        [fn = script.fn()](const TileKey& key) {
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
          return fn(key);
        },
        2);
    builder.request(row(10, 3, 0, 200));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::lock_guard lock(script.mutex);
  EXPECT_LT(script.count.size(), 200u);
}

TEST(TerrainCache, WorkersDefaultToTheHardware) {
  TileCache cache(heights());
  EXPECT_GE(cache.workerCount(), 1);
  EXPECT_EQ(cache.workerCount(),
            std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
}

}  // namespace
}  // namespace og::terrain

namespace og::terrain {
namespace {

/// The keys of the tiles some pass draws (those the sea does not cover), sorted.
std::vector<std::uint64_t> drawnKeys(const std::vector<const Tile*>& tiles) {
  std::vector<std::uint64_t> keys;
  for (const Tile* t : tiles)
    if (!t->coveredBySea()) keys.push_back(t->key.packed());
  std::sort(keys.begin(), keys.end());
  return keys;
}

double highestM(const std::vector<const Tile*>& tiles) {
  double h = -1e30;
  for (const Tile* t : tiles) h = std::max(h, t->maxHeightM);
  return h;
}

}  // namespace

// bench's sea-4m view over the deep Atlantic: no pass draws the sea floor there (the water
// volume's floor is out of reach), so tiles under unseen sea floor are not split (start-up).
// Land views select exactly the same tiles with the rule as without.
TEST(TerrainSelection, UnseenSeaFloorIsNotBuiltAndWhatIsDrawnIsUnchanged) {
  constexpr double kUnseenM = 300.0;  // about twice the default water's reach
  struct Case {
    double lat, lon, altM, heading, pitch;
    int w, h;
    bool deep;
  };
  for (const Case& c : {Case{20.0, -40.0, 4.0, 270.0, -10.0, 64, 36, true},
                        Case{20.0, -40.0, 4.0, 270.0, -10.0, 1280, 720, true},
                        Case{24.2, -78.2, 3000.0, 0.0, -30.0, 320, 180, false},  // Bahamas banks
                        Case{28.0, 87.0, 15000.0, 0.0, -10.0, 320, 180, false}}) {
    const geo::CameraView view = viewAt(c.lat, c.lon, c.altM, c.heading, c.pitch, c.w, c.h);
    SelectionParams on;
    on.widthPx = c.w;
    on.heightPx = c.h;
    on.unseenFloorDepthM = kUnseenM;
    SelectionParams off = on;
    off.unseenFloorDepthM = std::numeric_limits<double>::infinity();
    TileCache withRule(heights()), without(heights());
    SelectionStats stats;
    const auto tiles = selectTiles(withRule, view, on, &stats);
    const auto every = selectTiles(without, view, off);
    const std::string where = std::to_string(c.lat) + "," + std::to_string(c.lon) + " " + std::to_string(c.w);
    // What is drawn, and the water volume's test on the highest point, are the same.
    EXPECT_EQ(drawnKeys(tiles), drawnKeys(every)) << where;
    EXPECT_EQ(highestM(tiles) > -kUnseenM, highestM(every) > -kUnseenM) << where;
    // No tile below one whose descendants are all unseen sea floor was built.
    for (const Tile* t : tiles) {
      if (t->key.level <= on.minLevel) continue;
      const TileKey parent{t->key.level - 1, t->key.x / 2, t->key.y / 2};
      ASSERT_TRUE(withRule.contains(parent));
      EXPECT_FALSE(deepSeaFloorOnly(withRule.get(parent), kUnseenM)) << where << " level " << t->key.level;
    }
    if (c.deep) {
      EXPECT_GT(stats.deepSeaFloor, 0) << where;
      // At least a quarter fewer (58 against 82 at 64x36, 94 against 154 at 1280x720; the
      // 42 tiles of levels 0-2 are always built).
      EXPECT_LT(withRule.builtCount() * 4, without.builtCount() * 3)
          << where << ": " << withRule.builtCount() << " tiles built against " << without.builtCount();
    }
    std::printf("%s: %llu tiles built with the rule, %llu without; highest selected point %.0f m\n", where.c_str(),
                static_cast<unsigned long long>(withRule.builtCount()),
                static_cast<unsigned long long>(without.builtCount()), highestM(tiles));
  }
}

}  // namespace og::terrain
