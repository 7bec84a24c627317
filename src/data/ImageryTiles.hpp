#pragma once
// Imagery layers as streamed tiles (docs/data.md, "How imagery streams"). A user layer finer
// than its whole-layer texture (data::kImageryLayerSizePx² over its extent) is also read as a
// quadtree of kImageryTilePx² tiles on the terrain's own latitude/longitude grid
// (terrain/Tile.hpp: level 0 = two 180° × 180° tiles, each level halves them), straight from
// GDAL (a window warped to EPSG:4326; GDAL uses the file's overviews when reading coarser than
// the source), from the first level finer than the whole-layer texture down to the level whose
// texels match the source's resolution. Decoded tiles (with their mip-maps) are kept in a CPU
// cache in least-recently-used order under a byte budget, filled by background workers
// (core::BuildPool, as the terrain's tiles are).
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/BuildPool.hpp"
#include "data/GeoRaster.hpp"

namespace og::data {

/// Texels along the side of a tile's interior (the quadtree tile itself), level 0.
inline constexpr int kImageryTilePx = 256;
/// Border texels stored around the interior on every side: the source read past the tile's
/// edges (its neighbours' edge texels, on the same grid), so that linear filtering at an edge
/// blends with the neighbour as inside one texture instead of clamping (a half-texel seam when
/// magnified). 4 level-0 texels are one whole texel of mip level 2 and half one of level 3,
/// where the interior's edge falls on a texel centre, so filtering at the edge is exact down to
/// level 3 (8 × 8 level-0 texels a texel); the coarser levels (sampled where a pixel covers 16
/// level-0 texels or more) clamp at most a quarter of their texel past the border.
inline constexpr int kImageryTileBorderPx = 4;
/// Texels along a stored tile's side, borders included (level 0 of its mip chain): 264.
inline constexpr int kImageryTileStoredPx = kImageryTilePx + 2 * kImageryTileBorderPx;
/// Mip levels of a stored tile, 264² down to 1² as GL sizes them (264, 132, 66, 33, 16, ... 1).
inline constexpr int kImageryTileMips = 9;
/// Side of mip level m (0 .. kImageryTileMips - 1) of a stored tile, texels: floor(264 / 2^m).
constexpr int imageryTileMipPx(int m) { return (kImageryTileStoredPx >> m) > 0 ? kImageryTileStoredPx >> m : 1; }
static_assert((kImageryTileStoredPx >> (kImageryTileMips - 1)) == 1, "the mip chain ends at 1 texel");
/// Finest tile level (the terrain's kMaxLevel: ~2.7 m texels).
inline constexpr int kImageryMaxLevel = 16;

struct ImageryTileKey {
  int layer = 0;  ///< index of the user layer, 0 .. kMaxImageryLayers - 1
  int level = 0;  ///< 0 .. kImageryMaxLevel, as terrain::TileKey
  int x = 0;      ///< column from longitude -180°, 0 .. 2^(level+1) - 1
  int y = 0;      ///< row from latitude -90°, 0 .. 2^level - 1
  [[nodiscard]] std::uint64_t packed() const {
    return (static_cast<std::uint64_t>(layer) << 60) | (static_cast<std::uint64_t>(level) << 55) |
           (static_cast<std::uint64_t>(x) << 27) | static_cast<std::uint64_t>(y);
  }
  [[nodiscard]] double sizeDeg() const { return 180.0 / static_cast<double>(1 << level); }
  [[nodiscard]] double westDeg() const { return -180.0 + x * sizeDeg(); }
  [[nodiscard]] double southDeg() const { return -90.0 + y * sizeDeg(); }
  /// Side of a level-0 texel, degrees.
  [[nodiscard]] double texelDeg() const { return sizeDeg() / kImageryTilePx; }
  /// The tile `levels` levels up (levels <= level).
  [[nodiscard]] ImageryTileKey ancestor(int levels) const { return {layer, level - levels, x >> levels, y >> levels}; }
  friend bool operator==(const ImageryTileKey&, const ImageryTileKey&) = default;
};

/// Bytes of a tile's texels with its borders and mip chain.
std::size_t imageryTileBytes();

/// Byte offset of mip level m in ImageryTile::rgba.
std::size_t imageryTileMipOffset(int m);

struct ImageryTile {
  ImageryTileKey key;
  /// sRGB RGBA texels, rows south to north, alpha = coverage: the kImageryTileMips levels one
  /// after the other (imageryTileMipPx(m)² each, borders included), each the mean of the one
  /// before over its footprint in linear colour.
  std::vector<std::uint8_t> rgba;
  std::uint64_t lastUsedFrame = 0;
  [[nodiscard]] std::size_t bytes() const { return sizeof(ImageryTile) + rgba.capacity(); }
  /// Channel c of level-0 texel (x, y) counted from the interior's south-west texel: 0 ..
  /// kImageryTilePx - 1 inside, -kImageryTileBorderPx .. -1 and kImageryTilePx .. in the border.
  [[nodiscard]] std::uint8_t texel(int x, int y, int c) const {
    const auto s = static_cast<std::size_t>(kImageryTileStoredPx);
    return rgba[((static_cast<std::size_t>(y + kImageryTileBorderPx)) * s + static_cast<std::size_t>(x + kImageryTileBorderPx)) * 4 +
                static_cast<std::size_t>(c)];
  }
};

/// One user layer's tiles. read() is thread-safe (each thread reads with its own GDAL handle).
class ImageryTileSource {
 public:
  /// Opens `path` (georeferenced imagery GDAL reads; named by it in messages) as layer `layer`
  /// whose whole-layer texture is `wholePx`² texels. Throws og::InputError "FILE: problem".
  ImageryTileSource(const std::string& path, int layer, int wholePx);

