#include "terrain/Heightfield.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "core/GlslShim.hpp"
#include "geo/Wgs84.hpp"
#include "terrain/Tile.hpp"

namespace og::terrain {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// Detail amplitude per metre of the layer's relief across one cell. A layer averages its cell,
// so its relief understates the ground's (ETOPO5's Himalaya peaks are kilometres low); 2.5
// gives mountain slopes of ~25° at the 100 m scale, like real ranges.
constexpr double kReliefGain = 2.5;

namespace glsl {
using namespace og::glsl;
#include "terrain/detail.glsl"
}  // namespace glsl

}  // namespace

double DetailOctaves::wavelengthM(int k) const { return std::ldexp(longestM, -k); }

int DetailOctaves::countAtLeast(double wavelength) const {
  int k = 0;
  while (k < normalCount && wavelengthM(k) >= wavelength) ++k;
  return k;
}

glm::dvec3 detailLatticePoint(const DetailOctaves& o, int k, const glm::dvec3& unitUp) {
  return unitUp * (geo::kWgs84SemiMajorM / o.wavelengthM(k)) + glsl::detailOctaveOffset(k);
}

double detailSum(const DetailOctaves& o, const glm::dvec3& unitUp, int count, int gradientOctaves,
                 glm::dvec3* gradient) {
  double sum = 0.0;
  glm::dvec3 grad(0.0);
  for (int k = 0; k < count; ++k) {
    const glm::dvec3 p = detailLatticePoint(o, k, unitUp);
    const glm::dvec3 cell = glm::floor(p);
    const glm::dvec4 r = glsl::detailRidged(glm::ivec3(cell), p - cell);
    const double w = glsl::detailOctaveWeight(k) / o.norm;
    sum += w * r.x;
    // d/d(unitUp) of the lattice point is a / wavelength.
    if (k < gradientOctaves) grad += w * (geo::kWgs84SemiMajorM / o.wavelengthM(k)) * glm::dvec3(r.y, r.z, r.w);
  }
  if (gradient != nullptr) *gradient = grad;
  return std::clamp(sum, -1.0, 1.0);
}

Heightfield::Heightfield(data::LatLonGrid layer) : layer_(std::move(layer)) {
  if (layer_.wrapsLongitude && data::defaultLandMask().refines(layer_)) mask_ = &data::defaultLandMask();
  cellM_ = layer_.dLatDeg * kDeg * geo::kWgs84SemiMajorM;
  // Octaves from two layer cells (what the bilinear layer cannot show) down to the shortest.
  octaves_.longestM = 2.0 * cellM_;
  octaves_.normalCount = 0;
  octaves_.heightCount = 0;
  octaves_.norm = 0.0;
  while (octaves_.normalCount < 24 && octaves_.wavelengthM(octaves_.normalCount) >= kNormalShortestM) {
    if (octaves_.wavelengthM(octaves_.normalCount) >= kDetailShortestM) {
      octaves_.norm += glsl::detailOctaveWeight(octaves_.normalCount);
      ++octaves_.heightCount;
    }
    ++octaves_.normalCount;
  }
  if (octaves_.norm <= 0.0) octaves_.norm = 1.0;
}

double Heightfield::layerHeightM(double latitudeDeg, double longitudeDeg) const {
  const float v = layer_.sample(std::clamp(latitudeDeg, -90.0, 90.0), longitudeDeg);
  const double h = std::isfinite(v) ? static_cast<double>(v) : -1.0;
  if (mask_ == nullptr) return h;
  return mask_->constrainHeightM(h, latitudeDeg, longitudeDeg, layer_.sampleKeepDepth(latitudeDeg, longitudeDeg));
}

double Heightfield::detailAmplitudeM(double latitudeDeg, double longitudeDeg) const {
  return detailAmplitudeM(latitudeDeg, longitudeDeg, layerHeightM(latitudeDeg, longitudeDeg));
}

double Heightfield::detailAmplitudeM(double latitudeDeg, double longitudeDeg, double h) const {
  const double d = layer_.dLatDeg;
  const double relief =
      0.5 * (std::abs(layerHeightM(latitudeDeg + d, longitudeDeg) -
                      layerHeightM(latitudeDeg - d, longitudeDeg)) +
             std::abs(layerHeightM(latitudeDeg, longitudeDeg + d) -
                      layerHeightM(latitudeDeg, longitudeDeg - d)));
  // Rugged where the layer is rugged, flat plains stay flat; never more than 80 % of |h|, so
  // the coastline stays on the layer's zero contour, which the globe and ocean passes use too.
  const double amplitude = std::min(std::max(kReliefGain * relief, 0.03 * std::abs(h)), 0.8 * std::abs(h));
  return amplitude < 0.5 ? 0.0 : amplitude;
}

HeightSample Heightfield::sample(double latitudeDeg, double longitudeDeg, int normalOctaves,
                                 double stepDeg) const {
  HeightSample s;
  const double h = layerHeightM(latitudeDeg, longitudeDeg);
  const glm::dvec3 up = geodeticUpFast(latitudeDeg, longitudeDeg);
  s.detailAmplitudeM = detailAmplitudeM(latitudeDeg, longitudeDeg, h);
  glm::dvec3 grad(0.0);
  s.heightM = h;
  if (s.detailAmplitudeM > 0.0)
    s.heightM = h + s.detailAmplitudeM * detailSum(octaves_, up, octaves_.heightCount,
                                                   normalOctaves, &grad);
  // The layer's normal from central differences on the ellipsoid (ECEF), over at least half a
  // cell so the bilinear layer's facets do not show in the lighting.
  const double latN = std::min(latitudeDeg + stepDeg, 90.0), latS = std::max(latitudeDeg - stepDeg, -90.0);
  const glm::dvec3 pn = geodeticToEcefFast(latN, longitudeDeg, layerHeightM(latN, longitudeDeg));
  const glm::dvec3 ps = geodeticToEcefFast(latS, longitudeDeg, layerHeightM(latS, longitudeDeg));
  const glm::dvec3 pe = geodeticToEcefFast(latitudeDeg, longitudeDeg + stepDeg,
                                           layerHeightM(latitudeDeg, longitudeDeg + stepDeg));
  const glm::dvec3 pw = geodeticToEcefFast(latitudeDeg, longitudeDeg - stepDeg,
                                           layerHeightM(latitudeDeg, longitudeDeg - stepDeg));
  const glm::dvec3 c = glm::cross(pe - pw, pn - ps);
  const double len = glm::length(c), ns = glm::length(pn - ps);
  // At the poles the east-west difference vanishes: the vertical stands in.
  glm::dvec3 n = len > 1e-6 * ns * ns ? c / len : up;
  // Tilt by the detail's height gradient per metre along the surface (the unit sphere's
  // coordinates move 1/a per metre), tangential part only.
  const glm::dvec3 g = grad * (s.detailAmplitudeM / geo::kWgs84SemiMajorM);
  n = glm::normalize(n - (g - glm::dot(g, n) * n));
  s.normal = n;
  return s;
}

double Heightfield::heightM(double latitudeDeg, double longitudeDeg) const {
  const double h = layerHeightM(latitudeDeg, longitudeDeg);
  const double amplitude = detailAmplitudeM(latitudeDeg, longitudeDeg, h);
  if (amplitude <= 0.0) return h;
  return h + amplitude * detailSum(octaves_, geodeticUpFast(latitudeDeg, longitudeDeg),
                                   octaves_.heightCount, 0, nullptr);
}

}  // namespace og::terrain
