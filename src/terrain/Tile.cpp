#include "terrain/Tile.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geo/Wgs84.hpp"

namespace og::terrain {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
// Finest grid: kTileQuads << kMaxLevel steps over 180° (a power of two, so the step is exact).
constexpr double kFineStepDeg = 180.0 / static_cast<double>(static_cast<std::int64_t>(kTileQuads) << kMaxLevel);

// The grid vertex (row-major index) that is vertex s (0..kTileQuads) of edge e: 0 south, 1
// east, 2 north, 3 west, the skirts' order (terrain/tile_grid.glsl's tileGridPlace too).
constexpr std::uint32_t edgeVertex(std::uint32_t e, std::uint32_t s) {
  constexpr std::uint32_t n = kTileQuads + 1;
  const std::uint32_t i = e == 0 ? s : e == 1 ? n - 1 : e == 2 ? s : 0;
  const std::uint32_t j = e == 0 ? 0 : e == 1 ? s : e == 2 ? n - 1 : s;
  return j * n + i;
}

// How far the mesh of every `stride`-th vertex lies from the (kTileQuads + 1)² grid `ecef`
// (row-major, m; verticals `up`, heights above the ellipsoid `heightM`), its quads split as
// tileIndices(stride) splits them.
Tile::StrideDeviation strideDeviation(const std::vector<glm::dvec3>& ecef, const std::vector<glm::dvec3>& up,
                                      const std::vector<double>& heightM, int stride) {
  constexpr int n = kTileQuads + 1;
  auto at = [&](int i, int j) { return ecef[static_cast<std::size_t>(j * n + i)]; };
  auto heightAt = [&](int i, int j) { return heightM[static_cast<std::size_t>(j * n + i)]; };
  // Per grid vertex: its offset from the coarser mesh along its vertical and across it, and
  // the coarser mesh's height there (interpolated as its point is).
  struct Off {
    double vertical, across, fine, coarse;
  };
  std::vector<Off> offs(static_cast<std::size_t>(n * n));
  Tile::StrideDeviation worst;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int i0 = std::min(i / stride * stride, kTileQuads - stride);
      const int j0 = std::min(j / stride * stride, kTileQuads - stride);
      const double fx = static_cast<double>(i - i0) / stride, fy = static_cast<double>(j - j0) / stride;
      // Triangle a, b, d below the diagonal, a, d, c above it (of a quantity q at the corners).
      auto interpolate = [&](auto q) {
        const auto a = q(i0, j0), b = q(i0 + stride, j0), c = q(i0, j0 + stride), d = q(i0 + stride, j0 + stride);
        return fx >= fy ? a + fx * (b - a) + fy * (d - b) : a + fy * (c - a) + fx * (d - c);
      };
      const glm::dvec3 off = at(i, j) - interpolate(at);
      const glm::dvec3& u = up[static_cast<std::size_t>(j * n + i)];
      const double along = glm::dot(off, u);
      Off& o = offs[static_cast<std::size_t>(j * n + i)];
      o = {std::abs(along), glm::length(off - along * u), heightAt(i, j), interpolate(heightAt)};
      worst.verticalM = std::max(worst.verticalM, o.vertical);
      worst.horizontalM = std::max(worst.horizontalM, o.across);
    }
  // Above the sea, per triangle of the grid (on which both meshes are linear, the coarser one's
  // triangles being unions of the grid's): where any corner lies above the sea in either mesh,
  // the two clipped surfaces lie apart by at most the corners' largest offset, and by at most
  // the highest either reaches there (where one is under the sea, the other's height), plus the
  // chords' curvature. Corners under the sea count: the part above it between them and a
  // corner above depends on them.
  auto aboveSea = [&](std::initializer_list<const Off*> corners) {
    double vertical = 0.0, across = 0.0, highest = 0.0, curvature = 0.0;
    bool above = false;
    for (const Off* o : corners) {
      above = above || o->fine > 0.0 || o->coarse > 0.0;
      vertical = std::max(vertical, o->vertical);
      across = std::max(across, o->across);
      highest = std::max({highest, o->fine, o->coarse});
      curvature = std::max(curvature, o->vertical - std::abs(o->fine - o->coarse));
    }
    if (!above) return;
    worst.aboveSeaVerticalM = std::max(worst.aboveSeaVerticalM, std::min(vertical, highest + std::max(curvature, 0.0)));
    worst.aboveSeaHorizontalM = std::max(worst.aboveSeaHorizontalM, across);
  };
  auto o = [&](int i, int j) { return &offs[static_cast<std::size_t>(j * n + i)]; };
  for (int j = 0; j < kTileQuads; ++j)
    for (int i = 0; i < kTileQuads; ++i) {  // a, b, d and a, d, c (terrain::tileIndices)
      aboveSea({o(i, j), o(i + 1, j), o(i + 1, j + 1)});
      aboveSea({o(i, j), o(i + 1, j + 1), o(i, j + 1)});
    }
  return worst;
}
}  // namespace

