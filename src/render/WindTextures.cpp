#include "render/WindTextures.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace og::render {

WindTextures::WindTextures() {
  // A 1x1 calm texture keeps the sampler valid before any layer is set.
  wind_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(wind_.id(), 1, GL_RG32F, 1, 1);
  const float zero[2] = {0.0f, 0.0f};
  glTextureSubImage2D(wind_.id(), 0, 0, 0, 1, 1, GL_RG, GL_FLOAT, zero);
}

void WindTextures::setLayers(std::shared_ptr<const data::WindLayers> layers, int width, int height) {
  layers_ = std::move(layers);
  if (!layers_) return;
  const data::WindRaster raster = layers_->rasterize(width, height);
  wind_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(wind_.id(), 1, GL_RG32F, raster.width, raster.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(wind_.id(), 0, 0, 0, raster.width, raster.height, GL_RG, GL_FLOAT,
                      raster.uv.data());
  // Bilinear between cells: the layers are already smooth (blended edges), so is the sea.
  glTextureParameteri(wind_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(wind_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(wind_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(wind_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void WindTextures::setWaveSet(const ocean::WaveSet& set) {
  const auto& p = set.params;
  if (tableBuilt_ && p.windSpeedMs == tableFor_.windSpeedMs &&
      p.windDirectionDeg == tableFor_.windDirectionDeg && p.count == tableFor_.count &&
      p.seed == tableFor_.seed && p.lambdaMaxM == tableFor_.lambdaMaxM)
    return;
  const ocean::WindTables t = ocean::makeWindTables(set);
  const int columns = static_cast<int>(t.total.size());
  const int rows = 1 + static_cast<int>(set.waves.size());
  std::vector<float> texels(static_cast<std::size_t>(2 * columns * rows), 0.0f);
  auto at = [&](int c, int r) -> float* {
    return &texels[static_cast<std::size_t>(2 * (r * columns + c))];
  };
  for (int c = 0; c < columns; ++c) {
    const auto sc = static_cast<std::size_t>(c);
    at(c, 0)[0] = static_cast<float>(t.total[sc].up);
    at(c, 0)[1] = static_cast<float>(t.total[sc].cross);
    for (std::size_t i = 0; i < set.waves.size(); ++i)
      at(c, 1 + static_cast<int>(i))[0] = static_cast<float>(t.amplitudeM[sc][i]);
  }
  table_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(table_.id(), 1, GL_RG32F, columns, rows);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(table_.id(), 0, 0, 0, columns, rows, GL_RG, GL_FLOAT, texels.data());
  tableStepMs_ = t.speedStepMs;
  tableFor_ = p;
  tableBuilt_ = true;
}

void WindTextures::bind(const gl::Program& program, double speedMs, double directionDeg) const {
  glBindTextureUnit(1, wind_.id());
  glBindTextureUnit(10, table_.id());
  program.set("uLocalWind", layers_ ? 1 : 0);
  program.set("uOceanTableStep", static_cast<float>(tableStepMs_));
  program.set("uConstantWind", glm::vec2(static_cast<float>(speedMs),
                                         static_cast<float>(directionDeg * std::numbers::pi / 180.0)));
}

}  // namespace og::render
