// The deferred sea's surface buffer (render/OceanRenderer's drawDeferred): what the projected
// grid's vertices hand the sea's shading, written once per pixel by ocean/sea_surface.frag
// (the grid's nearest fragment) and read by ocean/ocean.frag compiled with OCEAN_DEFERRED, a
// full-screen pass per sea class. llvmpipe shades every 4 x 2-pixel block a triangle touches,
// so the grid's ~8-pixel cells shaded their pixels about twice over (docs/performance.md):
// drawn through this buffer the costly shading runs once per pixel.
// Layers of an RGBA32UI array texture, floats by their bits, smooth terms as half floats:
//   0: camera-relative position (ECEF axes, m), pixel footprint (m)
//   1: undisplaced position in the ocean frame (m), the vertices' mean slope
//   2: the vertices' slope covariance, Jacobian statistic x
//   3: Jacobian statistic y, floor depth (m), the floor's depth gradient in the triangle
//   4: halves: the vertices' pattern shares 0-4, aerial transmittance
//   5: halves: aerial in-scatter, the water's Sun and sky irradiance (3 + 2 channels)
//   6: halves: the sky irradiance's third channel, the fine-floor flag; the pixel's class where
//      the driver cannot export stencil values (SEA_CLASS_IN_SURFACE; 0: no sea)
// SEA_SURFACE_COMPACT (a frame without the water volume, the class in the stencil: render/
// OceanRenderer::surfaceCompact): layers 0-4 only, layer 3 holding the Jacobian statistic y and
// the aerial in-scatter as halves instead of the floor's values; each layer written and read
// costs llvmpipe about as much as a texture lookup per pixel.
// Needs (included first): ocean/patterns.glsl (PATTERN_COUNT).
const int SEA_SURFACE_LAYERS = 7;
#if PATTERN_COUNT != 5
#error "layer 4 holds five pattern shares"
#endif

uint seaHalves(float a, float b) { return packHalf2x16(vec2(a, b)); }

// Gradient of the floor's depth (m per m of the ocean frame's x and y) in the pixel's grid
// triangle, where the vertices' depths are interpolated linearly: from the screen derivatives
// of the depth and of the position (taken while the pixel's quad is whole). 0 where the
// triangle is seen edge-on.
vec2 floorDepthSlope(vec2 oceanXY, float depthM) {
  mat2 toScreen = mat2(dFdx(oceanXY), dFdy(oceanXY));  // columns: the position per pixel in x, in y
  float det = determinant(toScreen);
  vec2 perPixel = vec2(dFdx(depthM), dFdy(depthM));
  return abs(det) > 1e-12 * max(dot(toScreen[0], toScreen[0]) + dot(toScreen[1], toScreen[1]), 1e-30)
             ? perPixel * inverse(toScreen) : vec2(0.0);
}

// The values the sea's shading reads where the grid's vertices do not exist in its pass, with
// their neutral values where the program has no such varyings.
#ifdef OCEAN_SIMPLE_SKY
#define SEA_AERIAL_T vec3(1.0)
#define SEA_AERIAL_S vec3(0.0)
#else
#define SEA_AERIAL_T vTransmittance
#define SEA_AERIAL_S vInscatter
#endif
#if defined(OCEAN_NO_WATER_VOLUME)
#define SEA_FLOOR_DEPTH 1e4
#define SEA_FLOOR_FINE 0.0
#else
#define SEA_FLOOR_DEPTH vFloorDepthM
#define SEA_FLOOR_FINE vFloorFine
#endif
#if defined(OCEAN_NO_WATER_VOLUME) || defined(OCEAN_SIMPLE_SKY)
#define SEA_WATER_SUN vec3(0.0)
#define SEA_WATER_SKY vec3(0.0)
#else
#define SEA_WATER_SUN vWaterSunE
#define SEA_WATER_SKY vWaterSkyE
#endif

#ifdef SEA_SURFACE_WRITE
layout(location = 0) out uvec4 seaSurface0;
layout(location = 1) out uvec4 seaSurface1;
layout(location = 2) out uvec4 seaSurface2;
layout(location = 3) out uvec4 seaSurface3;
layout(location = 4) out uvec4 seaSurface4;
#ifndef SEA_SURFACE_COMPACT
layout(location = 5) out uvec4 seaSurface5;
layout(location = 6) out uvec4 seaSurface6;
#endif

