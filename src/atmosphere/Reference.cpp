#include "atmosphere/Reference.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <numbers>
#include <thread>

#include "core/GlslShim.hpp"

namespace og::atmosphere {

glm::dvec4 texture(const Table2D& t, glm::dvec2 uv) {
  const double x = uv.x * t.width - 0.5, y = uv.y * t.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  auto at = [&](double ix, double iy) {
    const int cx = std::clamp(static_cast<int>(ix), 0, t.width - 1);
    const int cy = std::clamp(static_cast<int>(iy), 0, t.height - 1);
    return t.texels[static_cast<std::size_t>(cy * t.width + cx)];
  };
  return glm::mix(glm::mix(at(fx, fy), at(fx + 1, fy), ax), glm::mix(at(fx, fy + 1), at(fx + 1, fy + 1), ax),
                  ay);
}

glm::dvec4 texture(const Table3D& t, glm::dvec3 uvw) {
  const double x = uvw.x * t.width - 0.5, y = uvw.y * t.height - 0.5, z = uvw.z * t.depth - 0.5;
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const double ax = x - fx, ay = y - fy, az = z - fz;
  auto at = [&](double ix, double iy, double iz) {
    const int cx = std::clamp(static_cast<int>(ix), 0, t.width - 1);
    const int cy = std::clamp(static_cast<int>(iy), 0, t.height - 1);
    const int cz = std::clamp(static_cast<int>(iz), 0, t.depth - 1);
    return t.texels[static_cast<std::size_t>((cz * t.height + cy) * t.width + cx)];
  };
  auto plane = [&](double iz) {
    return glm::mix(glm::mix(at(fx, fy, iz), at(fx + 1, fy, iz), ax),
                    glm::mix(at(fx, fy + 1, iz), at(fx + 1, fy + 1, iz), ax), ay);
  };
  return glm::mix(plane(fz), plane(fz + 1), az);
}

// The shared GLSL, compiled as C++ in double precision.
namespace shared {
using namespace og::glsl;
using Texture2D = Table2D;
using Texture3D = Table3D;
using og::atmosphere::texture;
constexpr Number PI = std::numbers::pi;
#include "atmosphere/functions.glsl"
#undef IN
#undef OUT
#undef INOUT
}  // namespace shared

namespace {

shared::AtmosphereParameters toShared(const Parameters& p) {
  shared::AtmosphereParameters a{};
  a.solarIrradiance = p.solarIrradiance;
  a.sunAngularRadius = p.sunAngularRadiusRad;
  a.bottomRadius = p.bottomRadiusM;
  a.topRadius = p.topRadiusM();
  a.rayleighScattering = p.rayleighScattering;
  a.rayleighScaleHeight = p.rayleighScaleHeightM;
  a.mieScattering = p.mieScattering;
  a.mieExtinction = p.mieExtinction;
  a.mieScaleHeight = p.mieScaleHeightM;
  a.miePhaseG = p.miePhaseG;
  a.ozoneAbsorption = p.ozoneAbsorption;
  a.ozoneCenterAltitude = p.ozoneCenterAltitudeM;
  a.ozoneHalfWidth = p.ozoneHalfWidthM;
  a.groundAlbedo = p.groundAlbedo;
  a.muSMin = p.muSMin;
  const TableSizes& t = p.tables;
  a.transmittanceWidth = t.transmittanceWidth;
  a.transmittanceHeight = t.transmittanceHeight;
  a.irradianceWidth = t.irradianceWidth;
  a.irradianceHeight = t.irradianceHeight;
  a.scatteringR = t.scatteringR;
  a.scatteringMu = t.scatteringMu;
  a.scatteringMuS = t.scatteringMuS;
  a.scatteringNu = t.scatteringNu;
  a.sphereSamples = t.sphereSamples;
  return a;
}

// Runs body(i) for i in [0, n) on all hardware threads.
void parallelFor(int n, const std::function<void(int)>& body) {
  const int threads = std::max(1, std::min(n, static_cast<int>(std::thread::hardware_concurrency())));
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k)
    pool.emplace_back([&] {
      for (int i = next++; i < n; i = next++) body(i);
    });
  for (auto& t : pool) t.join();
}

Table2D make2D(int w, int h) {
  return {w, h, std::vector<glm::dvec4>(static_cast<std::size_t>(w * h), glm::dvec4(0.0))};
}
Table3D make3D(const TableSizes& t) {
  const int w = t.scatteringNu * t.scatteringMuS, h = t.scatteringMu, d = t.scatteringR;
  return {w, h, d, std::vector<glm::dvec4>(static_cast<std::size_t>(w * h * d), glm::dvec4(0.0))};
}

// fill(x, y, centre) for every texel of a 2D table.
void fill2D(Table2D& t, const std::function<glm::dvec4(glm::dvec2)>& f) {
  parallelFor(t.height, [&](int y) {
    for (int x = 0; x < t.width; ++x)
      t.texels[static_cast<std::size_t>(y * t.width + x)] =
          f(glm::dvec2((x + 0.5) / t.width, (y + 0.5) / t.height));
  });
}
// f(index, texel centre in texels) for every texel of a 3D table.
void fill3D(const Table3D& shape, const std::function<void(std::size_t, glm::dvec3)>& f) {
  parallelFor(shape.depth * shape.height, [&](int zy) {
    const int z = zy / shape.height, y = zy % shape.height;
    for (int x = 0; x < shape.width; ++x)
      f(static_cast<std::size_t>((z * shape.height + y) * shape.width + x),
        glm::dvec3(x + 0.5, y + 0.5, z + 0.5));
  });
}

}  // namespace