  [[nodiscard]] int layer() const { return layer_; }
  [[nodiscard]] const GeoFootprint& footprint() const { return footprint_; }
  /// Levels streamed: minLevel() .. maxLevel(); none when minLevel() > maxLevel() (the
  /// whole-layer texture already holds every detail of the source).
  [[nodiscard]] int minLevel() const { return minLevel_; }
  [[nodiscard]] int maxLevel() const { return maxLevel_; }
  /// Whether the tile overlaps the layer's footprint.
  [[nodiscard]] bool overlaps(const ImageryTileKey& key) const;
  /// Reads a tile with its borders (kImageryTileBorderPx texels past each edge; past a pole the
  /// edge row repeated; across the antimeridian of a source that goes round the globe, read
  /// from its other end) and mip-maps it. Throws og::InputError "FILE: problem" (truncated).
  [[nodiscard]] ImageryTile read(const ImageryTileKey& key) const;

 private:
  /// Level 0 of a stored tile (kImageryTileStoredPx², borders included), as read() describes.
  [[nodiscard]] std::vector<std::uint8_t> readBordered(const GeoImageReader& reader, const ImageryTileKey& key) const;

  std::string path_;
  int layer_;
  GeoFootprint footprint_;
  int minLevel_ = 1;
  int maxLevel_ = 0;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<GeoImageReader>> idle_;  // handles no thread is using
};

/// Decoded tiles in least-recently-used order under a byte budget that is never exceeded
/// (tiles are uploaded to the GPU as they arrive, so any of them may go). Only the thread that
/// owns the cache (the render thread) calls it.
class ImageryTileCache {
 public:
  /// `sources` indexed by layer (nullptr: a layer without tiles). `budgetBytes` >= one tile.
  ImageryTileCache(std::vector<std::shared_ptr<const ImageryTileSource>> sources, std::size_t budgetBytes,
                   int workers = 2);

  /// Takes the tiles the workers finished (rethrowing the first exception one of them threw:
  /// a file that cannot be read any more ends the program with its message) and evicts to
  /// the budget. Returns the keys that arrived.
  std::vector<ImageryTileKey> collect();
  /// The cached tile (marked most recently used) or nullptr.
  const ImageryTile* find(const ImageryTileKey& key);
  /// Whether the tile is cached (its use unchanged).
  [[nodiscard]] bool contains(const ImageryTileKey& key) const { return map_.count(key.packed()) != 0; }
  /// Background requests, most wanted first, replacing earlier ones still queued.
  void request(std::span<const ImageryTileKey> keys);
  /// Reads these keys now (in parallel) and collects them; returns the keys that arrived.
  std::vector<ImageryTileKey> build(std::span<const ImageryTileKey> keys);
  [[nodiscard]] bool pending(const ImageryTileKey& key) const { return pool_.isPending(key); }
  [[nodiscard]] std::size_t pendingCount() const { return pool_.pending(); }
  void waitIdle() { pool_.waitIdle(); }

  [[nodiscard]] const ImageryTileSource* source(int layer) const;
  [[nodiscard]] std::size_t bytes() const { return bytes_; }
  [[nodiscard]] std::size_t budgetBytes() const { return budget_; }
  [[nodiscard]] std::size_t size() const { return map_.size(); }
  [[nodiscard]] std::uint64_t evictions() const { return evictions_; }
  [[nodiscard]] std::uint64_t readCount() const { return reads_; }

 private:
  std::list<ImageryTile> lru_;  // front = most recently used; each key once
  std::unordered_map<std::uint64_t, std::list<ImageryTile>::iterator> map_;  // by packed key
  std::vector<std::shared_ptr<const ImageryTileSource>> sources_;
  std::size_t budget_, bytes_ = 0;
  std::uint64_t evictions_ = 0, reads_ = 0;
  // Last: its workers are joined before the rest of the cache is destroyed.
  core::BuildPool<ImageryTileKey, ImageryTile> pool_;
};

}  // namespace og::data
