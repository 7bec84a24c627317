#include "terrain/Heightfield.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "geo/Wgs84.hpp"

namespace og::terrain {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Integer hash of a lattice point (xorshift-multiply mix), the same on every platform.
std::uint32_t hash3(std::int64_t x, std::int64_t y, std::int64_t z) {
  std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
  h ^= static_cast<std::uint64_t>(z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 29;
  return static_cast<std::uint32_t>(h);
}

// Gradient at a lattice point: one of the 12 cube-edge directions (Perlin's improved noise set).
double gradDot(std::uint32_t h, double x, double y, double z) {
  switch (h % 12u) {
    case 0: return x + y;
    case 1: return -x + y;
    case 2: return x - y;
    case 3: return -x - y;
    case 4: return x + z;
    case 5: return -x + z;
    case 6: return x - z;
    case 7: return -x - z;
    case 8: return y + z;
    case 9: return -y + z;
    case 10: return y - z;
    default: return -y - z;
  }
}

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// 3-D gradient noise, roughly in [-1, 1], C2-continuous.
double gradientNoise(double x, double y, double z) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy),
             iz = static_cast<std::int64_t>(fz);
  const double dx = x - fx, dy = y - fy, dz = z - fz;
  const double u = fade(dx), v = fade(dy), w = fade(dz);
  double c[2][2][2];
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        c[k][j][i] = gradDot(hash3(ix + i, iy + j, iz + k), dx - i, dy - j, dz - k);
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double y0 = lerp(lerp(c[0][0][0], c[0][0][1], u), lerp(c[0][1][0], c[0][1][1], u), v);
  const double y1 = lerp(lerp(c[1][0][0], c[1][0][1], u), lerp(c[1][1][0], c[1][1][1], u), v);
  return lerp(y0, y1, w);
}

}  // namespace

Heightfield::Heightfield(data::LatLonGrid layer) : layer_(std::move(layer)) {
  cellM_ = layer_.dLatDeg * kDeg * geo::kWgs84SemiMajorM;
}

double Heightfield::layerHeightM(double latitudeDeg, double longitudeDeg) const {
  const float v = layer_.sample(std::clamp(latitudeDeg, -90.0, 90.0), longitudeDeg);
  return std::isfinite(v) ? static_cast<double>(v) : -1.0;
}

double Heightfield::detail(double nx, double ny, double nz, double longestM) {
  // Octaves from longestM down to the shortest wavelength, gain 0.5 (a 1/f² spectrum, like
  // real relief). Evaluated on the sphere (not per tile), so it has no seams anywhere.
  double sum = 0.0, norm = 0.0, amplitude = 1.0;
  double scale = geo::kWgs84SemiMajorM / longestM;
  for (double lambda = longestM; lambda >= kDetailShortestM; lambda *= 0.5) {
    // Each octave gets its own offset so lattice points do not line up between octaves.
    const double off = 17.31 * (norm + 1.0);
    // Ridged: 1 - 2|noise| has sharp crests and rounded valleys, like eroded relief; 0.45 is
    // its approximate mean, removed so the detail does not lift the terrain on average.
    const double v = gradientNoise(nx * scale + off, ny * scale - off, nz * scale + 0.5 * off);
    sum += amplitude * (1.0 - 2.0 * std::abs(v) - 0.45);
    norm += amplitude;
    amplitude *= 0.5;
    scale *= 2.0;
  }
  return norm > 0.0 ? std::clamp(sum / norm, -1.0, 1.0) : 0.0;
}

double Heightfield::heightM(double latitudeDeg, double longitudeDeg) const {
  const double h = layerHeightM(latitudeDeg, longitudeDeg);
  // Local relief of the layer: height differences over one cell each way.
  const double d = layer_.dLatDeg;
  const double relief =
      0.5 * (std::abs(layerHeightM(latitudeDeg + d, longitudeDeg) -
                      layerHeightM(latitudeDeg - d, longitudeDeg)) +
             std::abs(layerHeightM(latitudeDeg, longitudeDeg + d) -
                      layerHeightM(latitudeDeg, longitudeDeg - d)));
  // Detail scaled to the relief (rugged where the layer is rugged, flat plains stay flat), and
  // never more than 80 % of |h|, so it never moves the coastline away from where the layer's
  // own zero contour is (the globe and ocean passes decide land and sea from the layer).
  const double amplitude = std::min(std::max(1.0 * relief, 0.03 * std::abs(h)), 0.8 * std::abs(h));
  if (amplitude < 0.5) return h;
  const double lat = latitudeDeg * kDeg, lon = longitudeDeg * kDeg;
  const double n = detail(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                          std::sin(lat), 2.0 * cellM_);
  return h + amplitude * n;
}

}  // namespace og::terrain
