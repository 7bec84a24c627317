#include "terrain/TileCache.hpp"

#include <utility>

namespace og::terrain {

TileCache::TileCache(std::shared_ptr<const Heightfield> heights, std::size_t budgetBytes)
    : heights_(std::move(heights)), budget_(budgetBytes) {}

const Tile& TileCache::get(const TileKey& key) {
  const std::uint64_t id = key.packed();
  if (auto it = map_.find(id); it != map_.end()) {
    lru_.splice(lru_.begin(), lru_, it->second);  // iterators stay valid
    it->second->lastUsedFrame = frame_;
    return *it->second;
  }
  lru_.push_front(buildTile(*heights_, key));
  ++built_;
  Tile& t = lru_.front();
  t.lastUsedFrame = frame_;
  map_[id] = lru_.begin();
  bytes_ += t.bytes();
  evict();
  return t;
}

void TileCache::evict() {
  // Oldest first; stop at the first tile of this frame (all younger ones are too).
  while (bytes_ > budget_ && !lru_.empty() && lru_.back().lastUsedFrame != frame_) {
    const Tile& t = lru_.back();
    bytes_ -= t.bytes();
    evicted_.push_back(t.key.packed());
    map_.erase(t.key.packed());
    lru_.pop_back();
  }
}

}  // namespace og::terrain
