#version 450 core
// The sky maps' radial sums (render/SkyRadialSums, read by atmosphere/skymap.glsl with
// SKY_RADIAL_SUMS): a layer of uSkyMap (a Sun zenith's, or the frame layer, the last:
// atmosphere/skymap_frame.comp) in polar coordinates of the stereographic map, x the azimuth
// (uSums' width over a turn, counter-clockwise from the map's +x, where the Sun lies), y the
// radius rho in [0, SKY_RADIAL_MAX_RHO]. Texel (i, j) holds the sky's integral along the radius
// from the zenith to its centre,
//   C(rho, phi) = integral_0^rho (S(r, phi) - B) dr,
// S the layer's radiance, B its value below the horizon (its corner texel; constant there: C
// is constant beyond the horizon's band, so no radius past the table is ever missed). The mip
// levels (GL's for the frame layer, skymap_radial_mip.comp's for the Sun layers) are C of the
// sky blurred over their texels (a box commutes with the integral), so the average of the sky along any radial stretch at a level
// of detail is two lookups, (C(rho2) - C(rho1)) / (rho2 - rho1) + B: the sea's reflected
// footprints are ellipses stretched radially (a slope along the view's azimuth tilts the mirror
// ray in elevation, one across it turns its azimuth by only ~2 slope x its elevation), so one
// radial stretch at the level of the footprint's width filters the ellipse, however long, where
// the paper's §7.3 averages up to nine lookups along it (Bruneton, Neyret & Holzschuch 2010).
// One invocation a column of a layer (z: the layers from uFirstLayer on): the integral is a
// running sum along it, each stretch between two texels' centres by its midpoint (the texels'
// common edge; from the zenith to the first centre, half a texel by its own midpoint).
layout(local_size_x = 64) in;
#include "atmosphere/skymap_common.glsl"
layout(binding = OG_UNIT_SKY_MAP) uniform sampler2DArray uSkyMap;
#ifdef SKY_RADIAL_FRAME  // the frame layer's sums: a texture of their own
layout(binding = 0, rgba32f) writeonly uniform image2D uSums;  // level 0
#else
layout(binding = 0, rgba32f) writeonly uniform image2DArray uSums;  // level 0, the same layers
#endif
uniform int uFirstLayer;

void main() {
  ivec2 size = imageSize(uSums).xy;
  int column = int(gl_GlobalInvocationID.x);
  if (column >= size.x) return;
  int layer = uFirstLayer + int(gl_GlobalInvocationID.z);
  vec3 below = texelFetch(uSkyMap, ivec3(0, 0, layer), 0).rgb;  // far below the horizon
  float phi = (float(column) + 0.5) / float(size.x) * 6.28318530717959;
  vec2 dir = vec2(cos(phi), sin(phi));
  float scale = 0.5 / SKYMAP_EXTENT;  // u -> texture coordinates (atmosphere/skymap.glsl)
  float step = SKY_RADIAL_MAX_RHO / float(size.y);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < size.y; ++j) {
    float rho = j == 0 ? 0.25 * step : float(j) * step;  // the stretch's midpoint
    vec2 tc = dir * rho * scale + 0.5;
    sum += (textureLod(uSkyMap, vec3(tc, float(layer)), 0.0).rgb - below) * (j == 0 ? 0.5 * step : step);
#ifdef SKY_RADIAL_FRAME
    imageStore(uSums, ivec2(column, j), vec4(sum, 0.0));
#else
    imageStore(uSums, ivec3(column, j, layer), vec4(sum, 0.0));
#endif
  }
}