double TileKey::sizeDeg() const { return 180.0 / static_cast<double>(1 << level); }
double TileKey::southDeg() const { return -90.0 + y * sizeDeg(); }
double TileKey::westDeg() const { return -180.0 + x * sizeDeg(); }

void tileVertexLatLon(const TileKey& key, int i, int j, double& latDeg, double& lonDeg) {
  const std::int64_t step = std::int64_t{1} << (kMaxLevel - key.level);
  const std::int64_t u = (static_cast<std::int64_t>(key.x) * kTileQuads + i) * step;
  const std::int64_t v = (static_cast<std::int64_t>(key.y) * kTileQuads + j) * step;
  latDeg = static_cast<double>(v) * kFineStepDeg - 90.0;
  lonDeg = static_cast<double>(u) * kFineStepDeg - 180.0;
}

glm::dvec3 geodeticToEcefFast(double latDeg, double lonDeg, double heightM) {
  const double a = geo::kWgs84SemiMajorM;
  const double b = geo::kWgs84SemiMinorM;
  const double e2 = 1.0 - (b * b) / (a * a);
  const double lat = latDeg * kDeg, lon = lonDeg * kDeg;
  const double s = std::sin(lat), c = std::cos(lat);
  const double n = a / std::sqrt(1.0 - e2 * s * s);
  return {(n + heightM) * c * std::cos(lon), (n + heightM) * c * std::sin(lon),
          (n * (1.0 - e2) + heightM) * s};
}

