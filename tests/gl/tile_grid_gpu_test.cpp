// terrain/tile_grid.glsl against the tile it reads: the fragments of a tile drawn from a coarser
// mesh (TERRAIN_COARSE) take their normal, height and detail amplitude from the full grid's
// triangle where they lie (render/TerrainRenderer::tileStrideIndex). Probed at every vertex
// (the grid's and the skirts' lowered ones: their places from gl_VertexID) and inside cells,
// against the triangles terrain::tileIndices() draws.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "data/Elevation.hpp"
#include "gl/Context.hpp"
#include "gl/Objects.hpp"
#include "gl/Probe.hpp"
#include "gl/Shader.hpp"
#include "gl/ShaderContract.hpp"
#include "terrain/Heightfield.hpp"
#include "terrain/Tile.hpp"

using namespace og;

namespace {
// A value of the full grid at place (x, y): linear over the triangle of terrain::tileIndices()
// that holds the point (the grid's part), found by its barycentric coordinates.
template <class Value>
auto gridValueAt(const std::vector<std::uint32_t>& grid, double x, double y, Value value) {
  constexpr int n = terrain::kTileQuads + 1;
  auto place = [](std::uint32_t k) { return glm::dvec2(k % n, k / n); };
  for (std::size_t t = 0; t + 2 < grid.size(); t += 3) {
    const glm::dvec2 a = place(grid[t]), b = place(grid[t + 1]), c = place(grid[t + 2]);
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double u = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
    const double v = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
    if (u >= -1e-9 && v >= -1e-9 && u + v <= 1.0 + 1e-9)
      return value(grid[t]) * (1.0 - u - v) + value(grid[t + 1]) * u + value(grid[t + 2]) * v;
  }
  ADD_FAILURE() << "no triangle holds " << x << ", " << y;
  return value(grid[0]);
}
}  // namespace

TEST(TileGridGpu, FullGridReadAtEveryVertexAndInsideItsTriangles) {
  const auto context = gl::createHeadlessContext();
  const terrain::Heightfield heights(std::make_shared<const data::LatLonGrid>(data::defaultElevation()));
  const terrain::Tile tile = terrain::buildTile(heights, terrain::TileKey{9, 759, 335});  // the Himalaya
  const gl::Buffer vertices = gl::createBuffer();
  glNamedBufferStorage(vertices.id(), static_cast<GLsizeiptr>(tile.vertices.size() * sizeof(terrain::TileVertex)),
                       tile.vertices.data(), 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kTileVerticesBinding, vertices.id());
  const gl::Program probe({{GL_COMPUTE_SHADER, "terrain/tile_grid_probe.comp"}});
  probe.set("uSkirtDepthM", static_cast<float>(tile.skirtDepthM));

  // Every vertex: its own normal and height (a skirt's lowered copy: its edge's, less the depth).
  std::vector<glm::vec4> values;
  for (int k = 0; k < terrain::kTileVertices; ++k) values.emplace_back(static_cast<float>(k), 0.0f, 0.0f, 0.0f);
  gl::runProbe(probe, values, static_cast<int>(values.size()), "tile grid probe, vertices");
  for (std::size_t k = 0; k < values.size(); ++k) {
    const terrain::TileVertex& v = tile.vertices[k];
    EXPECT_LT(glm::length(glm::vec3(values[k]) - v.normal), 1e-6f) << "vertex " << k;
    EXPECT_NEAR(values[k].w, v.heightM, 1e-3f * std::max(1.0f, std::abs(v.heightM))) << "vertex " << k;
  }

  // Inside cells, on both sides of their diagonals: the triangles tileIndices() draws.
  const std::vector<std::uint32_t> indices = terrain::tileIndices();
  const std::vector<std::uint32_t> grid(indices.begin(), indices.begin() + terrain::tileGridIndexCount(1));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> along(0.0, terrain::kTileQuads);
  std::vector<glm::dvec2> places;
  for (int s = 0; s < 400; ++s) places.emplace_back(along(rng), along(rng));
  values.clear();
  for (const glm::dvec2& p : places) values.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y), 0.0f, 1.0f);
  for (const glm::dvec2& p : places) values.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y), 0.0f, 2.0f);
  gl::runProbe(probe, values, static_cast<int>(values.size()), "tile grid probe, places");
  double worstNormal = 0.0, worstHeight = 0.0, worstAmplitude = 0.0;
  for (std::size_t s = 0; s < places.size(); ++s) {
    const glm::dvec2& p = places[s];
    const auto& vs = tile.vertices;
    const glm::dvec3 normal = gridValueAt(grid, p.x, p.y, [&](std::uint32_t k) { return glm::dvec3(vs[k].normal); });
    const double height = gridValueAt(grid, p.x, p.y, [&](std::uint32_t k) { return double{vs[k].heightM}; });
    const double amplitude = gridValueAt(grid, p.x, p.y, [&](std::uint32_t k) { return double{vs[k].detailAmplitudeM}; });
    worstNormal = std::max(worstNormal, glm::length(glm::dvec3(values[s]) - normal));
    worstHeight = std::max(worstHeight, std::abs(static_cast<double>(values[s].w) - height));
    worstAmplitude = std::max(worstAmplitude, std::abs(static_cast<double>(values[places.size() + s].x) - amplitude));
  }
  std::printf("inside cells: worst normal %.2e, height %.2e m, detail amplitude %.2e m (relief %.0f m)\n",
              worstNormal, worstHeight, worstAmplitude, tile.maxHeightM - tile.minHeightM);
  EXPECT_LT(worstNormal, 1e-5);
  EXPECT_LT(worstHeight, 1e-2);  // float weights over heights of thousands of metres
  EXPECT_LT(worstAmplitude, 1e-3);
}
