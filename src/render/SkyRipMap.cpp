#include "render/SkyRipMap.hpp"

#include "gl/ShaderContract.hpp"

namespace og::render {

void SkyRipMap::update(int skyMapSize, double frameKey) {
  if (texture_.id() != 0 && size_ == skyMapSize && frameKey == frameKey_) return;
  const int levels = gl::fullMipLevels(skyMapSize);  // as the sky maps' (Atmosphere::skyMapLevels)
  if (texture_.id() == 0 || size_ != skyMapSize) {
    texture_ = gl::createSquareArray(GL_RGBA16F, skyMapSize, kLayers, levels, GL_CLAMP_TO_EDGE);
    size_ = skyMapSize;
  }
  if (fill_.id() == 0) fill_ = gl::Program({{GL_COMPUTE_SHADER, "atmosphere/skymap_rip.comp"}});
  fill_.use();
  for (int level = 0; level < levels; ++level) {
    const int size = skyMapSize >> level;
    fill_.set("uLevel", level);
    glBindImageTexture(0, texture_.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const auto groups = static_cast<GLuint>((size + 7) / 8);
    glDispatchCompute(groups, groups, kLayers);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  gl::checkErrors("SkyRipMap::update");
  frameKey_ = frameKey;
}

void SkyRipMap::bind() const { glBindTextureUnit(gl::kUnitSkyRipMap, texture_.id()); }

std::vector<float> SkyRipMap::read() const {
  std::vector<float> texels(static_cast<std::size_t>(4 * size_ * size_ * kLayers));
  glGetTextureImage(texture_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)),
                    texels.data());
  return texels;
}

}  // namespace og::render
