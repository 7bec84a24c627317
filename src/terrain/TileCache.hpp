#pragma once
// Tiles built on demand and kept in least-recently-used order under a byte budget. Tiles used
// in the current frame are never evicted (the budget can then be exceeded for that frame).
// Builds run on a worker pool (TileBuilder): blocking and in parallel (buildMissing), or in the
// background (request). Only the thread that owns the cache (the render thread) touches it.
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "terrain/Heightfield.hpp"
#include "terrain/Tile.hpp"
#include "terrain/TileBuilder.hpp"

namespace og::terrain {

class TileCache {
 public:
  /// `budgetBytes`: the CPU memory the cached tiles may hold (default 96 MiB, ~1050 tiles).
  /// `workers`: build threads, <= 0 for std::thread::hardware_concurrency().
  explicit TileCache(std::shared_ptr<const Heightfield> heights,
                     std::size_t budgetBytes = std::size_t{96} << 20, int workers = 0);

  /// Starts a frame: takes the tiles the workers finished in the background (rethrowing an
  /// exception one of them threw); tiles fetched from now on are protected from eviction until
  /// the next call.
  void beginFrame();
  /// The tile, built now if not cached; marks it used in this frame. Valid until the tile is
  /// evicted (not before the next beginFrame()).
  const Tile& get(const TileKey& key);
  [[nodiscard]] bool contains(const TileKey& key) const { return map_.count(key.packed()) != 0; }
  /// Builds the keys not cached, in parallel, and waits for them (they are then protected
  /// until the next beginFrame()).
  void buildMissing(std::span<const TileKey> keys);
  /// Asks the workers for these keys (those not cached) in the background, most wanted first;
  /// replaces the requests of earlier calls still queued. They arrive at a later beginFrame().
  void request(std::span<const TileKey> keys);
  /// Tiles requested or being built and not yet in the cache.
  [[nodiscard]] std::size_t pending() const { return builder_.pending(); }
  /// Blocks until the workers are idle (tests, benchmarks); the next beginFrame() takes the tiles.
  void waitIdle() { builder_.waitIdle(); }

  [[nodiscard]] std::size_t bytes() const { return bytes_; }
  [[nodiscard]] std::size_t budgetBytes() const { return budget_; }
  [[nodiscard]] std::size_t size() const { return map_.size(); }
  /// Tiles built so far (by any route): equals the keys ever cached unless a key was built twice.
  [[nodiscard]] std::uint64_t builtCount() const { return built_; }
  [[nodiscard]] int workerCount() const { return builder_.workerCount(); }
  [[nodiscard]] const Heightfield& heights() const { return *heights_; }
  /// Keys (packed) evicted since the last call, so a GPU mirror can drop them too.
  std::vector<std::uint64_t> takeEvicted() { return std::exchange(evicted_, {}); }

 private:
  void collect();
  void evict();

  std::shared_ptr<const Heightfield> heights_;
  std::size_t budget_;
  std::size_t bytes_ = 0;
  std::uint64_t frame_ = 1;
  std::uint64_t built_ = 0;
  std::list<Tile> lru_;  // front = most recently used
  std::unordered_map<std::uint64_t, std::list<Tile>::iterator> map_;
  std::vector<std::uint64_t> evicted_;
  std::vector<TileKey> missing_;  // scratch
  // Last: its workers are joined before the rest of the cache is destroyed.
  TileBuilder builder_;
};

}  // namespace og::terrain
