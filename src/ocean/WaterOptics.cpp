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
  // K_d, 1/m, at (600, 550, 450) nm: Jerlov (1976) Table XXVII as printed (every 25 nm from
  // 310 to 700 nm; the rows used here are printed values, not interpolated).
  switch (type) {
    case JerlovWater::OceanI: return {"Jerlov I", {0.235, 0.063, 0.019}};
    case JerlovWater::OceanIB: return {"Jerlov IB", {0.245, 0.072, 0.036}};
    case JerlovWater::OceanII: return {"Jerlov II", {0.26, 0.089, 0.068}};
    case JerlovWater::OceanIII: return {"Jerlov III", {0.295, 0.12, 0.135}};
    case JerlovWater::Coastal1: return {"Jerlov 1C", {0.30, 0.12, 0.25}};
    case JerlovWater::Coastal3: return {"Jerlov 3C", {0.33, 0.19, 0.39}};
    case JerlovWater::Coastal5: return {"Jerlov 5C", {0.40, 0.30, 0.56}};
  }
  return jerlovWater(kDefaultWater);
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
