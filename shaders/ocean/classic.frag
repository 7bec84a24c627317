#version 450 core
// Classic ocean shading (seed 002): two bump maps scrolling across each other (the second with
// u and v swapped), a mirror reflection of the sky per pixel, a 1D Fresnel ramp indexed by N.V
// that tints towards green looking down and blue at grazing angles, and sparkles where the
// reflection meets the Sun. No filtering beyond the bump maps' mipmaps: the baseline the
// filtered model is measured against (it aliases and flickers in the distance).
#include "common/constants.glsl"
#include "common/types.glsl"
#include "geo/ellipsoid.glsl"
#include "ocean/brdf.glsl"
#include "ocean/lighting.glsl"
#include "render/elevation.glsl"
#include "ocean/coast.glsl"
#include "terrain/shadow.glsl"

in vec2 vOceanXY;
in vec3 vRelative;
in vec2 vSlope;
#include "render/outputs.glsl"

layout(binding = OG_UNIT_BUMP_MAP) uniform sampler2D uBumpMap;     // tangent-space normals, RG = xy * 0.5 + 0.5
layout(binding = OG_UNIT_FRESNEL_RAMP) uniform sampler1D uFresnelRamp; // RGB water colour, A = Fresnel, by N.V
uniform mat3 uEcefToOcean;
uniform vec2 uFieldOffset;
uniform float uTime;
uniform vec3 uSunDirOcean;
uniform vec3 uSunDirEcef;

const float BUMP_TILE_M = 8.0;                            // bump-map repeat on the sea, m
const vec4 BUMP_SPEED = vec4(0.031, 0.04, -0.03, 0.02);   // tiles per second, two maps

vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance);  // aerial perspective (the pass)

void main() {
  KEEP_SEA_SAMPLES(vRelative)  // no sea over land (ocean/coast.glsl)
  vec2 uv = (vOceanXY + uFieldOffset) / BUMP_TILE_M;
  vec2 uv0 = uv + uTime * BUMP_SPEED.xy;
  vec2 uv1 = uv.yx * 1.25 + uTime * BUMP_SPEED.zw;  // swapped so the maps never align
  vec2 b = (texture(uBumpMap, uv0).rg * 2.0 - 1.0 + texture(uBumpMap, uv1).rg * 2.0 - 1.0) * 0.25;
  vec3 n = normalize(vec3(-vSlope + b, 1.0));
  vec3 v = -normalize(uEcefToOcean * vRelative);
  if (dot(n, v) < 0.0) n = normalize(n - 2.0 * dot(n, v) * v);
  vec3 r = reflect(-v, n);
  r.z = abs(r.z);
  vec4 ramp = texture(uFresnelRamp, clamp(dot(n, v), 0.0, 1.0));
  // The ocean frame stands in for the local frame (the classic model is planar anyway); the sky
  // is point-sampled in the mirror direction, no filtering.
  float sunZenith = acos(clamp(uSunDirOcean.z, -1.0, 1.0));
  vec3 sky = skyMapRadianceStereo(stereographic(r), sunZenith, sunAzimuthCosSin(uSunDirOcean), vec2(0.0), vec2(0.0));
  // The terrain's shadows on the sea (the frame's up stands in for the local vertical).
  vec3 eSun = sunIrradiance(sunZenith) * sunVisibility(vRelative, transpose(uEcefToOcean)[2]);
  // Sparkles: the Sun seen in the mirror direction, a narrow Phong lobe.
  float sparkle = pow(max(dot(r, uSunDirOcean), 0.0), 800.0) * 60.0;
  vec3 water = ramp.rgb * (eSun * max(uSunDirOcean.z, 0.0) + skyIrradiance(sunZenith));
  vec3 radiance = mix(water, sky, ramp.a) + eSun * sparkle * ramp.a;
  fragRadiance = vec4(oceanSurfaceRadiance(vRelative, radiance), 1.0);
  fragAux = vec4(0.0);
}

#ifdef OCEAN_SIMPLE_SKY
vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance) { return radiance; }
#else
#include "render/aerial.glsl"
vec3 oceanSurfaceRadiance(vec3 relative, vec3 radiance) {
  float t = length(relative);
  return withAerialPerspective(radiance, relative / t, t, uSunDirEcef);
}
#endif
