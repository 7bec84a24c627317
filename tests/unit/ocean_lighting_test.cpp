// The CPU twin of shaders/ocean/lighting.glsl (ocean/Lighting.cpp compiles the shader's own
// code): its terms against the physics they stand for (Bruneton, Neyret & Holzschuch 2010,
// Algorithm 5.1) and against ocean/brdf.glsl's twin. The GPU against this twin:
// tests/gl/ocean_lighting_twin_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "ocean/Brdf.hpp"
#include "ocean/Lighting.hpp"

using namespace og::ocean;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
// Unit direction of zenith angle z and azimuth a (degrees) about +z, a from +x towards +y.
glm::dvec3 dir(double zDeg, double aDeg) {
  return {std::sin(zDeg * kDeg) * std::cos(aDeg * kDeg), std::sin(zDeg * kDeg) * std::sin(aDeg * kDeg),
          std::cos(zDeg * kDeg)};
}
// A sky brighter at the horizon and a blue-green sea.
lighting::Settings skyAndSea() {
  lighting::Settings s;
  s.skyZenithRadiance = {0.05, 0.08, 0.15};
  s.skyHorizonRadiance = {0.1, 0.12, 0.15};
  s.seaColorPerSr = {0.004, 0.012, 0.025};
  return s;
}
lighting::Settings onlyTerm(int term) {
  lighting::Settings s;
  s.terms = glm::dvec4(0.0);
  s.terms[term] = 1.0;
  s.seaColorPerSr = {0.004, 0.012, 0.025};
  return s;
}
}  // namespace

// Under a sky of one radiance L everywhere, the reflected sky is L times the effective Fresnel
// factor F̄ (Eq. 10): about R0 = 2 % looking down, rising towards grazing, never above 1.
TEST(OceanLightingTwin, UniformSkyReflectsTheEffectiveFresnelShare) {
  lighting::Settings s = onlyTerm(1);
  s.skyZenithRadiance = s.skyHorizonRadiance = glm::dvec3(0.3);
  lighting::SeaSample p;
  p.toSun = dir(30, 90);
  p.slopeCovariance = {0.004, 0.002, 0.0};
  double previous = 0.0;
  for (double zenith : {0.0, 20.0, 40.0, 60.0, 70.0}) {
    p.toEye = dir(zenith, 0);
    const glm::dvec3 l = lighting::seaRadiance(s, p);
    const double share = l.x / 0.3;
    EXPECT_NEAR(l.x, l.z, 1e-12) << zenith;  // a grey sky stays grey
    EXPECT_GT(share, previous) << zenith;
    EXPECT_LT(share, 1.0) << zenith;
    // F̄ of the view's slope variance (the wind along +y here: across-wind variance along x).
    const double sigmaV = std::sqrt(p.slopeCovariance.y);
    EXPECT_NEAR(share, brdf::effectiveFresnel(std::cos(zenith * kDeg), sigmaV), 1e-6) << zenith;
    previous = share;
  }
  p.toEye = dir(0, 0);
  EXPECT_NEAR(lighting::seaRadiance(s, p).x / 0.3, 0.02, 0.002);
}

// The Sun's term is the Ross BRDF (brdf.glsl, Eq. 6) of the slopes' covariance plus the Sun's
// disc, on the principal axes, times the Sun's irradiance.
TEST(OceanLightingTwin, SunTermIsTheRossBrdfOfTheSlopesAndTheDisc) {
  const lighting::Settings s = onlyTerm(0);
  lighting::SeaSample p;
  p.wind = glm::normalize(glm::dvec3(1.0, 2.0, 0.0));
  p.slopeCovariance = {0.012, 0.006, 0.002};
  for (double sunZenith : {10.0, 40.0, 75.0})
    for (double viewAzimuth : {180.0, 200.0, 120.0}) {
      p.toSun = dir(sunZenith, 0);
      p.toEye = dir(sunZenith + 5.0, viewAzimuth);
      const glm::dvec3 n = p.normal, tx = glm::normalize(p.wind - glm::dot(p.wind, n) * n);
      const glm::dvec3 ty = glm::cross(n, tx);
      const glm::dvec3 cov = p.slopeCovariance + brdf::sunDiscSlopeCovariance(
                                                     p.toEye, p.toSun, tx, ty, lighting::sunAngularRadiusRad());
      const brdf::SlopeAxes axes = brdf::slopePrincipalAxes(cov);
      const glm::dvec3 ax = axes.axis.x * tx + axes.axis.y * ty;
      const double expected = brdf::rossSun(p.toEye, p.toSun, n, ax, glm::cross(n, ax), axes.sigma2) *
                              lighting::sunIrradiance(sunZenith * kDeg).x;
      const double got = lighting::seaRadiance(s, p).x;
      EXPECT_NEAR(got, expected, 1e-5 * expected + 1e-12) << sunZenith << " " << viewAzimuth;
    }
  p.toSun = dir(95, 0);  // the Sun below the horizon lights nothing
  EXPECT_EQ(lighting::seaRadiance(s, p), glm::dvec3(0.0));
}

