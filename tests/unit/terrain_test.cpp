// Terrain LOD on the CPU: tile selection, crack-free seams, the cache's memory bound and the
// procedural detail's continuity.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <set>
#include <tuple>

#include "data/Elevation.hpp"
#include "geo/Camera.hpp"
#include "terrain/Heightfield.hpp"
#include "terrain/Selection.hpp"
#include "terrain/Tile.hpp"
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

}  // namespace
}  // namespace og::terrain
