#include "render/SkyRadialSums.hpp"

#include <array>

#include "gl/ShaderContract.hpp"

namespace og::render {

void SkyRadialSums::update(GLuint skyMapsId, int skyMapLayers, double frameKey) {
  if (texture_.id() != 0 && frameKey == frameKey_) return;
  if (texture_.id() == 0) {
    texture_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.id(), gl::fullMipLevels(kAzimuths), GL_RGBA32F, kAzimuths, kRadii);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);  // around the turn
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  if (fill_.id() == 0) fill_ = gl::Program({{GL_COMPUTE_SHADER, "atmosphere/skymap_radial.comp"}});
  glBindTextureUnit(gl::kUnitSkyMap, skyMapsId);
  // The frame layer's corner texel lies far below the horizon (|u| = 1.1 sqrt 2): the constant
  // the maps hold there (atmosphere/skymap_common.glsl's skyMapBelowHorizon).
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::array<float, 4> corner{};
  glGetTextureSubImage(skyMapsId, 0, 0, 0, skyMapLayers, 1, 1, 1, GL_RGBA, GL_FLOAT,
                       static_cast<GLsizei>(sizeof(corner)), corner.data());
  belowHorizon_ = glm::vec3(corner[0], corner[1], corner[2]);
  fill_.set("uBelowHorizon", belowHorizon_);
  fill_.use();
  glBindImageTexture(0, texture_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(static_cast<GLuint>((kAzimuths + 63) / 64), 1, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glGenerateTextureMipmap(texture_.id());
  gl::checkErrors("SkyRadialSums::update");
  frameKey_ = frameKey;
}

void SkyRadialSums::bind() const { glBindTextureUnit(gl::kUnitSkyRadialSums, texture_.id()); }

void SkyRadialSums::setUniforms(const gl::Program& program) const { program.set("uSkyBelowHorizon", belowHorizon_); }

std::vector<float> SkyRadialSums::read() const {
  std::vector<float> texels(static_cast<std::size_t>(4 * kAzimuths * kRadii));
  glGetTextureImage(texture_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)),
                    texels.data());
  return texels;
}

}  // namespace og::render