// The Sun's glint reflects about the mean Fresnel share of the Sun's flux (energy: the
// hemispherical integral of L cos(theta_v) over E_sun cos(theta_s)), whatever the roughness.
TEST(OceanLightingTwin, SunGlintReflectsAboutTheFresnelShareOfTheFlux) {
  const lighting::Settings s = onlyTerm(0);
  lighting::SeaSample p;
  p.toSun = dir(30, 0);
  for (double sigma2 : {0.005, 0.03}) {
    p.slopeCovariance = {sigma2, sigma2, 0.0};
    double flux = 0.0;
    const int nt = 180, np = 90;
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < np; ++j) {
        const double t = (i + 0.5) * 90.0 / nt, a = (j + 0.5) * 360.0 / np;
        p.toEye = dir(t, a);
        flux += lighting::seaRadiance(s, p).x * std::cos(t * kDeg) * std::sin(t * kDeg) *
                (0.5 * std::numbers::pi / nt) * (2.0 * std::numbers::pi / np);
      }
    const double albedo = flux / std::cos(30 * kDeg);
    EXPECT_GT(albedo, 0.015) << sigma2;
    EXPECT_LT(albedo, 0.05) << sigma2;
  }
}

// Light refracted from below: L_sea (E_sun cos + E_sky)(1 - F̄) (§5.3); foam: a Lambertian
// 0.4 over the covered share (Dupuy & Bruneton 2012 Eq. 2), mixed linearly with the clear sea.
TEST(OceanLightingTwin, RefractedLightAndFoamFollowTheirFormulas) {
  lighting::SeaSample p;
  p.toSun = dir(50, 30);
  p.toEye = dir(35, 200);
  p.slopeCovariance = {0.01, 0.01, 0.0};
  const double sunZenith = 50 * kDeg;
  const glm::dvec3 irradiance = lighting::sunIrradiance(sunZenith) * std::cos(sunZenith) +
                                lighting::skyIrradiance(sunZenith);
  const lighting::Settings refracted = onlyTerm(2);
  const double fbar = brdf::effectiveFresnel(std::cos(35 * kDeg), 0.1);
  const glm::dvec3 expected = refracted.seaColorPerSr * irradiance * (1.0 - fbar);
  const glm::dvec3 got = lighting::seaRadiance(refracted, p);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-9);

  lighting::Settings all;
  all.skyZenithRadiance = {0.05, 0.08, 0.15};
  all.skyHorizonRadiance = {0.1, 0.12, 0.15};
  all.seaColorPerSr = {0.004, 0.012, 0.025};
  const glm::dvec3 foam = lighting::foamReflectance() / std::numbers::pi * irradiance;
  const glm::dvec3 clear = lighting::seaRadiance(all, p);
  p.foamCoverage = 1.0;
  const glm::dvec3 covered = lighting::seaRadiance(all, p);
  p.foamCoverage = 0.25;
  const glm::dvec3 quarter = lighting::seaRadiance(all, p);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(covered[c], foam[c], 1e-12);
    EXPECT_NEAR(quarter[c], 0.75 * clear[c] + 0.25 * foam[c], 1e-12);
  }
}

// The shading happens in the point's own local frame: turning the whole scene (eye, normal,
// wind, vertical, Sun) about the Earth's centre changes nothing, at a pole as elsewhere.
TEST(OceanLightingTwin, ResultDoesNotDependOnWhereOnTheGlobeThePointIs) {
  const lighting::Settings s = skyAndSea();
  lighting::SeaSample p;
  p.toSun = dir(60, 10);
  p.toEye = dir(55, 175);
  p.normal = glm::normalize(glm::dvec3(0.05, -0.02, 1.0));
  p.wind = glm::normalize(glm::dvec3(0.3, 1.0, 0.0));
  p.slopeCovariance = {0.015, 0.007, 0.003};
  p.foamCoverage = 0.05;
  const glm::dvec3 atPole = lighting::seaRadiance(s, p);
  EXPECT_GT(atPole.x, 0.0);
  for (const glm::dvec3& axis : {glm::dvec3(1, 0, 0), glm::dvec3(0.3, 0.5, 0.8), glm::dvec3(0, 1, 0)}) {
    const glm::dmat3 r(glm::rotate(glm::dmat4(1.0), 1.1, glm::normalize(axis)));
    lighting::SeaSample q = p;
    q.toSun = r * p.toSun;
    q.toEye = r * p.toEye;
    q.normal = r * p.normal;
    q.wind = r * p.wind;
    q.up = r * p.up;
    const glm::dvec3 moved = lighting::seaRadiance(s, q);
    // To 1e-5: the wind tangent is nudged by 1e-6 along the local east (seaPoint), which turns.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(moved[c], atPole[c], 1e-5 * atPole[c]);
  }
}

