#pragma once
// The user layers' streamed tiles on the GPU (data/ImageryTiles.hpp; docs/data.md, "How
// imagery streams"): a 2D texture array of tile slots (sRGB, mip-mapped, kImageryTilePx²),
// grown on demand up to a byte budget and recycled in least-recently-used order, fed from the
// CPU cache. Each terrain tile drawn samples, per layer, the finest resident imagery tile that
// covers it: its own level's tile when resident, else the nearest resident ancestor (the texels
// scaled onto the terrain tile), else the layer's whole texture. Slots hold the tiles with their
// borders (data::kImageryTileBorderPx), so filtering blends across tile edges. A tile that arrives replaces
// its stand-in at once (no blend): the change is of texel size only, at the terrain's own tile
// boundaries, like the terrain's own LOD.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "data/ImageryTiles.hpp"
#include "geo/Camera.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "terrain/Tile.hpp"

namespace og::render {

/// Imagery tile cache use, for bench and the viewer.
struct ImageryTileStats {
  std::size_t cpuTiles = 0, cpuBytes = 0;  ///< decoded tiles in the CPU cache
  std::size_t gpuTiles = 0, gpuBytes = 0;  ///< tiles resident on the GPU; bytes allocated for slots
  std::size_t pending = 0;                 ///< tiles being read in the background
  std::uint64_t reads = 0;                 ///< tiles read from the files so far
  std::uint64_t cpuEvictions = 0, gpuEvictions = 0;
  int finestLevel = -1;                    ///< finest tile level drawn in the last frame (-1: none)
};

class ImageryTiles {
 public:
  /// `sources` indexed by layer (nullptr where a layer has no tiles). Budgets in bytes: the
  /// CPU cache's and the GPU slots' (at least one tile each). Needs a current GL context.
  ImageryTiles(std::vector<std::shared_ptr<const data::ImageryTileSource>> sources, std::size_t cpuBudgetBytes,
               std::size_t gpuBudgetBytes);

  /// Before the terrain draws `drawn`: uploads the tiles they want that have arrived and asks
  /// for the missing ones, in the background, or with `wait` reads them first (render, record).
  /// In the background each wanted tile's ancestors (down to the layer's first streamed level)
  /// are uploaded and kept resident with it, and asked for before it, coarse first: the first
  /// to arrive stands in, so a fast descent shows a coarser tile, not the whole texture.
  void prepare(std::span<const terrain::TileKey> drawn, bool wait);
  /// Asks in the background, after the frame's own requests, for the tiles a coming view will
  /// want (viewer: the camera a second ahead; record: the next frame), with their ancestors:
  /// those the terrain's split rule (terrain::SelectionParams) would pick there, judged on
  /// spheres round the tiles' ground, not on built terrain tiles. Until the next prefetch().
  void prefetch(const geo::CameraView& view, int widthPx, int heightPx);
  /// The imagery tiles `view` would want (keysForView), without ancestors, per layer.
  [[nodiscard]] std::vector<data::ImageryTileKey> keysForView(const geo::CameraView& view, int widthPx,
                                                              int heightPx) const;
  /// Whether `key` is on the GPU, in the CPU cache, or asked for (queued, being read, read).
  [[nodiscard]] bool residentOrRequested(const data::ImageryTileKey& key) const;
  /// The layer's tile wanted for drawing terrain tile `key` (level < 0: none).
  [[nodiscard]] data::ImageryTileKey wanted(int layer, const terrain::TileKey& key) const;
  /// Sets imagery.glsl's per-draw tile uniforms for terrain tile `key` on `program`.
  void bindTile(const gl::Program& program, const terrain::TileKey& key);
  /// Sets the per-draw uniforms to "no tiles" (the whole layer textures), e.g. the globe pass.
  static void bindNone(const gl::Program& program);
  /// Waits for the background reads (tests, benchmarks); the next prepare() uploads them.
  void waitIdle() { cache_.waitIdle(); }

  [[nodiscard]] ImageryTileStats stats() const;
  [[nodiscard]] std::size_t gpuBudgetBytes() const { return maxSlots_ * slotBytes_; }

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint64_t lastUsedFrame = 0;
    bool used = false;
  };
  /// `keys` with their ancestors down to their layer's first streamed level, each once, coarse
  /// levels first.
  [[nodiscard]] std::vector<data::ImageryTileKey> withAncestors(std::span<const data::ImageryTileKey> keys) const;
  /// Asks the workers for missing_ then prefetch_ (those not resident), replacing older requests.
  void requestMissing();
  /// The slot holding `key`, or -1.
  [[nodiscard]] int slotOf(const data::ImageryTileKey& key) const;
  /// Uploads a cached tile to a free or least recently used slot; -1 when every slot is in use
  /// this frame.
  int upload(const data::ImageryTile& tile);
  int freeSlot();
  void grow();
  void uploadArrived(std::span<const data::ImageryTileKey> keys);

  data::ImageryTileCache cache_;
  std::size_t slotBytes_;
  std::size_t maxSlots_;
  gl::Texture texture_;
  std::vector<Slot> slots_;  // size = the texture's layers
  std::unordered_map<std::uint64_t, int> slotByKey_;
  std::vector<data::ImageryTileKey> missing_;   ///< the last prepare()'s tiles not yet read
  std::vector<data::ImageryTileKey> prefetch_;  ///< the last prefetch()'s tiles
  std::uint64_t frame_ = 1;
  std::uint64_t gpuEvictions_ = 0;
  int finestLevel_ = -1;
};

}  // namespace og::render
