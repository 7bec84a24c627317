// CPU checks of shaders/ocean/water_optics.glsl compiled as C++ (src/ocean/WaterOptics.cpp):
// Beer-Lambert absorption, the march's d_max, Snell, and the floor's brightness against depth
// as the shallow-water model says (Maritorena et al. 1994).
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/WaterOptics.hpp"

using namespace og::ocean;

namespace {
const glm::dvec3 kK = jerlovWater(kDefaultWater).attenuationPerM;
const glm::dvec3 kZero{0.0};
// Radiance leaving the surface over a floor `depthM` deep, seen straight down, the Sun
// overhead (sun and sky irradiance below the surface), deep water `deep`.
glm::dvec3 nadir(double depthM, const glm::dvec3& deep, const glm::dvec3& sun, const glm::dvec3& sky) {
  const glm::dvec3 e = floorIrradiance(kK, depthM, 1.0, sun, 1.0, sky);
  return waterColumnRadiance(kK, deep, kCoralSandAlbedo, e, depthM, depthM, sun + sky);
}
}  // namespace

TEST(WaterOptics, ShaderConstantsMatchTheCpp) {
  EXPECT_EQ(shaderWaterIndex(), kWaterIndex);
  EXPECT_EQ(shaderWaterLeavingFactor(), kWaterLeavingFactor);
}

TEST(WaterOptics, TransmittanceIsBeerLambert) {
  for (double d : {0.0, 0.5, 3.0, 40.0}) {
    const glm::dvec3 t = waterTransmittance(kK, d);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], std::exp(-kK[c] * d), 1e-15);
    // Paths add: alpha(d1 + d2) = alpha(d1) alpha(d2).
    const glm::dvec3 t2 = waterTransmittance(kK, d + 7.0);
    const glm::dvec3 t7 = waterTransmittance(kK, 7.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t2[c], t[c] * t7[c], 1e-15);
  }
  EXPECT_EQ(waterTransmittance(kK, -5.0), glm::dvec3(1.0));  // no negative paths
}

TEST(WaterOptics, MarchStopsWhereEveryChannelIsBelowEpsilon) {
  const double dMax = waterMaxPathM(kK, kWaterEpsilon);
  const glm::dvec3 t = waterTransmittance(kK, dMax);
  EXPECT_NEAR(std::max(t.x, std::max(t.y, t.z)), kWaterEpsilon, 1e-12);
  // Clear ocean: blue carries furthest, ~170 m; coastal water far less.
  EXPECT_NEAR(dMax, -std::log(kWaterEpsilon) / kK.z, 1e-9);
  EXPECT_GT(dMax, 150.0);
  EXPECT_LT(waterMaxPathM(jerlovWater(JerlovWater::Coastal5).attenuationPerM, kWaterEpsilon), 25.0);
}

TEST(WaterOptics, SnellBendsRaysTowardsTheVertical) {
  EXPECT_DOUBLE_EQ(waterRefractedCosine(1.0), 1.0);
  // Grazing light enters at the critical angle, asin(1/n) from the vertical.
  EXPECT_NEAR(waterRefractedCosine(0.0), std::cos(std::asin(1.0 / kWaterIndex)), 1e-12);
  const double cosAir = std::cos(60.0 * M_PI / 180.0);
  const double sinWater = std::sin(60.0 * M_PI / 180.0) / kWaterIndex;
  EXPECT_NEAR(waterRefractedCosine(cosAir), std::sqrt(1.0 - sinWater * sinWater), 1e-12);
}

