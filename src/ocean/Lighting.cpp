#include "ocean/Lighting.hpp"

#include <mutex>
#include <tuple>
#include <numbers>

#include "core/GlslShim.hpp"
#include "geo/Wgs84.hpp"

namespace og::ocean::lighting {
namespace glsl {
using namespace og::glsl;
// The contract's constants (gl::contractDefines injects the same ones into the shaders).
#define OG_PI std::numbers::pi
#define OG_WGS84_A geo::kWgs84SemiMajorM
#define OG_WGS84_B geo::kWgs84SemiMinorM
// The analytic sky, the terms' weights and the validation's reference, as the tests' variants.
#define OCEAN_SIMPLE_SKY
#define OCEAN_LIGHTING_TERMS
#define OCEAN_VALIDATION_REFERENCE
// Uniforms become this namespace's variables, set under kUniformsLock before each evaluation.
#define uniform
#pragma GCC diagnostic push
// The analytic sky keeps the sky maps' signature (skymap.glsl), the Sun's azimuth unused.
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"
#include "ocean/radiance_terms.glsl"
#pragma GCC diagnostic pop
#undef uniform
#undef OCEAN_VALIDATION_REFERENCE
#undef OCEAN_LIGHTING_TERMS
#undef OCEAN_SIMPLE_SKY
#undef OG_WGS84_B
#undef OG_WGS84_A
#undef OG_PI
}  // namespace glsl

static_assert(glsl::SEA_RADIANCE_TERMS == std::tuple_size_v<decltype(RadianceTerms::k)>);

namespace {
std::mutex kUniformsLock;  // the twin's uniforms are globals: one evaluation at a time

void setUniforms(const Settings& s) {
  glsl::uSkyZenith = s.skyZenithRadiance;
  glsl::uSkyHorizon = s.skyHorizonRadiance;
  glsl::uSeaColor = s.seaColorPerSr;
  glsl::uLightingTerms = s.terms;
  glsl::gSeaSunVisibility = s.sunVisibility;
}

glsl::SeaRadianceTerms toGlsl(const RadianceTerms& terms) {
  glsl::SeaRadianceTerms t;
  for (std::size_t i = 0; i < terms.k.size(); ++i) t.k[i] = terms.k[i];
  return t;
}
RadianceTerms fromGlsl(const glsl::SeaRadianceTerms& t) {
  RadianceTerms terms;
  for (std::size_t i = 0; i < terms.k.size(); ++i) terms.k[i] = t.k[i];
  return terms;
}
}  // namespace

glm::dvec3 seaRadiance(const Settings& settings, const SeaSample& p) {
  OG_EXPECT_RANGE(p.foamCoverage, 0.0, 1.0);
  OG_EXPECT_RANGE(settings.sunVisibility, 0.0, 1.0);
  const std::lock_guard lock(kUniformsLock);
  setUniforms(settings);
  return glsl::seaRadianceWithFoam(p.toEye, p.normal, p.wind, p.slopeCovariance, p.up, p.toSun,
                                   p.foamCoverage);
}

glm::dvec3 seaRadianceMirror(const Settings& settings, const SeaSample& p,
                             const glm::dvec3& patchCovariance) {
  const std::lock_guard lock(kUniformsLock);
  setUniforms(settings);
  return glsl::seaRadianceMirror(p.toEye, p.normal, p.wind, patchCovariance, p.up, p.toSun);
}

glm::dvec3 clearSeaRadiance(const Settings& settings, const SlopePoint& point, const glm::dvec2& slope,
                            const glm::dvec3& cov) {
  const std::lock_guard lock(kUniformsLock);
  setUniforms(settings);
  return glsl::clearSeaRadiance(glsl::seaPlace(point.toEye, point.oceanToEcef, point.wind, point.up, point.toSun), slope, cov);
}

RadianceTerms seaRadianceTerms(const Settings& settings, const SlopePoint& point, const glm::dvec2& slope,
                               const glm::dvec3& cov, double slopeStep) {
  const std::lock_guard lock(kUniformsLock);
  setUniforms(settings);
  return fromGlsl(glsl::seaRadianceTerms(
      glsl::seaPlace(point.toEye, point.oceanToEcef, point.wind, point.up, point.toSun), slope, cov, slopeStep));
}

glm::dvec3 seaRadianceOfTerms(const RadianceTerms& terms, const glm::dvec2& slope, const glm::dvec3& cov) {
  return glsl::seaRadianceOfTerms(toGlsl(terms), slope, cov);
}

void foldAerialPerspective(RadianceTerms& terms, glm::dvec3& foam, const glm::dvec3& transmittance,
                           const glm::dvec3& inscatter) {
  glsl::SeaRadianceTerms t = toGlsl(terms);
  glsl::foldAerialPerspective(t, foam, transmittance, inscatter);
  terms = fromGlsl(t);
}

glm::dvec3 mixFoam(const Settings& settings, const glm::dvec3& clear, const glm::dvec3& foam, double coverage) {
  const std::lock_guard lock(kUniformsLock);
  setUniforms(settings);
  return glsl::mixFoam(clear, foam, coverage);
}

glm::dvec3 sunIrradiance(double sunZenithRad) { return glsl::sunIrradiance(sunZenithRad); }
glm::dvec3 skyIrradiance(double sunZenithRad) { return glsl::skyIrradiance(sunZenithRad); }
double sunAngularRadiusRad() { return glsl::SUN_ANGULAR_RADIUS_RAD; }
double foamReflectance() { return glsl::FOAM_REFLECTANCE; }

}  // namespace og::ocean::lighting
