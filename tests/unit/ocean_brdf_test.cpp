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

TEST(OceanBrdf, PrincipalAxesRecoverARotatedCovariance) {
  // A covariance of variances (0.04, 0.01) with its first axis 30° from tx: the cross term the
  // wind frame carries must turn the BRDF's axes, not be dropped.
  const double a = 30.0 * M_PI / 180.0;
  const glm::dvec2 axis{std::cos(a), std::sin(a)};
  const double c = axis.x, s = axis.y;
  const glm::dvec3 cov{c * c * 0.04 + s * s * 0.01, s * s * 0.04 + c * c * 0.01, c * s * 0.03};
  const SlopeAxes f = slopePrincipalAxes(cov);
  EXPECT_NEAR(f.sigma2.x, 0.04, 1e-12);
  EXPECT_NEAR(f.sigma2.y, 0.01, 1e-12);
  EXPECT_NEAR(std::abs(glm::dot(f.axis, axis)), 1.0, 1e-9);
  // The Ross lobe in the principal frame is the lobe of the rotated distribution: the density
  // of a slope along the first axis uses the 0.04 variance.
  const glm::dvec3 tx = c * kTx + s * kTy, ty = glm::cross(kN, tx);
  const glm::dvec3 v = dir(30, 180), l = dir(35, 10);
  EXPECT_NEAR(rossSun(v, l, kN, tx, ty, f.sigma2),
              rossSun(v, l, kN, c * kTx + s * kTy, -s * kTx + c * kTy, {0.04, 0.01}), 1e-9);
  // Diagonal input keeps the axes; a negative-free result for any positive semi-definite input.
  const SlopeAxes d = slopePrincipalAxes({0.01, 0.03, 0.0});
  EXPECT_NEAR(d.sigma2.x, 0.03, 1e-15);
  EXPECT_NEAR(std::abs(d.axis.y), 1.0, 1e-12);
  EXPECT_GE(slopePrincipalAxes({1e-6, 1e-6, 1e-6}).sigma2.y, 0.0);
}

// The glint of a flat sea is the Sun's disc: the radiance over view directions around the
// mirror direction has the disc's angular second moment (a disc of radius alpha: alpha²/4 per
// axis), in the plane of incidence and across it, at a high and a low Sun.
TEST(OceanBrdf, FlatSeaGlintHasTheSunsAngularSize) {
  const double alpha = 0.267 * M_PI / 180.0;
  for (const double elevationDeg : {60.0, 20.0, 5.0}) {
    const glm::dvec3 l = dir(90.0 - elevationDeg, 0.0);
    const glm::dvec3 mirror = dir(90.0 - elevationDeg, 180.0);  // towards the eye
    // View directions at angular offsets (e along the vertical of the view, c across it).
    const glm::dvec3 up = glm::normalize(glm::cross(glm::cross(mirror, kN), mirror));
    const glm::dvec3 side = glm::normalize(glm::cross(mirror, up));
    double sum = 0.0, sumE2 = 0.0, sumC2 = 0.0;
    const int n = 121;
    const double step = 6.0 * alpha / n;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double e = (i - n / 2) * step, c = (j - n / 2) * step;
        const glm::dvec3 v = glm::normalize(mirror + e * up + c * side);
        const SlopeAxes f = slopePrincipalAxes(sunDiscSlopeCovariance(v, l, kTx, kTy, alpha) +
                                               glm::dvec3(1e-12, 1e-12, 0.0));
        const glm::dvec3 tx = f.axis.x * kTx + f.axis.y * kTy;
        const double r = rossSun(v, l, kN, tx, glm::cross(kN, tx), f.sigma2);
        sum += r;
        sumE2 += r * e * e;
        sumC2 += r * c * c;
      }
    const double disc = alpha * alpha / 4.0;
    EXPECT_NEAR(sumE2 / sum / disc, 1.0, 0.15) << elevationDeg;
    EXPECT_NEAR(sumC2 / sum / disc, 1.0, 0.15) << elevationDeg;
    // Energy: a mirror reflects F E_sun cos(theta) per unit area into the glint, radiance
    // E_sun rossSun over solid angle seen at cos(theta): the integral of rossSun is F.
    const double reflected = sum * step * step;
    EXPECT_NEAR(reflected / fresnelSchlick(glm::dot(mirror, glm::normalize(mirror + l))), 1.0, 0.1)
        << elevationDeg;
  }
}

// The visible slopes' moments (projected-area weighting 1 - x / k of a unit Gaussian, zero
// beyond k) against a numerical integral; no change looking straight down, facets leaning
// towards the eye and a narrower spread at grazing angles.
TEST(OceanBrdf, VisibleSlopeMomentsMatchTheWeightedGaussian) {
  for (const double k : {0.2, 0.7, 1.5, 3.0}) {
    double m0 = 0.0, m1 = 0.0, m2 = 0.0;
    const double dx = 1e-4;
    for (double x = -10.0; x < k; x += dx) {
      const double w = (1.0 - x / k) * std::exp(-0.5 * x * x) * dx;
      m0 += w;
      m1 += w * x;
      m2 += w * x * x;
    }
    const double mean = m1 / m0, var = m2 / m0 - mean * mean;
    const glm::dvec2 v = visibleSlopeMoments(k);
    EXPECT_NEAR(v.x, mean, 0.01 + 0.01 * std::abs(mean)) << k;
    EXPECT_NEAR(v.y, var, 0.01 + 0.02 * var) << k;
    EXPECT_LT(v.x, 0.0) << k;
    EXPECT_LT(v.y, 1.0) << k;
  }
  EXPECT_EQ(visibleSlopeMoments(10.0), glm::dvec2(0.0, 1.0));
}
