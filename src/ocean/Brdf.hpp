#pragma once
// CPU twin of shaders/ocean/brdf.glsl (the same file compiled as C++ in double precision).
#include <glm/glm.hpp>

namespace og::ocean::brdf {

double fresnelSchlick(double cosTheta);
double smithLambda(double cosTheta, double sigmaPhi2);
double slopeDensity(const glm::dvec2& zeta, const glm::dvec2& sigma2);
/// Ross BRDF x cos(theta_l) for the Sun; multiply by the Sun's irradiance for radiance.
double rossSun(const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& n, const glm::dvec3& tx,
               const glm::dvec3& ty, const glm::dvec2& sigma2);
double effectiveFresnel(double cosV, double sigmaV);
glm::dvec3 reflectedBySlope(const glm::dvec3& v, const glm::dvec3& n, const glm::dvec3& tx,
                            const glm::dvec3& ty, const glm::dvec2& zeta);
glm::dvec2 stereographic(const glm::dvec3& r);

}  // namespace og::ocean::brdf
