// The projected grid's vertices computed once per frame by a compute pass
// (ocean/grid_vertices.comp) and read back (ocean/grid_cached.vert) by the deferred sea's surface
// pass (render/OceanRenderer's drawDeferred) and by the forward draw whose pixels take the
// vertices' radiance terms (OCEAN_RADIANCE_TERMS, in a buffer of their own): llvmpipe runs a
// draw's vertex shader on one thread, compute work groups on every core (docs/performance.md,
// "Eighth session"). Each vertex takes GRID_VERTEX_VEC4S vec4s, what ocean/sea_surface.frag
// reads of ocean/grid_vertex.glsl's outputs (the per-wind bands the deferred shading looks up
// per pixel are not kept); one layout for every program variant, the outputs a variant lacks
// left out.
// Needs (included first): ocean/grid_vertex.glsl with GRID_OUT empty (compute) or out (vertex).
#if PATTERN_COUNT != 5
#error "grid_vertex_buffer.glsl packs 5 patterns' shares"
#endif
const int GRID_VERTEX_VEC4S = 10;  // render/OceanRenderer::kGridVertexVec4s
// The compute pass writes the buffers, the passes after it read them.
#ifdef GRID_VERTEX_STORE
#define GRID_BUFFER_ACCESS writeonly
#else
#define GRID_BUFFER_ACCESS readonly
#endif
// Written as storage buffers, read as buffer textures (OceanRenderer::computeGridVertices binds
// them: gl::kUnitSeaGridVertices, kUnitSeaGridTerms): llvmpipe loads a storage buffer's values
// lane by lane where the lanes' addresses differ, a texel fetch for all lanes at once
// (docs/performance.md, "Thirty-fifth session").
#ifdef GRID_VERTEX_STORE
layout(std430, binding = 4) writeonly buffer GridVertices { vec4 gridVertices[]; };  // kGridVerticesBinding
#else
layout(binding = OG_UNIT_SEA_GRID_VERTICES) uniform samplerBuffer uGridVertexTexels;
#endif
#ifdef OCEAN_RADIANCE_TERMS
// The vertices' radiance terms (vRadianceTerms, SEA_RADIANCE_VEC4S each), for the forward draw of
// large cells (render/OceanRenderer::draw, computeGridVertices).
#ifdef GRID_VERTEX_STORE
// Binding 7 as grid_near_land.comp's NearLandIndices (GL 4.5 guarantees bindings 0-7; each pass
// binds its own buffer there).
layout(std430, binding = 7) writeonly buffer GridRadianceTerms { vec4 gridRadianceTerms[]; };  // kGridRadianceTermsBinding
#else
layout(binding = OG_UNIT_SEA_GRID_TERMS) uniform samplerBuffer uGridRadianceTermsTexels;
#endif
#endif
#ifdef OCEAN_SEA_CLASSIFY
// Each vertex's vNearLand > 0 (bit 0) and its floor within the water's reach (bit 1) again,
// 4 bytes a vertex, for ocean/grid_near_land.comp: its
// three reads a triangle from the vertices' 160-byte records were ~30 ns a triangle on
// llvmpipe (binding 2 as render/globe_pixels.glsl's: each pass binds its own buffer there).
layout(std430, binding = 2) GRID_BUFFER_ACCESS buffer GridNearLand { uint gridNearLand[]; };  // kGridNearLandBinding
#endif

