#include "render/AerialTable.hpp"

#include "gl/ShaderContract.hpp"

namespace og::render {

namespace {

// render/aerial.glsl's AERIAL_TABLE_SIZE (ν, d; 3 layers) and AERIAL_TERRAIN_SIZE (ν, d,
// altitude; 3 blocks along ν): keep equal.
constexpr int kSeaLevelNu = 64, kSeaLevelPath = 256;
constexpr int kTerrainNu = 16, kTerrainPath = 128, kTerrainAltitudes = 16;

}  // namespace

void AerialTable::update(const Atmosphere& atmosphere, const geo::CameraView& view,
                         const glm::dvec3& sunDirectionEcef) {
  const bool terrain = kind_ == Kind::terrain;
  const int nu = terrain ? kTerrainNu : kSeaLevelNu, path = terrain ? kTerrainPath : kSeaLevelPath;
  const int depth = terrain ? kTerrainAltitudes : 1;
  if (texture_.id() == 0) {
    texture_ = gl::createTexture(terrain ? GL_TEXTURE_3D : GL_TEXTURE_2D_ARRAY);
    if (terrain)
      glTextureStorage3D(texture_.id(), 1, GL_RGBA32F, 3 * nu, path, depth);
    else
      glTextureStorage3D(texture_.id(), 1, GL_RGBA32F, nu, path, 3);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (const GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTextureParameteri(texture_.id(), wrap, GL_CLAMP_TO_EDGE);
    program_ = terrain ? gl::Program({{GL_COMPUTE_SHADER, "render/aerial_table.comp"}}, {"AERIAL_TABLE_TERRAIN"})
                       : gl::Program({{GL_COMPUTE_SHADER, "render/aerial_table.comp"}});
  }
  program_.set("uCamUp", glm::vec3(view.enu.up));
  program_.set("uCamAltitude", static_cast<float>(view.position.heightM));
  program_.set("uSunDir", glm::vec3(glm::normalize(sunDirectionEcef)));
  atmosphere.bind(program_);
  program_.use();
  glBindImageTexture(0, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(static_cast<GLuint>((nu + 7) / 8), static_cast<GLuint>((path + 7) / 8), static_cast<GLuint>(depth));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindTextureUnit(terrain ? gl::kUnitTerrainAerialTable : gl::kUnitAerialTable, texture_.id());
}

}  // namespace og::render
