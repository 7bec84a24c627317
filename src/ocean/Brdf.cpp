#include "ocean/Brdf.hpp"

#include <algorithm>
#include <cmath>

#include "core/GlslShim.hpp"

namespace og::ocean::brdf {
namespace glsl {
using namespace og::glsl;
#include "ocean/brdf.glsl"
}  // namespace glsl

double fresnelSchlick(double c) { return glsl::fresnelSchlick(c); }
double smithLambda(double c, double s) { return glsl::smithLambda(c, s); }
double slopeDensity(const glm::dvec2& z, const glm::dvec2& s) { return glsl::slopeDensity(z, s); }
double rossSun(const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& n, const glm::dvec3& tx,
               const glm::dvec3& ty, const glm::dvec2& s) {
  return glsl::rossSun(v, l, n, tx, ty, s);
}
double effectiveFresnel(double c, double s) { return glsl::effectiveFresnel(c, s); }
glm::dvec3 reflectedBySlope(const glm::dvec3& v, const glm::dvec3& n, const glm::dvec3& tx,
                            const glm::dvec3& ty, const glm::dvec2& z) {
  return glsl::reflectedBySlope(v, n, tx, ty, z);
}
glm::dvec2 stereographic(const glm::dvec3& r) { return glsl::stereographic(r); }
glm::dvec2 visibleSlopeMoments(double k) { return glsl::visibleSlopeMoments(k); }
SlopeAxes slopePrincipalAxes(const glm::dvec3& c) {
  const glsl::SlopeFrame f = glsl::slopePrincipalAxes(c);
  return {f.sigma2, f.axis};
}
glm::dvec3 sunDiscSlopeCovariance(const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& tx,
                                  const glm::dvec3& ty, double alphaRad) {
  return glsl::sunDiscSlopeCovariance(v, l, tx, ty, alphaRad);
}

}  // namespace og::ocean::brdf
