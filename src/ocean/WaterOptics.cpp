#include "ocean/WaterOptics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/GlslShim.hpp"

namespace og::ocean {
namespace glsl {
using namespace og::glsl;
constexpr double PI = std::numbers::pi;
#include "ocean/water_optics.glsl"
}  // namespace glsl

WaterType jerlovWater(JerlovWater type) {
  // K_d, 1/m, at (600, 550, 450) nm.
  switch (type) {
    case JerlovWater::OceanI: return {"Jerlov I", {0.24, 0.064, 0.019}};
    case JerlovWater::OceanIB: return {"Jerlov IB", {0.24, 0.070, 0.032}};
    case JerlovWater::OceanII: return {"Jerlov II", {0.26, 0.089, 0.050}};
    case JerlovWater::OceanIII: return {"Jerlov III", {0.28, 0.12, 0.10}};
    case JerlovWater::Coastal1: return {"Jerlov 1C", {0.30, 0.13, 0.20}};
    case JerlovWater::Coastal3: return {"Jerlov 3C", {0.36, 0.19, 0.30}};
    case JerlovWater::Coastal5: return {"Jerlov 5C", {0.44, 0.26, 0.45}};
  }
  return {"Jerlov IB", {0.24, 0.070, 0.032}};
}

glm::dvec3 waterTransmittance(const glm::dvec3& k, double pathM) { return glsl::waterTransmittance(k, pathM); }
double waterMaxPathM(const glm::dvec3& k, double epsilon) { return glsl::waterMaxPathM(k, epsilon); }
double waterRefractedCosine(double cosAir) { return glsl::waterRefractedCosine(cosAir); }
double shaderWaterIndex() { return glsl::WATER_INDEX; }
double shaderWaterLeavingFactor() { return glsl::WATER_LEAVING_FACTOR; }
glm::dvec3 floorIrradiance(const glm::dvec3& k, double depthM, double cosSunWater, const glm::dvec3& sun,
                           double sunFactor, const glm::dvec3& sky) {
  return glsl::floorIrradiance(k, depthM, cosSunWater, sun, sunFactor, sky);
}
glm::dvec3 waterColumnRadiance(const glm::dvec3& k, const glm::dvec3& deep, const glm::dvec3& albedo,
                               const glm::dvec3& floorIrr, double depthM, double viewPathM,
                               const glm::dvec3& surfaceIrradiance) {
  return glsl::waterColumnRadiance(k, deep, albedo, floorIrr, depthM, viewPathM, surfaceIrradiance);
}

}  // namespace og::ocean
