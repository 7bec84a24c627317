// Sky maps for ocean reflections (Bruneton, Neyret & Holzschuch 2010, Sections 5.2 and 6):
// the sky radiance seen from sea level, one stereographic map per Sun zenith angle, and the
// sky's irradiance at sea level per Sun zenith angle. Prepared by og::render::Atmosphere, which
// binds them with Atmosphere::bindSkyMaps(); include this file and call:
//
//   vec2 skyMapStereo(vec3 dirLocal)
//       u = [x, y] / (1 + z): stereographic coordinates of a unit direction in a local frame
//       (x, y horizontal, z up); the zenith maps to 0, the horizon to the unit circle.
//
//   vec3 skyMapRadiance(vec3 reflectedDirLocal, float sunZenith, vec2 sunAzimuthCS,
//                       vec2 dUdx, vec2 dUdy)
//   vec3 skyMapRadianceStereo(vec2 u, float sunZenith, vec2 sunAzimuthCS, vec2 dUdx, vec2 dUdy)
//       Sky radiance arriving from direction reflectedDirLocal (unit, local frame as above),
//       filtered over the footprint given by the two stereographic-space gradients dUdx, dUdy
//       (the axes of the filter ellipse, e.g. Bruneton 2010 Fig. 9: 2 sigma_x dU/dzeta_x and
//       2 sigma_y dU/dzeta_y; pass zeros for a point sample), with textureGrad: hardware
//       anisotropy on a GPU; on llvmpipe one lookup in the frame layer's rip-map (SKY_RIP_MAP)
//       where the view reads the frame layer, else up to 4 lookups along the ellipse
//       (uSkyFilterProbes; Atmosphere::chooseSkyFilter). sunZenith: the Sun's zenith angle
//       at the surface point, radians [0, pi] (beyond 105° the last, dark layer is used);
//       sunAzimuthCS: (cos, sin) of the Sun's azimuth in the same local frame, counter-clockwise
//       from +x towards +y (common/constants.glsl's sunAzimuthCosSin of its direction there).
//       Directions below the horizon return the light the waves reflect from there,
//       0.17 E_sky / pi (atmosphere/skymap_common.glsl). The Sun's
//       disc is NOT in the maps (add it with the Sun's BRDF term). Layers are blended linearly in the Sun zenith angle.
//       Units: radiance relative to the solar irradiance at the top of the atmosphere, the
//       renderer's unit (a white Lambertian plate facing the unattenuated Sun has radiance 1/pi).
//
//   vec3 skyIrradiance(float sunZenith)
//       Irradiance of a horizontal surface at sea level by the sky alone (no direct Sun), same
//       units (so a Lambertian surface of albedo a has radiance a / pi * skyIrradiance).
//   vec3 sunIrradiance(float sunZenith)
//       Irradiance by the Sun's disc, attenuated by the atmosphere, on a surface facing the Sun
//       at sea level (multiply by max(cos(angle to the Sun), 0)); reddened at low Sun. Per
//       point from the transmittance table (atmosphere/model.glsl, bound by Atmosphere::bind):
//       functions.glsl's transmittanceToSun, the code the CPU reference compiles, so the
//       sunset's colour is exact to the table's resolution near the horizon (the table's
//       mu parameterisation concentrates texels there), not a zenith-linear 1D table.
#include "atmosphere/skymap_common.glsl"
#include "atmosphere/model.glsl"

// rgb radiance, mip-mapped; one layer per Sun zenith angle, then the frame layer
// (Atmosphere::prepareFrameSkyLayer: the maps at the camera's Sun zenith this frame).
layout(binding = OG_UNIT_SKY_MAP) uniform sampler2DArray uSkyMap;
layout(binding = OG_UNIT_SKY_IRRADIANCE) uniform sampler1DArray uSkyIrradiance;  // layer 0 sky (layer 1 Sun: unused)

vec2 skyMapStereo(vec3 dirLocal) { return dirLocal.xy / max(1.0 + dirLocal.z, 1e-4); }

// The sky filter (og::render::Atmosphere::chooseSkyFilter, set by Atmosphere::bind): 1 = one
// textureGrad over the footprint ellipse (the sampler's hardware anisotropy on a GPU); more =
// Bruneton 2010 §7.3, "an average of nine texture2D samples inside the elliptical filter
// support", for CPU rasterisers whose anisotropic filtering is slow and blurs wrongly (4 there:
// within a level of 9 at 8 bits, docs/performance.md).
uniform int uSkyFilterProbes;

