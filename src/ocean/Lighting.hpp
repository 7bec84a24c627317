#pragma once
// CPU twin of shaders/ocean/lighting.glsl (Algorithm 5.1 of Bruneton, Neyret & Holzschuch 2010:
// the Sun's glint, the filtered sky reflection, the light refracted from below, whitecaps): the
// same file compiled as C++ in double precision (through core/GlslShim.hpp), lit by the file's
// analytic sky (OCEAN_SIMPLE_SKY) since the precomputed sky maps live on the GPU. Over the open
// sea (no sea floor: the shallow-water hook returns the deep colour).
#include <array>

#include <glm/glm.hpp>

namespace og::ocean::lighting {

/// The uniforms lighting.glsl reads, as the renderer's validation variants set them. Radiance in
/// units of the Sun's irradiance at the top of the atmosphere (per steradian).
struct Settings {
  glm::dvec3 skyZenithRadiance{0.0};   ///< analytic sky at the zenith (uSkyZenith), >= 0
  glm::dvec3 skyHorizonRadiance{0.0};  ///< analytic sky at the horizon (uSkyHorizon), >= 0
  glm::dvec3 seaColorPerSr{0.0};       ///< upwelling radiance per unit irradiance (uSeaColor), 1/sr
  /// Weights of the Sun, sky, refracted and foam terms (uLightingTerms), each 0 or 1.
  glm::dvec4 terms{1.0};
  double sunVisibility = 1.0;  ///< share of the Sun's disc seen (gSeaSunVisibility), [0, 1]
};

/// One sea point. Directions unit, in one frame (ECEF in the renderer).
struct SeaSample {
  glm::dvec3 toEye{0.0, 0.0, 1.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};  ///< mean (resolved) normal
  glm::dvec3 wind{0.0, 1.0, 0.0};    ///< any vector with a horizontal component along the wind
  /// Unresolved slope covariance (xx, yy, xy) along/across the wind, dimensionless, xx, yy > 0.
  glm::dvec3 slopeCovariance{0.01, 0.01, 0.0};
  glm::dvec3 up{0.0, 0.0, 1.0};     ///< the ellipsoid normal
  glm::dvec3 toSun{0.0, 0.0, 1.0};
  double foamCoverage = 0.0;         ///< whitecap coverage W, [0, 1]
};

/// Radiance leaving the sea towards the eye (lighting.glsl seaRadianceWithFoam).
glm::dvec3 seaRadiance(const Settings& settings, const SeaSample& sample);
/// The reference of the validation (seaRadianceMirror): a mirror facet, the Sun's disc over a
/// patch of slope covariance patchCovariance (sample.slopeCovariance is not used).
glm::dvec3 seaRadianceMirror(const Settings& settings, const SeaSample& sample,
                             const glm::dvec3& patchCovariance);
/// shaders/ocean/radiance_terms.glsl: the clear sea's radiance (no foam) as the projected
/// grid's vertices hand it to the pixels of large cells, a quadratic in the pixel's resolved
/// mean slope (dz/dx, dz/dy in the ocean frame's axes) and unresolved slope covariance (xx, yy,
/// xy along/across the wind): k[0] + sum_d (k[1 + d] x_d + k[6 + d] x_d²) + k[11] x_0 x_1 over
/// x = (slope.x, slope.y, cov.x, cov.y, cov.z).
struct RadianceTerms {
  std::array<glm::dvec3, 12> k{};
};
/// Where the quadratic is taken, and the rest of the point: `oceanToEcef`'s columns are the
/// ocean frame's east, north and up in ECEF; toEye, wind, up, toSun as in SeaSample.
struct SlopePoint {
  glm::dvec3 toEye{0.0, 0.0, 1.0};
  glm::dmat3 oceanToEcef{1.0};
  glm::dvec3 wind{0.0, 1.0, 0.0};
  glm::dvec3 up{0.0, 0.0, 1.0};
  glm::dvec3 toSun{0.0, 0.0, 1.0};
};
/// The clear sea's radiance for a footprint of mean slope `slope` and covariance `cov`
/// (clearSeaRadiance: the slope's normal tilted onto the ellipsoid and turned to face the eye).
glm::dvec3 clearSeaRadiance(const Settings& settings, const SlopePoint& point, const glm::dvec2& slope,
                            const glm::dvec3& cov);
/// The quadratic about (slope, cov), in slope steps of `slopeStep` (> 0) and steps of a tenth of
/// the covariance's entries (seaRadianceTerms).
RadianceTerms seaRadianceTerms(const Settings& settings, const SlopePoint& point, const glm::dvec2& slope,
                               const glm::dvec3& cov, double slopeStep);
/// The quadratic's value (seaRadianceOfTerms), >= 0.
glm::dvec3 seaRadianceOfTerms(const RadianceTerms& terms, const glm::dvec2& slope, const glm::dvec3& cov);
/// The aerial perspective folded into the terms and the foam's radiance
/// (foldAerialPerspective): each times `transmittance`, `inscatter` added to the constant and
/// to the foam.
void foldAerialPerspective(RadianceTerms& terms, glm::dvec3& foam, const glm::dvec3& transmittance,
                           const glm::dvec3& inscatter);
/// The clear sea's and the foam's radiance mixed by the foam's coverage, [0, 1], and the
/// settings' foam weight (mixFoam).
glm::dvec3 mixFoam(const Settings& settings, const glm::dvec3& clear, const glm::dvec3& foam, double coverage);

/// Sun and sky irradiance at sea level of the analytic sky for a Sun zenith angle, rad, [0, pi].
glm::dvec3 sunIrradiance(double sunZenithRad);
glm::dvec3 skyIrradiance(double sunZenithRad);
/// The Sun's angular radius the glint convolves, rad (SUN_ANGULAR_RADIUS_RAD).
double sunAngularRadiusRad();
/// Whitecap reflectance (FOAM_REFLECTANCE, Koepke 1984), [0, 1].
double foamReflectance();

}  // namespace og::ocean::lighting