// Writes the fragment's values: the grid's varyings, its footprint (m), the floor's depth
// gradient in its triangle (floorDepthSlope) and its class (1..5, kept where SEA_CLASS_IN_SURFACE).
void writeSeaSurface(float footprintM, vec2 floorSlope, int seaClass) {
  seaSurface0 = uvec4(floatBitsToUint(vRelative), floatBitsToUint(footprintM));
  seaSurface1 = uvec4(floatBitsToUint(vOceanXY), floatBitsToUint(vPatternMean));
  seaSurface2 = uvec4(floatBitsToUint(vPatternCov), floatBitsToUint(vPatternJacobian.x));
  vec3 t = SEA_AERIAL_T, s = SEA_AERIAL_S, sunE = SEA_WATER_SUN, skyE = SEA_WATER_SKY;
#ifdef SEA_SURFACE_COMPACT
  seaSurface3 = uvec4(floatBitsToUint(vPatternJacobian.y), seaHalves(s.r, s.g), seaHalves(s.b, 0.0), 0u);
#else
  seaSurface3 = uvec4(floatBitsToUint(vec2(vPatternJacobian.y, SEA_FLOOR_DEPTH)), floatBitsToUint(floorSlope));
#endif
  seaSurface4 = uvec4(seaHalves(vPatternShare[0], vPatternShare[1]), seaHalves(vPatternShare[2], vPatternShare[3]),
                      seaHalves(vPatternShare[4], t.r), seaHalves(t.g, t.b));
#ifndef SEA_SURFACE_COMPACT
  seaSurface5 = uvec4(seaHalves(s.r, s.g), seaHalves(s.b, sunE.r), seaHalves(sunE.g, sunE.b), seaHalves(skyE.r, skyE.g));
  seaSurface6 = uvec4(seaHalves(skyE.b, SEA_FLOOR_FINE), uint(seaClass), 0u, 0u);
#endif
}
#elif defined(OCEAN_DEFERRED)
layout(binding = OG_UNIT_SEA_SURFACE) uniform usampler2DArray uSeaSurface;

// Reads the pixel's values into the globals the forward pass has as varyings (ocean/ocean.frag
// declares them with SEA_IN empty): returns the footprint (m) and the floor's depth gradient.
void readSeaSurface(out float footprintM, out vec2 floorSlope) {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uvec4 s0 = texelFetch(uSeaSurface, ivec3(p, 0), 0), s1 = texelFetch(uSeaSurface, ivec3(p, 1), 0);
  uvec4 s2 = texelFetch(uSeaSurface, ivec3(p, 2), 0), s3 = texelFetch(uSeaSurface, ivec3(p, 3), 0);
  uvec4 s4 = texelFetch(uSeaSurface, ivec3(p, 4), 0);
#ifdef SEA_SURFACE_COMPACT
  // Layer 3's in-scatter where the full layout has layer 5's (its other values unread).
  uvec4 s5 = uvec4(s3.yz, 0u, 0u), s6 = uvec4(0u);
#else
  uvec4 s5 = texelFetch(uSeaSurface, ivec3(p, 5), 0), s6 = texelFetch(uSeaSurface, ivec3(p, 6), 0);
#endif
  vRelative = uintBitsToFloat(s0.xyz);
  footprintM = uintBitsToFloat(s0.w);
  vOceanXY = uintBitsToFloat(s1.xy);
  vPatternMean = uintBitsToFloat(s1.zw);
  vPatternCov = uintBitsToFloat(s2.xyz);
  vPatternJacobian = uintBitsToFloat(uvec2(s2.w, s3.x));
  floorSlope = uintBitsToFloat(s3.zw);
  vec2 a = unpackHalf2x16(s4.x), b = unpackHalf2x16(s4.y), c = unpackHalf2x16(s4.z), d = unpackHalf2x16(s4.w);
  vPatternShare = float[PATTERN_COUNT](a.x, a.y, b.x, b.y, c.x);
  vec2 e = unpackHalf2x16(s5.x), f = unpackHalf2x16(s5.y), g = unpackHalf2x16(s5.z), h = unpackHalf2x16(s5.w);
  vec2 i = unpackHalf2x16(s6.x);
#ifndef OCEAN_SIMPLE_SKY
  vTransmittance = vec3(c.y, d);
  vInscatter = vec3(e, f.x);
#endif
#ifndef OCEAN_NO_WATER_VOLUME
  vFloorDepthM = uintBitsToFloat(s3.y);
  vFloorFine = i.y;
#ifndef OCEAN_SIMPLE_SKY
  vWaterSunE = vec3(f.y, g);
  vWaterSkyE = vec3(h, i.x);
#endif
#endif
}
#endif
