#include "terrain/Heightfield.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "core/Error.hpp"
#include "core/GlslShim.hpp"
#include "geo/Wgs84.hpp"
#include "terrain/Tile.hpp"

namespace og::terrain {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// Under the sea (the coast's floor, issue 15): detail amplitude per metre of the layer's relief
// across two cells, as before the land's calibration.
constexpr double kSeaReliefGain = 2.5;

namespace glsl {
using namespace og::glsl;
#include "terrain/detail.glsl"
}  // namespace glsl

}  // namespace

double detailHurst() { return -std::log2(glsl::DETAIL_GAIN); }

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
  if (count > o.normalCount || (count > 0 && o.weight[0] == 0.0))
    throw InternalError("detailSum: octave tables not filled (Heightfield fills them)");
  double sum = 0.0;
  glm::dvec3 grad(0.0);
  for (int k = 0; k < count; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const glm::dvec3 p = unitUp * o.latticeScale[i] + glsl::detailOctaveOffset(k);  // detailLatticePoint
    const glm::dvec3 cell = glm::floor(p);
    const glm::dvec4 r = glsl::detailRidged(glm::ivec3(cell), p - cell);
    const double w = o.weight[i] / o.norm;
    sum += w * r.x;
    // d/d(unitUp) of the lattice point is a / wavelength.
    if (k < gradientOctaves) grad += w * o.latticeScale[i] * glm::dvec3(r.y, r.z, r.w);
  }
  if (gradient != nullptr) *gradient = grad;
  return std::clamp(sum, -1.0, 1.0);
}

Heightfield::Heightfield(std::shared_ptr<const data::LatLonGrid> layer) : layer_(std::move(layer)) {
  if (!layer_) throw InternalError("Heightfield: no elevation layer");
  if (layer_->wrapsLongitude && data::defaultLandMask().refines(*layer_)) mask_ = &data::defaultLandMask();
  cellM_ = layer_->dLatDeg * kDeg * geo::kWgs84SemiMajorM;
  // Octaves from two layer cells (what the bilinear layer cannot show) down to the shortest.
  octaves_.longestM = 2.0 * cellM_;
  octaves_.normalCount = 0;
  octaves_.heightCount = 0;
  octaves_.norm = 0.0;
  while (octaves_.normalCount < DetailOctaves::kMaxOctaves && octaves_.wavelengthM(octaves_.normalCount) >= kNormalShortestM) {
    if (octaves_.wavelengthM(octaves_.normalCount) >= kDetailShortestM) {
      octaves_.norm += glsl::detailOctaveWeight(octaves_.normalCount);
      ++octaves_.heightCount;
    }
    ++octaves_.normalCount;
  }
  if (octaves_.norm <= 0.0) octaves_.norm = 1.0;
  for (int k = 0; k < octaves_.normalCount; ++k) {
    octaves_.weight.at(static_cast<std::size_t>(k)) = glsl::detailOctaveWeight(k);
    octaves_.latticeScale.at(static_cast<std::size_t>(k)) = geo::kWgs84SemiMajorM / octaves_.wavelengthM(k);
  }
  // The land's detail amplitude per metre of the layer's RMS difference σ(Δ) (below): the
  // weights' sum times octave 0's a_0 = (λ_0 / c) S(λ_0) sqrt(1 - 4^(H-1)) for σ(Δ) = 1 m.
  amplitudePerRms_ = octaves_.norm * octaves_.longestM / kRidgedSlopeRms *
                     calibratedRmsSlope(1.0, octaves_.longestM) *
                     std::sqrt(1.0 - std::pow(4.0, detailHurst() - 1.0));
}

double Heightfield::layerHeightM(double latitudeDeg, double longitudeDeg) const {
  const float v = layer_->sample(std::clamp(latitudeDeg, -90.0, 90.0), longitudeDeg);
  const double h = std::isfinite(v) ? static_cast<double>(v) : -1.0;
  if (mask_ == nullptr) return h;
  return mask_->constrainHeightM(h, latitudeDeg, longitudeDeg, layer_->sampleKeepDepth(latitudeDeg, longitudeDeg));
}

double Heightfield::detailAmplitudeM(double latitudeDeg, double longitudeDeg) const {
  return detailAmplitudeM(latitudeDeg, longitudeDeg, layerHeightM(latitudeDeg, longitudeDeg));
}

double Heightfield::detailShadingAmplitudeM(double latitudeDeg, double longitudeDeg) const {
  return detailShadingAmplitudeM(latitudeDeg, longitudeDeg, layerHeightM(latitudeDeg, longitudeDeg));
}

double Heightfield::layerRmsDifferenceM(double latitudeDeg, double longitudeDeg) const {
  return layerRmsDifferenceM(latitudeDeg, longitudeDeg, layerHeightM(latitudeDeg, longitudeDeg));
}

double Heightfield::layerRmsDifferenceM(double latitudeDeg, double longitudeDeg, double h) const {
  // The layer's own heights, not the coastline mask's constraint (which would make a cliff of
  // every lake shore), each at least sea level: land's relief is measured from the sea's
  // surface, not from the sea floor a cell offshore.
  auto height = [&](double lat, double lon) {
    const float v = layer_->sample(std::clamp(lat, -90.0, 90.0), lon);
    return std::isfinite(v) ? std::max(static_cast<double>(v), 0.0) : 0.0;
  };
  h = std::max(h, 0.0);
  // One cell north, south, east and west, the east-west step widened to the same metres.
  const double d = layer_->dLatDeg;
  const double dLon = d / std::max(std::cos(latitudeDeg * kDeg), 0.05);
  const double n = height(latitudeDeg + d, longitudeDeg) - h;
  const double s = height(latitudeDeg - d, longitudeDeg) - h;
  const double e = height(latitudeDeg, longitudeDeg + dLon) - h;
  const double w = height(latitudeDeg, longitudeDeg - dLon) - h;
  return std::sqrt(0.25 * (n * n + s * s + e * e + w * w));
}