// The Done-when item: floor brightness falls with depth as the absorption model says. With no
// in-scattering, seen vertically under an overhead Sun, L(z) = 0.54 A / pi E exp(-2 K z).
TEST(WaterOptics, FloorBrightnessFallsWithDepthAsBeerLambertSays) {
  const glm::dvec3 sun(0.8), sky(0.15);
  const glm::dvec3 l0 = nadir(0.0, kZero, sun, sky);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(l0[c], kWaterLeavingFactor * kCoralSandAlbedo[c] / M_PI * 0.95, 1e-12);
  for (double z : {1.0, 2.0, 5.0, 10.0, 20.0, 40.0}) {
    const glm::dvec3 l = nadir(z, kZero, sun, sky);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(std::log(l[c] / l0[c]), -2.0 * kK[c] * z, 1e-9) << z << " m, channel " << c;
  }
  // Slant paths: the Sun at 60 degrees (refracted to ~40) and the view along 10 m of water.
  const double cosSun = waterRefractedCosine(0.5);
  const glm::dvec3 e = floorIrradiance(kK, 5.0, cosSun, sun, 1.0, kZero);
  const glm::dvec3 l = waterColumnRadiance(kK, kZero, kCoralSandAlbedo, e, 5.0, 10.0, sun);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(l[c], kWaterLeavingFactor * kCoralSandAlbedo[c] / M_PI * sun[c] * std::exp(-kK[c] * (5.0 / cosSun + 10.0)), 1e-12);
}

// With in-scattering: R(H) = R_inf + (A' - R_inf) exp(-2 K H) (Maritorena et al. 1994 Eq. 9),
// A' = 0.54 A / pi; deep water gives back the deep sea's colour.
TEST(WaterOptics, ShallowReflectanceFollowsMaritorena) {
  const glm::dvec3 deep(0.0015, 0.004, 0.007), sun(1.0);
  for (double z : {0.0, 3.0, 12.0, 30.0}) {
    const glm::dvec3 r = nadir(z, deep, sun, kZero);
    for (int c = 0; c < 3; ++c) {
      const double a = kWaterLeavingFactor * kCoralSandAlbedo[c] / M_PI;
      EXPECT_NEAR(r[c], deep[c] + (a - deep[c]) * std::exp(-2.0 * kK[c] * z), 1e-12);
    }
  }
  const glm::dvec3 far = nadir(1e4, deep, sun, kZero);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(far[c], deep[c], 1e-12);
}

// Why banks are turquoise: over 5 m of clear water a sand floor keeps its green and blue but
// loses most of its red; coastal water loses the blue too (greener).
TEST(WaterOptics, ClearShallowWaterIsTurquoiseCoastalWaterGreener) {
  const glm::dvec3 sand = nadir(5.0, glm::dvec3(0.0015, 0.004, 0.007), glm::dvec3(1.0), kZero);
  EXPECT_GT(sand.y, 2.0 * sand.x);
  EXPECT_GT(sand.z, 2.0 * sand.x);
  const glm::dvec3 kc = jerlovWater(JerlovWater::Coastal5).attenuationPerM;
  EXPECT_GT(kc.z, kc.y);  // coastal: blue absorbed more than green (CDOM, chlorophyll)
  EXPECT_LT(kK.z, kK.y);  // clear ocean: blue the most transparent
  // Types ordered from clearest to most turbid at every wavelength.
  const JerlovWater order[] = {JerlovWater::OceanI, JerlovWater::OceanIB, JerlovWater::OceanII,
                               JerlovWater::OceanIII, JerlovWater::Coastal1, JerlovWater::Coastal3,
                               JerlovWater::Coastal5};
  for (int i = 1; i < 7; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_GE(jerlovWater(order[i]).attenuationPerM[c], jerlovWater(order[i - 1]).attenuationPerM[c]);
}

// The water types are Jerlov's (1976) Table XXVII as printed, at 600, 550 and 450 nm: the
// renderer's IB, and the two ends of the oceanic and coastal ranges (a slip of a digit shows).
TEST(WaterOptics, WaterTypesAreJerlovsTable) {
  const auto expectK = [](JerlovWater t, glm::dvec3 k) {
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(jerlovWater(t).attenuationPerM[c], k[c]) << jerlovWater(t).name << " " << c;
  };
  expectK(JerlovWater::OceanIB, {0.245, 0.072, 0.036});
  expectK(JerlovWater::OceanI, {0.235, 0.063, 0.019});
  expectK(JerlovWater::OceanIII, {0.295, 0.12, 0.135});
  expectK(JerlovWater::Coastal5, {0.40, 0.30, 0.56});
  EXPECT_EQ(kDefaultWater, JerlovWater::OceanIB);
}
