// The deferred sea's visibility buffer (OCEANGLOBE_SEA_SURFACE=visibility, the default on
// software renderers: render/OceanRenderer::drawDeferred): the surface pass writes only each
// pixel's nearest grid triangle (ocean/sea_visibility.frag: gl_PrimitiveID + 1, 0 where no
// sea), and the shading (a full-screen pass per class, or compute shaders) interpolates that
// triangle's three vertex records (ocean/grid_vertex_buffer.glsl) at the pixel's centre
// itself, perspective-correct as the rasteriser does the surface pass's inputs: the surface
// pass's fragments interpolate nothing and write 4 bytes instead of 64, the shading reads 21-30
// vec4s a pixel instead of 4-6 (on llvmpipe sea-4m's surface pass 37 -> 12 ms of one thread,
// its shading unchanged; for GPUs whose pixel shaders are few, the H200's run on 2 of its 66
// TPCs: docs/performance.md, "Thirty-fifth session"). Where the frame has one class, or, in a
// frame in classes, for its deep triangles (no land near, no floor in reach: their own
// classes, OceanRenderer::kVisibilityClass); never with the coast test (the surface pass's).
// SEA_VISIBILITY_MULTISAMPLE (compute shaders only): a triangle a sample (a multisampled
// frame), each pixel shaded once from its first sample with sea into a single-sampled image,
// then written to those samples (ocean/sea_radiance_copy.frag, the stencil's class per sample)
// as a forward draw's fragment is written to the samples its triangle covers.
// Needs (included first): ocean/sea_surface.glsl's deferred part (uSeaSurface, SEA_SURFACE_SIZE,
// seaRayDirection, SEA_CLASS_BITS, floorDepthSlopeOf) and ocean/ocean.frag's globals.
#include "ocean/grid_vertex_buffer.glsl"  // (uGridVertexTexels, unpackGridVertex)
// The grid's index list as a buffer texture, as its vertex records (ocean/grid_vertex_buffer.glsl):
// llvmpipe loads a storage buffer's values lane by lane where the pixels' addresses differ, a
// texel fetch for all lanes at once (sea-4m's shading at 1280 x 720: 139 -> 106 ms of one
// thread; docs/performance.md, "Thirty-fifth session").
layout(binding = OG_UNIT_SEA_GRID_INDICES) uniform usamplerBuffer uGridIndexTexels;

// Triangle `triangle`'s corner `k`'s record.
void gridCornerRecord(uint triangle, int k, out vec4 r[GRID_VERTEX_VEC4S]) {
  int at = int(texelFetch(uGridIndexTexels, int(3u * triangle) + k).r) * GRID_VERTEX_VEC4S;
  for (int i = 0; i < GRID_VERTEX_VEC4S; ++i) r[i] = texelFetch(uGridVertexTexels, at + i);
}

// The weights (summing to 1) of the clip-space corners c[0..2] whose weighted point projects to
// the normalised device position `ndc`: the perspective-correct barycentrics a rasteriser
// interpolates a fragment's inputs with (beyond the triangle: its plane extended).
vec3 clipBarycentrics(vec4 c[3], vec2 ndc) {
  vec3 w = vec3(c[0].w, c[1].w, c[2].w);
  vec3 b = cross(vec3(c[0].x, c[1].x, c[2].x) - ndc.x * w, vec3(c[0].y, c[1].y, c[2].y) - ndc.y * w);
  return b / (b.x + b.y + b.z);
}

// The pixel's triangle + 1 (its first sample's with sea, multisampled); 0 where it has no sea.
uint seaVisibilityAt(ivec2 pixel) {
#ifdef SEA_VISIBILITY_MULTISAMPLE
  uint triangle = 0u;
  for (int s = textureSamples(uSeaSurface) - 1; s >= 0; --s) {
    uint t = texelFetch(uSeaSurface, pixel, s).r;
    if (t != 0u) triangle = t;
  }
  return triangle;
#else
  return texelFetch(uSeaSurface, pixel, 0).r;
#endif
}

// The normalised device position of pixel `pixel`'s centre in a frame of `size` pixels.
vec2 pixelNdc(ivec2 pixel, vec2 size) { return (vec2(pixel) + 0.5) / size * 2.0 - 1.0; }

// The pixel's values from its triangle into the globals the forward pass has as varyings, as
// the surface buffer's readSeaSurface gives them: returns the footprint (m) and the floor's
// depth gradient. Only for pixels with a triangle (the class test: seaClassAt, the stencil).
void readSeaSurface(out float footprintM, out vec2 floorSlope) {
  ivec2 p = SEA_PIXEL;  // (ocean/ocean.frag)
  uint triangle = seaVisibilityAt(p) - 1u;
  vec4 r0[GRID_VERTEX_VEC4S], r1[GRID_VERTEX_VEC4S], r2[GRID_VERTEX_VEC4S];
  gridCornerRecord(triangle, 0, r0);
  gridCornerRecord(triangle, 1, r1);
  gridCornerRecord(triangle, 2, r2);
  vec2 size = vec2(SEA_SURFACE_SIZE);
  vec4 corners[3] = vec4[3](r0[0], r1[0], r2[0]);
  vec3 b = clipBarycentrics(corners, pixelNdc(p, size));
  vec4 r[GRID_VERTEX_VEC4S];
  for (int k = 0; k < GRID_VERTEX_VEC4S; ++k) r[k] = b.x * r0[k] + b.y * r1[k] + b.z * r2[k];
  unpackGridVertex(r);
  vRelative = length(vRelative) * seaRayDirection(p);  // on the pixel's ray, as the surface buffer gives it
  // The position's change to the next pixel in x and in y within the pixel's 2 x 2 quad, the
  // triangle's plane extended over it as a fragment quad's helpers extend it (llvmpipe's dFdx,
  // dFdy: the quad's row and column differences).
  ivec2 q = p & ~1;
  vec3 dbx = clipBarycentrics(corners, pixelNdc(ivec2(q.x + 1, p.y), size)) -
             clipBarycentrics(corners, pixelNdc(ivec2(q.x, p.y), size));
  vec3 dby = clipBarycentrics(corners, pixelNdc(ivec2(p.x, q.y + 1), size)) -
             clipBarycentrics(corners, pixelNdc(ivec2(p.x, q.y), size));
  mat3x2 xy = mat3x2(vec2(r0[1].w, r0[2].x), vec2(r1[1].w, r1[2].x), vec2(r2[1].w, r2[2].x));
  vec2 xyPerX = xy * dbx, xyPerY = xy * dby;
  // The class's bits dropped as the surface buffer drops them, so both paths shade alike.
  footprintM = uintBitsToFloat(floatBitsToUint(max(length(xyPerX), length(xyPerY))) & ~SEA_CLASS_BITS);
#ifndef OCEAN_NO_WATER_VOLUME
  vec3 depthM = vec3(r0[6].w, r1[6].w, r2[6].w);  // (vFloorDepthM's place in the record)
  floorSlope = floorDepthSlopeOf(mat2(xyPerX, xyPerY), vec2(dot(depthM, dbx), dot(depthM, dby)));
#else
  floorSlope = vec2(0.0);
#endif
}