ReferenceTables precomputeReference(const Parameters& p) {
  const shared::AtmosphereParameters a = toShared(p);
  const TableSizes& ts = p.tables;
  ReferenceTables out;
  out.transmittance = make2D(ts.transmittanceWidth, ts.transmittanceHeight);
  fill2D(out.transmittance, [&](glm::dvec2 uv) {
    double r = 0, mu = 0;
    shared::transmittanceRMu(a, uv, r, mu);
    return glm::dvec4(shared::computeTransmittanceToTop(a, r, mu), 1.0);
  });
  const Table2D& T = out.transmittance;
  Table2D deltaIrradiance = make2D(ts.irradianceWidth, ts.irradianceHeight);
  fill2D(deltaIrradiance, [&](glm::dvec2 uv) {
    double r = 0, muS = 0;
    shared::irradianceRMuS(a, uv, r, muS);
    return glm::dvec4(shared::computeDirectIrradiance(a, T, r, muS), 1.0);
  });
  out.irradiance = make2D(ts.irradianceWidth, ts.irradianceHeight);
  Table3D deltaRayleigh = make3D(ts), deltaMie = make3D(ts), deltaMultiple = make3D(ts),
          deltaDensity = make3D(ts);
  fill3D(deltaRayleigh, [&](std::size_t i, glm::dvec3 c) {
    double r = 0, mu = 0, muS = 0, nu = 0;
    bool hits = false;
    shared::scatteringTexelParameters(a, c, r, mu, muS, nu, hits);
    glm::dvec3 ray(0.0), mie(0.0);
    shared::computeSingleScattering(a, T, r, mu, muS, nu, hits, ray, mie);
    deltaRayleigh.texels[i] = glm::dvec4(ray, 1.0);
    deltaMie.texels[i] = glm::dvec4(mie, 1.0);
  });
  out.scattering = deltaRayleigh;
  out.singleMie = deltaMie;
  for (int order = 2; order <= p.scatteringOrders; ++order) {
    fill3D(deltaDensity, [&](std::size_t i, glm::dvec3 c) {
      double r = 0, mu = 0, muS = 0, nu = 0;
      bool hits = false;
      shared::scatteringTexelParameters(a, c, r, mu, muS, nu, hits);
      deltaDensity.texels[i] = glm::dvec4(
          shared::computeScatteringDensity(a, T, deltaRayleigh, deltaMie, deltaMultiple,
                                           deltaIrradiance, r, mu, muS, nu, order),
          1.0);
    });
    fill2D(deltaIrradiance, [&](glm::dvec2 uv) {
      double r = 0, muS = 0;
      shared::irradianceRMuS(a, uv, r, muS);
      return glm::dvec4(shared::computeIndirectIrradiance(a, deltaRayleigh, deltaMie,
                                                          deltaMultiple, r, muS, order - 1),
                        1.0);
    });
    for (std::size_t i = 0; i < out.irradiance.texels.size(); ++i)
      out.irradiance.texels[i] += glm::dvec4(glm::dvec3(deltaIrradiance.texels[i]), 0.0);
    Table3D next = make3D(ts);
    fill3D(next, [&](std::size_t i, glm::dvec3 c) {
      double r = 0, mu = 0, muS = 0, nu = 0;
      bool hits = false;
      shared::scatteringTexelParameters(a, c, r, mu, muS, nu, hits);
      const glm::dvec3 l =
          shared::computeMultipleScattering(a, T, deltaDensity, r, mu, muS, nu, hits);
      next.texels[i] = glm::dvec4(l, 1.0);
      out.scattering.texels[i] += glm::dvec4(l / shared::rayleighPhase(nu), 0.0);
    });
    deltaMultiple = std::move(next);
  }
  return out;
}

glm::dvec3 referenceSkyRadiance(const Parameters& p, const ReferenceTables& t, double r, double mu,
                                double muS, double nu, glm::dvec3* transmittance) {
  glm::dvec3 tr(1.0);
  const glm::dvec3 l = shared::skyRadiance(toShared(p), t.transmittance, t.scattering,
                                           t.singleMie, r, mu, muS, nu, tr);
  if (transmittance) *transmittance = tr;
  return l;
}

glm::dvec3 referenceSkyRadianceToPoint(const Parameters& p, const ReferenceTables& t, double r,
                                       double mu, double muS, double nu, double d,
                                       glm::dvec3* transmittance) {
  glm::dvec3 tr(1.0);
  const glm::dvec3 l = shared::skyRadianceToPoint(toShared(p), t.transmittance, t.scattering,
                                                  t.singleMie, r, mu, muS, nu, d, tr);
  if (transmittance) *transmittance = tr;
  return l;
}

glm::dvec3 referenceSunAndSkyIrradiance(const Parameters& p, const ReferenceTables& t, double r,
                                        double muS, glm::dvec3& sky) {
  return shared::sunAndSkyIrradiance(toShared(p), t.transmittance, t.irradiance, r, muS, sky);
}

glm::dvec3 referenceTransmittanceToTop(const Parameters& p, double r, double mu) {
  return shared::computeTransmittanceToTop(toShared(p), r, mu);
}

}  // namespace og::atmosphere