#if defined(GRID_VERTEX_STORE) && defined(OCEAN_SEA_CLASSIFY) && !defined(OCEAN_NO_WATER_VOLUME)
uniform float uWaterReachM;  // as ocean/sea_class.glsl's (OceanRenderer::setClassUniforms)
#endif
#ifdef GRID_VERTEX_STORE
// After gridVertex(i): its outputs (globals here) into the buffer.
void storeGridVertex(int i, vec4 position) {
  int at = i * GRID_VERTEX_VEC4S;
  gridVertices[at] = position;
  gridVertices[at + 1] = vec4(vRelative, vOceanXY.x);
  gridVertices[at + 2] = vec4(vOceanXY.y, vPatternMean, vPatternJacobian.x);
  gridVertices[at + 3] = vec4(vPatternJacobian.y, vPatternCov);
  gridVertices[at + 4] = vec4(vPatternShare[0], vPatternShare[1], vPatternShare[2], vPatternShare[3]);
  vec3 transmittance = vec3(0.0), inscatter = vec3(0.0), sunE = vec3(0.0), skyE = vec3(0.0);
  float floorDepthM = 0.0, floorFine = 0.0, nearLand = 0.0, nearShadow = 0.0, gridRow = 0.0;
#ifndef OCEAN_SIMPLE_SKY
  transmittance = vTransmittance;
  inscatter = vInscatter;
#endif
#ifndef OCEAN_NO_WATER_VOLUME
  floorDepthM = vFloorDepthM;
  floorFine = vFloorFine;
#ifndef OCEAN_SIMPLE_SKY
  sunE = vWaterSunE;
  skyE = vWaterSkyE;
#endif
#endif
#ifdef OCEAN_SEA_CLASSIFY
  nearLand = vNearLand;
  nearShadow = vNearShadow;
  gridRow = float(vGridRow);
  uint flags = vNearLand > 0.0 ? 1u : 0u;
#ifndef OCEAN_NO_WATER_VOLUME
  if (vFloorDepthM <= uWaterReachM) flags |= 2u;  // (ocean/sea_class.glsl's floor test)
#endif
  gridNearLand[i] = flags;
#endif
  gridVertices[at + 5] = vec4(vPatternShare[4], transmittance);
  gridVertices[at + 6] = vec4(inscatter, floorDepthM);
  gridVertices[at + 7] = vec4(floorFine, sunE);
  gridVertices[at + 8] = vec4(skyE, nearLand);
  gridVertices[at + 9] = vec4(nearShadow, gridRow, 0.0, 0.0);
#ifdef OCEAN_RADIANCE_TERMS
  for (int k = 0; k < SEA_RADIANCE_VEC4S; ++k) gridRadianceTerms[i * SEA_RADIANCE_VEC4S + k] = vRadianceTerms[k];
#endif
}
#else
// A vertex's record (its GRID_VERTEX_VEC4S vec4s, or three vertices' weighted sum: the
// visibility buffer's pixels, ocean/sea_visibility.glsl) into the outputs it holds, its
// position (record[0]) aside. The flat ones (OCEAN_SEA_CLASSIFY) are whole vertices' only.
void unpackGridVertex(vec4 r[GRID_VERTEX_VEC4S]) {
  vRelative = r[1].xyz;
  vOceanXY = vec2(r[1].w, r[2].x);
  vPatternMean = r[2].yz;
  vPatternJacobian = vec2(r[2].w, r[3].x);
  vPatternCov = r[3].yzw;
  vPatternShare = float[PATTERN_COUNT](r[4].x, r[4].y, r[4].z, r[4].w, r[5].x);
#ifndef OCEAN_SIMPLE_SKY
  vTransmittance = r[5].yzw;
  vInscatter = r[6].xyz;
#endif
#ifndef OCEAN_NO_WATER_VOLUME
  vFloorDepthM = r[6].w;
  vFloorFine = r[7].x;
#ifndef OCEAN_SIMPLE_SKY
  vWaterSunE = r[7].yzw;
  vWaterSkyE = r[8].xyz;
#endif
#endif
#ifdef OCEAN_SEA_CLASSIFY
  vNearLand = r[8].w;
  vNearShadow = r[9].x;
  vGridRow = int(r[9].y);
#endif
}

// Vertex i's record.
void gridVertexRecord(int i, out vec4 r[GRID_VERTEX_VEC4S]) {
  for (int k = 0; k < GRID_VERTEX_VEC4S; ++k) r[k] = texelFetch(uGridVertexTexels, i * GRID_VERTEX_VEC4S + k);
}

// Vertex i's outputs from the buffer; returns its clip-space position.
vec4 loadGridVertex(int i) {
  vec4 r[GRID_VERTEX_VEC4S];
  gridVertexRecord(i, r);
  unpackGridVertex(r);
#ifdef OCEAN_RADIANCE_TERMS
  for (int k = 0; k < SEA_RADIANCE_VEC4S; ++k) vRadianceTerms[k] = texelFetch(uGridRadianceTermsTexels, i * SEA_RADIANCE_VEC4S + k);
#endif
  return r[0];
}
#ifdef OCEAN_SEA_CLASSIFY
// Whether vertex i's vNearLand > 0, and its floor is within the water's reach
// (ocean/grid_near_land.comp).
bool gridVertexNearLand(int i) { return (gridNearLand[i] & 1u) != 0u; }
bool gridVertexFloor(int i) { return (gridNearLand[i] & 2u) != 0u; }
#endif
#endif
