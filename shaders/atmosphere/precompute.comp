#version 450 core
// GPU precomputation of the atmosphere tables, one pass per PASS value (set by
// og::render::Atmosphere); each invocation fills one texel from atmosphere/functions.glsl.
//   1 transmittance      -> uOut2D                (Eq. 5)
//   2 direct irradiance  -> uOut2D                (E[L0], delta irradiance)
//   3 single scattering  -> uOut3D (Rayleigh), uOut3DB (Mie)
//   4 scattering density -> uOut3D                (J of order uOrder)
//   5 indirect irradiance-> uOut2D (delta), uAccum2D += delta   (E[L_{uOrder}])
//   6 multiple scattering-> uOut3D (delta), uAccum3D += delta / Rayleigh phase
//   7 sky maps           -> uSkyMap layers        (stereographic, per Sun zenith; below the
//                           horizon 0.17 E_sky / pi: atmosphere/skymap_common.glsl)
//   8 sea-level sky and Sun irradiance per Sun zenith -> uOut1DArray
#include "atmosphere/definitions.glsl"
#include "atmosphere/functions.glsl"
#include "atmosphere/skymap_common.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

uniform AtmosphereParameters uAtmosphere;
uniform int uOrder;
uniform ivec3 uSize;  // texels of the output

layout(binding = 0) uniform sampler2D uTransmittance;
layout(binding = 1) uniform sampler3D uSingleRayleigh;
layout(binding = 2) uniform sampler3D uSingleMie;
layout(binding = 3) uniform sampler3D uMultiple;   // delta multiple scattering, or J in pass 6
layout(binding = 4) uniform sampler2D uIrradiance; // delta irradiance of order - 2 (pass 4)
layout(binding = 5) uniform sampler3D uScattering; // final tables (passes 7 and 8)
layout(binding = 6) uniform sampler2D uIrradianceTotal;

layout(binding = 0, rgba32f) uniform writeonly image2D uOut2D;
layout(binding = 1, rgba32f) uniform image2D uAccum2D;
layout(binding = 2, rgba32f) uniform writeonly image3D uOut3D;
layout(binding = 3, rgba32f) uniform writeonly image3D uOut3DB;
layout(binding = 4, rgba32f) uniform image3D uAccum3D;
layout(binding = 5, rgba16f) uniform writeonly image2DArray uSkyMap;
layout(binding = 6, rgba32f) uniform writeonly image1DArray uOut1DArray;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(id, uSize))) return;
  vec3 centre = vec3(id) + 0.5;
#if PASS == 1
  float r, mu;
  transmittanceRMu(uAtmosphere, centre.xy / vec2(uSize.xy), r, mu);
  imageStore(uOut2D, id.xy, vec4(computeTransmittanceToTop(uAtmosphere, r, mu), 1.0));
#elif PASS == 2
  float r, muS;
  irradianceRMuS(uAtmosphere, centre.xy / vec2(uSize.xy), r, muS);
  imageStore(uOut2D, id.xy, vec4(computeDirectIrradiance(uAtmosphere, uTransmittance, r, muS), 1.0));
#elif PASS == 3
  float r, mu, muS, nu;
  bool hits;
  scatteringTexelParameters(uAtmosphere, centre, r, mu, muS, nu, hits);
  vec3 rayleigh, mie;
  computeSingleScattering(uAtmosphere, uTransmittance, r, mu, muS, nu, hits, rayleigh, mie);
  imageStore(uOut3D, id, vec4(rayleigh, 1.0));
  imageStore(uOut3DB, id, vec4(mie, 1.0));
#elif PASS == 4
  float r, mu, muS, nu;
  bool hits;
  scatteringTexelParameters(uAtmosphere, centre, r, mu, muS, nu, hits);
  vec3 j = computeScatteringDensity(uAtmosphere, uTransmittance, uSingleRayleigh, uSingleMie,
                                    uMultiple, uIrradiance, r, mu, muS, nu, uOrder);
  imageStore(uOut3D, id, vec4(j, 1.0));
#elif PASS == 5
  float r, muS;
  irradianceRMuS(uAtmosphere, centre.xy / vec2(uSize.xy), r, muS);
  vec3 e = computeIndirectIrradiance(uAtmosphere, uSingleRayleigh, uSingleMie, uMultiple, r, muS,
                                     uOrder);
  imageStore(uOut2D, id.xy, vec4(e, 1.0));
  imageStore(uAccum2D, id.xy, imageLoad(uAccum2D, id.xy) + vec4(e, 0.0));
#elif PASS == 6
  float r, mu, muS, nu;
  bool hits;
  scatteringTexelParameters(uAtmosphere, centre, r, mu, muS, nu, hits);
  vec3 l = computeMultipleScattering(uAtmosphere, uTransmittance, uMultiple, r, mu, muS, nu, hits);
  imageStore(uOut3D, id, vec4(l, 1.0));
  imageStore(uAccum3D, id, imageLoad(uAccum3D, id) + vec4(l / rayleighPhase(nu), 0.0));
#elif PASS == 7
  vec3 dir = skyMapDirection(centre.xy / vec2(uSize.xy));
  float muS = cos(skyMapLayerZenith(id.z, uSize.z));
  vec3 sun = vec3(sqrt(max(1.0 - muS * muS, 0.0)), 0.0, muS);
  vec3 t;
  vec3 l = skyRadiance(uAtmosphere, uTransmittance, uScattering, uSingleMie,
                       uAtmosphere.bottomRadius, dir.z, muS, dot(dir, sun), t);
  if (skyMapIsBelowHorizon(centre.xy / vec2(uSize.xy)))
    l = skyMapBelowHorizon(sampleIrradiance(uAtmosphere, uIrradianceTotal, uAtmosphere.bottomRadius, muS));
  imageStore(uSkyMap, id, vec4(l, 1.0));
#elif PASS == 8
  float muS = cos(skyIrradianceZenith(id.x, uSize.x));
  vec3 sky;
  vec3 sunIrr = sunAndSkyIrradiance(uAtmosphere, uTransmittance, uIrradianceTotal,
                                    uAtmosphere.bottomRadius, muS, sky);
  imageStore(uOut1DArray, ivec2(id.x, 0), vec4(sky, 1.0));
  imageStore(uOut1DArray, ivec2(id.x, 1), vec4(sunIrr, 1.0));
#endif
}
