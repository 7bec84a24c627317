#include "render/WindTextures.hpp"

#include "gl/ShaderContract.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace og::render {

WindTextures::WindTextures() { setConstantWind(constant_); }

void WindTextures::setLayers(std::shared_ptr<const data::WindLayers> layers, int width, int height) {
  layers_ = std::move(layers);
  maxSpeedMs_ = 0.0;
  constantUploaded_ = false;
  width_ = width;
  height_ = height;
  if (!layers_) {
    setConstantWind(constant_);
    return;
  }
  key_ = layers_->timeKey();
  maxSpeedMs_ = upload(layers_->rasterize(width_, height_));
  ++uploads_;
  // Over every time step, so that the waves are not rebuilt as the winds change.
  if (layers_->timeVarying()) maxSpeedMs_ = std::max(maxSpeedMs_, layers_->maxSpeedMs());
}

void WindTextures::setTime(std::optional<UtcTime> time) {
  if (!time || !layers_ || !layers_->timeVarying()) return;
  data::WindTimeKey key = layers_->timeKey(*time);
  if (key == key_) return;
  (void)upload(layers_->at(*time).rasterize(width_, height_));  // the strongest wind stays that of all steps
  ++uploads_;
  key_ = std::move(key);
}

void WindTextures::setConstantWind(const geo::Wind& wind) {
  const bool same = constantUploaded_ && wind.speedMs == constant_.speedMs && wind.towardsDeg == constant_.towardsDeg;
  constant_ = wind;
  if (layers_ || same) return;
  // One cell: a stack with no layers is its fallback everywhere.
  (void)upload(data::WindLayers(wind.vector()).rasterize(1, 1));
  constantUploaded_ = true;
}

double WindTextures::upload(const data::WindRaster& raster) {
  double strongest = 0.0;
  for (std::size_t i = 0; i + 1 < raster.uv.size(); i += 2)
    strongest = std::max(strongest, static_cast<double>(std::hypot(raster.uv[i], raster.uv[i + 1])));
  if (raster.width != textureWidth_ || raster.height != textureHeight_) {
    textureWidth_ = raster.width;
    textureHeight_ = raster.height;
    wind_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(wind_.id(), 1, GL_RG32F, raster.width, raster.height);
    // Bilinear between cells: the layers are already smooth (blended edges), so is the sea.
    glTextureParameteri(wind_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(wind_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(wind_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(wind_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(wind_.id(), 0, 0, 0, raster.width, raster.height, GL_RG, GL_FLOAT,
                      raster.uv.data());
  return strongest;
}

void WindTextures::bind(const gl::Program&) const { glBindTextureUnit(gl::kUnitWind, wind_.id()); }

}  // namespace og::render
