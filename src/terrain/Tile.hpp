#pragma once
// Terrain tiles: a geographic quadtree. Level 0 has two tiles (west and east hemispheres, each
// 180° x 180°); each level halves a tile's extent in latitude and longitude. A tile is a
// (kTileQuads + 1)² grid of vertices at regular latitudes/longitudes plus a skirt along its
// four edges. Vertex latitudes/longitudes come from integer positions on the finest grid, so a
// vertex shared by tiles of any levels has bit-identical coordinates, height and position.
#include <glm/glm.hpp>

#include <array>
#include <iterator>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "terrain/Heightfield.hpp"

namespace og::terrain {

inline constexpr int kTileQuads = 32;                    ///< quads along a tile edge
inline constexpr int kTileGridVertices = (kTileQuads + 1) * (kTileQuads + 1);
inline constexpr int kTileVertices = kTileGridVertices + 4 * (kTileQuads + 1);  ///< with skirts
inline constexpr int kMaxLevel = 16;                     ///< finest level (~20 m spacing)
/// The meshes of a tile's grid: every vertex, every 2nd vertex (tileIndices(stride)). The
/// coarser is drawn where it lies within a fraction of a pixel of the full grid, the fragments
/// still shaded from the full grid's vertices (render/TerrainRenderer::tileStrideIndex). (Every 4th
/// vertex: from orbit at 1280 x 720 no tile's lies within half a pixel.)
inline constexpr int kTileStrides[] = {1, 2};

struct TileKey {
  int level = 0;  ///< 0 .. kMaxLevel
  int x = 0;      ///< column from longitude -180, 0 .. 2^(level+1) - 1
  int y = 0;      ///< row from latitude -90, 0 .. 2^level - 1
  [[nodiscard]] std::uint64_t packed() const {
    return (static_cast<std::uint64_t>(level) << 56) | (static_cast<std::uint64_t>(x) << 28) |
           static_cast<std::uint64_t>(y);
  }
  [[nodiscard]] TileKey child(int i) const { return {level + 1, 2 * x + (i & 1), 2 * y + (i >> 1)}; }
  [[nodiscard]] double sizeDeg() const;      ///< extent in latitude and longitude, degrees
  [[nodiscard]] double southDeg() const;
  [[nodiscard]] double westDeg() const;
  friend bool operator==(const TileKey&, const TileKey&) = default;
};

/// Latitude and longitude (degrees) of grid vertex (i, j) (i east, j north, 0..kTileQuads) of a
/// tile, computed from its position on the finest grid so neighbours agree exactly.
void tileVertexLatLon(const TileKey& key, int i, int j, double& latDeg, double& lonDeg);

/// Per-vertex data as uploaded (float, 10 per vertex).
struct TileVertex {
  glm::vec3 position;  ///< relative to the tile centre, m (ECEF axes)
  glm::vec3 normal;    ///< unit, ECEF axes (the vertical on a tile the sea covers, never drawn: Tile::coveredBySea)
  float heightM;       ///< above sea level, m
  float latitudeRad;
  float longitudeRad;
  float detailAmplitudeM;  ///< scale of the detail's normalised sum in the pixel normals here, m (0: none; HeightSample::shadingAmplitudeM)
  /// Where the parent tile's mesh puts this vertex, minus its position, m (ECEF axes): zero at
  /// the vertices the parent shares, the midpoint of the parent's edge or diagonal elsewhere.
  /// The vertex shader morphs towards it as the tile nears its parent's detail (no popping).
  glm::vec3 morph;
};
static_assert(sizeof(TileVertex) == 52);

struct Tile {
  TileKey key;
  glm::dvec3 centreEcef{0.0};            ///< ECEF, m: the origin of the vertex positions
  std::vector<glm::dvec3> positions;     ///< relative to centreEcef, m (double, CPU side)
  std::vector<TileVertex> vertices;      ///< the same as uploaded (float)
  glm::dvec3 boundCentreEcef{0.0};       ///< bounding sphere of every vertex (skirts included)
  double boundRadiusM = 0.0;
  double minHeightM = 0.0, maxHeightM = 0.0;
  double spacingM = 0.0;                 ///< vertex spacing north-south, m
  double skirtDepthM = 0.0;              ///< how far the skirts hang below the edges, m
  /// How far the mesh of each stride after the first (kTileStrides) lies from the full grid:
  /// the most a grid vertex lies off it along its vertical (mostly the ellipsoid's curvature
  /// under a longer chord, and the relief) and across it (a chord across the grid's curved
  /// parallels and meridians), m.
  struct StrideDeviation {
    double verticalM = 0.0, horizontalM = 0.0;
    /// The same for the parts above sea level, which the shadow maps draw (terrain.vert's
    /// TERRAIN_SHADOW_CASTER clips the rest): over the grid's triangles with a corner above the
    /// sea in either mesh, their corners' largest offset, vertically no more than the highest
    /// either mesh reaches there plus the chords' curvature. 0 for a tile all under the sea.
    double aboveSeaVerticalM = 0.0, aboveSeaHorizontalM = 0.0;
  };
  std::array<StrideDeviation, std::size(kTileStrides) - 1> strideDeviation{};
  glm::dvec3 middleUp{0.0, 0.0, 1.0};  ///< the geodetic vertical at the middle vertex (unit, ECEF)
  /// The largest angle between middleUp and the geodetic vertical anywhere on the tile, rad (a
  /// cell's diagonal more than at its vertices).
  double upConeRad = 0.0;
  int normalOctaves = 0;                 ///< detail octaves in the vertex normals (the rest per pixel)
  std::uint64_t lastUsedFrame = 0;

  /// Wholly under a metre of water or more: the sea covers it (the sea pass draws the floor
  /// through the water itself, ocean/water_volume.glsl; split with less care).
  [[nodiscard]] bool coveredBySea() const { return maxHeightM < -1.0; }

  /// Memory held by the tile's CPU arrays, bytes.
  [[nodiscard]] std::size_t bytes() const {
    return sizeof(Tile) + positions.capacity() * sizeof(glm::dvec3) +
           vertices.capacity() * sizeof(TileVertex);
  }
};

/// Builds a tile from the height function. Deterministic.
Tile buildTile(const Heightfield& heights, const TileKey& key);

/// Triangle indices shared by every tile (the grid, then the skirts), counter-clockwise seen
/// from above, joining every `stride`-th vertex (1 or 2: kTileStrides) of the grid and of the
/// skirts. Every quad is split along the diagonal from (i, j) to (i + stride, j + stride).
const std::vector<std::uint32_t>& tileIndices(int stride = 1);
/// How many of tileIndices(stride) are the grid's (the skirts' follow).
int tileGridIndexCount(int stride);

/// Closed-form geodetic -> ECEF (m): the same arithmetic for every caller, so shared vertices
/// match bit for bit.
glm::dvec3 geodeticToEcefFast(double latDeg, double lonDeg, double heightM);

/// The geodetic normal (unit, ECEF axes) at a latitude/longitude in degrees, closed form.
glm::dvec3 geodeticUpFast(double latDeg, double lonDeg);

}  // namespace og::terrain