glm::dvec3 geodeticUpFast(double latDeg, double lonDeg) {
  const double lat = latDeg * kDeg, lon = lonDeg * kDeg;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

Tile buildTile(const Heightfield& heights, const TileKey& key) {
  constexpr int n = kTileQuads + 1;
  Tile t;
  t.key = key;
  t.spacingM = key.sizeDeg() / kTileQuads * kDeg * geo::kWgs84SemiMajorM;
  const double midLat = key.southDeg() + 0.5 * key.sizeDeg();
  const double midLon = key.westDeg() + 0.5 * key.sizeDeg();
  t.centreEcef = geodeticToEcefFast(midLat, midLon, 0.0);

  // The mesh's normals carry the detail octaves at least four vertex spacings long (which it
  // resolves); the fragment shader adds the finer ones.
  t.normalOctaves = heights.octaves().countAtLeast(4.0 * t.spacingM);
  const double stepDeg = 0.5 * std::max(key.sizeDeg() / kTileQuads, heights.layer().dLatDeg);

  std::vector<HeightSample> samples(static_cast<std::size_t>(n * n));
  std::vector<glm::dvec3> ecef(static_cast<std::size_t>(n * n)), gradients(static_cast<std::size_t>(n * n));
  std::vector<double> lats(static_cast<std::size_t>(n * n)), lons(static_cast<std::size_t>(n * n));
  t.minHeightM = 1e30;
  t.maxHeightM = -1e30;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(j * n + i);
      tileVertexLatLon(key, i, j, lats[k], lons[k]);
      samples[k] = heights.sampleHeight(lats[k], lons[k], t.normalOctaves, &gradients[k]);
      const double h = samples[k].heightM;
      ecef[k] = geodeticToEcefFast(lats[k], lons[k], h);
      t.minHeightM = std::min(t.minHeightM, h);
      t.maxHeightM = std::max(t.maxHeightM, h);
    }
  std::vector<glm::dvec3> ups(lats.size());
  for (std::size_t k = 0; k < lats.size(); ++k) ups[k] = geodeticUpFast(lats[k], lons[k]);
  // Normals (four more layer samples a vertex) only where a tile can be drawn: the sea hides a
  // tile it covers everywhere it is seen (TerrainRenderer::tilesToDraw), whose vertical stands
  // in. Most tiles a view near the open sea visits are such (docs/performance.md, start-up).
  for (std::size_t k = 0; k < samples.size(); ++k)
    samples[k].normal = t.coveredBySea() ? ups[k]
                                         : heights.normalAt(lats[k], lons[k], stepDeg, gradients[k],
                                                            samples[k].shadingAmplitudeM);

  // Skirt depth: hides the gaps at T-junctions with coarser neighbours, which are at most the
  // height differences across a cell of this tile.
  const double skirt = std::clamp(0.5 * (t.maxHeightM - t.minHeightM) + 0.1 * t.spacingM, 20.0, 20000.0);
  t.skirtDepthM = skirt;
  std::vector<double> heightsM(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) heightsM[k] = samples[k].heightM;
  for (std::size_t k = 1; k < std::size(kTileStrides); ++k)
    t.strideDeviation[k - 1] = strideDeviation(ecef, ups, heightsM, kTileStrides[k]);
  t.middleUp = ups[static_cast<std::size_t>((n / 2) * n + n / 2)];
  double leastCos = 1.0;
  for (const glm::dvec3& u : ups) leastCos = std::min(leastCos, glm::dot(t.middleUp, u));
  t.upConeRad = std::acos(std::clamp(leastCos, -1.0, 1.0)) + std::sqrt(2.0) * key.sizeDeg() / kTileQuads * kDeg;

  t.positions.reserve(kTileVertices);
  t.vertices.reserve(kTileVertices);
  // Morph targets: the parent's mesh at each vertex. A parent quad covers 2x2 of ours and is
  // split along the same diagonal (indices a, b, d / a, d, c: from (i, j) to (i+1, j+1)).
  std::vector<glm::dvec3> morph(static_cast<std::size_t>(n * n), glm::dvec3(0.0));
  auto at = [&](int i, int j) { return ecef[static_cast<std::size_t>(j * n + i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // Parity on the finest grid's lattice of the parent: the parent's vertices are ours at
      // even global indices (x * kTileQuads + i), i.e. even i and j since kTileQuads is even.
      const bool oddI = (i & 1) != 0, oddJ = (j & 1) != 0;
      glm::dvec3 target = at(i, j);
      if (oddI && oddJ)
        target = 0.5 * (at(i - 1, j - 1) + at(i + 1, j + 1));
      else if (oddI)
        target = 0.5 * (at(i - 1, j) + at(i + 1, j));
      else if (oddJ)
        target = 0.5 * (at(i, j - 1) + at(i, j + 1));
      morph[static_cast<std::size_t>(j * n + i)] = target - at(i, j);
    }

  auto push = [&](std::size_t k, double depth) {
    const double lat = lats[k] * kDeg, lon = lons[k] * kDeg;
    const glm::dvec3 p = ecef[k] - depth * ups[k] - t.centreEcef;
    t.positions.push_back(p);
    t.vertices.push_back({glm::vec3(p), glm::vec3(samples[k].normal),
                          static_cast<float>(samples[k].heightM - depth), static_cast<float>(lat),
                          static_cast<float>(lon), static_cast<float>(samples[k].shadingAmplitudeM),
                          glm::vec3(morph[k])});
  };
  for (std::size_t k = 0; k < samples.size(); ++k) push(k, 0.0);
  // Skirts: south edge, east edge, north edge, west edge, each kTileQuads + 1 vertices.
  for (std::uint32_t e = 0; e < 4; ++e)
    for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(n); ++s) push(edgeVertex(e, s), skirt);

  // Bounding sphere about the tile's middle vertex: the mesh lies in the vertices' hull.
  t.boundCentreEcef = t.centreEcef + t.positions[static_cast<std::size_t>((n / 2) * n + n / 2)];
  double r2 = 0.0;
  for (const auto& p : t.positions) {
    const glm::dvec3 d = p + t.centreEcef - t.boundCentreEcef;
    r2 = std::max(r2, glm::dot(d, d));
  }
  t.boundRadiusM = std::sqrt(r2) * 1.0001 + 1.0;
  return t;
}

namespace {
std::vector<std::uint32_t> makeTileIndices(std::uint32_t stride) {
  constexpr std::uint32_t n = kTileQuads + 1;
  const std::uint32_t quads = kTileQuads / stride;
  std::vector<std::uint32_t> v;
  v.reserve(6 * quads * quads + 4 * 6 * quads);
  for (std::uint32_t j = 0; j < kTileQuads; j += stride)
    for (std::uint32_t i = 0; i < kTileQuads; i += stride) {
      const std::uint32_t a = j * n + i, b = a + stride, c = a + stride * n, d = c + stride;
      v.insert(v.end(), {a, b, d, a, d, c});
    }
  // Skirt strips: edge vertex s of edge e joined to its lowered copy.
  for (std::uint32_t e = 0; e < 4; ++e)
    for (std::uint32_t s = 0; s < kTileQuads; s += stride) {
      const std::uint32_t top0 = edgeVertex(e, s), top1 = edgeVertex(e, s + stride);
      const std::uint32_t low0 = n * n + e * n + s, low1 = low0 + stride;
      v.insert(v.end(), {top0, top1, low1, top0, low1, low0});
    }
  return v;
}

int strideIndex(int stride) {
  for (std::size_t k = 0; k < std::size(kTileStrides); ++k)
    if (kTileStrides[k] == stride) return static_cast<int>(k);
  throw std::invalid_argument("terrain tile stride " + std::to_string(stride) + " is not one of terrain::kTileStrides");
}
}  // namespace

const std::vector<std::uint32_t>& tileIndices(int stride) {
  static const std::array<std::vector<std::uint32_t>, std::size(kTileStrides)> indices = [] {
    std::array<std::vector<std::uint32_t>, std::size(kTileStrides)> a;
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = makeTileIndices(static_cast<std::uint32_t>(kTileStrides[k]));
    return a;
  }();
  return indices[static_cast<std::size_t>(strideIndex(stride))];
}

int tileGridIndexCount(int stride) {
  const int quads = kTileQuads / kTileStrides[strideIndex(stride)];
  return 6 * quads * quads;
}

}  // namespace og::terrain
