#include "render/ImageryTiles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_set>

#include "core/Error.hpp"
#include "data/Imagery.hpp"
#include "geo/Wgs84.hpp"
#include "gl/ShaderContract.hpp"
#include "terrain/Selection.hpp"

namespace og::render {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr int kFirstSlots = 16;  // slots allocated at first, doubled as needed up to the budget

gl::Texture slotArray(int slots) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(t.id(), data::kImageryTileMips, GL_SRGB8_ALPHA8, data::kImageryTileStoredPx,
                     data::kImageryTileStoredPx, slots);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

/// A sphere round a tile's ground from 500 m below the sea to 9 km above it: through its corners,
/// edge midpoints and centre, widened by the arc's bulge between them.
struct TileSphere {
  glm::dvec3 centreEcef;
  double radiusM;
};
TileSphere sphereOf(const terrain::TileKey& key) {
  const double s = key.sizeDeg(), south = key.southDeg(), west = key.westDeg();
  const glm::dvec3 centre = terrain::geodeticToEcefFast(south + 0.5 * s, west + 0.5 * s, 0.0);
  double r = 0.0;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j)
      for (const double h : {-500.0, 9000.0})
        r = std::max(r, glm::length(terrain::geodeticToEcefFast(south + 0.5 * j * s, west + 0.5 * i * s, h) - centre));
  return {centre, r + geo::kWgs84SemiMajorM * (1.0 - std::cos(0.25 * s * kDegToRad))};
}

}  // namespace

ImageryTiles::ImageryTiles(std::vector<std::shared_ptr<const data::ImageryTileSource>> sources,
                           std::size_t cpuBudgetBytes, std::size_t gpuBudgetBytes)
    : cache_(std::move(sources), cpuBudgetBytes), slotBytes_(data::imageryTileBytes()) {
  GLint maxLayers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  maxSlots_ = std::min(gpuBudgetBytes / slotBytes_, static_cast<std::size_t>(std::max(maxLayers, 1)));
  if (maxSlots_ == 0) throw InternalError("imagery GPU cache budget below one tile: " + std::to_string(gpuBudgetBytes));
  const int first = static_cast<int>(std::min<std::size_t>(kFirstSlots, maxSlots_));
  texture_ = slotArray(first);
  slots_.resize(static_cast<std::size_t>(first));
}

data::ImageryTileKey ImageryTiles::wanted(int layer, const terrain::TileKey& key) const {
  const data::ImageryTileSource* s = cache_.source(layer);
  if (s == nullptr || s->minLevel() > s->maxLevel()) return {layer, -1, 0, 0};
  const int level = std::min(key.level, s->maxLevel());
  if (level < s->minLevel()) return {layer, -1, 0, 0};
  const data::ImageryTileKey k{layer, key.level, key.x, key.y};
  const data::ImageryTileKey a = k.ancestor(key.level - level);
  return s->overlaps(a) ? a : data::ImageryTileKey{layer, -1, 0, 0};
}

int ImageryTiles::slotOf(const data::ImageryTileKey& key) const {
  const auto it = slotByKey_.find(key.packed());
  return it == slotByKey_.end() ? -1 : it->second;
}

void ImageryTiles::grow() {
  const int old = static_cast<int>(slots_.size());
  const int size = static_cast<int>(std::min<std::size_t>(2 * slots_.size(), maxSlots_));
  gl::Texture bigger = slotArray(size);
  for (int m = 0; m < data::kImageryTileMips; ++m) {
    const int px = data::imageryTileMipPx(m);
    glCopyImageSubData(texture_.id(), GL_TEXTURE_2D_ARRAY, m, 0, 0, 0, bigger.id(), GL_TEXTURE_2D_ARRAY, m, 0, 0, 0,
                       px, px, old);
  }
  texture_ = std::move(bigger);
  slots_.resize(static_cast<std::size_t>(size));
}

int ImageryTiles::freeSlot() {
  for (std::size_t i = 0; i < slots_.size(); ++i)
    if (!slots_[i].used) return static_cast<int>(i);
  if (slots_.size() < maxSlots_) {
    grow();
    return freeSlot();
  }
  // The least recently used slot not drawn in this frame.
  int oldest = -1;
  for (std::size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].lastUsedFrame != frame_ &&
        (oldest < 0 || slots_[i].lastUsedFrame < slots_[static_cast<std::size_t>(oldest)].lastUsedFrame))
      oldest = static_cast<int>(i);
  if (oldest >= 0) {
    slotByKey_.erase(slots_[static_cast<std::size_t>(oldest)].key);
    slots_[static_cast<std::size_t>(oldest)].used = false;
    ++gpuEvictions_;
  }
  return oldest;
}

