#pragma once
// Parameters of the precomputed atmosphere (Bruneton & Neyret 2008) with Earth defaults, the
// sizes of its tables, and the key that identifies a set of tables in the on-disk cache.
// Physics only: no GL here (the GPU precomputation is og::render::Atmosphere).
#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace og::atmosphere {

/// Table resolutions and integration sample counts. Defaults keep the start-up precomputation
/// on a 2-core llvmpipe to a few seconds (docs/performance.md); tests use small().
struct TableSizes {
  int transmittanceWidth = 128;  ///< along the view zenith cosine mu
  int transmittanceHeight = 32;  ///< along the radius r
  int irradianceWidth = 64;      ///< along the Sun zenith cosine mu_s
  int irradianceHeight = 16;     ///< along r
  int scatteringR = 16;          ///< 4D scattering table: r
  int scatteringMu = 64;         ///< mu, even (half towards the ground)
  int scatteringMuS = 16;        ///< mu_s
  int scatteringNu = 8;          ///< view-Sun cosine nu
  int sphereSamples = 8;         ///< zenith steps of the direction integrals (azimuth: twice)
  int skyMapSize = 128;          ///< sky map width = height, texels (power of two)
  int skyMapLayers = 32;         ///< Sun zenith layers of the sky maps, >= 16
  int skyIrradianceEntries = 64; ///< Sun zenith entries of the sea-level irradiance table

  /// Small tables for tests (fast on llvmpipe and on the CPU reference).
  static TableSizes small();
  bool operator==(const TableSizes&) const = default;
};

/// The atmosphere. Lengths in metres, scattering coefficients in 1/m at altitude 0, for the
/// three wavelengths (680, 550, 440) nm of the renderer's (R, G, B).
struct Parameters {
  /// Solar irradiance at the top of the atmosphere per channel, in the renderer's unit (the
  /// Sun's irradiance: 1 = a white Sun; radiance of a white plate facing it = 1/pi).
  glm::dvec3 solarIrradiance{1.0, 1.0, 1.0};
  double sunAngularRadiusRad = 0.004675;  ///< the Sun's apparent radius, radians
  /// Radius of the ground sphere of the tables (the renderer looks tables up at
  /// bottomRadiusM + altitude above the WGS84 ellipsoid). Default: the mean Earth radius.
  double bottomRadiusM = 6371000.0;
  double thicknessM = 60000.0;  ///< top of the atmosphere above the ground, m (> 0)
  /// Rayleigh (air molecules): scattering at altitude 0 (Eq. 1), no absorption.
  glm::dvec3 rayleighScattering{5.802e-6, 13.558e-6, 33.1e-6};
  double rayleighScaleHeightM = 8000.0;
  /// Mie (aerosols, Eq. 3): scattering and extinction (scattering + absorption) at altitude 0.
  glm::dvec3 mieScattering{3.996e-6, 3.996e-6, 3.996e-6};
  glm::dvec3 mieExtinction{4.44e-6, 4.44e-6, 4.44e-6};
  double mieScaleHeightM = 1200.0;
  double miePhaseG = 0.8;  ///< Cornette-Shanks asymmetry (Eq. 4), (-1, 1)
  /// Ozone: absorption at the peak of a tent profile (0 at center +- half width).
  glm::dvec3 ozoneAbsorption{0.650e-6, 1.881e-6, 0.085e-6};
  double ozoneCenterAltitudeM = 25000.0;
  double ozoneHalfWidthM = 15000.0;
  glm::dvec3 groundAlbedo{0.1, 0.1, 0.1};  ///< average ground reflectance for the tables
  /// Lowest Sun zenith cosine the scattering tables resolve (the paper's -0.2, Sun 101.5°
  /// from the zenith); lower Suns read the values at this bound.
  double muSMin = -0.2;
  int scatteringOrders = 4;  ///< single + multiple scattering orders, [1, 10]
  TableSizes tables;

  [[nodiscard]] double topRadiusM() const { return bottomRadiusM + thicknessM; }
};

/// The Earth defaults (as default-constructed).
Parameters earth();

/// The first problem with `p` (a coefficient negative or not finite, a size out of range), or
/// nothing when it can be precomputed.
std::optional<std::string> validate(const Parameters& p);

/// 64-bit FNV-1a over every field of `p` (exact bit patterns) and `salt` (e.g. the text of the
/// shaders that compute the tables, so a change of the code invalidates cached tables).
std::uint64_t cacheKey(const Parameters& p, std::string_view salt);

}  // namespace og::atmosphere
