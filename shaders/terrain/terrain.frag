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
  // Triangles of a tile's row at a pole collapse onto the pole; llvmpipe can still emit a
  // fragment for them with undefined (NaN) attributes. They cover nothing: drop them.
  if (any(isnan(vInfo)) || any(isnan(vRelative)) || any(isnan(vNormal))) discard;
  float heightM = vInfo.x;
  float lat = vInfo.y, lon = vInfo.z;
  vec3 up = vec3(cos(lat) * cos(lon), cos(lat) * sin(lon), sin(lat));
  // Triangles that collapse at a pole give no normal (zero or NaN): the vertical stands in.
  vec3 n = dot(vNormal, vNormal) > 1e-20 ? normalize(vNormal) : up;
  float t = length(vRelative);
  vec3 dir = vRelative / t;
  // Seen from below (a skirt or a back face at a grazing angle): light it like its surroundings.
  if (dot(n, dir) > 0.0) {
    vec3 m = n - dot(n, dir) * dir;  // zero when the face looks straight away from the eye
    n = dot(m, m) > 1e-12 ? normalize(m) : up;
  }
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
