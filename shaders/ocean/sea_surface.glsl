// The deferred sea's surface buffer (render/OceanRenderer's drawDeferred): what the projected
// grid's vertices hand the sea's shading, written once per pixel by ocean/sea_surface.frag
// (the grid's nearest fragment) and read by ocean/ocean.frag compiled with OCEAN_DEFERRED, a
// full-screen pass per sea class. llvmpipe shades every 4 x 2-pixel block a triangle touches,
// so the grid's ~8-pixel cells shaded their pixels about twice over (docs/performance.md):
// drawn through this buffer the costly shading runs once per pixel.
// Layers of an RGBA32UI array texture, floats by their bits, smooth terms as half floats:
//   0: distance to the eye along the pixel's ray (m), pixel footprint (m; its lowest
//      SEA_CLASS_BITS bits the pixel's class where the driver cannot export stencil values,
//      SEA_CLASS_IN_SURFACE, 0 where no sea was drawn; dropped from the footprint everywhere, so
//      both paths shade alike), undisplaced position in the ocean frame (m)
//   1: the vertices' mean slope, their slope covariance's xx and yy
//   2: the Jacobian statistics; halves: the covariance's xy, the aerial in-scatter
//   3: halves: the vertices' pattern shares 0-4, the aerial transmittance
//   4: floor depth (m), the floor's depth gradient in the triangle; halves: the water's Sun
//      irradiance (red, green)
//   5: halves: the water's Sun irradiance (blue) and sky irradiance, the fine-floor flag
// The position is not stored: the interpolated point of the grid's triangle at the pixel's
// centre lies on the pixel's ray, so its distance along the ray gives it back (seaRayDirection).
// SEA_SURFACE_COMPACT (a frame without the water volume: render/OceanRenderer::surfaceCompact):
// layers 0-3 only; each layer written and read costs llvmpipe about as much as a texture lookup
// per pixel (and a GPU's few raster units 16 bytes a pixel).
// Needs (included first): ocean/patterns.glsl (PATTERN_COUNT).
const int SEA_SURFACE_LAYERS = 6;
#if PATTERN_COUNT != 5
#error "layer 3 holds five pattern shares"
#endif

uint seaHalves(float a, float b) { return packHalf2x16(vec2(a, b)); }
// The class's bits in layer 0's footprint (ocean/sea_class_stencil.frag reads them too): three
// bits of its mantissa, 1e-6 of its value.
const uint SEA_CLASS_BITS = uint(OG_SEA_CLASS_BITS);

// Gradient of the floor's depth (m per m of the ocean frame's x and y) in the pixel's grid
// triangle, where the vertices' depths are interpolated linearly: from the change per pixel of
// the position (`toScreen`'s columns: in x, in y) and of the depth (`perPixel`). 0 where the
// triangle is seen edge-on.
vec2 floorDepthSlopeOf(mat2 toScreen, vec2 perPixel) {
  float det = determinant(toScreen);
  return abs(det) > 1e-12 * max(dot(toScreen[0], toScreen[0]) + dot(toScreen[1], toScreen[1]), 1e-30)
             ? perPixel * inverse(toScreen) : vec2(0.0);
}
#ifndef OCEAN_COMPUTE  // (screen derivatives: the grid's fragments)
// The same from the screen derivatives (taken while the pixel's quad is whole).
vec2 floorDepthSlope(vec2 oceanXY, float depthM) {
  return floorDepthSlopeOf(mat2(dFdx(oceanXY), dFdy(oceanXY)), vec2(dFdx(depthM), dFdy(depthM)));
}
#endif

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
#ifndef SEA_SURFACE_COMPACT
layout(location = 4) out uvec4 seaSurface4;
layout(location = 5) out uvec4 seaSurface5;
#endif

