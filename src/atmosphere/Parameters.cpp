#include "atmosphere/Parameters.hpp"

#include <bit>
#include <cmath>

namespace og::atmosphere {

TableSizes TableSizes::small() {
  TableSizes t;
  t.transmittanceWidth = 64;
  t.transmittanceHeight = 16;
  t.irradianceWidth = 32;
  t.irradianceHeight = 8;
  t.scatteringR = 8;
  t.scatteringMu = 32;
  t.scatteringMuS = 8;
  t.scatteringNu = 4;
  t.sphereSamples = 6;
  t.skyMapSize = 32;
  t.skyMapLayers = 16;
  t.skyIrradianceEntries = 32;
  return t;
}

Parameters earth() { return Parameters{}; }

namespace {
bool finiteNonNegative(const glm::dvec3& v) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(v[i]) || v[i] < 0.0) return false;
  return true;
}
bool inRange(int v, int lo, int hi) { return v >= lo && v <= hi; }
}  // namespace

std::optional<std::string> validate(const Parameters& p) {
  if (!finiteNonNegative(p.solarIrradiance)) return "solar irradiance must be finite and >= 0";
  if (!(p.sunAngularRadiusRad > 0.0 && p.sunAngularRadiusRad < 0.1))
    return "Sun angular radius must be within (0, 5.7) degrees";
  if (!(p.bottomRadiusM >= 1000.0 && p.bottomRadiusM <= 1e8))
    return "bottom radius must be within [1 km, 100 000 km]";
  if (!(p.thicknessM >= 1000.0 && p.thicknessM <= 1e6))
    return "atmosphere thickness must be within [1 km, 1000 km]";
  if (!finiteNonNegative(p.rayleighScattering)) return "Rayleigh scattering must be finite and >= 0";
  if (!finiteNonNegative(p.mieScattering)) return "Mie scattering must be finite and >= 0";
  if (!finiteNonNegative(p.mieExtinction)) return "Mie extinction must be finite and >= 0";
  for (int i = 0; i < 3; ++i)
    if (p.mieExtinction[i] < p.mieScattering[i])
      return "Mie extinction must be at least Mie scattering";
  if (!finiteNonNegative(p.ozoneAbsorption)) return "ozone absorption must be finite and >= 0";
  if (!finiteNonNegative(p.groundAlbedo) || p.groundAlbedo.x > 1.0 || p.groundAlbedo.y > 1.0 ||
      p.groundAlbedo.z > 1.0)
    return "ground albedo must be within [0, 1]";
  if (!(p.rayleighScaleHeightM > 0.0 && p.rayleighScaleHeightM < 1e6) ||
      !(p.mieScaleHeightM > 0.0 && p.mieScaleHeightM < 1e6))
    return "scale heights must be within (0, 1000 km)";
  if (!(p.ozoneHalfWidthM > 0.0 && p.ozoneHalfWidthM < 1e6) ||
      !(std::isfinite(p.ozoneCenterAltitudeM)))
    return "ozone layer altitude and half width must be finite, the width > 0";
  if (!(p.miePhaseG > -0.999 && p.miePhaseG < 0.999)) return "Mie g must be within (-1, 1)";
  if (!(p.muSMin >= -1.0 && p.muSMin <= 0.0)) return "mu_s min must be within [-1, 0]";
  if (!inRange(p.scatteringOrders, 1, 10)) return "scattering orders must be within [1, 10]";
  const TableSizes& t = p.tables;
  if (!inRange(t.transmittanceWidth, 4, 1024) || !inRange(t.transmittanceHeight, 4, 1024) ||
      !inRange(t.irradianceWidth, 4, 1024) || !inRange(t.irradianceHeight, 2, 1024) ||
      !inRange(t.scatteringR, 2, 128) || !inRange(t.scatteringMu, 4, 512) ||
      t.scatteringMu % 2 != 0 || !inRange(t.scatteringMuS, 2, 128) ||
      !inRange(t.scatteringNu, 2, 64) || !inRange(t.sphereSamples, 2, 64) ||
      !inRange(t.skyIrradianceEntries, 2, 4096) || !inRange(t.skyMapLayers, 16, 256) ||
      !inRange(t.skyMapSize, 8, 2048) || (t.skyMapSize & (t.skyMapSize - 1)) != 0)
    return "table sizes out of range (sky maps: >= 16 layers, power-of-two size)";
  return std::nullopt;
}

namespace {
struct Fnv {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= b[i];
      h *= 1099511628211ull;
    }
  }
  void f(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    bytes(&bits, sizeof bits);
  }
  void v(const glm::dvec3& x) {
    f(x.x);
    f(x.y);
    f(x.z);
  }
  void i(int x) {
    const auto w = static_cast<std::int64_t>(x);
    bytes(&w, sizeof w);
  }
};
}  // namespace

std::uint64_t cacheKey(const Parameters& p, std::string_view salt) {
  Fnv k;
  const std::string_view version = "oceanglobe-atmosphere-tables-v1";
  k.bytes(version.data(), version.size());
  k.v(p.solarIrradiance);
  k.f(p.sunAngularRadiusRad);
  k.f(p.bottomRadiusM);
  k.f(p.thicknessM);
  k.v(p.rayleighScattering);
  k.f(p.rayleighScaleHeightM);
  k.v(p.mieScattering);
  k.v(p.mieExtinction);
  k.f(p.mieScaleHeightM);
  k.f(p.miePhaseG);
  k.v(p.ozoneAbsorption);
  k.f(p.ozoneCenterAltitudeM);
  k.f(p.ozoneHalfWidthM);
  k.v(p.groundAlbedo);
  k.f(p.muSMin);
  k.i(p.scatteringOrders);
  const TableSizes& t = p.tables;
  for (int x : {t.transmittanceWidth, t.transmittanceHeight, t.irradianceWidth,
                t.irradianceHeight, t.scatteringR, t.scatteringMu, t.scatteringMuS,
                t.scatteringNu, t.sphereSamples})
    k.i(x);
  k.bytes(salt.data(), salt.size());
  return k.h;
}

}  // namespace og::atmosphere
