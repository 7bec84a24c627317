#pragma once
// Imagery on the GPU (shaders/terrain/imagery.glsl): the day colour that the globe's land and
// the terrain use as albedo, and the night lights. Three textures, all sRGB-encoded (the
// sampler returns linear colour) and mip-mapped:
//  * gl::kUnitImageryDay: the base day image, global (the embedded Blue Marble, 2048 × 1024);
//  * gl::kUnitImageryNight: the night lights, global (the embedded Earth at night, 2048 × 1024);
//  * gl::kUnitImageryLayers: the `--imagery-layer`s, a 2D array of kImageryLayerSizePx² layers
//    each over its own latitude/longitude extent, alpha = coverage, later layers on top.
// Each user layer is one whole mip-mapped texture: ~21 MiB of GPU memory per 2048² layer, at
// most data::kMaxImageryLayers (8) layers, so ≤ 170 MiB; it is what the globe pass (above the
// terrain) and any terrain not yet covered by a finer tile show. A layer read from a file
// finer than that texture also streams as tiles (render/ImageryTiles.hpp) for the terrain,
// under the CPU and GPU cache budgets (setCacheBudgets).
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "data/GeoRaster.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "render/ImageryTiles.hpp"
#include "terrain/Tile.hpp"

namespace og::render {

class ImageryTextures {
 public:
  /// Needs a current GL context. Uploads the embedded day and night images.
  ImageryTextures();

  /// Default imagery tile cache budgets (docs/data.md): 256 MiB of CPU and of GPU memory.
  static constexpr std::size_t kDefaultCacheBytes = std::size_t{256} << 20;

  /// Replaces the user's imagery layers (later ones on top); empty: only the base image.
  /// All layers must be square and of one size (data::loadImageryLayers makes them so). Layers
  /// read from a file finer than their texture stream tiles from it (throws og::InputError
  /// "FILE: problem" when it cannot be opened again).
  void setLayers(const std::vector<data::GeoImage>& layers);
  /// The streamed tiles' cache budgets, bytes (each at least one tile); applies to the next
  /// setLayers().
  void setCacheBudgets(std::size_t cpuBytes, std::size_t gpuBytes) {
    cpuBudget_ = cpuBytes;
    gpuBudget_ = gpuBytes;
  }

  /// Before the terrain draws these tiles: streams the imagery tiles they want (with `wait`,
  /// reads them before returning). No-op without streamed layers.
  void prepareTiles(std::span<const terrain::TileKey> drawn, bool wait);
  /// Asks in the background for the tiles a coming view will want (ImageryTiles::prefetch):
  /// the viewer's camera a second ahead, record's next frame. No-op without streamed layers.
  void prefetchTiles(const geo::CameraView& view, int widthPx, int heightPx);
  /// Sets the per-draw uniforms for terrain tile `key` (after bind()).
  void bindTile(const gl::Program& program, const terrain::TileKey& key);
  /// true: never wait for imagery tiles, even in frames whose terrain waits for its own (they
  /// arrive in a later frame; ancestors stand in). Default false: they follow the terrain.
  void setTilesInBackground(bool background) { tilesInBackground_ = background; }
  /// The streamed tiles (nullptr when no layer streams).
  [[nodiscard]] ImageryTiles* tiles() { return tiles_.get(); }
  [[nodiscard]] const ImageryTiles* tiles() const { return tiles_.get(); }
  /// Tile cache use (zeros when no layer streams).
  [[nodiscard]] ImageryTileStats tileStats() const { return tiles_ ? tiles_->stats() : ImageryTileStats{}; }

  /// Scales the night lights' radiance (1 = the default; 0 = none). See imagery.glsl.
  void setNightLights(float scale) { nightScale_ = scale; }
  [[nodiscard]] float nightLights() const { return nightScale_; }

  /// The user's layers loaded (setLayers), 0..data::kMaxImageryLayers.
  [[nodiscard]] int layerCount() const { return layerCount_; }

  /// Draws land with the stand-in material ramps instead of the imagery (comparisons, tests).
  void setEnabled(bool enabled) { enabled_ = enabled; }
  [[nodiscard]] bool enabled() const { return enabled_; }

  /// Bytes of GPU memory the imagery textures hold (with mip-maps).
  [[nodiscard]] std::size_t gpuBytes() const { return bytes_; }

  /// Binds the textures (gl::kUnitImagery*) and sets imagery.glsl's uniforms on `program`.
  void bind(const gl::Program& program) const;

 private:
  /// Opens the tile sources of the layers read from files finer than their textures.
  void streamTiles(const std::vector<data::GeoImage>& layers);

  gl::Texture day_;
  gl::Texture night_;
  gl::Texture layers_;
  int layerCount_ = 0;
  std::vector<glm::vec4> layerBounds_;  ///< west, south, east, north, radians
  float layerTexelRad_ = 1.0f;          ///< angular size of a layer texel (the finest layer's)
  float dayTexelRad_ = 1.0f;
  float nightScale_ = 1.0f;
  bool enabled_ = true;
  std::size_t bytes_ = 0;
  std::size_t cpuBudget_ = kDefaultCacheBytes;
  std::size_t gpuBudget_ = kDefaultCacheBytes;
  std::unique_ptr<ImageryTiles> tiles_;
  bool tilesInBackground_ = false;
};

}  // namespace og::render
