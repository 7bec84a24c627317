#include "render/LandMaskTexture.hpp"

#include <cstdint>

#include "core/Error.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {

LandMaskTexture::LandMaskTexture(const data::LandMask* mask) {
  texture_ = gl::createTexture(GL_TEXTURE_2D);
  if (mask != nullptr && !(mask->width() == 2 * mask->height() && mask->width() % 8 == 0))
    throw InternalError("land mask: the GPU takes a global mask of square cells, width a multiple of 8");
  const int w = mask != nullptr ? mask->bytesPerRow() : 1;
  const int h = mask != nullptr ? mask->height() : 1;
  glTextureStorage2D(texture_.id(), 1, GL_R8UI, w, h);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::uint8_t water = 0;
  glTextureSubImage2D(texture_.id(), 0, 0, 0, w, h, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                      mask != nullptr ? mask->packedBits().data() : &water);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  active_ = mask != nullptr;
  bytes_ = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
}

void LandMaskTexture::bind() const { glBindTextureUnit(gl::kUnitLandMask, texture_.id()); }

}  // namespace og::render
