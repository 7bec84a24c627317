// The atmosphere model for rendering passes: the shared functions, the parameters uniform and
// the precomputed tables on fixed texture units (bound by og::render::Atmosphere::bind):
//   2 transmittance (2D), 3 scattering (3D: Rayleigh + multiple / Rayleigh phase),
//   4 single Mie scattering (3D), 5 sky irradiance (2D).
#include "atmosphere/definitions.glsl"
#include "atmosphere/functions.glsl"

uniform AtmosphereParameters uAtmosphere;
layout(binding = OG_UNIT_ATM_TRANSMITTANCE) uniform sampler2D uAtmTransmittance;
layout(binding = OG_UNIT_ATM_SCATTERING) uniform sampler3D uAtmScattering;
layout(binding = OG_UNIT_ATM_SINGLE_MIE) uniform sampler3D uAtmSingleMie;
layout(binding = OG_UNIT_ATM_IRRADIANCE) uniform sampler2D uAtmIrradiance;
