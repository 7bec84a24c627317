#include "terrain/ReliefStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geo/Wgs84.hpp"
#include "terrain/Tile.hpp"

namespace og::terrain {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

/// Metres per degree of latitude (on the sphere of radius a, as the tiles' spacing).
constexpr double kMetresPerDeg = geo::kWgs84SemiMajorM * kDeg;

/// Calls f(lat, lon) on a grid of the layer's row spacing inside the box.
template <class F>
void forEachPoint(const data::LatLonGrid& layer, const RegionBox& box, F&& f) {
  const double step = layer.dLatDeg;
  for (double lat = box.southDeg; lat <= box.northDeg; lat += step)
    for (double lon = box.westDeg; lon <= box.eastDeg; lon += step / std::max(std::cos(lat * kDeg), 0.05))
      f(lat, lon);
}

}  // namespace

LagStatistics layerLagStatistics(const data::LatLonGrid& layer, const RegionBox& box, double lagM) {
  double sum = 0.0;
  long n = 0;
  forEachPoint(layer, box, [&](double lat, double lon) {
    const double dLat = lagM / kMetresPerDeg, dLon = dLat / std::max(std::cos(lat * kDeg), 0.05);
    const double h = static_cast<double>(layer.sample(lat, lon));
    const double hn = static_cast<double>(layer.sample(lat + dLat, lon));
    const double he = static_cast<double>(layer.sample(lat, lon + dLon));
    if (!std::isfinite(h) || !std::isfinite(hn) || !std::isfinite(he)) return;
    sum += (hn - h) * (hn - h) + (he - h) * (he - h);
    n += 2;
  });
  return {lagM, n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0};
}

double layerMeanGradient(const data::LatLonGrid& layer, const RegionBox& box) {
  double sum = 0.0;
  long n = 0;
  const double cellM = layer.dLatDeg * kMetresPerDeg;
  forEachPoint(layer, box, [&](double lat, double lon) {
    const double d = layer.dLatDeg, dLon = d / std::max(std::cos(lat * kDeg), 0.05);
    auto at = [&](double la, double lo) { return static_cast<double>(layer.sample(la, lo)); };
    const double gx = (at(lat, lon + dLon) - at(lat, lon - dLon)) / (2.0 * cellM);
    const double gy = (at(lat + d, lon) - at(lat - d, lon)) / (2.0 * cellM);
    if (!std::isfinite(gx) || !std::isfinite(gy)) return;
    sum += std::hypot(gx, gy);
    ++n;
  });
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

double detailRmsSlope(const Heightfield& heights, const RegionBox& box, double scaleM, int samples) {
  const DetailOctaves& o = heights.octaves();
  const int count = o.countAtLeast(scaleM);
  double sum = 0.0;
  long n = 0;
  // A low-discrepancy (golden-ratio) sequence over the box: no lattice alignment.
  for (int i = 0; i < samples; ++i) {
    const double u = std::fmod(0.5 + i * 0.6180339887498949, 1.0);
    const double v = (i + 0.5) / samples;
    const double lat = box.southDeg + v * (box.northDeg - box.southDeg);
    const double lon = box.westDeg + u * (box.eastDeg - box.westDeg);
    const double amplitude = heights.detailShadingAmplitudeM(lat, lon);
    const glm::dvec3 up = geodeticUpFast(lat, lon);
    glm::dvec3 grad(0.0);
    detailSum(o, up, count, count, &grad);
    // Per metre along the surface (the unit sphere moves 1/a per metre), tangential part.
    const glm::dvec3 g = grad * (amplitude / geo::kWgs84SemiMajorM);
    const glm::dvec3 t = g - glm::dot(g, up) * up;
    sum += 0.5 * glm::dot(t, t);  // one horizontal component of two
    ++n;
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

}  // namespace og::terrain
