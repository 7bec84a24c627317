#include "terrain/TileBuilder.hpp"

#include <utility>

namespace og::terrain {

TileBuilder::TileBuilder(std::shared_ptr<const Heightfield> heights, int workers)
    : core::BuildPool<TileKey, Tile>([h = std::move(heights)](const TileKey& key) { return buildTile(*h, key); },
                                     workers) {}

}  // namespace og::terrain
