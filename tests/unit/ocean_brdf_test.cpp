// CPU checks of shaders/ocean/brdf.glsl, compiled as C++ (src/ocean/Brdf.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/Brdf.hpp"

using namespace og::ocean::brdf;

namespace {
const glm::dvec3 kN{0, 0, 1}, kTx{1, 0, 0}, kTy{0, 1, 0};
glm::dvec3 dir(double zenithDeg, double azimuthDeg) {
  const double t = zenithDeg * M_PI / 180.0, p = azimuthDeg * M_PI / 180.0;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}
}  // namespace

TEST(OceanBrdf, RossBrdfIsReciprocal) {
  const glm::dvec2 s{0.03, 0.02};
  for (double zv : {10.0, 45.0, 80.0})
    for (double zl : {5.0, 30.0, 70.0}) {
      const glm::dvec3 v = dir(zv, 20), l = dir(zl, 200);
      // f(v, l) = rossSun(v, l) / cos(theta_l) must equal f(l, v).
      EXPECT_NEAR(rossSun(v, l, kN, kTx, kTy, s) / l.z, rossSun(l, v, kN, kTx, kTy, s) / v.z,
                  1e-12 * (1 + rossSun(v, l, kN, kTx, kTy, s)));
    }
}

TEST(OceanBrdf, DirectionalAlbedoIsAboutTheMeanFresnel) {
  // Integrate rossSun (BRDF x cos) over the hemisphere of light directions for a near-normal
  // view: a mirror-like sea reflects about R0 = 2% of uniform light, never more than 100%.
  for (double sigma2 : {0.005, 0.03, 0.08}) {
    const glm::dvec3 v = dir(20, 0);
    double albedo = 0.0;
    const int nt = 400, np = 200;
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < np; ++j) {
        const double t = (i + 0.5) * 0.5 * M_PI / nt, p = (j + 0.5) * 2 * M_PI / np;
        const glm::dvec3 l = dir(t * 180 / M_PI, p * 180 / M_PI);
        albedo += rossSun(v, l, kN, kTx, kTy, {sigma2, sigma2}) * std::sin(t) * (0.5 * M_PI / nt) *
                  (2 * M_PI / np);
      }
    EXPECT_GT(albedo, 0.015) << sigma2;
    EXPECT_LT(albedo, 0.05) << sigma2;
  }
}

TEST(OceanBrdf, GlintPeaksAtTheMirrorDirectionAndWidensWithRoughness) {
  const glm::dvec3 l = dir(60, 180);
  const glm::dvec3 mirror = dir(60, 0);
  const glm::dvec3 off = dir(20, 0);  // facet tilt 20°: far out in the calm tail
  const double calmPeak = rossSun(mirror, l, kN, kTx, kTy, {0.005, 0.005});
  const double roughPeak = rossSun(mirror, l, kN, kTx, kTy, {0.05, 0.05});
  EXPECT_GT(calmPeak, 5.0 * roughPeak);  // calm: high narrow peak
  EXPECT_GT(rossSun(off, l, kN, kTx, kTy, {0.05, 0.05}),
            rossSun(off, l, kN, kTx, kTy, {0.005, 0.005}));  // rough: broad
  EXPECT_GT(calmPeak, rossSun(off, l, kN, kTx, kTy, {0.005, 0.005}));
}

TEST(OceanBrdf, SmithLambdaLimits) {
  EXPECT_NEAR(smithLambda(1.0, 0.02), 0.0, 1e-6);      // looking straight down: no masking
  EXPECT_GT(smithLambda(0.05, 0.02), smithLambda(0.5, 0.02));  // grows toward grazing
  EXPECT_GT(smithLambda(0.2, 0.08), smithLambda(0.2, 0.01));   // and with roughness
}

TEST(OceanBrdf, EffectiveFresnelReducesToSchlickOnAFlatSea) {
  for (double c : {0.05, 0.3, 0.7, 1.0}) EXPECT_NEAR(effectiveFresnel(c, 0.0), fresnelSchlick(c), 1e-12);
  EXPECT_LT(effectiveFresnel(0.05, 0.2), fresnelSchlick(0.05));  // roughness lowers grazing F
  EXPECT_NEAR(fresnelSchlick(1.0), 0.02, 1e-12);
}

TEST(OceanBrdf, StereographicMapsZenithAndHorizon) {
  EXPECT_NEAR(glm::length(stereographic({0, 0, 1})), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(stereographic(glm::normalize(glm::dvec3{1, 1, 0}))), 1.0, 1e-12);
  const glm::dvec3 r = reflectedBySlope(dir(30, 0), kN, kTx, kTy, {0, 0});
  EXPECT_NEAR(glm::length(r - dir(30, 180)), 0.0, 1e-12);  // flat facet: mirror
}
