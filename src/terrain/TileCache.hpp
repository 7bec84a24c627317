#pragma once
// Tiles built on demand and kept in least-recently-used order under a byte budget. Tiles used
// in the current frame are never evicted (the budget can then be exceeded for that frame).
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "terrain/Heightfield.hpp"
#include "terrain/Tile.hpp"

namespace og::terrain {

class TileCache {
 public:
  /// `budgetBytes`: the CPU memory the cached tiles may hold (default 96 MiB, ~1800 tiles).
  explicit TileCache(std::shared_ptr<const Heightfield> heights,
                     std::size_t budgetBytes = std::size_t{96} << 20);

  /// Starts a frame: tiles fetched from now on are protected from eviction until the next.
  void beginFrame() { ++frame_; }
  /// The tile, built now if not cached; marks it used in this frame. Valid until the tile is
  /// evicted (not before the next beginFrame()).
  const Tile& get(const TileKey& key);
  [[nodiscard]] bool contains(const TileKey& key) const { return map_.count(key.packed()) != 0; }

  [[nodiscard]] std::size_t bytes() const { return bytes_; }
  [[nodiscard]] std::size_t budgetBytes() const { return budget_; }
  [[nodiscard]] std::size_t size() const { return map_.size(); }
  [[nodiscard]] std::uint64_t builtCount() const { return built_; }
  [[nodiscard]] const Heightfield& heights() const { return *heights_; }
  /// Keys (packed) evicted since the last call, so a GPU mirror can drop them too.
  std::vector<std::uint64_t> takeEvicted() { return std::exchange(evicted_, {}); }

 private:
  void evict();

  std::shared_ptr<const Heightfield> heights_;
  std::size_t budget_;
  std::size_t bytes_ = 0;
  std::uint64_t frame_ = 1;
  std::uint64_t built_ = 0;
  std::list<Tile> lru_;  // front = most recently used
  std::unordered_map<std::uint64_t, std::list<Tile>::iterator> map_;
  std::vector<std::uint64_t> evicted_;
};

}  // namespace og::terrain
