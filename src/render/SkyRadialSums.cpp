#include "render/SkyRadialSums.hpp"

#include <algorithm>
#include <vector>

#include "gl/ShaderContract.hpp"

namespace og::render {
namespace {

gl::Texture sumsTexture(GLenum target, int layers) {
  gl::Texture t = gl::createTexture(target);
  const int levels = gl::fullMipLevels(SkyRadialSums::kAzimuths);
  if (target == GL_TEXTURE_2D)
    glTextureStorage2D(t.id(), levels, GL_RGBA32F, SkyRadialSums::kAzimuths, SkyRadialSums::kRadii);
  else
    glTextureStorage3D(t.id(), levels, GL_RGBA32F, SkyRadialSums::kAzimuths, SkyRadialSums::kRadii, layers);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);  // around the turn
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

}  // namespace

void SkyRadialSums::fill(GLuint skyMapsId, int first, int count, bool frame) {
  // A compute program on its first use, the frame layer's variant (SKY_RADIAL_FRAME) or the
  // Sun layers'.
  const auto made = [frame](gl::Program& program, const char* shader) -> gl::Program& {
    if (program.id() == 0)
      program = gl::Program({{GL_COMPUTE_SHADER, shader}},
                            frame ? std::vector<std::string>{"SKY_RADIAL_FRAME"} : std::vector<std::string>{});
    return program;
  };
  const GLuint target = frame ? frame_.id() : layers_.id();
  const GLboolean layered = frame ? GL_FALSE : GL_TRUE;
  const gl::Program& program = made(frame ? fillFrame_ : fillLayers_, "atmosphere/skymap_radial.comp");
  glBindTextureUnit(gl::kUnitSkyMap, skyMapsId);
  program.set("uFirstLayer", first);
  program.use();
  glBindImageTexture(0, target, 0, layered, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(static_cast<GLuint>((kAzimuths + 63) / 64), 1, static_cast<GLuint>(count));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  // The mip levels by a compute of their own (skymap_radial_mip.comp), each layer in z.
  made(frame ? frameMips_ : mips_, "atmosphere/skymap_radial_mip.comp").use();
  for (int level = 1; level < gl::fullMipLevels(kAzimuths); ++level) {
    glBindImageTexture(0, target, level - 1, layered, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, target, level, layered, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const auto w = static_cast<GLuint>(std::max(kAzimuths >> level, 1)), h = static_cast<GLuint>(std::max(kRadii >> level, 1));
    glDispatchCompute((w + 7) / 8, (h + 7) / 8, static_cast<GLuint>(count));
    // (The update bit for read()'s glGetTextureSubImage in the tests.)
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
  for (GLuint unit : {0u, 1u}) glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
}

void SkyRadialSums::updateFrameLayer(GLuint skyMapsId, int skyMapLayers, double frameKey,
                                     const glm::vec3& belowHorizon) {
  if (frame_.id() != 0 && frameKey == frameKey_) return;
  if (frame_.id() == 0) frame_ = sumsTexture(GL_TEXTURE_2D, 1);
  skyMapLayers_ = skyMapLayers;
  belowHorizon_.resize(static_cast<std::size_t>(skyMapLayers + 1), glm::vec3(0.0f));
  belowHorizon_.back() = belowHorizon;
  fill(skyMapsId, skyMapLayers, 1, true);
  gl::checkErrors("SkyRadialSums::updateFrameLayer");
  frameKey_ = frameKey;
}

void SkyRadialSums::ensureSunLayers(GLuint skyMapsId, const std::vector<glm::vec3>& belowHorizon) {
  if (layers_.id() != 0) return;
  const auto layers = static_cast<int>(belowHorizon.size());
  layers_ = sumsTexture(GL_TEXTURE_2D_ARRAY, layers);
  skyMapLayers_ = layers;
  belowHorizon_.resize(static_cast<std::size_t>(layers + 1), glm::vec3(0.0f));
  std::copy(belowHorizon.begin(), belowHorizon.end(), belowHorizon_.begin());
  fill(skyMapsId, 0, layers, false);
  gl::checkErrors("SkyRadialSums::ensureSunLayers");
}

void SkyRadialSums::bind() const {
  if (frame_.id() != 0) glBindTextureUnit(gl::kUnitSkyRadialSums, frame_.id());
  if (layers_.id() != 0) glBindTextureUnit(gl::kUnitSkyRadialSumsLayers, layers_.id());
}

void SkyRadialSums::setUniforms(const gl::Program& program) const {
  if (belowHorizon_.empty()) return;
  if (const GLint at = program.location("uSkyBelowHorizonLayers"); at >= 0)
    glProgramUniform3fv(program.id(), at, static_cast<GLsizei>(belowHorizon_.size() - 1), &belowHorizon_[0].x);
  program.set("uSkyBelowHorizon", belowHorizon_.back());
}

glm::vec3 SkyRadialSums::belowHorizon(int layer) const { return belowHorizon_.at(static_cast<std::size_t>(layer)); }

std::vector<float> SkyRadialSums::read(int layer, int level) const {
  const int w = std::max(kAzimuths >> level, 1), h = std::max(kRadii >> level, 1);
  std::vector<float> texels(static_cast<std::size_t>(4 * w * h));
  const bool frame = layer == skyMapLayers_;
  glGetTextureSubImage(frame ? frame_.id() : layers_.id(), level, 0, 0, frame ? 0 : layer, w, h, 1, GL_RGBA,
                       GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  return texels;
}

}  // namespace og::render
