#include "render/WaterVolume.hpp"

#include <array>
#include <cmath>

#include "geo/Wgs84.hpp"
#include "terrain/Heightfield.hpp"

namespace og::render {

void setWaterOptics(const gl::Program& p, const ocean::WaterType& water) {
  p.set("uWaterAttenuation", glm::vec3(water.attenuationPerM));
  p.set("uFloorAlbedo", glm::vec3(ocean::kCoralSandAlbedo));
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

}  // namespace og::render
