// The atmosphere model for rendering passes: the shared functions, the parameters uniform and
// the precomputed tables on fixed texture units (bound by og::render::Atmosphere::bind):
//   2 transmittance (2D), 3 scattering (3D: Rayleigh + multiple / Rayleigh phase),
//   4 single Mie scattering (3D), 5 sky irradiance (2D).
#include "atmosphere/definitions.glsl"
#include "atmosphere/functions.glsl"

uniform AtmosphereParameters uAtmosphere;
layout(binding = 2) uniform sampler2D uAtmTransmittance;
layout(binding = 3) uniform sampler3D uAtmScattering;
layout(binding = 4) uniform sampler3D uAtmSingleMie;
layout(binding = 5) uniform sampler2D uAtmIrradiance;
