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

/// Texels as linear floats: colour decoded from sRGB, alpha 0..255.
std::vector<float> toLinear(const std::vector<std::uint8_t>& rgba) {
  const auto& lin = srgbToLinear();
  std::vector<float> out(rgba.size());
  for (std::size_t i = 0; i < rgba.size(); ++i) out[i] = i % 4 < 3 ? lin[rgba[i]] : static_cast<float>(rgba[i]);
  return out;
}

/// Appends linear texels (toLinear) to `bytes`, colour encoded to sRGB, alpha rounded.
void appendEncoded(std::vector<std::uint8_t>& bytes, const std::vector<float>& texels) {
  for (std::size_t i = 0; i < texels.size(); ++i)
    bytes.push_back(i % 4 < 3 ? linearToSrgb(texels[i]) : static_cast<std::uint8_t>(std::lround(texels[i])));
}

/// The linear texels `in` (`rows` × `cols`) shrunk along x to m columns and transposed (m rows
/// × `rows` columns): each texel the mean over its footprint [i cols/m, (i+1) cols/m), texels
/// partly inside weighted by the part inside (the mean of a pair when cols = 2m; 33 -> 16 takes
/// 2.0625 texels a texel). Applied twice it shrinks both ways.
std::vector<float> shrinkTransposed(const std::vector<float>& in, int rows, int cols, int m) {
  const auto at = [](int r, int c, int width) {
    return (static_cast<std::size_t>(r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)) * 4;
  };
  std::vector<float> out(static_cast<std::size_t>(m) * static_cast<std::size_t>(rows) * 4, 0.0f);
  const double step = static_cast<double>(cols) / m;
  for (int i = 0; i < m; ++i) {
    const double a = i * step, b = (i + 1) * step;
    for (int j = static_cast<int>(a); j < cols && j < b; ++j) {
      const auto w = static_cast<float>((std::min(b, j + 1.0) - std::max(a, static_cast<double>(j))) / step);
      for (int r = 0; r < rows; ++r)
        for (std::size_t c = 0; c < 4; ++c) out[at(i, r, rows) + c] += w * in[at(r, j, cols) + c];
    }
  }
  return out;
}

/// A stored tile's level 0 (sRGB bytes) with its whole mip chain: each level the mean of the one
/// before over its footprint, in linear colour (alpha linearly).
std::vector<std::uint8_t> withMips(std::vector<std::uint8_t> level0) {
  std::vector<float> level = toLinear(level0);
  level0.reserve(imageryTileBytes());
  for (int m = 1; m < kImageryTileMips; ++m) {
    const int n = imageryTileMipPx(m - 1), half = imageryTileMipPx(m);
    level = shrinkTransposed(shrinkTransposed(level, n, n, half), half, n, half);
    appendEncoded(level0, level);
  }
  return level0;
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

std::size_t imageryTileMipOffset(int m) {
  std::size_t n = 0;
  for (int k = 0; k < m; ++k) n += static_cast<std::size_t>(imageryTileMipPx(k)) * static_cast<std::size_t>(imageryTileMipPx(k)) * 4;
  return n;
}

std::size_t imageryTileBytes() { return imageryTileMipOffset(kImageryTileMips); }

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
  std::vector<std::uint8_t> level0 = readBordered(*reader, key);
  {
    std::lock_guard lock(mutex_);
    idle_.push_back(std::move(reader));
  }
  ImageryTile tile;
  tile.key = key;
  tile.rgba = withMips(std::move(level0));
  return tile;
}

std::vector<std::uint8_t> ImageryTileSource::readBordered(const GeoImageReader& reader, const ImageryTileKey& key) const {
  constexpr int B = kImageryTileBorderPx, S = kImageryTileStoredPx;
  const double t = key.texelDeg(), size = key.sizeDeg();
  // Tiles west of the footprint's own longitudes (a source given in 0..360°) read shifted.
  double west = key.westDeg();
  if (west + size <= footprint_.westDeg) west += 360.0;
  else if (west >= footprint_.eastDeg) west -= 360.0;
  // No rows past a pole (nothing is there; Web Mercator could not even project them).
  const double south = key.southDeg(), north = south + size;
  const int below = south <= -90.0 + 0.5 * t ? 0 : B, above = north >= 90.0 - 0.5 * t ? 0 : B;
  const int rows = kImageryTilePx + below + above;
  GeoImage img = reader.read(west - B * t, south - below * t, west + size + B * t, north + above * t, S, rows);
  // A source round the whole globe continues past its own west and east edges.
  if (footprint_.eastDeg - footprint_.westDeg >= 360.0 - 0.5 * t) {
    const auto borrow = [&](double fromWest, int column) {
      const GeoImage strip = reader.read(fromWest, south - below * t, fromWest + B * t, north + above * t, B, rows);
      for (int r = 0; r < rows; ++r)
        for (int c = 0; c < B; ++c) {
          const std::size_t from = (static_cast<std::size_t>(r) * B + static_cast<std::size_t>(c)) * 4;
          const std::size_t to = (static_cast<std::size_t>(r) * S + static_cast<std::size_t>(column + c)) * 4;
          if (strip.rgba[from + 3] > img.rgba[to + 3]) std::copy_n(strip.rgba.begin() + static_cast<std::ptrdiff_t>(from), 4,
                                                                  img.rgba.begin() + static_cast<std::ptrdiff_t>(to));
        }
    };
    if (west - B * t < footprint_.westDeg) borrow(west - B * t + 360.0, 0);
    if (west + size + B * t > footprint_.eastDeg) borrow(west + size - 360.0, S - B);
  }
  // Into the stored square, the rows past a pole repeating the last row read.
  std::vector<std::uint8_t> stored(static_cast<std::size_t>(S) * S * 4);
  const std::size_t rowBytes = static_cast<std::size_t>(S) * 4;
  for (int r = 0; r < S; ++r) {
    const int from = std::clamp(r - (B - below), 0, rows - 1);
    std::copy_n(img.rgba.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(from) * rowBytes), rowBytes,
                stored.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(r) * rowBytes));
  }
  return stored;
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
