#version 450 core
// Terrain shading: Lambertian stand-in materials (terrain/material.glsl) lit by the Sun
// attenuated to the point's altitude and by the sky's irradiance (tilted by the slope), then
// aerial perspective along the eye-to-point path ending at the point's altitude. Radiance in
// Sun-irradiance units, like the globe pass.
#include "common/constants.glsl"
#include "atmosphere/model.glsl"
#include "render/aerial.glsl"
#include "terrain/material.glsl"

in vec3 vRelative;
in vec3 vNormal;
in vec4 vInfo;  // height m, latitude rad, longitude rad, slope
out vec4 fragRadiance;

uniform vec3 uSunDir;  // unit, ECEF axes

// Aerial perspective to a point at altitude hP (the tables' sphere, as in globe.frag): the
// path's zenith cosine is the one joining the eye's radius to R + hP over distance t.
vec3 aerialToAltitude(vec3 surface, vec3 dir, float t, float hP) {
  if (hP <= 0.0) return withAerialPerspective(surface, dir, t, uSunDir);
  float R = uAtmosphere.bottomRadius;
  float r = R + uCamAltitude;
  float rP = R + hP;
  float d = max(t, 1e-3);
  float mu = clamp((rP * rP - r * r - d * d) / (2.0 * r * d), -1.0, 1.0);
  vec3 transmittance;
  vec3 inscatter = skyRadianceToPoint(uAtmosphere, uAtmTransmittance, uAtmScattering,
                                      uAtmSingleMie, r, mu, dot(uSunDir, uCamUp),
                                      dot(dir, uSunDir), d, transmittance);
  return surface * transmittance + inscatter;
}

void main() {
  float heightM = vInfo.x;
  float lat = vInfo.y, lon = vInfo.z;
  vec3 up = vec3(cos(lat) * cos(lon), cos(lat) * sin(lon), sin(lat));
  vec3 n = normalize(vNormal);
  float t = length(vRelative);
  vec3 dir = vRelative / t;
  // Seen from below (a skirt or a back face at a grazing angle): light it like its surroundings.
  if (dot(n, dir) > 0.0) n = normalize(n - 2.0 * dot(n, dir) * dir * 0.5);
  float hP = max(heightM, 0.0);
  vec3 skyIrr;
  vec3 sunIrr = sunAndSkyIrradiance(uAtmosphere, uAtmTransmittance, uAtmIrradiance,
                                    uAtmosphere.bottomRadius + hP, dot(up, uSunDir), skyIrr);
  vec3 albedo = terrainAlbedo(heightM, vInfo.w, lat);
  // Sky light on a tilted surface: the part of the sky dome it sees.
  float skyView = 0.5 + 0.5 * dot(n, up);
  vec3 surface = albedo / PI * (sunIrr * max(dot(n, uSunDir), 0.0) + skyIrr * skyView);
  fragRadiance = vec4(aerialToAltitude(surface, dir, t, hP), 1.0);
}
