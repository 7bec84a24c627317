#include "render/ImageryTiles.hpp"

#include <algorithm>
#include <array>
#include <unordered_set>

#include "core/Error.hpp"
#include "data/Imagery.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr int kFirstSlots = 16;  // slots allocated at first, doubled as needed up to the budget

gl::Texture slotArray(int slots) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(t.id(), data::kImageryTileMips, GL_SRGB8_ALPHA8, data::kImageryTilePx, data::kImageryTilePx, slots);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
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
  for (int m = 0, px = data::kImageryTilePx; m < data::kImageryTileMips; ++m, px /= 2)
    glCopyImageSubData(texture_.id(), GL_TEXTURE_2D_ARRAY, m, 0, 0, 0, bigger.id(), GL_TEXTURE_2D_ARRAY, m, 0, 0, 0,
                       px, px, old);
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
  std::size_t offset = 0;
  for (int m = 0, px = data::kImageryTilePx; m < data::kImageryTileMips; ++m, px /= 2) {
    glTextureSubImage3D(texture_.id(), m, 0, 0, slot, px, px, 1, GL_RGBA, GL_UNSIGNED_BYTE, tile.rgba.data() + offset);
    offset += static_cast<std::size_t>(px) * static_cast<std::size_t>(px) * 4;
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
  std::vector<data::ImageryTileKey> missing;
  std::unordered_set<std::uint64_t> seen;
  for (const terrain::TileKey& t : drawn)
    for (int layer = 0; layer < data::kMaxImageryLayers; ++layer) {
      const data::ImageryTileKey k = wanted(layer, t);
      if (k.level < 0 || !seen.insert(k.packed()).second) continue;
      if (const int slot = slotOf(k); slot >= 0) {
        slots_[static_cast<std::size_t>(slot)].lastUsedFrame = frame_;
      } else if (const data::ImageryTile* tile = cache_.find(k)) {
        upload(*tile);
      } else {
        missing.push_back(k);
      }
    }
  // Coarse tiles first: they stand in for the most terrain.
  std::stable_sort(missing.begin(), missing.end(), [](const auto& a, const auto& b) { return a.level < b.level; });
  if (!wait) {
    cache_.request(missing);
    return;
  }
  // In batches the CPU cache holds at once, each uploaded before the next evicts it.
  const std::size_t batch = std::max<std::size_t>(1, cache_.budgetBytes() / (slotBytes_ + sizeof(data::ImageryTile)));
  for (std::size_t i = 0; i < missing.size(); i += batch) {
    const std::span<const data::ImageryTileKey> part(missing.data() + i, std::min(batch, missing.size() - i));
    uploadArrived(cache_.build(part));
  }
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
      bounds[i] = glm::vec4(glm::dvec4(k.westDeg(), k.southDeg(), k.westDeg() + k.sizeDeg(), k.southDeg() + k.sizeDeg()) * kDegToRad);
      texel[i] = static_cast<float>(k.sizeDeg() / data::kImageryTilePx * kDegToRad);
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
