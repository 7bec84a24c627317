// Sky maps for ocean reflections (Bruneton, Neyret & Holzschuch 2010, Sections 5.2 and 6):
// the sky radiance seen from sea level, one stereographic map per Sun zenith angle, and the
// sky's irradiance at sea level per Sun zenith angle. Prepared by og::render::Atmosphere, which
// binds them with Atmosphere::bindSkyMaps(); include this file and call:
//
//   vec2 skyMapStereo(vec3 dirLocal)
//       u = [x, y] / (1 + z): stereographic coordinates of a unit direction in a local frame
//       (x, y horizontal, z up); the zenith maps to 0, the horizon to the unit circle.
//
//   vec3 skyMapRadiance(vec3 reflectedDirLocal, float sunZenith, float sunAzimuth,
//                       vec2 dUdx, vec2 dUdy)
//   vec3 skyMapRadianceStereo(vec2 u, float sunZenith, float sunAzimuth, vec2 dUdx, vec2 dUdy)
//       Sky radiance arriving from direction reflectedDirLocal (unit, local frame as above),
//       filtered over the footprint given by the two stereographic-space gradients dUdx, dUdy
//       (the axes of the filter ellipse, e.g. Bruneton 2010 Fig. 9: 2 sigma_x dU/dzeta_x and
//       2 sigma_y dU/dzeta_y; pass zeros for a point sample), with textureGrad (trilinear; the
//       sampler's anisotropy is 1, see docs/atmosphere.md). sunZenith: the Sun's zenith angle
//       at the surface point, radians [0, pi] (beyond 105° the last, dark layer is used);
//       sunAzimuth: the Sun's azimuth in the same local frame, radians, counter-clockwise from
//       +x towards +y (atan(sun.y, sun.x)). Directions below the horizon return the horizon's
//       radiance in that azimuth. The Sun's disc is NOT in the maps (add it with the Sun's
//       BRDF term). Layers are blended linearly in the Sun zenith angle.
//       Units: radiance relative to the solar irradiance at the top of the atmosphere, the
//       renderer's unit (a white Lambertian plate facing the unattenuated Sun has radiance 1/pi).
//
//   vec3 skyIrradiance(float sunZenith)
//       Irradiance of a horizontal surface at sea level by the sky alone (no direct Sun), same
//       units (so a Lambertian surface of albedo a has radiance a / pi * skyIrradiance).
//   vec3 sunIrradiance(float sunZenith)
//       Irradiance by the Sun's disc, attenuated by the atmosphere, on a surface facing the Sun
//       at sea level (multiply by max(cos(angle to the Sun), 0)); reddened at low Sun.
#include "atmosphere/skymap_common.glsl"

layout(binding = OG_UNIT_SKY_MAP) uniform sampler2DArray uSkyMap;         // rgb radiance, mip-mapped
layout(binding = OG_UNIT_SKY_IRRADIANCE) uniform sampler1DArray uSkyIrradiance;  // layer 0 sky, layer 1 Sun

vec2 skyMapStereo(vec3 dirLocal) { return dirLocal.xy / max(1.0 + dirLocal.z, 1e-4); }

vec3 skyMapRadianceStereo(vec2 u, float sunZenith, float sunAzimuth, vec2 dUdx, vec2 dUdy) {
  // Rotate by -sunAzimuth so the Sun lies along +x, as in the stored maps.
  float c = cos(sunAzimuth), s = sin(sunAzimuth);
  mat2 toMap = mat2(c, -s, s, c);
  float scale = 0.5 / SKYMAP_EXTENT;
  vec2 tc = toMap * u * scale + 0.5;
  vec2 gx = toMap * dUdx * scale, gy = toMap * dUdy * scale;
  int layers = textureSize(uSkyMap, 0).z;
  float f = clamp(sunZenith / SKYMAP_MAX_ZENITH, 0.0, 1.0) * float(layers - 1);
  float l0 = min(floor(f), float(layers - 2));
  vec3 a = textureGrad(uSkyMap, vec3(tc, l0), gx, gy).rgb;
  vec3 b = textureGrad(uSkyMap, vec3(tc, l0 + 1.0), gx, gy).rgb;
  return mix(a, b, f - l0);
}

vec3 skyMapRadiance(vec3 reflectedDirLocal, float sunZenith, float sunAzimuth, vec2 dUdx,
                    vec2 dUdy) {
  vec3 d = reflectedDirLocal;
  if (d.z < 0.0) d = vec3(normalize(d.xy + vec2(1e-9, 0.0)), 0.0);
  return skyMapRadianceStereo(skyMapStereo(d), sunZenith, sunAzimuth, dUdx, dUdy);
}

float skyIrradianceCoord(float sunZenith) {
  float n = float(textureSize(uSkyIrradiance, 0).x);
  return (clamp(sunZenith / 3.14159265358979, 0.0, 1.0) * (n - 1.0) + 0.5) / n;
}
vec3 skyIrradiance(float sunZenith) {
  return texture(uSkyIrradiance, vec2(skyIrradianceCoord(sunZenith), 0.0)).rgb;
}
vec3 sunIrradiance(float sunZenith) {
  return texture(uSkyIrradiance, vec2(skyIrradianceCoord(sunZenith), 1.0)).rgb;
}
