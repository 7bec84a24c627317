#include "render/LandMaskTexture.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <future>
#include <numbers>
#include <vector>

#include <glm/vec4.hpp>

#include "core/Error.hpp"
#include "geo/Wgs84.hpp"
#include "gl/Probe.hpp"
#include "gl/Shader.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {

LandMaskTexture::LandMaskTexture(const data::LandMask* mask) {
  texture_ = gl::createTexture(GL_TEXTURE_2D);
  if (mask != nullptr && !(mask->width() == 2 * mask->height() && mask->width() % 8 == 0))
    throw InternalError("land mask: the GPU takes a global mask of square cells, width a multiple of 8");
  // One 32-bit texel per 8 columns holding columns 8x - 4 ... 8x + 11 (wrapping in longitude):
  // the land bits in the low half, the refined bits (the fine level's) in the high half. Any
  // three neighbouring cells of a row lie in one texel, so the shader's 3 x 3 B-spline
  // (terrain/landmask.glsl) takes one fetch a row, and the fine level learns from the same
  // fetch whether it needs its blocks.
  // Start-up: the fine level's texels (the rank index and the blocks, 14 MiB) are built on a
  // helper thread while this one packs the 2′ texels.
  std::future<FineTexels> fine;
  if (mask != nullptr && mask->hasFineLevel())
    fine = std::async(std::launch::async, [mask] { return fineTexels(*mask); });
  const int w = mask != nullptr ? mask->bytesPerRow() : 1;
  const int h = mask != nullptr ? mask->height() : 1;
  std::vector<std::uint32_t> texels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  if (mask != nullptr) {
    const auto n = static_cast<std::size_t>(w);
    const auto pack = [n](const std::uint8_t* in, std::uint32_t* out, unsigned shift) {
      // Start-up: no modulo per texel (14.6 M of them); the row's ends wrap.
      unsigned before = in[n - 1], here = in[0];
      for (std::size_t x = 0; x < n; ++x) {
        const unsigned after = in[x + 1 < n ? x + 1 : 0];
        out[x] |= ((before >> 4) | (here << 4) | ((after & 0xFu) << 12)) << shift;
        before = here;
        here = after;
      }
    };
    for (int r = 0; r < h; ++r) {
      const std::size_t at = static_cast<std::size_t>(r) * n;
      pack(mask->packedBits().data() + at, texels.data() + at, 0);
      if (mask->hasFineLevel()) pack(mask->refinedBits().data() + at, texels.data() + at, 16);
    }
  }
  glTextureStorage2D(texture_.id(), 1, GL_R32UI, w, h);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, w, h, GL_RED_INTEGER, GL_UNSIGNED_INT, texels.data());
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  active_ = mask != nullptr;
  cellRad_ = mask != nullptr ? std::numbers::pi / h : 0.0;
  bytes_ = texels.size() * sizeof(std::uint32_t);
  noMips_ = gl::createTexture(GL_TEXTURE_2D);
  const std::uint8_t noFraction = 0;
  glTextureStorage2D(noMips_.id(), 1, GL_R8, 1, 1);
  glTextureSubImage2D(noMips_.id(), 0, 0, 0, 1, 1, GL_RED, GL_UNSIGNED_BYTE, &noFraction);
  if (fine.valid()) {
    uploadFineLevel(fine.get());
    fineCellRad_ = std::numbers::pi / (8.0 * h);  // landmask.glsl's fineCellRad
  } else {
    fine_ = gl::createTexture(GL_TEXTURE_2D);
    const std::uint32_t none[4] = {0, 0, 0, 0};
    glTextureStorage2D(fine_.id(), 1, GL_RGBA32UI, 1, 1);
    glTextureSubImage2D(fine_.id(), 0, 0, 0, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT, none);
  }
}

bool LandMaskTexture::fineLevelUnresolved(const geo::CameraView& view, int heightPx) const {
  if (fineCellRad_ <= 0.0) return true;
  // coastFootprintRad = t pixelRad / (a max(cos, 0.2)) >= t pixelRad / a; 1 % for the floats.
  return geo::smallestGroundFootprintRad(view, heightPx, geo::kHighestGroundM) >=
         1.01 * kFineCellsUnweighted * fineCellRad_;
}