// Writes the fragment's values: the grid's varyings, its footprint (m), the floor's depth
// gradient in its triangle (floorDepthSlope) and its class (1..5, kept where SEA_CLASS_IN_SURFACE).
void writeSeaSurface(float footprintM, vec2 floorSlope, int seaClass) {
  vec3 t = SEA_AERIAL_T, s = SEA_AERIAL_S;
  uint footprintBits = floatBitsToUint(footprintM) & ~SEA_CLASS_BITS;
#ifdef SEA_CLASS_IN_SURFACE
  footprintBits |= uint(seaClass);
#endif
  seaSurface0 = uvec4(floatBitsToUint(length(vRelative)), footprintBits, floatBitsToUint(vOceanXY));
  seaSurface1 = uvec4(floatBitsToUint(vPatternMean), floatBitsToUint(vPatternCov.xy));
  seaSurface2 = uvec4(floatBitsToUint(vPatternJacobian), seaHalves(vPatternCov.z, s.r), seaHalves(s.g, s.b));
  seaSurface3 = uvec4(seaHalves(vPatternShare[0], vPatternShare[1]), seaHalves(vPatternShare[2], vPatternShare[3]),
                      seaHalves(vPatternShare[4], t.r), seaHalves(t.g, t.b));
#ifndef SEA_SURFACE_COMPACT
  vec3 sunE = SEA_WATER_SUN, skyE = SEA_WATER_SKY;
  seaSurface4 = uvec4(floatBitsToUint(SEA_FLOOR_DEPTH), floatBitsToUint(floorSlope), seaHalves(sunE.r, sunE.g));
  seaSurface5 = uvec4(seaHalves(sunE.b, skyE.r), seaHalves(skyE.g, skyE.b), seaHalves(SEA_FLOOR_FINE, 0.0), 0u);
#endif
}
#elif defined(OCEAN_DEFERRED)
#if defined(SEA_VISIBILITY_MULTISAMPLE)  // the visibility buffer, a triangle a sample
layout(binding = OG_UNIT_SEA_SURFACE) uniform usampler2DMS uSeaSurface;
#define SEA_SURFACE_SIZE textureSize(uSeaSurface)
#elif defined(SEA_VISIBILITY)  // the visibility buffer
layout(binding = OG_UNIT_SEA_SURFACE) uniform usampler2D uSeaSurface;
#define SEA_SURFACE_SIZE textureSize(uSeaSurface, 0)
#else
layout(binding = OG_UNIT_SEA_SURFACE) uniform usampler2DArray uSeaSurface;
#define SEA_SURFACE_SIZE textureSize(uSeaSurface, 0).xy
#endif
#include "geo/camera_ray.glsl"

// The unit ray through the pixel's centre, ECEF axes (geo::CameraView::rayDirection).
vec3 seaRayDirection(ivec2 pixel) {
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(SEA_SURFACE_SIZE) * 2.0 - 1.0;
  return cameraRay(ndc);
}

#ifdef SEA_VISIBILITY
#include "ocean/sea_visibility.glsl"  // readSeaSurface from the pixel's triangle
#else
// Reads the pixel's values into the globals the forward pass has as varyings (ocean/ocean.frag
// declares them with SEA_IN empty): returns the footprint (m) and the floor's depth gradient.
void readSeaSurface(out float footprintM, out vec2 floorSlope) {
  ivec2 p = SEA_PIXEL;  // (ocean/ocean.frag)
  uvec4 s0 = texelFetch(uSeaSurface, ivec3(p, 0), 0), s1 = texelFetch(uSeaSurface, ivec3(p, 1), 0);
  uvec4 s2 = texelFetch(uSeaSurface, ivec3(p, 2), 0), s3 = texelFetch(uSeaSurface, ivec3(p, 3), 0);
  vRelative = uintBitsToFloat(s0.x) * seaRayDirection(p);
  footprintM = uintBitsToFloat(s0.y & ~SEA_CLASS_BITS);
  vOceanXY = uintBitsToFloat(s0.zw);
  vPatternMean = uintBitsToFloat(s1.xy);
  vec2 covXyS = unpackHalf2x16(s2.z), s2w = unpackHalf2x16(s2.w);
  vPatternCov = vec3(uintBitsToFloat(s1.zw), covXyS.x);
  vPatternJacobian = uintBitsToFloat(s2.xy);
  vec2 a = unpackHalf2x16(s3.x), b = unpackHalf2x16(s3.y), c = unpackHalf2x16(s3.z), d = unpackHalf2x16(s3.w);
  vPatternShare = float[PATTERN_COUNT](a.x, a.y, b.x, b.y, c.x);
#ifndef OCEAN_SIMPLE_SKY
  vTransmittance = vec3(c.y, d);
  vInscatter = vec3(covXyS.y, s2w);
#endif
#ifndef OCEAN_NO_WATER_VOLUME
  uvec4 s4 = texelFetch(uSeaSurface, ivec3(p, 4), 0), s5 = texelFetch(uSeaSurface, ivec3(p, 5), 0);
  vFloorDepthM = uintBitsToFloat(s4.x);
  floorSlope = uintBitsToFloat(s4.yz);
  vec2 e = unpackHalf2x16(s4.w), f = unpackHalf2x16(s5.x), g = unpackHalf2x16(s5.y);
  vFloorFine = unpackHalf2x16(s5.z).x;
#ifndef OCEAN_SIMPLE_SKY
  vWaterSunE = vec3(e, f.x);
  vWaterSkyE = vec3(f.y, g);
#endif
#else
  floorSlope = vec2(0.0);
#endif
}
#endif
#endif
