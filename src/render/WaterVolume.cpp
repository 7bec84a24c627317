#include "render/WaterVolume.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "geo/Wgs84.hpp"
#include "terrain/Heightfield.hpp"

namespace og::render {

void setWaterOptics(const gl::Program& p, const ocean::WaterType& water) {
  p.set("uWaterAttenuation", glm::vec3(water.attenuationPerM));
  p.set("uFloorAlbedo", glm::vec3(ocean::kCoralSandAlbedo));
}

double layerMaxSlope(const data::LatLonGrid& layer) {
  const auto height = [&](int column, int row) {
    const float v = layer.at(column, row);
    return std::isfinite(v) ? static_cast<double>(v) : -1.0;
  };
  const double deg = 3.14159265358979323846 / 180.0;
  const double rowM = geo::kWgs84SemiMajorM * layer.dLatDeg * deg;
  double most = 0.0;
  for (int row = 0; row < layer.height; ++row) {
    const double lat = (layer.lat0Deg + row * layer.dLatDeg) * deg;
    const double columnM = geo::kWgs84SemiMajorM * layer.dLonDeg * deg * std::max(std::cos(lat), 1e-3);
    for (int column = 0; column < layer.width; ++column) {
      const double h = height(column, row);
      const int next = column + 1 < layer.width ? column + 1 : (layer.wrapsLongitude ? 0 : -1);
      if (next >= 0) most = std::max(most, std::abs(height(next, row) - h) / columnM);
      if (row + 1 < layer.height) most = std::max(most, std::abs(height(column, row + 1) - h) / rowM);
    }
  }
  return most;
}

void setFloorDetail(const gl::Program& p, const geo::CameraView& view) {
  terrain::DetailOctaves o;
  o.longestM = kFloorDetailLongestM;
  o.heightCount = 0;
  o.normalCount = kFloorDetailOctaves;
  std::array<glm::ivec3, kFloorDetailOctaves> cells{};
  std::array<glm::vec3, kFloorDetailOctaves> fracs{};
  for (int k = 0; k < kFloorDetailOctaves; ++k) {
    const glm::dvec3 q = terrain::detailLatticePoint(o, k, view.enu.up);
    const glm::dvec3 c = glm::floor(q);
    cells[static_cast<std::size_t>(k)] = glm::ivec3(c);
    fracs[static_cast<std::size_t>(k)] = glm::vec3(q - c);
  }
  const GLint cellAt = p.location("uFloorCell");
  if (cellAt < 0) return;  // a variant without the water volume
  glProgramUniform3iv(p.id(), cellAt, kFloorDetailOctaves, &cells[0].x);
  glProgramUniform3fv(p.id(), p.location("uFloorFrac"), kFloorDetailOctaves, &fracs[0].x);
  p.set("uFloorScale0", static_cast<float>(geo::kWgs84SemiMajorM / o.longestM));
  const double ab = geo::kWgs84SemiMajorM / geo::kWgs84SemiMinorM;
  const glm::dvec3 foot = view.positionEcef - view.position.heightM * view.enu.up;
  p.set("uFloorEyeUp", glm::vec3(view.enu.up));
  p.set("uFloorEyeHeightM", static_cast<float>(view.position.heightM));
  p.set("uFloorEyeFootScale", static_cast<float>(glm::length(foot * glm::dvec3(1.0, 1.0, ab * ab))));
}

std::vector<std::string> waterVolumeDefines() {
  return {"CAUSTIC_PATTERNS " + std::to_string(kCausticPatterns)};
}

namespace {
std::vector<std::string> causticDefines() {
  std::vector<std::string> d = OceanPatterns::shaderDefines();
  for (const std::string& define : waterVolumeDefines()) d.push_back(define);
  return d;
}
}  // namespace

CausticCurvature::CausticCurvature() : program_({{GL_COMPUTE_SHADER, "ocean/caustic_curvature.comp"}}, causticDefines()) {}

void CausticCurvature::update(const OceanPatterns& patterns, double timeS) {
  const GLuint source = patterns.slopesTexture();
  if (source == source_ && timeS == timeS_) return;
  const int n = patterns.patterns().params.fftSize;
  const int layers = ocean::kPatternSets * kCausticPatterns;
  if (n != size_) {
    texture_ = gl::createSquareArray(GL_R16F, n, layers, gl::fullMipLevels(n), GL_REPEAT);  // tiles as the patterns
    size_ = n;
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindTextureUnit(gl::kUnitPatternSlopes, source);  // where the sea samples the slopes too (OceanPatterns::bind)
  glBindImageTexture(0, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R16F);
  program_.use();
  glDispatchCompute(static_cast<GLuint>((n + 7) / 8), static_cast<GLuint>((n + 7) / 8), static_cast<GLuint>(layers));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glGenerateTextureMipmap(texture_.id());
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R16F);
  gl::checkErrors("CausticCurvature::update");
  source_ = source;
  timeS_ = timeS;
}

void CausticCurvature::bind() const { glBindTextureUnit(kCausticCurvatureUnit, texture_.id()); }

}  // namespace og::render
