#include "terrain/TileCache.hpp"

#include <utility>

namespace og::terrain {

TileCache::TileCache(std::shared_ptr<const Heightfield> heights, std::size_t budgetBytes, int workers)
    : heights_(std::move(heights)), budget_(budgetBytes), builder_(heights_, workers) {}

void TileCache::beginFrame() {
  ++frame_;
  collect();
}

const Tile& TileCache::get(const TileKey& key) {
  auto it = map_.find(key.packed());
  if (it == map_.end()) {
    // Through the pool, so a key already requested in the background is not built twice.
    buildMissing(std::span(&key, 1));
    it = map_.find(key.packed());
  }
  lru_.splice(lru_.begin(), lru_, it->second);  // iterators stay valid
  it->second->lastUsedFrame = frame_;
  return *it->second;
}

void TileCache::buildMissing(std::span<const TileKey> keys) {
  missing_.clear();
  for (const TileKey& k : keys)
    if (!contains(k)) missing_.push_back(k);
  if (missing_.empty()) return;
  builder_.build(missing_);
  collect();
}

void TileCache::request(std::span<const TileKey> keys) {
  missing_.clear();
  for (const TileKey& k : keys)
    if (!contains(k)) missing_.push_back(k);
  builder_.request(missing_);
}

void TileCache::collect() {
  TileBuilder::Finished f = builder_.takeFinished();
  for (Tile& t : f.tiles) {
    ++built_;
    const std::uint64_t id = t.key.packed();
    if (contains(t.key)) continue;  // cannot happen (keys are built once); keep the cached one
    // Delivered tiles count as used in this frame: they were asked for by the latest frames,
    // and a frame that evicted them before drawing them would ask again.
    t.lastUsedFrame = frame_;
    bytes_ += t.bytes();
    lru_.push_front(std::move(t));
    map_[id] = lru_.begin();
  }
  evict();
  if (f.error) std::rethrow_exception(f.error);
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
