// A terrain tile's vertex buffer read as storage (terrain::TileVertex, 13 floats a vertex:
// position, normal, height, latitude, longitude, detail amplitude, morph) and the place of a
// vertex in the tile's grid. terrain/tile_aerial.comp reads the vertices the eye may see;
// the terrain's fragments drawn from a coarser mesh (TERRAIN_COARSE: every 2nd vertex,
// render/TerrainRenderer::tileStrideIndex) read the full grid's normal, height, detail
// amplitude and aerial perspective where the full grid's triangles would have put them.
layout(std430, binding = OG_TILE_VERTICES_BINDING) readonly buffer TileVertices { float tileVertices[]; };

const int TILE_GRID_SIDE = OG_TILE_QUADS + 1;  // vertices along a grid row
// A tile's vertices with its skirts' (terrain::kTileVertices).
const int TILE_VERTEX_COUNT = TILE_GRID_SIDE * TILE_GRID_SIDE + 4 * TILE_GRID_SIDE;

// terrain::TileVertex in floats: its size, and where its position, normal, info (height,
// latitude, longitude, detail amplitude) and morph start.
const int TILE_VERTEX_FLOATS = 13;
const int TILE_VERTEX_POSITION = 0, TILE_VERTEX_NORMAL = 3, TILE_VERTEX_INFO = 6, TILE_VERTEX_MORPH = 10;

vec3 tileVertexVec3(int vertex, int field) {
  int at = TILE_VERTEX_FLOATS * vertex + field;
  return vec3(tileVertices[at], tileVertices[at + 1], tileVertices[at + 2]);
}
vec4 tileVertexInfo(int vertex) {
  int at = TILE_VERTEX_FLOATS * vertex + TILE_VERTEX_INFO;
  return vec4(tileVertices[at], tileVertices[at + 1], tileVertices[at + 2], tileVertices[at + 3]);
}

// Grid column and row (0..OG_TILE_QUADS) of vertex `index` (terrain/Tile.cpp's order: the grid
// row by row from the south-west, then the skirts' lowered copies of the south, east, north and
// west edges), and 1 for a skirt's lowered vertex, 0 for the grid's.
vec3 tileGridPlace(int index) {
  const int n = TILE_GRID_SIDE;
  if (index < n * n) return vec3(float(index % n), float(index / n), 0.0);
  int edge = (index - n * n) / n, s = (index - n * n) % n;
  ivec2 g = edge == 0 ? ivec2(s, 0) : edge == 1 ? ivec2(n - 1, s) : edge == 2 ? ivec2(s, n - 1) : ivec2(0, s);
  return vec3(vec2(g), 1.0);
}

// The full grid's triangle at grid place g (column, row; fractional), as terrain::tileIndices
// splits its quads: a, b, d below the diagonal from (i, j) to (i + 1, j + 1), a, d, c above it
// (there `b` is c, with the axes swapped). A value interpolated over it as the rasteriser
// would: value(a) + w.x (value(b) - value(a)) + w.y (value(d) - value(b)).
struct TileGridTriangle {
  int a, b, d;
  vec2 w;
};
TileGridTriangle tileGridTriangle(vec2 g) {
  const int n = TILE_GRID_SIDE;
  g = clamp(g, vec2(0.0), vec2(float(OG_TILE_QUADS)));
  vec2 c = min(floor(g), vec2(float(OG_TILE_QUADS - 1)));
  vec2 f = g - c;
  bool below = f.x >= f.y;
  TileGridTriangle t;
  t.a = int(c.y) * n + int(c.x);
  t.b = below ? t.a + 1 : t.a + n;
  t.d = t.a + n + 1;
  t.w = below ? f : f.yx;
  return t;
}

uniform float uSkirtDepthM;  // the tile's skirts' depth, m (terrain::Tile::skirtDepthM)

// The full grid's normal (xyz, not normalised), height (w, m) and detail amplitude (m) over
// triangle t, at `skirt` of the way down a skirt (the place's z: 0 on the grid, 1 at a skirt's
// lowered edge; the height lowered by that much of the skirts' depth).
struct TileGridSample {
  vec4 normalHeight;
  float detailAmplitudeM;
};
TileGridSample tileGridSample(TileGridTriangle t, float skirt) {
  vec4 infoA = tileVertexInfo(t.a), infoB = tileVertexInfo(t.b), infoD = tileVertexInfo(t.d);
  vec4 nhA = vec4(tileVertexVec3(t.a, TILE_VERTEX_NORMAL), infoA.x);
  vec4 nhB = vec4(tileVertexVec3(t.b, TILE_VERTEX_NORMAL), infoB.x);
  vec4 nhD = vec4(tileVertexVec3(t.d, TILE_VERTEX_NORMAL), infoD.x);
  TileGridSample s;
  s.normalHeight = nhA + t.w.x * (nhB - nhA) + t.w.y * (nhD - nhB);
  s.normalHeight.w -= skirt * uSkirtDepthM;
  s.detailAmplitudeM = 0.0;
#ifndef TERRAIN_NO_DETAIL
  s.detailAmplitudeM = infoA.w + t.w.x * (infoB.w - infoA.w) + t.w.y * (infoD.w - infoB.w);
#endif
  return s;
}

#ifdef TERRAIN_AERIAL_BUFFER
// The full grid's aerial perspective over triangle t, from the tile aerial buffer
// (terrain/tile_aerial.glsl, included first).
void tileGridAerial(TileGridTriangle t, out vec3 transmittance, out vec3 inscatter) {
  int a = tileAerialSlot(t.a), b = tileAerialSlot(t.b), d = tileAerialSlot(t.d);
  vec3 tA = tileAerial[a].rgb, tB = tileAerial[b].rgb, tD = tileAerial[d].rgb;
  vec3 iA = tileAerial[a + 1].rgb, iB = tileAerial[b + 1].rgb, iD = tileAerial[d + 1].rgb;
  transmittance = tA + t.w.x * (tB - tA) + t.w.y * (tD - tB);
  inscatter = iA + t.w.x * (iB - iA) + t.w.y * (iD - iB);
}
#endif
