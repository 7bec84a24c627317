#include "data/ImageryTiles.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/Error.hpp"

namespace og::data {
namespace {

/// sRGB-encoded byte -> linear value (IEC 61966-2-1).
const std::array<float, 256>& srgbToLinear() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[static_cast<std::size_t>(i)] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

/// Linear value -> sRGB-encoded byte (IEC 61966-2-1).
std::uint8_t linearToSrgb(float v) {
  const double c = std::clamp(static_cast<double>(v), 0.0, 1.0);
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(s * 255.0));
}

/// Appends to `texels` the mip level below the one of side `size` starting at `offset`: each
/// texel the mean of four, colour averaged in linear light, alpha linearly.
void appendHalf(std::vector<std::uint8_t>& texels, std::size_t offset, int size) {
  const auto& lin = srgbToLinear();
  const int half = size / 2;
  const auto at = [&](int x, int y, int c) {
    return texels[offset + (static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x)) * 4 +
                  static_cast<std::size_t>(c)];
  };
  std::vector<std::uint8_t> out(static_cast<std::size_t>(half) * static_cast<std::size_t>(half) * 4);
  for (int y = 0; y < half; ++y)
    for (int x = 0; x < half; ++x)
      for (int c = 0; c < 4; ++c) {
        float sum = 0.0f;
        for (int k = 0; k < 4; ++k) {
          const std::uint8_t v = at(2 * x + (k & 1), 2 * y + (k >> 1), c);
          sum += c < 3 ? lin[v] : static_cast<float>(v);
        }
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(half) + static_cast<std::size_t>(x)) * 4 +
                              static_cast<std::size_t>(c);
        out[i] = c < 3 ? linearToSrgb(0.25f * sum) : static_cast<std::uint8_t>(std::lround(0.25f * sum));
      }
  texels.insert(texels.end(), out.begin(), out.end());
}

/// Smallest level whose tile texels (degrees) are finer than `cellDeg` (or equal, `orEqual`).
int levelFinerThan(double cellDeg, bool orEqual) {
  for (int level = 0; level <= kImageryMaxLevel; ++level) {
    const double texel = 180.0 / static_cast<double>(1 << level) / kImageryTilePx;
    if (texel < cellDeg || (orEqual && texel <= cellDeg * (1.0 + 1e-9))) return level;
  }
  return kImageryMaxLevel;
}

}  // namespace

std::size_t imageryTileBytes() {
  std::size_t n = 0;
  for (int m = 0, s = kImageryTilePx; m < kImageryTileMips; ++m, s /= 2) n += static_cast<std::size_t>(s) * static_cast<std::size_t>(s) * 4;
  return n;
}

ImageryTileSource::ImageryTileSource(const std::string& path, int layer, int wholePx) : path_(path), layer_(layer) {
  auto reader = std::make_unique<GeoImageReader>(path, path);
  footprint_ = reader->footprint();
  const GeoFootprint& f = footprint_;
  const double wholeCellDeg = std::max(f.eastDeg - f.westDeg, f.northDeg - f.southDeg) / wholePx;
  const double sourceCellDeg = f.cellDeg();
  if (sourceCellDeg < wholeCellDeg) {
    minLevel_ = levelFinerThan(wholeCellDeg, false);
    maxLevel_ = std::max(minLevel_, levelFinerThan(sourceCellDeg, true));
  }
  idle_.push_back(std::move(reader));
}

bool ImageryTileSource::overlaps(const ImageryTileKey& key) const {
  const double w = key.westDeg(), s = key.southDeg(), size = key.sizeDeg();
  if (s >= footprint_.northDeg || s + size <= footprint_.southDeg) return false;
  for (const double shift : {-360.0, 0.0, 360.0})
    if (w + shift < footprint_.eastDeg && w + shift + size > footprint_.westDeg) return true;
  return false;
}

ImageryTile ImageryTileSource::read(const ImageryTileKey& key) const {
  std::unique_ptr<GeoImageReader> reader;
  {
    std::lock_guard lock(mutex_);
    if (!idle_.empty()) {
      reader = std::move(idle_.back());
      idle_.pop_back();
    }
  }
  if (!reader) reader = std::make_unique<GeoImageReader>(path_, path_);
  // Tiles west of the footprint's own longitudes (a source given in 0..360°) read shifted.
  double west = key.westDeg();
  if (west + key.sizeDeg() <= footprint_.westDeg) west += 360.0;
  else if (west >= footprint_.eastDeg) west -= 360.0;
  GeoImage img = reader->read(west, key.southDeg(), west + key.sizeDeg(), key.southDeg() + key.sizeDeg(),
                              kImageryTilePx, kImageryTilePx);
  {
    std::lock_guard lock(mutex_);
    idle_.push_back(std::move(reader));
  }
  ImageryTile tile;
  tile.key = key;
  tile.rgba = std::move(img.rgba);
  tile.rgba.reserve(imageryTileBytes());
  std::size_t offset = 0;
  for (int size = kImageryTilePx; size > 1; size /= 2) {
    appendHalf(tile.rgba, offset, size);
    offset += static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4;
  }
  return tile;
}

ImageryTileCache::ImageryTileCache(std::vector<std::shared_ptr<const ImageryTileSource>> sources,
                                   std::size_t budgetBytes, int workers)
    : sources_(std::move(sources)),
      budget_(budgetBytes),
      pool_([s = sources_](const ImageryTileKey& key) { return s[static_cast<std::size_t>(key.layer)]->read(key); },
            workers) {
  if (budget_ < imageryTileBytes() + sizeof(ImageryTile))
    throw InternalError("imagery CPU cache budget below one tile: " + std::to_string(budget_));
}

const ImageryTileSource* ImageryTileCache::source(int layer) const {
  return layer >= 0 && layer < static_cast<int>(sources_.size()) ? sources_[static_cast<std::size_t>(layer)].get() : nullptr;
}

std::vector<ImageryTileKey> ImageryTileCache::collect() {
  auto finished = pool_.takeFinished();
  std::vector<ImageryTileKey> arrived;
  for (ImageryTile& t : finished.tiles) {
    ++reads_;
    if (map_.count(t.key.packed()) != 0) continue;
    arrived.push_back(t.key);
    bytes_ += t.bytes();
    lru_.push_front(std::move(t));
    map_[lru_.front().key.packed()] = lru_.begin();
  }
  while (bytes_ > budget_ && !lru_.empty()) {  // oldest first, whatever frame used them
    bytes_ -= lru_.back().bytes();
    map_.erase(lru_.back().key.packed());
    lru_.pop_back();
    ++evictions_;
  }
  if (finished.error) std::rethrow_exception(finished.error);
  return arrived;
}

const ImageryTile* ImageryTileCache::find(const ImageryTileKey& key) {
  const auto it = map_.find(key.packed());
  if (it == map_.end()) return nullptr;
  lru_.splice(lru_.begin(), lru_, it->second);
  return &*it->second;
}

void ImageryTileCache::request(std::span<const ImageryTileKey> keys) { pool_.request(keys); }

std::vector<ImageryTileKey> ImageryTileCache::build(std::span<const ImageryTileKey> keys) {
  pool_.build(keys);
  return collect();
}

}  // namespace og::data
