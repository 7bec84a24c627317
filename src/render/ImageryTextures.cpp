#include "render/ImageryTextures.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <string>

#include "core/Error.hpp"
#include "data/Imagery.hpp"
#include "data/ImageryTiles.hpp"
#include "data/SrgbMips.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

int mipLevels(int w, int h) {
  return 1 + static_cast<int>(std::floor(std::log2(static_cast<double>(std::max(w, h)))));
}

/// Bytes of an RGBA8 texture with a full mip chain (4/3 of the base level).
std::size_t mippedBytes(int w, int h, int layers) {
  return static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4u * static_cast<std::size_t>(layers) * 4u / 3u;
}

void setSampling(GLuint tex, bool wrapS) {
  glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(tex, GL_TEXTURE_WRAP_S, wrapS ? GL_REPEAT : GL_CLAMP_TO_EDGE);
  glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

/// A global image as a mip-mapped sRGB texture, row 0 at the south (t = 0), with its mip
/// chain `levels` (data::srgbMipChain: made on the CPU, glGenerateMipmap costs ~50 ms an image
/// on llvmpipe).
gl::Texture globalTexture(const data::GeoImage& img, const std::vector<data::SrgbLevel>& levels) {
  if (!img.coversGlobe()) throw InternalError(img.label + ": a base image must cover the globe");
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), mipLevels(img.width, img.height), GL_SRGB8_ALPHA8, img.width, img.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  for (std::size_t k = 0; k < levels.size(); ++k)
    glTextureSubImage2D(t.id(), static_cast<GLint>(k + 1), 0, 0, levels[k].width, levels[k].height, GL_RGBA,
                        GL_UNSIGNED_BYTE, levels[k].rgba.data());
  setSampling(t.id(), true);
  return t;
}

}  // namespace

ImageryTextures::ImageryTextures() {
  const data::GeoImage& day = data::defaultDayImagery();
  const data::GeoImage& night = data::defaultNightLights();
  // The night image's levels on a second core while the day's are made here.
  auto nightLevels = std::async(std::launch::async, [&night] { return data::srgbMipChain(night.width, night.height, night.rgba); });
  day_ = globalTexture(day, data::srgbMipChain(day.width, day.height, day.rgba));
  night_ = globalTexture(night, nightLevels.get());
  dayTexelRad_ = static_cast<float>((day.northDeg - day.southDeg) / day.height * kDegToRad);
  bytes_ = mippedBytes(day.width, day.height, 1) + mippedBytes(night.width, night.height, 1);
  setLayers({});
}

void ImageryTextures::setLayers(const std::vector<data::GeoImage>& layers) {
  layerCount_ = static_cast<int>(std::min<std::size_t>(layers.size(), data::kMaxImageryLayers));
  const int size = layers.empty() ? 1 : layers.front().width;
  if (layers_.id() != 0) bytes_ -= mippedBytes(size, size, 0);
  layers_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(layers_.id(), mipLevels(size, size), GL_SRGB8_ALPHA8, size, size, std::max(layerCount_, 1));
  layerBounds_.assign(static_cast<std::size_t>(data::kMaxImageryLayers), glm::vec4(0.0f));
  double finest = 1e9;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < layerCount_; ++i) {
    const data::GeoImage& img = layers[static_cast<std::size_t>(i)];
    if (img.width != size || img.height != size)
      throw InternalError(img.label + ": imagery layers must all be " + std::to_string(size) + " pixels square");
    glTextureSubImage3D(layers_.id(), 0, 0, 0, i, size, size, 1, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    layerBounds_[static_cast<std::size_t>(i)] =
        glm::vec4(static_cast<float>(img.westDeg * kDegToRad), static_cast<float>(img.southDeg * kDegToRad),
                  static_cast<float>(img.eastDeg * kDegToRad), static_cast<float>(img.northDeg * kDegToRad));
    finest = std::min(finest, (img.northDeg - img.southDeg) / size * kDegToRad);
  }
  glGenerateTextureMipmap(layers_.id());
  setSampling(layers_.id(), false);
  layerTexelRad_ = static_cast<float>(layerCount_ > 0 ? finest : 1.0);
  bytes_ = mippedBytes(2048, 1024, 2) + mippedBytes(size, size, layerCount_);
  streamTiles(layers);
}

void ImageryTextures::streamTiles(const std::vector<data::GeoImage>& layers) {
  tiles_.reset();  // joins its readers before new ones open
  std::vector<std::shared_ptr<const data::ImageryTileSource>> sources(static_cast<std::size_t>(data::kMaxImageryLayers));
  bool any = false;
  for (int i = 0; i < layerCount_; ++i) {
    const data::GeoImage& img = layers[static_cast<std::size_t>(i)];
    if (img.sourcePath.empty()) continue;
    auto source = std::make_shared<const data::ImageryTileSource>(img.sourcePath, i, img.width);
    if (source->minLevel() > source->maxLevel()) continue;  // the whole texture holds it all
    sources[static_cast<std::size_t>(i)] = std::move(source);
    any = true;
  }
  if (any) tiles_ = std::make_unique<ImageryTiles>(std::move(sources), cpuBudget_, gpuBudget_);
}

void ImageryTextures::prepareTiles(std::span<const terrain::TileKey> drawn, bool wait) {
  if (tiles_ && enabled_) tiles_->prepare(drawn, wait && !tilesInBackground_);
}

void ImageryTextures::prefetchTiles(const geo::CameraView& view, int widthPx, int heightPx) {
  if (tiles_ && enabled_) tiles_->prefetch(view, widthPx, heightPx);
}

void ImageryTextures::bindTile(const gl::Program& program, const terrain::TileKey& key) {
  if (tiles_ && enabled_) tiles_->bindTile(program, key);
}

void ImageryTextures::bind(const gl::Program& program) const {
  glBindTextureUnit(gl::kUnitImageryDay, day_.id());
  glBindTextureUnit(gl::kUnitImageryNight, night_.id());
  glBindTextureUnit(gl::kUnitImageryLayers, layers_.id());
  glBindTextureUnit(gl::kUnitImageryTiles, layers_.id());  // a 2D array until a tile binds its own
  ImageryTiles::bindNone(program);
  program.set("uImageryEnabled", enabled_ ? 1 : 0);
  program.set("uImageryDayTexelRad", dayTexelRad_);
  program.set("uImageryLayerCount", layerCount_);
  program.set("uImageryLayerTexelRad", layerTexelRad_);
  for (int i = 0; i < data::kMaxImageryLayers; ++i) {
    const std::string name = "uImageryLayerBounds[" + std::to_string(i) + "]";
    program.set(name.c_str(), layerBounds_[static_cast<std::size_t>(i)]);
  }
  program.set("uNightLights", nightScale_);
}

}  // namespace og::render