double Heightfield::calibratedRmsSlope(double rmsDifferenceM, double scaleM) const {
  // S(L) = G (σ(Δ) / Δ) (L / Δ)^(H - 1): the self-affine law (structure function σ(L) ∝ L^H,
  // Gagnon et al. 2006) anchored on the layer's RMS slope at its cell Δ, times G for what the
  // layer's averaging over its cells smooths away (docs/terrain.md, "Calibration").
  return kLayerSlopeGain * (rmsDifferenceM / cellM_) * std::pow(scaleM / cellM_, detailHurst() - 1.0);
}

double Heightfield::detailAmplitudeM(double latitudeDeg, double longitudeDeg, double h) const {
  return detailAmplitudeFromShadingM(h, detailShadingAmplitudeM(latitudeDeg, longitudeDeg, h));
}

double Heightfield::detailAmplitudeFromShadingM(double h, double shadingAmplitudeM) {
  if (h <= 0.0) return shadingAmplitudeM;  // the sea's: the same (seaDetailAmplitudeM)
  // Never more than 80 % of the height, so the coastline stays on the layer's zero contour,
  // which the globe and ocean passes use too.
  const double amplitude = std::min(shadingAmplitudeM, 0.8 * h);
  return amplitude < 0.5 ? 0.0 : amplitude;
}

double Heightfield::detailShadingAmplitudeM(double latitudeDeg, double longitudeDeg, double h) const {
  if (h <= 0.0) return seaDetailAmplitudeM(latitudeDeg, longitudeDeg, h);
  // Land: octave k adds the slope variance the law puts between scales 2 λ_k and λ_k,
  // S(λ_k)² (1 - 4^(H-1)); its slope is a_k c / λ_k (c: the ridged noise's RMS gradient), so
  // a_k = (λ_k / c) S(λ_k) sqrt(1 - 4^(H-1)), which falls as λ_k^H like the octaves' weights:
  // the detail's amplitude (octave 0's times the weights' sum) follows from octave 0.
  // Linear in σ(Δ): the factor is amplitudePerRms_ (the constructor's).
  // Flat plains stay flat (a smooth layer gives little); plateaus keep some relief (3 % of
  // their height).
  const double amplitude =
      std::max(amplitudePerRms_ * layerRmsDifferenceM(latitudeDeg, longitudeDeg, h), 0.03 * h);
  return amplitude < 0.5 ? 0.0 : amplitude;
}

double Heightfield::seaDetailAmplitudeM(double latitudeDeg, double longitudeDeg, double h) const {
  const double d = layer_->dLatDeg;
  const double relief =
      0.5 * (std::abs(layerHeightM(latitudeDeg + d, longitudeDeg) -
                      layerHeightM(latitudeDeg - d, longitudeDeg)) +
             std::abs(layerHeightM(latitudeDeg, longitudeDeg + d) -
                      layerHeightM(latitudeDeg, longitudeDeg - d)));
  const double amplitude = std::min(std::max(kSeaReliefGain * relief, 0.03 * std::abs(h)), 0.8 * std::abs(h));
  return amplitude < 0.5 ? 0.0 : amplitude;
}

HeightSample Heightfield::sampleHeight(double latitudeDeg, double longitudeDeg, int normalOctaves,
                                       glm::dvec3* detailGradient) const {
  HeightSample s;
  const double h = layerHeightM(latitudeDeg, longitudeDeg);
  s.shadingAmplitudeM = detailShadingAmplitudeM(latitudeDeg, longitudeDeg, h);
  s.detailAmplitudeM = detailAmplitudeFromShadingM(h, s.shadingAmplitudeM);
  glm::dvec3 grad(0.0);
  s.heightM = h;
  if (s.shadingAmplitudeM > 0.0) {
    const glm::dvec3 up = geodeticUpFast(latitudeDeg, longitudeDeg);
    const double sum = detailSum(octaves_, up, octaves_.heightCount, normalOctaves, &grad);
    if (s.detailAmplitudeM > 0.0) s.heightM = h + s.detailAmplitudeM * sum;
  }
  *detailGradient = grad;
  return s;
}

glm::dvec3 Heightfield::normalAt(double latitudeDeg, double longitudeDeg, double stepDeg,
                                 const glm::dvec3& detailGradient, double shadingAmplitudeM) const {
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
  const glm::dvec3 up = geodeticUpFast(latitudeDeg, longitudeDeg);
  glm::dvec3 n = len > 1e-6 * ns * ns ? c / len : up;
  // Tilt by the detail's height gradient per metre along the surface (the unit sphere's
  // coordinates move 1/a per metre), tangential part only. With the shading's amplitude, as
  // the fragment shader's finer octaves: an octave lights the same whether a tile's vertex
  // normals or its pixels carry it, so tiles of different levels meet without a seam.
  const glm::dvec3 g = detailGradient * (shadingAmplitudeM / geo::kWgs84SemiMajorM);
  return glm::normalize(n - (g - glm::dot(g, n) * n));
}

HeightSample Heightfield::sample(double latitudeDeg, double longitudeDeg, int normalOctaves,
                                 double stepDeg) const {
  glm::dvec3 grad(0.0);
  HeightSample s = sampleHeight(latitudeDeg, longitudeDeg, normalOctaves, &grad);
  s.normal = normalAt(latitudeDeg, longitudeDeg, stepDeg, grad, s.shadingAmplitudeM);
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
