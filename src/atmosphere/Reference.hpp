#pragma once
// Double-precision CPU reference of the atmosphere: the same functions as the GPU passes
// (shaders/atmosphere/functions.glsl compiled as C++ with GLM double types), tables with
// GL_LINEAR / clamp-to-edge sampling, and the full precomputation. Slow: meant for tests with
// TableSizes::small().
#include <glm/glm.hpp>

#include <vector>

#include "atmosphere/Parameters.hpp"

namespace og::atmosphere {

/// A 2D table, texel (x, y) at texels[y * width + x] (the layout of a GL texture).
struct Table2D {
  int width = 0;
  int height = 0;
  std::vector<glm::dvec4> texels;
};

/// A 3D table, texel (x, y, z) at texels[(z * height + y) * width + x].
struct Table3D {
  int width = 0;
  int height = 0;
  int depth = 0;
  std::vector<glm::dvec4> texels;
};

/// Bilinear / trilinear lookups at normalised coordinates, clamped to the edge texels.
glm::dvec4 texture(const Table2D& t, glm::dvec2 uv);
glm::dvec4 texture(const Table3D& t, glm::dvec3 uvw);

/// The final tables, laid out as the GPU textures (og::render::Atmosphere).
struct ReferenceTables {
  Table2D transmittance;  ///< rgb: transmittance to the top boundary
  Table2D irradiance;     ///< rgb: indirect (sky) irradiance of a horizontal surface
  Table3D scattering;     ///< rgb: Rayleigh single + multiple / Rayleigh phase
  Table3D singleMie;      ///< rgb: single Mie scattering
};

/// Precomputes all tables (p.scatteringOrders orders) on the CPU, in parallel.
ReferenceTables precomputeReference(const Parameters& p);

/// A viewer at radius r (m) looking along zenith cosine mu with the Sun at zenith cosine muS
/// and view-Sun cosine nu. Radiance relative to p.solarIrradiance units, Sun disc excluded.
glm::dvec3 referenceSkyRadiance(const Parameters& p, const ReferenceTables& t, double r, double mu,
                                double muS, double nu, glm::dvec3* transmittance = nullptr);
/// Aerial perspective to a point d metres along the ray; its transmittance in `transmittance`.
glm::dvec3 referenceSkyRadianceToPoint(const Parameters& p, const ReferenceTables& t, double r,
                                       double mu, double muS, double nu, double d,
                                       glm::dvec3* transmittance = nullptr);
/// Sun irradiance on a surface facing the Sun at radius r, and the sky irradiance of a
/// horizontal surface there (in `sky`).
glm::dvec3 referenceSunAndSkyIrradiance(const Parameters& p, const ReferenceTables& t, double r,
                                        double muS, glm::dvec3& sky);
/// Transmittance to the top boundary integrated directly (Eq. 5), without tables.
glm::dvec3 referenceTransmittanceToTop(const Parameters& p, double r, double mu);

}  // namespace og::atmosphere
