#version 450 core
// The globe as the WGS84 ellipsoid, ray-cast per pixel in the eye-relative frame, lit by the
// Sun, land and sea from the elevation layer. A stand-in surface model until the atmosphere,
// ocean and terrain passes replace it; it fixes the conventions they share: radiance in units
// of the Sun's irradiance (a white Lambertian plate facing the Sun has radiance 1/pi), alpha =
// coverage, reversed-Z depth = near / view distance.
#include "common/constants.glsl"
#include "geo/ellipsoid.glsl"

in vec2 vNdc;
out vec4 fragRadiance;

uniform vec3 uRight;       // camera basis, ECEF axes
uniform vec3 uUp;
uniform vec3 uForward;
uniform vec2 uTanHalfFov;  // (tan(fov_y/2) * aspect, tan(fov_y/2))
uniform vec2 uPixelNdc;    // size of one pixel in NDC
uniform float uNear;       // near plane, m
uniform vec3 uSunDir;      // unit, ECEF axes

layout(binding = 0) uniform sampler2D uElevation;  // metres, rows south to north
uniform vec4 uElevationMap;  // (lon0, lat0, dLon, dLat) in radians, cell centres
uniform vec2 uElevationSize; // (columns, rows)
uniform int uElevationWraps; // 1 when the columns cover 360 degrees

float elevationAt(vec2 latLon) {
  vec2 cell = vec2((latLon.y - uElevationMap.x) / uElevationMap.z,
                   (latLon.x - uElevationMap.y) / uElevationMap.w);
  if (uElevationWraps == 1) cell.x = mod(cell.x, uElevationSize.x);
  vec2 uv = (cell + 0.5) / uElevationSize;
  if (uElevationWraps == 0 && (uv.x < 0.0 || uv.x > 1.0)) return -1.0;
  return texture(uElevation, uv).r;
}

vec3 landAlbedo(float elevation, float latitude) {
  // Stand-in ramp until imagery/material layers exist: lowland green, upland brown, snow.
  vec3 lowland = vec3(0.09, 0.14, 0.05);
  vec3 upland = vec3(0.22, 0.17, 0.11);
  vec3 snow = vec3(0.80, 0.82, 0.86);
  vec3 c = mix(lowland, upland, smoothstep(200.0, 1800.0, elevation));
  float snowLine = mix(5000.0, 0.0, smoothstep(0.6, 1.2, abs(latitude)));
  return mix(c, snow, smoothstep(snowLine - 300.0, snowLine + 300.0, elevation));
}

// Smith's masking term for a Gaussian slope distribution of total mean-square slope sigma2
// (Eq. 5 of Bruneton 2010 with sigma_phi^2 = sigma2 / 2), erfc by a rational approximation.
float smithLambda(float cosTheta, float sigma2) {
  float c = clamp(cosTheta, 1e-4, 0.9999);
  float a = c / (sqrt(sigma2 * (1.0 - c * c)));  // 1 / (sqrt(2 sigma_phi^2) tan(theta))
  float erfcA = 2.0 * exp(-a * a) / (2.319 * a + sqrt(4.0 + 1.52 * a * a));
  return max(0.0, (exp(-a * a) - a * sqrt(PI) * erfcA) / (2.0 * a * sqrt(PI)));
}

vec3 shade(vec3 dir, float t) {
  vec3 n = ellipsoidNormal(dir, t);
  vec2 latLon = latLonOfNormal(n);
  float h = elevationAt(latLon);
  float muS = dot(n, uSunDir);
  float lit = max(muS, 0.0);
  if (h > 0.0) return landAlbedo(h, latLon.x) / PI * lit;
  // Sea: dark diffuse body plus the Sun's glint through an isotropic Ross/Smith BRDF of
  // fixed roughness (Cox-Munk mean-square slope at ~7 m/s). The ocean issue replaces this with
  // the wind-driven, filtered Bruneton 2010 model.
  const float sigma2 = 0.04;
  vec3 v = -dir;
  vec3 hv = normalize(v + uSunDir);
  float nh = max(dot(n, hv), 1e-4), nv = max(dot(n, v), 1e-4);
  float tan2 = (1.0 - nh * nh) / (nh * nh);
  float p = exp(-tan2 / sigma2) / (PI * sigma2);  // slope pdf, isotropic
  float fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(v, hv), 0.0), 5.0);
  float shadowing = 1.0 + smithLambda(nv, sigma2) + smithLambda(muS, sigma2);
  float glint = muS > 0.0 ? fresnel * p / (4.0 * nh * nh * nh * nh * nv * shadowing) : 0.0;
  return vec3(0.004, 0.016, 0.035) * lit + vec3(glint);  // glint already holds cos(theta_l)
}

void main() {
  // 4 rotated-grid samples per pixel: an anti-aliased limb and coastline.
  const vec2 offsets[4] = vec2[4](vec2(-0.125, -0.375), vec2(0.375, -0.125),
                                  vec2(0.125, 0.375), vec2(-0.375, 0.125));
  vec3 radiance = vec3(0.0);
  float coverage = 0.0;
  float nearestT = 1e30;
  for (int i = 0; i < 4; ++i) {
    vec2 ndc = vNdc + offsets[i] * uPixelNdc;
    vec3 dir = normalize(uForward + ndc.x * uTanHalfFov.x * uRight + ndc.y * uTanHalfFov.y * uUp);
    float t = intersectEllipsoid(dir);
    if (t < 0.0) continue;
    radiance += shade(dir, t);
    coverage += 1.0;
    nearestT = min(nearestT, t * dot(dir, uForward));
  }
  fragRadiance = vec4(radiance * 0.25, coverage * 0.25);
  gl_FragDepth = coverage > 0.0 ? clamp(uNear / nearestT, 0.0, 1.0) : 0.0;
}
