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
//       anisotropy on a GPU; on llvmpipe two lookups a layer in the layers' radial sums
//       (SKY_RADIAL_SUMS), else up to 4 lookups along the ellipse
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

#ifdef SKY_RADIAL_SUMS
// The sky maps' radial sums (render/SkyRadialSums, atmosphere/skymap_radial.comp): each layer's
// integral along each radius of the map, polar (x the azimuth over a turn, y |u| over
// SKY_RADIAL_MAX_RHO), less the layer's radiance below the horizon: the frame layer's
// (uSkyRadialSums, uSkyBelowHorizon) and the Sun layers' (uSkyRadialSumsLayers,
// uSkyBelowHorizonLayers[layer]).
layout(binding = OG_UNIT_SKY_RADIAL_SUMS) uniform sampler2D uSkyRadialSums;
layout(binding = OG_UNIT_SKY_RADIAL_SUMS_LAYERS) uniform sampler2DArray uSkyRadialSumsLayers;
uniform vec3 uSkyBelowHorizon;
const int SKY_RADIAL_MAX_LAYERS = 256;  // atmosphere::TableSizes' most Sun layers
uniform vec3 uSkyBelowHorizonLayers[SKY_RADIAL_MAX_LAYERS];

// The footprint with axes gx, gy (texture space) as a stretch along the map's radius: the
// reflected footprints are stretched along it (atmosphere/skymap_radial.comp), so the sky is
// averaged over the footprint's radial extent exactly, as a difference of the sums at its two
// ends, at the level of detail of its tangential extent (the probes' isotropic width along the
// ellipse). A stretch shorter than a texel of that level is widened to one: the difference then
// interpolates the sky linearly, as a bilinear lookup would. A stretch across the zenith adds
// the sums of its two sides.
struct SkyStretch {
  float phi;         // azimuth, turns
  float rho1, rho2;  // its ends (rho1 < 0: across the zenith)
  float lod, perU;   // the level read, texels per unit of u along the radius
  float length;      // rho2 - rho1
};
SkyStretch skyRadialStretch(vec2 tc, vec2 gx, vec2 gy) {
  float toU = 2.0 * SKYMAP_EXTENT;  // texture space -> u (skyMapRadianceStereo's scale)
  vec2 u = (tc - 0.5) * toU;
  float rho = length(u);
  vec2 radial = rho > 1e-6 ? u / rho : vec2(1.0, 0.0);
  vec2 across = vec2(-radial.y, radial.x);
  float alongU = length(vec2(dot(gx, radial), dot(gy, radial))) * toU;
  float acrossU = length(vec2(dot(gx, across), dot(gy, across))) * toU;
  // The level whose texels span the footprint's width along the radius. Texels are square in u
  // on the horizon's circle; inside it they are narrower around (by rho), so there the sky is
  // blurred across the radius a little less than the footprint is wide: the level that blurs
  // around by the full width blurs along the radius by 1/rho of it, which brightened the sea
  // below the horizon's reflection (from 2 m at sunset: 6.8 % of pixels over 2 levels from the
  // probes' limit, against 0.3 % so). At most the level whose texels are a quarter of the
  // radius's table: coarser ones hold a texel or two along it, whose differences vanish.
#ifdef SKY_FRAME_LAYER
  float rows = float(textureSize(uSkyRadialSums, 0).y);
#else
  float rows = float(textureSize(uSkyRadialSumsLayers, 0).y);
#endif
  SkyStretch st;
  st.perU = rows / SKY_RADIAL_MAX_RHO;
  st.lod = clamp(log2(max(acrossU * st.perU, 1e-8)), 0.0, log2(rows) - 2.0);
  st.length = max(alongU, exp2(st.lod) / st.perU);
  st.rho1 = rho - 0.5 * st.length;
  st.rho2 = rho + 0.5 * st.length;
  st.phi = atan(radial.y, radial.x) * (1.0 / 6.28318530717959);
  return st;
}
// The sums at radius rho (>= 0) and azimuth phi (turns) at level lod, of the frame layer
// (SKY_FRAME_LAYER) or of Sun layer `layer`: texel 0's centre lies half a texel of the level
// from the zenith, and the table clamps to it there; nearer, the sum falls linearly to 0 (the
// sky is smooth at the zenith), from half a texel of the coarser of the two levels read.
vec3 skyRadialSumAt(float phi, float rho, float layer, float lod, float perU) {
  float h = 0.5 * exp2(ceil(lod)) / perU;
  vec2 tc = vec2(phi, min(max(rho, h), SKY_RADIAL_MAX_RHO) / SKY_RADIAL_MAX_RHO);
#ifdef SKY_FRAME_LAYER
  vec3 c = textureLod(uSkyRadialSums, tc, lod).rgb;
#else
  vec3 c = textureLod(uSkyRadialSumsLayers, vec3(tc, layer), lod).rgb;
#endif
  return c * min(rho / h, 1.0);
}
// The sky of the frame layer (SKY_FRAME_LAYER) or of Sun layer `layer` averaged over the
// stretch: two lookups.
vec3 skyRadialAverage(SkyStretch st, float layer) {
  vec3 c2 = skyRadialSumAt(st.phi, st.rho2, layer, st.lod, st.perU);
  vec3 c1 = skyRadialSumAt(st.rho1 < 0.0 ? st.phi + 0.5 : st.phi, abs(st.rho1), layer, st.lod, st.perU);
#ifdef SKY_FRAME_LAYER
  vec3 below = uSkyBelowHorizon;
#else
  vec3 below = uSkyBelowHorizonLayers[int(layer)];
#endif
  return (c2 - sign(st.rho1) * c1) / st.length + below;
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
#ifdef SKY_RADIAL_SUMS
  return skyRadialAverage(skyRadialStretch(tc, gx, gy), float(layers));
#else
  return skyMapLayerFiltered(tc, float(layers), gx, gy);
#endif
#else
  float f = clamp(sunZenith / SKYMAP_MAX_ZENITH, 0.0, 1.0) * float(layers - 1);
  float l0 = min(floor(f), float(layers - 2));
#ifdef SKY_RADIAL_SUMS  // one stretch, two lookups a layer
  SkyStretch st = skyRadialStretch(tc, gx, gy);
  vec3 a = skyRadialAverage(st, l0);
  vec3 b = skyRadialAverage(st, l0 + 1.0);
#else
  vec3 a = skyMapLayerFiltered(tc, l0, gx, gy);
  vec3 b = skyMapLayerFiltered(tc, l0 + 1.0, gx, gy);
#endif
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
