#version 450 core
// The classic real-time ocean of Isidoro, Vlachos & Brennan (ShaderX, seed 002), our baseline:
// four sine waves move the vertices along the normal; the same projected grid as the filtered
// model carries them (the original used a flat mesh), so the two differ only in their shading
// model and filtering.
#include "common/types.glsl"
#include "geo/ellipsoid.glsl"

uniform ivec2 uGridSize;
uniform vec4 uGridMarginNdc;
#include "geo/camera_ray.glsl"
uniform mat4 uViewProjection;
uniform mat3 uEcefToOcean;
uniform float uEyeHeight;
uniform vec2 uFieldOffset;   // wave-field position of the ocean frame's origin (mod the tile), m
uniform float uTime;         // s

out vec2 vOceanXY;
out vec3 vRelative;
out vec2 vSlope;             // d(height)/d(x, y) of the four sines

// Four waves: direction * spatial frequency (cycles per metre), height (m), speed (cycles/s),
// phase offset (cycles). The paper's defaults, scaled to metres with a 40 m texture unit.
const vec2 CLASSIC_DIR[4] = vec2[4](vec2(0.25, 0.0), vec2(0.0, 0.15), vec2(-0.7, -0.7), vec2(-0.8, 0.1));
const vec4 CLASSIC_HEIGHT = vec4(0.32, 0.40, 0.02, 0.02);
const vec4 CLASSIC_SPEED = vec4(0.2, 0.15, 0.4, 0.4);
const vec4 CLASSIC_OFFSET = vec4(0.0, 0.2, 0.0, 0.0);
const float CLASSIC_TEXEL_M = 40.0;

void main() {
  int ix = gl_VertexID % uGridSize.x;
  int iy = gl_VertexID / uGridSize.x;
  vec2 lo = -1.0 - uGridMarginNdc.xz, hi = 1.0 + uGridMarginNdc.yw;
  vec2 ndc = mix(lo, hi, vec2(ix, iy) / vec2(uGridSize - 1));
  vec3 dir = cameraRay(ndc);
  float t = intersectEllipsoid(dir);
  vec3 up = transpose(uEcefToOcean)[2];
  if (t < 0.0) {
    float dip = acos(clamp(WGS84_A / (WGS84_A + uEyeHeight), 0.0, 1.0)) + 1e-5;
    vec3 horizontal = normalize(dir - dot(dir, up) * up);
    dir = normalize(horizontal * cos(dip) - up * sin(dip));
    t = intersectEllipsoid(dir);
    if (t < 0.0) t = sqrt(uEyeHeight * (2.0 * WGS84_A + uEyeHeight));
  }
  vec3 rel = t * dir;
  vec3 local = uEcefToOcean * rel + vec3(0.0, 0.0, uEyeHeight);
  vec2 uv = (local.xy + uFieldOffset) / CLASSIC_TEXEL_M;
  float height = 0.0;
  vec2 slope = vec2(0.0);
  for (int i = 0; i < 4; ++i) {
    float phase = 6.2831853 * (dot(CLASSIC_DIR[i], uv) + CLASSIC_SPEED[i] * uTime + CLASSIC_OFFSET[i]);
    height += CLASSIC_HEIGHT[i] * sin(phase);
    slope += CLASSIC_HEIGHT[i] * cos(phase) * 6.2831853 * CLASSIC_DIR[i] / CLASSIC_TEXEL_M;
  }
  vRelative = rel + up * height;
  vOceanXY = local.xy;
  vSlope = slope;
  gl_Position = uViewProjection * vec4(vRelative, 1.0);
}