// One sky-map layer over the footprint with axes gx, gy (texture space, a pixel's extent).
vec3 skyMapLayerFiltered(vec2 tc, float layer, vec2 gx, vec2 gy) {
  if (uSkyFilterProbes <= 1) return textureGrad(uSkyMap, vec3(tc, layer), gx, gy).rgb;
  // Up to uSkyFilterProbes isotropic lookups spread along the major axis, each over 1/n of it
  // and the minor axis: together they tile the ellipse's extent. n follows the ellipse's
  // elongation (major / minor, at most uSkyFilterProbes), so near-round footprints cost one
  // lookup; a longer ellipse's lookups each blur over more than the minor axis.
  bool xMajor = dot(gx, gx) >= dot(gy, gy);
  vec2 major = xMajor ? gx : gy, minor = xMajor ? gy : gx;
  float ratio = length(major) / max(length(minor), 1e-8);
  int n = int(clamp(ceil(ratio), 1.0, float(uSkyFilterProbes)));
  vec2 step = major / float(n);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < n; ++k)
    sum += textureGrad(uSkyMap, vec3(tc + (float(k) + 0.5 - 0.5 * float(n)) * step, layer), step, minor).rgb;
  return sum / float(n);
}

#ifdef SKY_RIP_MAP
// The frame layer's radial rip-map (render/SkyRipMap, atmosphere/skymap_rip.comp): layer j
// blurred along the map's radial direction by 2^j texels of every mip level.
layout(binding = OG_UNIT_SKY_RIP_MAP) uniform sampler2DArray uSkyRipMap;

// The frame layer over the footprint with axes gx, gy (texture space) in one lookup: the layer
// whose radial blur matches the ellipse's radial extent over its tangential one (nearest power
// of 2), read with the gradients' radial parts shrunk by that blur, so that the isotropic
// lookup's level of detail follows what is left (the tangential extent, or radial / 8 for
// longer ellipses). Reflected footprints stretch radially (atmosphere/skymap_rip.comp).
vec3 skyRipMapFiltered(vec2 tc, vec2 gx, vec2 gy) {
  vec2 centred = tc - 0.5;
  float r = length(centred);
  vec2 radial = r > 1e-6 ? centred / r : vec2(1.0, 0.0);
  vec2 along = vec2(dot(gx, radial), dot(gy, radial));                              // radial parts
  vec2 across = vec2(dot(gx, vec2(-radial.y, radial.x)), dot(gy, vec2(-radial.y, radial.x)));
  float layers = float(textureSize(uSkyRipMap, 0).z - 1);
  float j = clamp(round(0.5 * log2(max(dot(along, along), 1e-20) / max(dot(across, across), 1e-20))), 0.0, layers);
  float shrink = exp2(-j) - 1.0;
  return textureGrad(uSkyRipMap, vec3(tc, j), gx + shrink * along.x * radial, gy + shrink * along.y * radial).rgb;
}
#endif

vec3 skyMapRadianceStereo(vec2 u, float sunZenith, vec2 sunAzimuthCS, vec2 dUdx, vec2 dUdy) {
  // Rotate by -(the Sun's azimuth) so the Sun lies along +x, as in the stored maps.
  float c = sunAzimuthCS.x, s = sunAzimuthCS.y;
  mat2 toMap = mat2(c, -s, s, c);
  float scale = 0.5 / SKYMAP_EXTENT;
  vec2 tc = toMap * u * scale + 0.5;
  vec2 gx = toMap * dUdx * scale, gy = toMap * dUdy * scale;
  int layers = textureSize(uSkyMap, 0).z - 1;  // the last is the frame layer
#ifdef SKY_FRAME_LAYER
  // A view whose Sun zenith angle hardly varies (the sea from a few metres: the horizon is a
  // few km away) reads the two layers around the camera's, blended once per frame: one
  // filtered lookup instead of two.
#ifdef SKY_RIP_MAP
  return skyRipMapFiltered(tc, gx, gy);
#else
  return skyMapLayerFiltered(tc, float(layers), gx, gy);
#endif
#else
  float f = clamp(sunZenith / SKYMAP_MAX_ZENITH, 0.0, 1.0) * float(layers - 1);
  float l0 = min(floor(f), float(layers - 2));
  vec3 a = skyMapLayerFiltered(tc, l0, gx, gy);
  vec3 b = skyMapLayerFiltered(tc, l0 + 1.0, gx, gy);
  return mix(a, b, f - l0);
#endif
}

vec3 skyMapRadiance(vec3 reflectedDirLocal, float sunZenith, vec2 sunAzimuthCS, vec2 dUdx,
                    vec2 dUdy) {
  return skyMapRadianceStereo(skyMapStereo(reflectedDirLocal), sunZenith, sunAzimuthCS, dUdx, dUdy);
}

float skyIrradianceCoord(float sunZenith) {
  float n = float(textureSize(uSkyIrradiance, 0).x);
  return (clamp(sunZenith / 3.14159265358979, 0.0, 1.0) * (n - 1.0) + 0.5) / n;
}
vec3 skyIrradiance(float sunZenith) {
  return texture(uSkyIrradiance, vec2(skyIrradianceCoord(sunZenith), 0.0)).rgb;
}
vec3 sunIrradiance(float sunZenith) {
  return uAtmosphere.solarIrradiance * transmittanceToSun(uAtmosphere, uAtmTransmittance,
                                                          uAtmosphere.bottomRadius, cos(sunZenith));
}