void LandMaskTexture::uploadFractionMips(const data::LandFractionMips& mips) {
  if (!active_ || mipsUploaded_) return;
  mips_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(mips_.id(), mips.levels(), GL_R8, mips.levelWidth(0), mips.levelHeight(0));
  GLint alignment = 4;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // (rows of any length)
  for (int level = 0; level < mips.levels(); ++level)
    glTextureSubImage2D(mips_.id(), level, 0, 0, mips.levelWidth(level), mips.levelHeight(level), GL_RED,
                        GL_UNSIGNED_BYTE, mips.levelBytes(level).data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  glTextureParameteri(mips_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(mips_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(mips_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);         // longitude wraps
  glTextureParameteri(mips_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);  // rows clamp
  bytes_ += mips.bytes();
  mipsUploaded_ = true;
}

bool LandMaskTexture::fractionMipsWeighed(const geo::CameraView& view, int heightPx) const {
  if (!active_ || heightPx <= 0) return false;
  // The farthest ground a ray meets: over the sea's horizon to the horizon of the highest
  // ground; the passes' pixel angle is the centre pixel's, 2 tan(fov / 2) / height.
  const double a = geo::kWgs84SemiMajorM, h = std::max(view.position.heightM, 0.0), top = geo::kHighestGroundM;
  const double farthestM = std::sqrt(h * (2.0 * a + h)) + std::sqrt(top * (2.0 * a + top));
  const double largestPixelRad = 2.0 * std::tan(0.5 * view.verticalFovRad) / heightPx;
  return farthestM * largestPixelRad / (a * 0.2) > 0.99 * cellRad_;
}

bool LandMaskTexture::fractionMipsOnly(const geo::CameraView& view, int heightPx) const {
  return mipsUploaded_ && geo::smallestGroundFootprintRad(view, heightPx, geo::kHighestGroundM) >= 1.01 * 2.0 * cellRad_;
}

LandMaskTexture::FineTexels LandMaskTexture::fineTexels(const data::LandMask& mask) {
  // The rank index: per row, one texel per 96 cells (three 32-bit words of refined bits and
  // the refined cells before them), then the blocks two a texel.
  const int perRow = (mask.width() + 95) / 96, stride = mask.bytesPerRow();
  const std::vector<std::uint64_t>& blocks = mask.blocks();
  const std::size_t rankTexels = static_cast<std::size_t>(perRow) * static_cast<std::size_t>(mask.height());
  const std::size_t total = rankTexels + (blocks.size() + 1) / 2;
  FineTexels f;
  f.height = static_cast<int>((total + kFineWidth - 1) / kFineWidth);
  f.texels.assign(static_cast<std::size_t>(kFineWidth) * static_cast<std::size_t>(f.height) * 4, 0);
  std::uint32_t before = 0;
  for (int r = 0; r < mask.height(); ++r) {
    const std::uint8_t* row = mask.refinedBits().data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(stride);
    for (int k = 0; k < perRow; ++k) {
      std::uint32_t* t = f.texels.data() + 4 * (static_cast<std::size_t>(r) * static_cast<std::size_t>(perRow) + static_cast<std::size_t>(k));
      t[3] = before;
      for (int b = 12 * k; b < std::min(12 * k + 12, stride); ++b)
        t[(b - 12 * k) / 4] |= static_cast<std::uint32_t>(row[b]) << (8 * ((b - 12 * k) % 4));
      // A popcount a word, not a byte: on baseline x86-64 each is a library call.
      before += static_cast<std::uint32_t>(std::popcount(t[0]) + std::popcount(t[1]) + std::popcount(t[2]));
    }
  }
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    std::uint32_t* t = f.texels.data() + 4 * rankTexels + 2 * i;
    t[0] = static_cast<std::uint32_t>(blocks[i]);
    t[1] = static_cast<std::uint32_t>(blocks[i] >> 32);
  }
  return f;
}

void LandMaskTexture::uploadFineLevel(const FineTexels& f) {
  fine_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(fine_.id(), 1, GL_RGBA32UI, kFineWidth, f.height);
  glTextureSubImage2D(fine_.id(), 0, 0, 0, kFineWidth, f.height, GL_RGBA_INTEGER, GL_UNSIGNED_INT, f.texels.data());
  glTextureParameteri(fine_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(fine_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  bytes_ += f.texels.size() * sizeof(std::uint32_t);
}

void LandMaskTexture::bind(bool fractionMips) const {
  glBindTextureUnit(gl::kUnitLandMask, texture_.id());
  glBindTextureUnit(gl::kUnitLandMaskFine, fine_.id());
  glBindTextureUnit(gl::kUnitLandFraction, fractionMips && mipsUploaded_ ? mips_.id() : noMips_.id());
}

std::vector<float> LandMaskTexture::probeLandFraction(const std::vector<glm::vec3>& latLonFootprintRad) const {
  if (latLonFootprintRad.empty()) return {};
  std::vector<glm::vec4> values;
  for (const glm::vec3& p : latLonFootprintRad) values.emplace_back(p.x, p.y, p.z, 0.0f);
  gl::Program probe({{GL_COMPUTE_SHADER, "terrain/landmask_probe.comp"}}, {"LANDMASK_PYRAMID"});
  bind(true);
  gl::runProbe(probe, values, static_cast<int>(values.size()), "LandMaskTexture::probeLandFraction");
  std::vector<float> out;
  for (const glm::vec4& v : values) out.push_back(v.x);
  return out;
}

}  // namespace og::render
