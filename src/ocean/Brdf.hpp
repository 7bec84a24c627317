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
/// Principal axes of a slope covariance (xx, yy, xy) in a (tx, ty) frame: variances along them,
/// largest first, and the first axis as (cos, sin) in (tx, ty).
struct SlopeAxes {
  glm::dvec2 sigma2;
  glm::dvec2 axis;
};
SlopeAxes slopePrincipalAxes(const glm::dvec3& covariance);
/// Mean and variance (units of sigma, sigma²) of the slopes seen along the view's azimuth,
/// a Gaussian weighted by projected area 1 - zeta / k, k = cot(theta_v) / sigma.
glm::dvec2 visibleSlopeMoments(double k);
/// The Sun's disc of angular radius alphaRad as a facet slope covariance (xx, yy, xy) in (tx, ty).
glm::dvec3 sunDiscSlopeCovariance(const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& tx,
                                  const glm::dvec3& ty, double alphaRad);

}  // namespace og::ocean::brdf
