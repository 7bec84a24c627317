#pragma once
// A pool of worker threads that build terrain tiles (buildTile, a pure function of the shared,
// immutable Heightfield and the key): core::BuildPool over terrain tiles. Workers touch nothing
// but their own queue state and the tiles they build; the caller (the render thread) takes
// finished tiles and owns the cache. Each key is built at most once while it is queued, in
// flight or finished but not yet taken.
#include <memory>

#include "core/BuildPool.hpp"
#include "terrain/Heightfield.hpp"
#include "terrain/Tile.hpp"

namespace og::terrain {

class TileBuilder : public core::BuildPool<TileKey, Tile> {
 public:
  /// Any thread-safe build function (tests).
  using core::BuildPool<TileKey, Tile>::BuildPool;
  /// buildTile on `heights` (kept alive by the pool). `workers` <= 0:
  /// std::thread::hardware_concurrency() (at least 1).
  explicit TileBuilder(std::shared_ptr<const Heightfield> heights, int workers = 0);
};

}  // namespace og::terrain