int ImageryTiles::upload(const data::ImageryTile& tile) {
  const int slot = freeSlot();
  if (slot < 0) return -1;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int m = 0; m < data::kImageryTileMips; ++m) {
    const int px = data::imageryTileMipPx(m);
    glTextureSubImage3D(texture_.id(), m, 0, 0, slot, px, px, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                        tile.rgba.data() + data::imageryTileMipOffset(m));
  }
  slots_[static_cast<std::size_t>(slot)] = {tile.key.packed(), frame_, true};
  slotByKey_[tile.key.packed()] = slot;
  return slot;
}

void ImageryTiles::uploadArrived(std::span<const data::ImageryTileKey> keys) {
  for (const data::ImageryTileKey& k : keys)
    if (slotOf(k) < 0)
      if (const data::ImageryTile* t = cache_.find(k)) upload(*t);
}

void ImageryTiles::prepare(std::span<const terrain::TileKey> drawn, bool wait) {
  ++frame_;
  finestLevel_ = -1;
  cache_.collect();
  std::vector<data::ImageryTileKey> keys;
  std::unordered_set<std::uint64_t> seen;
  for (const terrain::TileKey& t : drawn)
    for (int layer = 0; layer < data::kMaxImageryLayers; ++layer)
      if (const data::ImageryTileKey k = wanted(layer, t); k.level >= 0 && seen.insert(k.packed()).second)
        keys.push_back(k);
  // Coarse first: they stand in for the most terrain. In the background each tile's ancestors
  // come with it (and stay resident while it is wanted): the first to arrive stands in.
  if (wait)
    std::stable_sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) { return a.level < b.level; });
  else
    keys = withAncestors(keys);
  missing_.clear();
  for (const data::ImageryTileKey& k : keys) {
    if (const int slot = slotOf(k); slot >= 0) {
      slots_[static_cast<std::size_t>(slot)].lastUsedFrame = frame_;  // kept while drawn or standing in
    } else if (const data::ImageryTile* tile = cache_.find(k)) {
      upload(*tile);
    } else {
      missing_.push_back(k);
    }
  }
  if (wait) {
    // In batches the CPU cache holds at once, each uploaded before the next evicts it.
    const std::size_t batch = std::max<std::size_t>(1, cache_.budgetBytes() / (slotBytes_ + sizeof(data::ImageryTile)));
    for (std::size_t i = 0; i < missing_.size(); i += batch) {
      const std::span<const data::ImageryTileKey> part(missing_.data() + i, std::min(batch, missing_.size() - i));
      uploadArrived(cache_.build(part));
    }
    missing_.clear();
  }
  requestMissing();
}

void ImageryTiles::prefetch(const geo::CameraView& view, int widthPx, int heightPx) {
  prefetch_ = withAncestors(keysForView(view, widthPx, heightPx));
  requestMissing();
}

void ImageryTiles::requestMissing() {
  std::vector<data::ImageryTileKey> keys = missing_;  // coarse first (withAncestors' order)
  std::unordered_set<std::uint64_t> seen;
  for (const data::ImageryTileKey& k : keys) seen.insert(k.packed());
  for (const data::ImageryTileKey& k : prefetch_)
    if (slotOf(k) < 0 && !cache_.contains(k) && seen.insert(k.packed()).second) keys.push_back(k);
  cache_.request(keys);
}

std::vector<data::ImageryTileKey> ImageryTiles::keysForView(const geo::CameraView& view, int widthPx, int heightPx) const {
  int deepest = -1;  // no need to walk past the finest level any layer streams
  for (int layer = 0; layer < data::kMaxImageryLayers; ++layer)
    if (const data::ImageryTileSource* s = cache_.source(layer)) deepest = std::max(deepest, s->maxLevel());
  const auto overlapsAny = [&](const terrain::TileKey& key) {
    for (int layer = 0; layer < data::kMaxImageryLayers; ++layer)
      if (const data::ImageryTileSource* s = cache_.source(layer); s != nullptr && s->overlaps({layer, key.level, key.x, key.y}))
        return true;
    return false;
  };
  const terrain::SelectionParams params;  // the terrain's own split rule
  const double pxPerRad = heightPx / (2.0 * std::tan(0.5 * view.verticalFovRad));
  std::vector<data::ImageryTileKey> out;
  std::vector<terrain::TileKey> level{{0, 0, 0}, {0, 1, 0}}, next;
  while (!level.empty()) {
    next.clear();
    for (const terrain::TileKey& key : level) {
      if (!overlapsAny(key)) continue;
      const TileSphere b = sphereOf(key);
      if (!terrain::inFrustum(view, widthPx, heightPx, b.centreEcef, b.radiusM) ||
          !terrain::aboveHorizon(view.positionEcef, b.centreEcef, b.radiusM))
        continue;
      // Vertex spacing (north-south) in pixels at the nearest point, as terrain::tileErrorPx.
      const double spacingM = key.sizeDeg() / terrain::kTileQuads * kDegToRad * geo::kWgs84SemiMajorM;
      const double errorPx = spacingM / std::max(glm::length(b.centreEcef - view.positionEcef) - b.radiusM, 1.0) * pxPerRad;
      if (key.level < deepest && (key.level < params.minLevel || errorPx > params.maxSpacingPx)) {
        for (int i = 0; i < 4; ++i) next.push_back(key.child(i));
        continue;
      }
      for (int layer = 0; layer < data::kMaxImageryLayers; ++layer)
        if (const data::ImageryTileKey k = wanted(layer, key); k.level >= 0) out.push_back(k);
    }
    std::swap(level, next);
  }
  return out;
}

