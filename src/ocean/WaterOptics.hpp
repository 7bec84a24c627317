#pragma once
// Water optics for shallow seas (seed 001, Baboud & Decoret 2006; Maritorena et al. 1994): CPU
// twin of shaders/ocean/water_optics.glsl (the same file compiled as C++ in double precision),
// and the water types and sea-floor albedo the renderer feeds it.
#include <glm/glm.hpp>

#include <string_view>

namespace og::ocean {

/// Jerlov's optical water types (Jerlov 1976, "Marine Optics"): oceanic I (clearest) to III and
/// coastal 1 to 9 (more turbid), defined by their diffuse attenuation spectra K_d(lambda).
enum class JerlovWater { OceanI, OceanIB, OceanII, OceanIII, Coastal1, Coastal3, Coastal5 };

struct WaterType {
  std::string_view name;
  /// Diffuse attenuation coefficient K_d, 1/m, per RGB channel: Jerlov's K_d at 600, 550 and
  /// 450 nm (R, G, B; near the dominant wavelengths of the sRGB primaries).
  glm::dvec3 attenuationPerM{0.0};
};

/// The K_d of a Jerlov type at 600, 550 and 450 nm: Jerlov (1976, "Marine Optics", Table
/// XXVII), the printed rows (checked against the digitised table of the Dstl dataset as shipped
/// with the `jerlov` Python package, jerlov1976_kd.csv); Solonenko & Mobley (2015, Appl. Opt.
/// 54, 5392) derive the types' absorption and scattering from such K_d spectra. The channels'
/// wavelengths are near the dominant wavelengths of the sRGB primaries (~610, 550, 465 nm) and
/// on Jerlov's 25 nm grid. Austin & Petzold (1986) later revised the oceanic types (IB at 450
/// nm: 0.0355 instead of 0.036); the printed table is kept.
WaterType jerlovWater(JerlovWater type);

/// The water the renderer uses: clear tropical ocean (Jerlov IB), the water of coral banks
/// such as the Bahamas.
inline constexpr JerlovWater kDefaultWater = JerlovWater::OceanIB;

/// Reflectance of a clean coral-sand floor at 600, 550 and 450 nm (Maritorena et al. 1994,
/// Fig. 6, as digitised for Hydrolight/OSOAA: 0.34 at 450 nm, rising to ~0.5 at 600 nm).
inline constexpr glm::dvec3 kCoralSandAlbedo{0.50, 0.45, 0.34};

/// The fraction of the light left when the march along a ray through water stops (seed 001,
/// Eq. 6's epsilon): 1/256, less than one level of an 8-bit picture.
inline constexpr double kWaterEpsilon = 1.0 / 256.0;

// --- the shader's functions (shaders/ocean/water_optics.glsl), in double -------------------
inline constexpr double kWaterIndex = 1.34;          ///< WATER_INDEX
inline constexpr double kWaterLeavingFactor = 0.54;  ///< WATER_LEAVING_FACTOR
/// The shader's own constants (for the test that keeps the two above in sync).
double shaderWaterIndex();
double shaderWaterLeavingFactor();
glm::dvec3 waterTransmittance(const glm::dvec3& attenuationPerM, double pathM);
double waterMaxPathM(const glm::dvec3& attenuationPerM, double epsilon);
double waterRefractedCosine(double cosAir);
glm::dvec3 floorIrradiance(const glm::dvec3& attenuationPerM, double depthM, double cosSunWater,
                           const glm::dvec3& sunBelowSurface, double sunFactor,
                           const glm::dvec3& skyBelowSurface);
glm::dvec3 waterColumnRadiance(const glm::dvec3& attenuationPerM, const glm::dvec3& deepReflectance,
                               const glm::dvec3& floorAlbedo, const glm::dvec3& floorIrr, double depthM,
                               double viewPathM, const glm::dvec3& surfaceIrradiance);

}  // namespace og::ocean