// The vertices' quadratic (shaders/ocean/radiance_terms.glsl): exact at the point it is taken
// about; within 5 % of the radiance for the pixels of a cell, whose mean slopes lie within the
// step of it and whose covariances vary by a tenth, in and beside the glint, under the sky and
// towards grazing; and its square terms matter: without them the worst pixel is several times
// farther off.
TEST(OceanRadianceTerms, QuadraticMatchesTheRadianceOverACellsPixels) {
  const lighting::Settings s = skyAndSea();
  lighting::SlopePoint point;
  point.toSun = dir(60, 0);
  point.wind = glm::normalize(glm::dvec3(0.3, 1.0, 0.0));
  const glm::dvec2 slope(0.02, -0.01);
  const glm::dvec3 cov(0.02, 0.012, 0.002);
  double worst = 0.0, worstLinear = 0.0;
  // Towards grazing the pixels' footprints are long and resolve less: their slopes spread less.
  for (const auto& [eye, step] : {std::pair{dir(55, 180), 0.06}, std::pair{dir(40, 170), 0.06}, std::pair{dir(50, 90), 0.06},
                                  std::pair{dir(20, 0), 0.06}, std::pair{dir(75, 200), 0.03}}) {
    point.toEye = eye;
    const lighting::RadianceTerms t = lighting::seaRadianceTerms(s, point, slope, cov, step);
    const glm::dvec3 at = lighting::clearSeaRadiance(s, point, slope, cov);
    const glm::dvec3 quadAt = lighting::seaRadianceOfTerms(t, slope, cov);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(quadAt[c], at[c], 1e-9 * at[c]);
    for (int a = 0; a < 8; ++a)
      for (const double r : {0.5, 1.0})
        for (const double scale : {0.9, 1.0, 1.1}) {
          const double dx = r * std::cos(a * std::numbers::pi / 4), dy = r * std::sin(a * std::numbers::pi / 4);
          const glm::dvec2 ps = slope + step * glm::dvec2(dx, dy);
          const glm::dvec3 pc(cov.x * scale, cov.y * (2.0 - scale), cov.z * scale);
          const glm::dvec3 direct = lighting::clearSeaRadiance(s, point, ps, pc);
          const glm::dvec3 quad = lighting::seaRadianceOfTerms(t, ps, pc);
          // The linear part alone: the quadratic's value and gradient at the point it is taken about.
          glm::dvec3 lin = quadAt;
          const std::array<double, 5> x{ps.x, ps.y, pc.x, pc.y, pc.z}, e{slope.x, slope.y, cov.x, cov.y, cov.z};
          for (std::size_t d = 0; d < 5; ++d) lin += (t.k[1 + d] + 2.0 * t.k[6 + d] * e[d]) * (x[d] - e[d]);
          lin += t.k[11] * (e[1] * (x[0] - e[0]) + e[0] * (x[1] - e[1]));
          for (int c = 0; c < 3; ++c) {
            const double scaleOf = glm::length(direct);
            worst = std::max(worst, std::abs(quad[c] - direct[c]) / scaleOf);
            worstLinear = std::max(worstLinear, std::abs(lin[c] - direct[c]) / scaleOf);
          }
        }
  }
  EXPECT_LT(worst, 0.05);  // of the radiance's length: 0.040 measured
  EXPECT_GT(worstLinear, 4.0 * worst) << worstLinear;
}

// The aerial perspective folded into the vertices' terms (foldAerialPerspective): the pixel's
// mix of the folded quadratic and foam is the per-pixel radiance's, mixFoam(R, F, W) T + I, at
// any mean slope, covariance and whitecap coverage.
TEST(OceanRadianceTerms, FoldedAerialPerspectiveIsTheRadiancesThroughThePath) {
  const lighting::Settings s = skyAndSea();
  lighting::SlopePoint point;
  point.toSun = dir(50, 0);
  point.toEye = dir(45, 170);
  const glm::dvec2 slope(0.01, 0.02);
  const glm::dvec3 cov(0.018, 0.011, 0.001);
  const lighting::RadianceTerms t = lighting::seaRadianceTerms(s, point, slope, cov, 0.05);
  const glm::dvec3 foam(0.3, 0.31, 0.32), transmittance(0.7, 0.8, 0.9), inscatter(0.02, 0.03, 0.05);
  lighting::RadianceTerms folded = t;
  glm::dvec3 foldedFoam = foam;
  lighting::foldAerialPerspective(folded, foldedFoam, transmittance, inscatter);
  for (const double w : {0.0, 0.3, 1.0}) {
    const glm::dvec2 ps = slope + glm::dvec2(0.03, -0.02);
    const glm::dvec3 pc = cov * 1.1;
    const glm::dvec3 expected =
        lighting::mixFoam(s, lighting::seaRadianceOfTerms(t, ps, pc), foam, w) * transmittance + inscatter;
    const glm::dvec3 got = lighting::mixFoam(s, lighting::seaRadianceOfTerms(folded, ps, pc), foldedFoam, w);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-12) << w;
  }
}