bool ImageryTiles::residentOrRequested(const data::ImageryTileKey& key) const {
  return slotOf(key) >= 0 || cache_.contains(key) || cache_.pending(key);
}

std::vector<data::ImageryTileKey> ImageryTiles::withAncestors(std::span<const data::ImageryTileKey> keys) const {
  std::vector<data::ImageryTileKey> out;
  std::unordered_set<std::uint64_t> seen;
  for (const data::ImageryTileKey& key : keys)
    for (data::ImageryTileKey k = key; k.level >= cache_.source(k.layer)->minLevel(); k = k.ancestor(1))
      if (!seen.insert(k.packed()).second) break;  // so are its ancestors
      else out.push_back(k);
  // Coarse first: they stand in for the most terrain.
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.level < b.level; });
  return out;
}

void ImageryTiles::bindTile(const gl::Program& program, const terrain::TileKey& key) {
  std::array<GLint, data::kMaxImageryLayers> slots{};
  std::array<glm::vec4, data::kMaxImageryLayers> bounds{};
  std::array<float, data::kMaxImageryLayers> texel{};
  slots.fill(-1);
  for (int layer = 0; layer < data::kMaxImageryLayers; ++layer) {
    data::ImageryTileKey k = wanted(layer, key);
    const data::ImageryTileSource* s = cache_.source(layer);
    for (; k.level >= 0 && k.level >= s->minLevel(); k = k.ancestor(1)) {
      const int slot = slotOf(k);
      if (slot < 0) continue;
      slots_[static_cast<std::size_t>(slot)].lastUsedFrame = frame_;
      const auto i = static_cast<std::size_t>(layer);
      slots[i] = slot;
      // The stored square's bounds, borders included: the shader maps into it directly.
      const double b = data::kImageryTileBorderPx * k.texelDeg();
      bounds[i] = glm::vec4(glm::dvec4(k.westDeg() - b, k.southDeg() - b, k.westDeg() + k.sizeDeg() + b,
                                       k.southDeg() + k.sizeDeg() + b) * kDegToRad);
      texel[i] = static_cast<float>(k.texelDeg() * kDegToRad);
      finestLevel_ = std::max(finestLevel_, k.level);
      break;
    }
  }
  glBindTextureUnit(gl::kUnitImageryTiles, texture_.id());
  glProgramUniform1iv(program.id(), program.location("uImageryTileSlot"), data::kMaxImageryLayers, slots.data());
  glProgramUniform4fv(program.id(), program.location("uImageryTileBounds"), data::kMaxImageryLayers, &bounds[0].x);
  glProgramUniform1fv(program.id(), program.location("uImageryTileTexelRad"), data::kMaxImageryLayers, texel.data());
}

void ImageryTiles::bindNone(const gl::Program& program) {
  std::array<GLint, data::kMaxImageryLayers> slots{};
  slots.fill(-1);
  glProgramUniform1iv(program.id(), program.location("uImageryTileSlot"), data::kMaxImageryLayers, slots.data());
}

ImageryTileStats ImageryTiles::stats() const {
  ImageryTileStats s;
  s.cpuTiles = cache_.size();
  s.cpuBytes = cache_.bytes();
  s.gpuTiles = slotByKey_.size();
  s.gpuBytes = slots_.size() * slotBytes_;
  s.pending = cache_.pendingCount();
  s.reads = cache_.readCount();
  s.cpuEvictions = cache_.evictions();
  s.gpuEvictions = gpuEvictions_;
  s.finestLevel = finestLevel_;
  return s;
}

}  // namespace og::render
