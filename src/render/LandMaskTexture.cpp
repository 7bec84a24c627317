#include "render/LandMaskTexture.hpp"

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "core/Error.hpp"
#include "gl/Probe.hpp"
#include "gl/Shader.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {

LandMaskTexture::LandMaskTexture(const data::LandMask* mask) {
  texture_ = gl::createTexture(GL_TEXTURE_2D);
  if (mask != nullptr && !(mask->width() == 2 * mask->height() && mask->width() % 8 == 0))
    throw InternalError("land mask: the GPU takes a global mask of square cells, width a multiple of 8");
  // One 16-bit texel per 8 columns holding columns 8x - 4 ... 8x + 11 (wrapping in longitude):
  // any three neighbouring cells of a row lie in one texel, so the shader's 3 x 3 B-spline
  // (terrain/landmask.glsl) takes one fetch a row.
  const int w = mask != nullptr ? mask->bytesPerRow() : 1;
  const int h = mask != nullptr ? mask->height() : 1;
  std::vector<std::uint16_t> texels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  if (mask != nullptr) {
    const std::vector<std::uint8_t>& bits = mask->packedBits();
    const auto n = static_cast<std::size_t>(w);
    for (int r = 0; r < h; ++r) {
      // Start-up: no modulo per texel (14.6 M of them); the row's ends wrap.
      const std::uint8_t* in = bits.data() + static_cast<std::size_t>(r) * n;
      std::uint16_t* out = texels.data() + static_cast<std::size_t>(r) * n;
      unsigned before = in[n - 1], here = in[0];
      for (std::size_t x = 0; x < n; ++x) {
        const unsigned after = in[x + 1 < n ? x + 1 : 0];
        out[x] = static_cast<std::uint16_t>((before >> 4) | (here << 4) | ((after & 0xFu) << 12));
        before = here;
        here = after;
      }
    }
  }
  glTextureStorage2D(texture_.id(), 1, GL_R16UI, w, h);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, w, h, GL_RED_INTEGER, GL_UNSIGNED_SHORT, texels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  active_ = mask != nullptr;
  bytes_ = texels.size() * sizeof(std::uint16_t);
}

void LandMaskTexture::bind() const { glBindTextureUnit(gl::kUnitLandMask, texture_.id()); }

std::vector<float> LandMaskTexture::probeLandFraction(const std::vector<glm::vec2>& latLonRad) const {
  if (latLonRad.empty()) return {};
  std::vector<glm::vec4> values;
  for (const glm::vec2& p : latLonRad) values.emplace_back(p.x, p.y, 0.0f, 0.0f);
  gl::Program probe({{GL_COMPUTE_SHADER, "terrain/landmask_probe.comp"}});
  bind();
  gl::runProbe(probe, values, static_cast<int>(values.size()), "LandMaskTexture::probeLandFraction");
  std::vector<float> out;
  for (const glm::vec4& v : values) out.push_back(v.x);
  return out;
}

}  // namespace og::render
