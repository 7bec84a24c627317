#include "render/TerrainRenderer.hpp"

#include <algorithm>
#include <limits>
#include <numbers>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstddef>

#include "core/Error.hpp"
#include "geo/Sun.hpp"
#include "geo/Wgs84.hpp"
#include "gl/ShaderContract.hpp"
#include "ocean/WaterOptics.hpp"

namespace og::render {

TerrainRenderer::TerrainRenderer(std::shared_ptr<const data::LatLonGrid> elevation, const Atmosphere* atmosphere)
    : atmosphere_(atmosphere),
      cache_(std::make_shared<const terrain::Heightfield>(std::move(elevation))),
      vao_(gl::createVertexArray()),
      indices_(gl::createBuffer()) {
  // Sea floor beyond the water volume's reach is never seen (GlobeRenderer::drawOcean's test).
  const double waterReachM = ocean::waterMaxPathM(ocean::jerlovWater(ocean::kDefaultWater).attenuationPerM,
                                                  ocean::kWaterEpsilon);
  params_.unseenFloorDepthM = 2.0 * waterReachM;
  // The water volume looks the floor's shadow up where the refracted Sun ray to a seen floor
  // point left the surface (ocean/water_volume.glsl's floorSunVisibility): off the view rays by
  // the refracted view ray's run (at most the water's reach) and the Sun ray's back up (at most
  // 1.13 of it, the critical angle's tangent): the shadow maps' crops take that in.
  floorShadowReachM_ = 2.13 * waterReachM;
  // Every stride's mesh, one after another.
  static_assert(terrain::kTileQuads == static_cast<int>(gl::kTerrainTileQuads), "terrain/tile_grid.glsl's grid");
  std::vector<std::uint32_t> idx;
  for (std::size_t k = 0; k < strideIndices_.size(); ++k) {
    const auto& strided = terrain::tileIndices(terrain::kTileStrides[k]);
    const int grid = terrain::tileGridIndexCount(terrain::kTileStrides[k]);
    strideIndices_[k] = {static_cast<int>(idx.size()), grid, static_cast<int>(strided.size()) - grid};
    idx.insert(idx.end(), strided.begin(), strided.end());
  }
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)),
                       idx.data(), 0);
  const GLuint vao = vao_.id();
  glVertexArrayElementBuffer(vao, indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glEnableVertexArrayAttrib(vao, 2);
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(terrain::TileVertex, position));
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(terrain::TileVertex, normal));
  glVertexArrayAttribFormat(vao, 2, 4, GL_FLOAT, GL_FALSE, offsetof(terrain::TileVertex, heightM));
  glVertexArrayAttribFormat(vao, 3, 3, GL_FLOAT, GL_FALSE, offsetof(terrain::TileVertex, morph));
  for (GLuint a = 0; a < 4; ++a) glVertexArrayAttribBinding(vao, a, 0);
  gl::checkErrors("TerrainRenderer setup");
}

const gl::Program& TerrainRenderer::variant(unsigned bits) {
  gl::Program& p = variants_[bits];
  if (p.id() == 0) {
    std::vector<std::string> defines;
    if ((bits & kLandOnly) != 0) defines.emplace_back("TERRAIN_LAND_ONLY");
    if ((bits & kNoNight) != 0) defines.emplace_back("TERRAIN_NO_NIGHT");
    if ((bits & kNoDetail) != 0) defines.emplace_back("TERRAIN_NO_DETAIL");
    if ((bits & kCoarse) != 0) defines.emplace_back("TERRAIN_COARSE");
    if ((bits & kShadowsOff) != 0) defines.emplace_back("SHADOWS_OFF");
    if ((bits & kNoImageryLayers) != 0) defines.emplace_back("IMAGERY_NO_LAYERS");
    if ((bits & kCoarseMask) != 0) defines.emplace_back("LANDMASK_COARSE_ONLY");
    if ((bits & kFilteredMask) != 0) defines.emplace_back("LANDMASK_FILTERED_ONLY");
    if ((bits & kPyramid) != 0) defines.emplace_back("LANDMASK_PYRAMID");
    if ((bits & kAerialTable) != 0) defines.emplace_back("TERRAIN_AERIAL_TABLE");
    if ((bits & kAerialBuffer) != 0) defines.emplace_back("TERRAIN_AERIAL_BUFFER");
    if ((bits & kCoverage) != 0) defines.insert(defines.end(), {"TERRAIN_COVERAGE", "TERRAIN_DEPTH_ONLY"});
    if ((bits & kAfterCoverage) != 0) defines.emplace_back("TERRAIN_AFTER_COVERAGE");
    if ((bits & kGlobeLand) != 0) defines.emplace_back("TERRAIN_GLOBE_LAND");
    p = gl::Program({{GL_VERTEX_SHADER, "terrain/terrain.vert"}, {GL_FRAGMENT_SHADER, "terrain/terrain.frag"}},
                    defines);
  }
  return p;
}

std::vector<float> TerrainRenderer::shadowMapDepths(int cascade) const {
  std::vector<float> depths(static_cast<std::size_t>(kShadowMapSize) * kShadowMapSize, 1.0f);
  if (shadowMap_.id() == 0) return depths;
  glGetTextureSubImage(shadowMap_.id(), 0, 0, 0, cascade, kShadowMapSize, kShadowMapSize, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                       static_cast<GLsizei>(depths.size() * sizeof(float)), depths.data());
  gl::checkErrors("TerrainRenderer::shadowMapDepths");
  return depths;
}

void TerrainRenderer::ensureShadowMap() {
  // Made on the first frame that casts shadows: 32 MiB that llvmpipe zeroes, which a view of
  // the open ocean never needs (start-up, docs/performance.md).
  if (shadowMap_.id() != 0) return;
  shadowProgram_ = gl::Program({{GL_VERTEX_SHADER, "terrain/terrain.vert"},
                                {GL_FRAGMENT_SHADER, "terrain/shadow_depth.frag"}},
                               {"TERRAIN_DEPTH_ONLY", "TERRAIN_SHADOW_CASTER"});  // so is its program
  shadowMap_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
  shadowFbo_ = gl::createFramebuffer();
  glTextureStorage3D(shadowMap_.id(), 1, GL_DEPTH_COMPONENT32F, kShadowMapSize, kShadowMapSize,
                     kShadowCascades);
  glTextureParameteri(shadowMap_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(shadowMap_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(shadowMap_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(shadowMap_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(shadowMap_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(shadowMap_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glNamedFramebufferTextureLayer(shadowFbo_.id(), GL_DEPTH_ATTACHMENT, shadowMap_.id(), 0, 0);
  glNamedFramebufferDrawBuffer(shadowFbo_.id(), GL_NONE);
  if (glCheckNamedFramebufferStatus(shadowFbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw InternalError("terrain shadow map framebuffer incomplete");
}

void TerrainRenderer::setTileUniforms(const gl::Program& p, const terrain::Tile& t, const geo::CameraView& view) const {
  const glm::vec4 u = tileUniforms(t, view);
  p.set("uTileOffset", glm::vec3(u));
  p.set("uMorphScale", u.w);
}

glm::vec4 TerrainRenderer::tileUniforms(const terrain::Tile& t, const geo::CameraView& view) const {
  // Camera-relative tile origin in double, then float: never float world coordinates.
  return {glm::vec3(t.centreEcef - view.positionEcef), morphScale(t, view)};
}

float TerrainRenderer::morphScale(const terrain::Tile& t, const geo::CameraView& view) const {
  // Tiles at forced levels never had a parent drawn.
  if (t.key.level <= params_.minLevel) return 0.0f;
  // The parent's spacing (twice the tile's) in pixels at 1 m, over the limit.
  const double spacingPx = terrain::tileSpacingPx(view, params_.heightPx, t, 1.0);
  return static_cast<float>(2.0 * spacingPx / params_.maxSpacingPx);
}

const gl::Buffer& TerrainRenderer::tileBuffer(const terrain::Tile& t) {
  auto [it, fresh] = gpu_.try_emplace(t.key.packed());
  if (fresh) {
    it->second.vertices = gl::createBuffer();
    glNamedBufferStorage(it->second.vertices.id(),
                         static_cast<GLsizeiptr>(t.vertices.size() * sizeof(terrain::TileVertex)),
                         t.vertices.data(), 0);
  }
  return it->second.vertices;
}

void TerrainRenderer::bindTile(const terrain::Tile& t) {
  glVertexArrayVertexBuffer(vao_.id(), 0, tileBuffer(t).id(), 0, sizeof(terrain::TileVertex));
}

void TerrainRenderer::computeTileAerial(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                                        const glm::dvec3& sunDirectionEcef) {
  static_assert(sizeof(terrain::TileVertex) == 13 * sizeof(float) && offsetof(terrain::TileVertex, normal) == 3 * sizeof(float) &&
                    offsetof(terrain::TileVertex, heightM) == 6 * sizeof(float) &&
                    offsetof(terrain::TileVertex, morph) == 10 * sizeof(float),
                "terrain/tile_grid.glsl's TILE_VERTEX_FLOATS and fields");
  static_assert(terrain::kTileVertices == (gl::kTerrainTileQuads + 1) * (gl::kTerrainTileQuads + 5),
                "terrain/tile_grid.glsl's TILE_VERTEX_COUNT");
  gl::Program& p = tileAerialProgram_;
  if (p.id() == 0) p = gl::Program({{GL_COMPUTE_SHADER, "terrain/tile_aerial.comp"}});

  // One dispatch (each costs llvmpipe ~0.2 ms of waiting): the tiles' vertices copied one after
  // another, and each tile's uniforms as a vec4 (tile_aerial.comp).
  constexpr std::size_t kTileBytes = terrain::kTileVertices * sizeof(terrain::TileVertex);
  const auto grow = [](gl::Buffer& buffer, std::size_t& capacity, std::size_t bytes, GLbitfield flags) {
    if (bytes > capacity)  // (by doubling at least)
      gl::ensureBufferCapacity(buffer, capacity, std::max(bytes, 2 * capacity), flags);
  };
  grow(tileAerial_, tileAerialBytes_, tiles.size() * terrain::kTileVertices * 2 * sizeof(glm::vec4), 0);
  grow(tileAerialVertices_, tileAerialVerticesBytes_, tiles.size() * kTileBytes, 0);
  grow(tileAerialTiles_, tileAerialTilesBytes_, tiles.size() * sizeof(glm::vec4), GL_DYNAMIC_STORAGE_BIT);
  std::vector<glm::vec4> perTile(tiles.size());
  tileFirstVertex_.clear();
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const terrain::Tile& t = *tiles[k];
    tileFirstVertex_[&t] = static_cast<int>(k) * terrain::kTileVertices;
    perTile[k] = tileUniforms(t, view);
    glCopyNamedBufferSubData(tileBuffer(t).id(), tileAerialVertices_.id(), 0, static_cast<GLintptr>(k * kTileBytes),
                             static_cast<GLsizeiptr>(kTileBytes));
  }
  glNamedBufferSubData(tileAerialTiles_.id(), 0, static_cast<GLsizeiptr>(perTile.size() * sizeof(glm::vec4)),
                       perTile.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kTerrainAerialBinding, tileAerial_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kTileVerticesBinding, tileAerialVertices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kTileAerialTilesBinding, tileAerialTiles_.id());
  // Only the vertices the eye may see (llvmpipe runs every invocation dispatched in full).
  listTileAerialVertices(view, tiles);
  stats_.aerialVertices = static_cast<int>(tileAerialListed_.size());
  if (tileAerialListed_.empty()) return;
  const std::size_t listBytes = tileAerialListed_.size() * sizeof(std::int32_t);
  grow(tileAerialList_, tileAerialListBytes_, listBytes, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferSubData(tileAerialList_.id(), 0, static_cast<GLsizeiptr>(listBytes), tileAerialListed_.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kTileAerialListBinding, tileAerialList_.id());
  setAerialUniforms(p, view, sunDirectionEcef);
  p.set("uListed", static_cast<int>(tileAerialListed_.size()));
  p.use();
  // Rows of at most 65 535 work groups (GL's least limit on a dimension), each of 64 vertices.
  const std::size_t groups = (tileAerialListed_.size() + 63) / 64, perRow = std::min<std::size_t>(groups, 65535);
  glDispatchCompute(static_cast<GLuint>(perRow), static_cast<GLuint>((groups + perRow - 1) / perRow), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void TerrainRenderer::listTileAerialVertices(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles) {
  // A point P the eye E sees: the segment between them misses the ellipsoid, so also the ball of
  // radius b within it, and the angle between them at the centre is at most
  // acos(b / |E|) + acos(b / |P|), with |P| at most a + the tile's highest point.
  const double a = geo::kWgs84SemiMajorM, b = geo::kWgs84SemiMinorM;
  const double eyeR = glm::length(view.positionEcef);
  const glm::dvec3 eyeDir = view.positionEcef / eyeR;
  const double eyeCap = std::acos(std::clamp(b / eyeR, -1.0, 1.0));
  tileAerialListed_.clear();
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const terrain::Tile& t = *tiles[k];
    // A seen fragment reads the vertices of its triangle of the full grid, within a cell's
    // diagonal of it (two of a coarser mesh's cells): a grid cell spans at most pi / (2^level
    // kTileQuads) of latitude and of arc along a parallel.
    const double cellRad = std::numbers::pi / (static_cast<double>(1 << t.key.level) * terrain::kTileQuads);
    const double reach = eyeCap + std::acos(b / (a + std::max(t.maxHeightM, 0.0))) + 2.0 * std::numbers::sqrt2 * cellRad;
    const double cosReach = std::cos(std::min(reach, std::numbers::pi));
    const int first = static_cast<int>(k) * terrain::kTileVertices;
    const int n = std::min(terrain::kTileVertices, static_cast<int>(t.positions.size()));
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 p = t.centreEcef + t.positions[static_cast<std::size_t>(i)];
      if (glm::dot(eyeDir, p) >= cosReach * glm::length(p)) tileAerialListed_.push_back(first + i);
    }
  }
}

namespace {
// The index buffer's offset of its `first` index, as glDrawElements takes it.
const void* indexOffset(int first) {
  return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * sizeof(std::uint32_t));
}

// The highest vertex of `t` (m above sea level) over `rect` of a shadow map (xy
// camera-relative along lx, ly), widened by two of its cells so that the triangles reaching in
// count: what the tile casts into that map (the sea's classes bound its shadows' reach by it,
// render/OceanRenderer::shadowReachM). Coarse tiles' bounding spheres overlap the rectangle
// while their heights (a far island's peaks) lie outside it.
double maxHeightOverRect(const terrain::Tile& t, const glm::dvec3& eyeEcef, const glm::dvec3& lx,
                         const glm::dvec3& ly, const LightRect& rect) {
  const glm::dvec3 c = t.centreEcef - eyeEcef;
  const glm::dvec2 lo = rect.lo - 2.0 * t.spacingM, hi = rect.hi + 2.0 * t.spacingM;
  double most = -1e30;
  for (std::size_t k = 0; k < t.positions.size() && k < t.vertices.size(); ++k) {
    const glm::dvec3 p = c + t.positions[k];
    const glm::dvec2 xy(glm::dot(p, lx), glm::dot(p, ly));
    if (xy.x >= lo.x && xy.x <= hi.x && xy.y >= lo.y && xy.y <= hi.y)
      most = std::max(most, static_cast<double>(t.vertices[k].heightM));
  }
  return most;
}
}  // namespace

namespace {
// A cascade's square in the light's frame (x, y along lx, ly, camera-relative): over the tiles
// within `reach` of the eye, clamped to +-reach; a 2 m box when none is.
struct ShadowBox {
  glm::dvec2 mid;
  double half;
};
ShadowBox shadowBox(const std::vector<const terrain::Tile*>& tiles, const glm::dvec3& eyeEcef, const glm::dvec3& lx,
                    const glm::dvec3& ly, double reach) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const terrain::Tile* t : tiles) {
    const glm::dvec3 c = t->boundCentreEcef - eyeEcef;
    const double r = t->boundRadiusM;
    if (glm::length(c) - r > reach) continue;
    const glm::dvec2 xy(glm::dot(c, lx), glm::dot(c, ly));
    lo = glm::min(lo, xy - r);
    hi = glm::max(hi, xy + r);
  }
  lo = glm::max(lo, glm::dvec2(-reach));
  hi = glm::min(hi, glm::dvec2(reach));
  if (!(hi.x > lo.x && hi.y > lo.y)) {  // nothing near: an empty box far below
    lo = glm::dvec2(-1.0);
    hi = glm::dvec2(1.0);
  }
  // Square texels: the larger extent sets the scale.
  return {0.5 * (lo + hi), 0.5 * std::max(hi.x - lo.x, hi.y - lo.y)};
}
}  // namespace

int TerrainRenderer::shadowCascadeTexels(const geo::CameraView& view, const std::vector<const terrain::Tile*>& casting,
                                         double half, double nearestServedM, const glm::dvec3& sunDirectionEcef) const {
  const double sinSun = glm::dot(sunDirectionEcef, view.enu.up);
  if (!shadowTexelsFitted_ || casting.empty() || sinSun < 0.05) return kShadowMapSize;  // low Sun: long shadows
  const double tanSun = sinSun / std::sqrt(1.0 - sinSun * sinSun);
  double nearestCasterM = 1e300, longestShadowM = 0.0;
  for (const terrain::Tile* t : casting) {
    const double distanceM = glm::length(t->boundCentreEcef - view.positionEcef) - t->boundRadiusM;
    nearestCasterM = std::min(nearestCasterM, std::max(distanceM, 0.0));
    longestShadowM = std::max(longestShadowM, std::max(t->maxHeightM, 0.0) / tanSun);
  }
  // The nearest point the cascade can shadow, and the ground a screen pixel spans there, as
  // the map's texels measure it: a texel falls on level ground stretched by 1 / sin(the
  // Sun's elevation) towards the Sun (and its normal offset, 1.5 texels, with it).
  const double nearestM = std::max(nearestServedM, nearestCasterM - longestShadowM);
  const double pixelM = nearestM * 2.0 * std::tan(0.5 * view.verticalFovRad) / params_.heightPx * sinSun;
  int texels = kShadowMapSize;
  while (texels > kShadowMinTexels && 4.0 * half / texels <= pixelM) texels /= 2;
  return texels;
}

void TerrainRenderer::renderShadowMap(const geo::CameraView& view,
                                      const std::vector<const terrain::Tile*>& tiles,
                                      const glm::dvec3& sunDirectionEcef) {
  shadows_.on = false;
  shadows_.casterMaxHeightM = -1e30;
  stats_.shadowTileDraws = stats_.shadowCoarseTileDraws = 0;
  const glm::dvec3 s = glm::normalize(sunDirectionEcef);
  const double h = view.position.heightM;
  // Shadows of relief matter within a few hundred km; from farther out they are sub-pixel.
  // With the Sun below the horizon the terrain gets no direct light to shadow.
  if (h > 1.0e6 || glm::dot(s, view.enu.up) < -0.2 || tiles.empty()) return;
  ensureShadowMap();
  // Cascades: the far one over the receivers within reach of the eye (by height: 30 h,
  // 20..400 km), the near one over an eighth of that, in a frame whose z axis points at the
  // Sun. Camera-relative throughout. The near cascade serves the points well inside its reach.
  const double farReach = std::clamp(30.0 * h, 20000.0, 400000.0);
  shadows_.splitM = static_cast<float>(0.8 * farReach / std::pow(8.0, kShadowCascades - 1));
  const glm::dvec3 helper = std::abs(s.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 lx = glm::normalize(glm::cross(helper, s));
  const glm::dvec3 ly = glm::cross(s, lx);
  // Casters: every tile in view (its depth range along the Sun); receivers: the ground and the
  // sea between the tiles' lowest and highest points.
  double zLo = 1e300, zHi = -1e300, lowM = 0.0, highM = 0.0;
  for (const terrain::Tile* t : tiles) {
    const double z = glm::dot(t->boundCentreEcef - view.positionEcef, s);
    zLo = std::min(zLo, z - t->boundRadiusM);
    zHi = std::max(zHi, z + t->boundRadiusM);
    lowM = std::min(lowM, t->minHeightM);
    highM = std::max(highM, t->maxHeightM);
  }

  GLint previousFbo = 0, viewport[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFbo);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo_.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CLIP_DISTANCE0);  // the ground below sea level (TERRAIN_SHADOW_CASTER)
  glEnable(GL_SCISSOR_TEST);    // the cascades' crops
  shadowProgram_.use();
  glBindVertexArray(vao_.id());
  for (int cascade = 0; cascade < kShadowCascades; ++cascade) {
    const auto [mid, half] =
        shadowBox(tiles, view.positionEcef, lx, ly, farReach / std::pow(8.0, kShadowCascades - 1 - cascade));
    // Camera-relative ECEF -> clip: x, y over the box, depth 0 nearest the Sun (zHi) .. 1 (zLo).
    glm::dmat4 m(1.0);
    for (int col = 0; col < 3; ++col) {
      m[col][0] = lx[col] / half;
      m[col][1] = ly[col] / half;
      m[col][2] = -s[col] / (zHi - zLo);
    }
    m[3][0] = -mid.x / half;
    m[3][1] = -mid.y / half;
    m[3][2] = zHi / (zHi - zLo);
    const double servedFromM = cascade == 0 ? 0.0 : static_cast<double>(shadows_.splitM);
    const int texels = shadowCascadeTexels(view, tilesOver(tiles, view.positionEcef, lx, ly, {mid - half, mid + half}),
                                           half, servedFromM, s);
    // The part of the map over the receivers the cascade serves, on the same texels.
    const double servedToM = cascade == 0 ? static_cast<double>(shadows_.splitM) : 1e9;
    LightRect receivers = shadowCropped_ ? shadowReceiverRect(view, lx, ly, servedFromM, servedToM, lowM - kShadowSlabMarginM,
                                                              highM + kShadowSlabMarginM)
                                         : LightRect{mid - half, mid + half};
    if (!receivers.empty()) {
      receivers.lo -= floorShadowReachM_;
      receivers.hi += floorShadowReachM_;
    }
    const glm::ivec4 crop = shadowCropTexels(receivers, mid, half, texels);
    const double metresPerTexel = 2.0 * half / texels;
    const LightRect drawn{mid - half + glm::dvec2(crop.x, crop.y) * metresPerTexel,
                          mid - half + glm::dvec2(crop.z, crop.w) * metresPerTexel};
    // Only tiles over the part drawn cast into it.
    const std::vector<const terrain::Tile*> casting =
        crop.z > crop.x && crop.w > crop.y ? tilesOver(tiles, view.positionEcef, lx, ly, drawn) : std::vector<const terrain::Tile*>{};
    for (const terrain::Tile* t : casting)
      shadows_.casterMaxHeightM = std::max(shadows_.casterMaxHeightM, maxHeightOverRect(*t, view.positionEcef, lx, ly, drawn));
    const double share = static_cast<double>(texels) / kShadowMapSize;  // of the map's side
    glm::dmat4 toTexture(1.0);  // clip x, y in [-1, 1] -> uv in [0, share]
    toTexture[0][0] = toTexture[1][1] = toTexture[3][0] = toTexture[3][1] = 0.5 * share;
    const auto k = static_cast<std::size_t>(cascade);
    shadows_.matrices[k] = glm::mat4(toTexture * m);
    shadows_.texelM[k] = static_cast<float>(metresPerTexel);
    // The lookups' bound: the crop less the filter's texel beyond the point (terrain/shadow.glsl).
    shadows_.cropUv[k] = casting.empty() ? glm::vec4(1.0f, 1.0f, 0.0f, 0.0f)
                                         : glm::vec4(glm::vec4(crop) + glm::vec4(1.0f, 1.0f, -1.0f, -1.0f)) /
                                               static_cast<float>(kShadowMapSize);
    drawShadowCascade(view, cascade, glm::mat4(m), casting, texels, crop, metresPerTexel, s);
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CLIP_DISTANCE0);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFbo));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  shadows_.on = true;
}

glm::ivec4 TerrainRenderer::shadowCropTexels(const LightRect& receivers, const glm::dvec2& mid, double half, int texels) {
  if (receivers.empty()) return {0, 0, 0, 0};
  // Texel coordinates of the receivers, and kShadowCropMarginTexels around them: the lookups'
  // offset along the normal (1.5 texels) and their filter's texel beyond it.
  const glm::dvec2 lo = ((receivers.lo - mid) / half + 1.0) * (0.5 * texels) - static_cast<double>(kShadowCropMarginTexels);
  const glm::dvec2 hi = ((receivers.hi - mid) / half + 1.0) * (0.5 * texels) + static_cast<double>(kShadowCropMarginTexels);
  const glm::dvec2 top(texels);
  const glm::ivec2 a(glm::clamp(glm::floor(lo), glm::dvec2(0.0), top)), b(glm::clamp(glm::ceil(hi), glm::dvec2(0.0), top));
  return b.x > a.x && b.y > a.y ? glm::ivec4(a, b) : glm::ivec4(0);
}

std::vector<const terrain::Tile*> TerrainRenderer::tilesOver(const std::vector<const terrain::Tile*>& tiles,
                                                             const glm::dvec3& eyeEcef, const glm::dvec3& lx,
                                                             const glm::dvec3& ly, const LightRect& rect) {
  std::vector<const terrain::Tile*> over;
  for (const terrain::Tile* t : tiles) {
    const glm::dvec3 c = t->boundCentreEcef - eyeEcef;
    const glm::dvec2 xy(glm::dot(c, lx), glm::dot(c, ly));
    const double r = t->boundRadiusM;
    if (xy.x + r < rect.lo.x || xy.x - r > rect.hi.x || xy.y + r < rect.lo.y || xy.y - r > rect.hi.y) continue;
    over.push_back(t);
  }
  return over;
}

void TerrainRenderer::drawShadowCascade(const geo::CameraView& view, int cascade, const glm::mat4& lightClip,
                                        const std::vector<const terrain::Tile*>& casting, int texels,
                                        const glm::ivec4& crop, double texelM, const glm::dvec3& sunDirectionEcef) {
  // A cascade with nothing in it is neither cleared nor drawn: its lookups find every point lit
  // (its crop is empty).
  if (casting.empty()) return;
  glNamedFramebufferTextureLayer(shadowFbo_.id(), GL_DEPTH_ATTACHMENT, shadowMap_.id(), 0, cascade);
  glScissor(crop.x, crop.y, crop.z - crop.x, crop.w - crop.y);
  const float one = 1.0f;
  glClearNamedFramebufferfv(shadowFbo_.id(), GL_DEPTH, 0, &one);
  glViewport(0, 0, texels, texels);
  shadowProgram_.set("uViewProjection", lightClip);
  for (const terrain::Tile* t : casting) {
    setTileUniforms(shadowProgram_, *t, view);
    bindTile(*t);
    const std::size_t k = shadowStride(*t, sunDirectionEcef, texelM);
    const StrideIndices& mesh = strideIndices_[k];
    glDrawElements(GL_TRIANGLES, mesh.grid + mesh.skirts, GL_UNSIGNED_INT, indexOffset(mesh.first));
    ++stats_.shadowTileDraws;
    stats_.shadowCoarseTileDraws += static_cast<int>(k);
  }
}

std::size_t TerrainRenderer::shadowStride(const terrain::Tile& t, const glm::dvec3& sunDirectionEcef, double texelM) const {
  if (!shadowStridesOn_) return 0;
  // The lookups (terrain/shadow.glsl) stand 1.5 texels off the surface along its normal and
  // reach a texel and a half across the rays: over level ground under a Sun e up, a caster
  // may rise by (1.5 - cos e) texels before the surface shades itself. The coarser mesh may
  // take half of that (at the Sun's lowest over the tile), and kShadowStrideTexels at most.
  const double sinSun = glm::dot(t.middleUp, sunDirectionEcef);
  const double lowestSunRad = std::max(std::asin(std::clamp(sinSun, -1.0, 1.0)) - t.upConeRad, 0.0);
  const double allowedTexels = std::min(kShadowStrideTexels, 0.5 * (1.5 - std::cos(lowestSunRad)));
  const terrain::Tile::StrideDeviation& d = t.strideDeviation[0];
  return d.aboveSeaVerticalM + d.aboveSeaHorizontalM <= allowedTexels * texelM ? 1 : 0;
}

void TerrainRenderer::drawWaterTiles(int landClassStencil) {
  if (waterTiles_.empty()) return;
  if (timer_ != nullptr) timer_->mark("terrain");
  landClassStencil_ = landClassStencil;  // (tileBits' kGlobeLand, drawTileGroup's stencil test)
  drawCovered(waterView_, waterTiles_, waterBits_, waterSunDirection_, true);
  landClassStencil_ = 0;
  waterTiles_.clear();
  gl::checkErrors("TerrainRenderer::drawWaterTiles");
}

void TerrainRenderer::drawCovered(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                                  unsigned frameBits, const glm::dvec3& sunDirectionEcef, bool seaFromGlobe) {
  if (tiles.empty()) return;
  // Above the grid's ceiling the globe's depth, drawn before, already fails the sea floor's
  // fragments before the shader over the sea's classes (llvmpipe tests early when nothing but
  // the depth is on; the land's class keeps the far plane, where every tile fragment shades):
  // there the first draw would only add its cost (coast-30km's terrain +7 %, orbit's +17 %).
  // Multisampled, llvmpipe shades a fragment before its depth test anyway (docs/performance.md):
  // the first draw would only add its cost there too.
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (seaFromGlobe || samples > 1 || !coveragePassOn_) {
    drawTiles(view, tiles, frameBits, sunDirectionEcef, seaFromGlobe);
    return;
  }
  // Tiles the sea's horizon may hide are drawn in one pass, after the others: the horizon's clip
  // cuts most of their fragments before any shader (from near the sea, the far coasts beyond the
  // horizon show a strip of a few pixels), so their first draw would cost its vertices and
  // triangles for nothing (the strait from 2 m at 320 x 180: 16 tiles).
  std::vector<const terrain::Tile*> covered, behindHorizon;
  for (const terrain::Tile* t : tiles)
    (coverageBeyondHorizon_ || !seaHorizonMayHide(*t, view) ? covered : behindHorizon).push_back(t);
  if (!covered.empty()) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // (its discards are the coast's: the frame's land-mask variant, as the one-pass draw's)
    drawTiles(view, covered, kCoverage | (frameBits & kLandMaskBits), sunDirectionEcef, seaFromGlobe);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    drawTiles(view, covered, frameBits | kAfterCoverage, sunDirectionEcef, seaFromGlobe, GL_EQUAL);
    glDepthFunc(GL_GREATER);  // as draw() leaves it
    glDepthMask(GL_TRUE);
  }
  drawTiles(view, behindHorizon, frameBits, sunDirectionEcef, seaFromGlobe);
  stats_.onePassBeyondHorizon += static_cast<int>(behindHorizon.size());
}

bool TerrainRenderer::seaHorizonMayHide(const terrain::Tile& t, const geo::CameraView& view) const {
  return seaHorizonClip_ &&
         terrain::seaHorizonMayHide(*seaHorizonClip_, t.boundCentreEcef - view.positionEcef, t.boundRadiusM);
}

void TerrainRenderer::drawTiles(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                                unsigned bits, const glm::dvec3& sunDirectionEcef, bool seaFromGlobe,
                                GLenum depthFunc) {
  // Each tile with its own variant's bits (tileBits), the tiles of a variant together.
  std::vector<std::pair<unsigned, std::vector<const terrain::Tile*>>> groups;
  for (const terrain::Tile* t : tiles) {
    const unsigned tileVariant = bits | tileBits(*t, view, bits, sunDirectionEcef);
    auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == tileVariant; });
    if (group == groups.end()) group = groups.insert(groups.end(), {tileVariant, {}});
    group->second.push_back(t);
  }
  for (const auto& [groupBits, group] : groups)
    drawTileGroup(view, group, groupBits, sunDirectionEcef, seaFromGlobe, depthFunc);
}

void TerrainRenderer::drawTileGroup(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                                    unsigned bits, const glm::dvec3& sunDirectionEcef, bool seaFromGlobe,
                                    GLenum depthFunc) {
  const gl::Program& p = variant(bits);
  setFrameUniforms(p, view, sunDirectionEcef, seaFromGlobe);
  p.set("uFloorClipM", static_cast<float>(floorClip_.clipM));
  p.set("uFloorClipFarM", static_cast<float>(floorClip_.farM));
  const bool clipFloor = floorClip_.clipM > 0.0 && (bits & kLandOnly) == 0;
  if (clipFloor) glEnable(GL_CLIP_DISTANCE0);
  // Set in every frame, a cone that cuts nothing in those without the clip: llvmpipe cut by the
  // distance though GL_CLIP_DISTANCE1 was off, and a former frame's cone took the far coasts
  // away (TerrainRender.NoFormerHorizonClipAfterClimbing; the H200 failed the horizon clip's
  // test at its 4 samples as llvmpipe did before this, not rerun there since).
  const std::optional<terrain::SeaHorizonCone>& cone = seaHorizonClip_;
  p.set("uSeaHorizonAxis", cone ? glm::vec3(cone->axis) : glm::vec3(0.0f, 0.0f, 1.0f));
  p.set("uSeaHorizonCone", cone ? glm::vec3(cone->cosHalfAngle(), cone->sinHalfAngle(), cone->capM())
                                : glm::vec3(0.0f, 0.0f, 1.0e30f));  // (every distance ~1e30)
  glBindTextureUnit(gl::kUnitShadowMap, shadowMap_.id());
  const bool aerialBuffer = (bits & kAerialBuffer) != 0 && (bits & kCoverage) == 0;
  if (aerialBuffer) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kTerrainAerialBinding, tileAerial_.id());
  p.use();
  glBindVertexArray(vao_.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(depthFunc);
  glDepthMask(depthFunc == GL_EQUAL ? GL_FALSE : GL_TRUE);
  const bool overLandClass = (bits & kGlobeLand) != 0;
  if (overLandClass) {  // the globe's land class, whatever the tiles all above the sea set (drawWaterTiles)
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, landClassStencil_, kLandTilesStencilBit - 1);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0);  // (no stencil writes: llvmpipe then tests it before the shader)
  }
  // A heightfield seen from above hides its back faces behind front ones: cull them (the
  // skirts, seen from either side, are drawn without culling). Fragments are not free even
  // when hidden: llvmpipe shades them before the depth test when multisampling.
  glFrontFace(GL_CCW);
  glCullFace(GL_BACK);
  for (const terrain::Tile* t : tiles) {
    // The horizon's clip only for a tile it may cut: an enabled clip distance costs llvmpipe's
    // clipper every triangle (mountain-15km's terrain pass +4 % where it cut none).
    if (seaHorizonMayHide(*t, view))
      glEnable(GL_CLIP_DISTANCE1);
    else
      glDisable(GL_CLIP_DISTANCE1);
    setTileUniforms(p, *t, view);
    p.set("uDetailFirst", t->normalOctaves);
    // Only tiles with water at a vertex look the coast up per pixel (terrain.frag).
    p.set("uTileHasWater", t->minHeightM <= 0.0 ? 1 : 0);
    if (aerialBuffer) p.set("uFirstVertex", tileFirstVertex_.at(t));
    if (imagery_ != nullptr) imagery_->bindTile(p, t->key);
    bindTile(*t);
    const std::size_t stride = (bits & kCoarse) != 0 ? tileStrideIndex(*t, view) : 0;  // into kTileStrides
    if (stride > 0) {  // the full grid's vertices, read by the fragments (terrain/tile_grid.glsl)
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kTileVerticesBinding, tileBuffer(*t).id());
      p.set("uSkirtDepthM", static_cast<float>(t->skirtDepthM));
    }
    if ((bits & kCoverage) == 0) {  // (counted once: drawCovered draws a tile twice)
      stats_.coarseTiles += stride > 0 ? 1 : 0;
      stats_.globeLandTiles += overLandClass ? 1 : 0;
      stats_.dayTiles += (bits & kNoNight) != 0 ? 1 : 0;
    }
    const StrideIndices& mesh = strideIndices_[stride];
    glEnable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, mesh.grid, GL_UNSIGNED_INT, indexOffset(mesh.first));
    glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, mesh.skirts, GL_UNSIGNED_INT, indexOffset(mesh.first + mesh.grid));
  }
  if (clipFloor) glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_CLIP_DISTANCE1);
  if (overLandClass) {
    glStencilMask(0xff);
    glDisable(GL_STENCIL_TEST);
  }
}

std::optional<TerrainRenderer::ScreenScale> TerrainRenderer::tileScreenScale(const terrain::Tile& t,
                                                                            const geo::CameraView& view) const {
  const glm::dvec3 toCentre = t.boundCentreEcef - view.positionEcef;
  const double centreM = glm::length(toCentre);
  if (centreM <= t.boundRadiusM) return std::nullopt;
  // A vertical offset moves a point on screen by its part across the view ray: at most the
  // sine of the largest angle between a vertical on the tile and a ray to a point of it.
  const double toEdge = std::asin(t.boundRadiusM / centreM);
  const double facing = std::acos(std::clamp(-glm::dot(t.middleUp, toCentre) / centreM, -1.0, 1.0));
  const double across = facing + t.upConeRad + toEdge >= 0.5 * std::numbers::pi ? 1.0 : std::sin(facing + t.upConeRad + toEdge);
  // The smallest pixel the tile can reach: the one farthest off the axis its sphere reaches.
  const double offAxisRad = std::acos(std::clamp(glm::dot(toCentre, view.forward) / centreM, -1.0, 1.0)) + toEdge;
  return ScreenScale{across, 1.0 / (geo::smallestPixelAngleRad(view, params_.heightPx, offAxisRad) * (centreM - t.boundRadiusM)),
                     centreM};
}

double TerrainRenderer::reliefShiftPx(const terrain::Tile& t, const std::optional<ScreenScale>& s) {
  if (!s) return std::numeric_limits<double>::infinity();
  // A point of the tile at height h (or depth) lies |h| along its vertical from its foot on the
  // ellipsoid, which the ray through it passes within that much of on screen.
  return std::max({t.maxHeightM, -t.minHeightM, 0.0}) * s->across * s->pixelsPerM;
}

std::size_t TerrainRenderer::tileStrideIndex(const terrain::Tile& t, const geo::CameraView& view) const {
  return coarseThisFrame_ ? tileStrideIndex(t, view, tileScreenScale(t, view)) : 0;
}

std::size_t TerrainRenderer::tileStrideIndex(const terrain::Tile& t, const geo::CameraView& view,
                                             const std::optional<ScreenScale>& s) const {
  if (!coarseThisFrame_ || !s) return 0;
  // terrain/tile_vertex.glsl's morph weight is 0 within half the morph scale of the eye.
  const double morph = morphScale(t, view);
  if (morph > 0.0 && s->centreM + t.boundRadiusM > 0.5 * morph) return 0;
  for (std::size_t k = std::size(terrain::kTileStrides) - 1; k >= 1; --k) {
    const terrain::Tile::StrideDeviation& d = t.strideDeviation[k - 1];
    const double shiftM = d.verticalM * s->across + d.horizontalM;
    if (shiftM * s->pixelsPerM <= kStrideDeviationPx && d.verticalM <= t.skirtDepthM) return k;
  }
  return 0;
}

unsigned TerrainRenderer::tileBits(const terrain::Tile& t, const geo::CameraView& view, unsigned bits,
                                   const glm::dvec3& sunDirectionEcef) const {
  const std::optional<ScreenScale> scale =
      coarseThisFrame_ || landClassStencil_ > 0 ? tileScreenScale(t, view) : std::nullopt;  // (once a tile)
  unsigned own = tileStrideIndex(t, view, scale) > 0 ? kCoarse : 0u;
  if (landClassStencil_ > 0 && reliefShiftPx(t, scale) <= kGlobeLandShiftPx) own |= kGlobeLand;
  if ((bits & (kNoNight | kCoverage)) != 0 || !dayTilesOn_) return own;
  // terrain.frag's night lights are 0 where the Sun is above a point's horizon: leave their
  // lookup out of tiles whose every vertical (within upConeRad of the middle one) has the Sun
  // at least a degree up (llvmpipe runs it for every pixel of a draw that has it: orbit's
  // terrain pass -10 % of one thread with the terminator in view).
  const double sunFromMiddleRad = std::acos(std::clamp(glm::dot(t.middleUp, glm::normalize(sunDirectionEcef)), -1.0, 1.0));
  const bool sunUpOnTile = sunFromMiddleRad + t.upConeRad + std::numbers::pi / 180.0 < 0.5 * std::numbers::pi;
  return own | (sunUpOnTile ? kNoNight : 0u);
}

TerrainRenderer::FloorClip TerrainRenderer::floorClip(const geo::CameraView& view, int heightPx) const {
  if (!floorClipOn_ || view.position.heightM <= 0.0) return {};  // (the eye at or under the sea: its crossing test differs)
  const data::LandMask* mask = cache_.heights().landMask();
  if (mask == nullptr) return {1e9, 1e9};  // terrain.frag discards all of that floor
  // terrain.frag's coast test blends the levels by its footprint, t pixelRad / (0.2 a) at most
  // (terrain/landmask.glsl's coastFootprintRad) for a fragment t away: up to one fine cell the
  // fine level alone decides. The pixel's angle is largest at the frame's centre (10 % of
  // margin for the shader's screen derivatives).
  const bool fine = mask->hasFineLevel() && !coarseMask_;
  const double pixelRad = 1.1 * 2.0 * std::tan(0.5 * view.verticalFovRad) / heightPx;
  const double fineCellRad = mask->cellDeg() / data::LandMask::kFinePerCell * std::numbers::pi / 180.0;
  const double lat = view.position.latitudeDeg, lon = view.position.longitudeDeg;
  double r = 0.0;
  for (double step = 0.5 * kMaxFloorClipM; step >= 16.0; step *= 0.5)
    if (mask->waterAround(lat, lon, r + step, fine)) r += step;
  // Farther than the fine level's reach the coarse level must hold no land either; and no
  // farther than kFloorClipFarM in any case, which bounds the shader's error in its crossing:
  // from the floor point it steps towards the eye (at most its distance) in latitude and
  // longitude over the equatorial radius (up to 0.7 % off the meridian's) and along neither a
  // great circle (off it by the step² tan(latitude) / 2R), and measures across the eye's
  // vertical, not along the ground (2e-5 off at 65 km).
  const double fineReachM = fineCellRad * 0.2 * geo::kWgs84SemiMajorM / pixelRad;
  const double farM = std::min(!fine || mask->waterAround(lat, lon, r, false) ? kFloorClipFarM : fineReachM, kFloorClipFarM);
  const double tanLat = std::tan(std::min(std::abs(lat) + 1.0, 89.0) * std::numbers::pi / 180.0);
  const double marginM = 0.01 * farM + farM * farM * tanLat / (2.0 * 6.3e6) + 20.0;
  return r > marginM ? FloorClip{r - marginM, farM} : FloorClip{};
}

double TerrainRenderer::seaSeenMaxHeightM(const geo::CameraView& view,
                                          const std::vector<const terrain::Tile*>& tiles) const {
  // The sea a pixel or more below its horizon (the mean sea's, from the eye's height): from 2 m
  // at 720p the sea beyond ~1 km lies within a pixel of it, seen at grazing angles, where the
  // floor's light would tint at most that one row; the tile under the eye may hold coasts
  // 10 km away. The mean surface, not a trough: seen that far, a trough hides behind the crest
  // before it (a point z under the mean at distance x shows over a crest z' above it δ nearer
  // only if (eye + z) δ / x > z + z', so for δ of a wavelength and x of a kilometre from metres
  // up, the points seen stand near the crests, less far below the horizon than the mean). Over
  // the sea's horizon first (the ellipsoid seaCrestM_ down, no crest higher), then vertex by
  // vertex, each as the sea's surface over it with its cells around it, in the view's frustum.
  const double eyeM = std::max(view.position.heightM, 0.1);
  const double earthM = geo::kWgs84SemiMajorM;
  const double pixelRad = 2.0 * std::tan(0.5 * view.verticalFovRad) / params_.heightPx;
  const double horizonDipRad = std::sqrt(2.0 * eyeM / earthM);
  const auto seen = [&](const glm::dvec3& centre, double radius) {
    return terrain::aboveHorizon(view.positionEcef, centre, radius, seaCrestM_, seaCrestM_) &&
           terrain::inFrustum(view, params_.widthPx, params_.heightPx, centre, radius);
  };
  const auto belowHorizon = [&](const glm::dvec3& centre, double radius) {
    const double x = std::max(glm::length(centre - view.positionEcef) - radius, 1.0);
    return eyeM / x + 0.5 * x / earthM - horizonDipRad >= pixelRad;  // the mean sea's depression there
  };
  double highest = -1e30;
  for (const terrain::Tile* t : tiles) {
    const double tileTop = t->maxHeightM + 1.5 * t->spacingM;
    if (t->minHeightM > 0.0 || tileTop <= highest || !seen(t->boundCentreEcef, t->boundRadiusM)) continue;
    for (int k = 0; k < terrain::kTileGridVertices; ++k) {
      const terrain::TileVertex& v = t->vertices[static_cast<std::size_t>(k)];
      const double h = static_cast<double>(v.heightM);
      // The floor around the vertex, within its cells, rises at most a 45° slope higher.
      const double around = h + 1.5 * t->spacingM;
      if (around <= highest) continue;
      // The sea's surface over (or beside) the vertex: its point moved to sea level.
      const double lat = static_cast<double>(v.latitudeRad), lon = static_cast<double>(v.longitudeRad);
      const glm::dvec3 up(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
      const glm::dvec3 sea = t->centreEcef + t->positions[static_cast<std::size_t>(k)] - h * up;
      if (belowHorizon(sea, 1.5 * t->spacingM) && seen(sea, 1.5 * t->spacingM)) highest = around;
    }
  }
  return highest;
}

void TerrainRenderer::setAerialUniforms(const gl::Program& p, const geo::CameraView& view,
                                        const glm::dvec3& sunDirectionEcef) const {
  p.set("uSunDir", glm::vec3(glm::normalize(sunDirectionEcef)));
  p.set("uCamUp", glm::vec3(view.enu.up));
  p.set("uCamAltitude", static_cast<float>(view.position.heightM));
  if (atmosphere_ != nullptr) atmosphere_->bind(p);
}

void TerrainRenderer::setFrameUniforms(const gl::Program& p, const geo::CameraView& view,
                                       const glm::dvec3& sunDirectionEcef, bool seaFromGlobe) const {
  p.set("uViewProjection", glm::mat4(view.viewProjection()));
  setAerialUniforms(p, view, sunDirectionEcef);
  p.set("uSeaFromGlobe", seaFromGlobe ? 1 : 0);
  setDetailUniforms(p, view);
  shadows_.apply(p);
  if (imagery_ != nullptr) imagery_->bind(p);
  p.set("uImageryEnabled", imagery_ != nullptr && imagery_->enabled() ? 1 : 0);
}

void SunShadows::apply(const gl::Program& p) const {
  p.set("uShadowOn", on ? 1 : 0);
  if (!on) return;
  glProgramUniformMatrix4fv(p.id(), p.location("uShadowMatrix"), kCascades, GL_FALSE, &matrices[0][0][0]);
  glProgramUniform1fv(p.id(), p.location("uShadowTexelM"), kCascades, texelM.data());
  glProgramUniform4fv(p.id(), p.location("uShadowCropUv"), kCascades, &cropUv[0][0]);
  p.set("uShadowSplitM", splitM);
}

bool TerrainRenderer::detailUnresolved(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles) const {
  const terrain::DetailOctaves& o = cache_.heights().octaves();
  // terrain.frag's footprint: the geodetic normal's change across a pixel, at least the ground
  // it spans over the largest radius of curvature, a² / b.
  const double a = geo::kWgs84SemiMajorM, b = geo::kWgs84SemiMinorM;
  for (const terrain::Tile* t : tiles) {
    // No point of the tile is nearer than its bounding sphere, nor than the eye's height over
    // the tile's highest point (the ellipsoid's nearest point to the eye lies along its normal);
    // none lies farther off the axis than the sphere's edge.
    const glm::dvec3 toTile = t->boundCentreEcef - view.positionEcef;
    const double distanceM = glm::length(toTile);
    const double nearestM = std::max({distanceM - t->boundRadiusM, view.position.heightM - t->maxHeightM, 0.0});
    const double offAxisRad = std::acos(std::clamp(glm::dot(toTile, view.forward) / std::max(distanceM, 1e-9), -1.0, 1.0)) +
                              (distanceM > t->boundRadiusM ? std::asin(t->boundRadiusM / distanceM) : std::numbers::pi);
    const double footprint = nearestM * geo::smallestPixelAngleRad(view, params_.heightPx, offAxisRad) * b / (a * a);
    const double cells = footprint * (a / o.longestM) * std::exp2(t->normalOctaves);  // uDetailScale0 2^first
    if (t->normalOctaves < o.normalCount && cells < kDetailUnresolvedCells) return false;
  }
  return true;
}

bool TerrainRenderer::skipDetail(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles) const {
  return detailSkip_ == DetailSkip::always ||
         (detailSkip_ == DetailSkip::whereUnresolved && detailUnresolved(view, tiles));
}

void TerrainRenderer::setDetailUniforms(const gl::Program& p, const geo::CameraView& view) const {
  // Each octave's lattice coordinate at the eye, split in double into a cell and a position
  // in it: the shader continues from there with small camera-relative offsets.
  const terrain::DetailOctaves& o = cache_.heights().octaves();
  const int count = std::min(o.normalCount, kMaxDetailOctaves);
  std::array<glm::ivec3, kMaxDetailOctaves> cells{};
  std::array<glm::vec3, kMaxDetailOctaves> fracs{};
  for (int k = 0; k < count; ++k) {
    const glm::dvec3 q = terrain::detailLatticePoint(o, k, view.enu.up);
    const glm::dvec3 c = glm::floor(q);
    cells[static_cast<std::size_t>(k)] = glm::ivec3(c);
    fracs[static_cast<std::size_t>(k)] = glm::vec3(q - c);
  }
  glProgramUniform3iv(p.id(), p.location("uDetailCell"), count, &cells[0].x);
  glProgramUniform3fv(p.id(), p.location("uDetailFrac"), count, &fracs[0].x);
  p.set("uDetailCount", count);
  p.set("uDetailNorm", static_cast<float>(o.norm));
  p.set("uDetailScale0", static_cast<float>(geo::kWgs84SemiMajorM / o.longestM));
  // The eye's foot point on the ellipsoid, scaled by diag(1, 1, a²/b²): its length.
  const double ab = geo::kWgs84SemiMajorM / geo::kWgs84SemiMinorM;
  const glm::dvec3 foot = view.positionEcef - view.position.heightM * view.enu.up;
  p.set("uEyeFootScale", static_cast<float>(glm::length(foot * glm::dvec3(1.0, 1.0, ab * ab))));
}

std::vector<const terrain::Tile*> TerrainRenderer::tilesToDraw(const geo::CameraView& view,
                                                               const std::vector<const terrain::Tile*>& tiles) const {
  // The sea's horizon hides far more than the selection's occluder (11.5 km down, inside all
  // bathymetry) from near the sea: from 2 m it is 36 km away against 380, and the coarse tiles
  // of coasts beyond it cost their vertices' aerial perspective and their pixels' coast test
  // for nothing (docs/performance.md, eleventh session).
  const bool seaHorizon = seaHorizonCulling_ && cache_.heights().coastFromMask();
  std::vector<const terrain::Tile*> drawn;
  drawn.reserve(tiles.size());
  for (const terrain::Tile* t : tiles) {
    if (t->coveredBySea()) continue;  // the grid's sea, or the globe's from orbit, hides it
    if (seaHorizon && !terrain::aboveSeaHorizon(view.positionEcef, *t)) continue;
    drawn.push_back(t);
  }
  return drawn;
}

void TerrainRenderer::prepareImagery(const std::vector<const terrain::Tile*>& tiles) {
  std::vector<terrain::TileKey> keys;
  keys.reserve(tiles.size());
  for (const terrain::Tile* t : tiles) keys.push_back(t->key);
  imagery_->prepareTiles(keys, params_.wait);
}

void TerrainRenderer::draw(const geo::CameraView& view, int width, int height,
                           const glm::dvec3& sunDirectionEcef, bool seaFromGlobe) {
  params_.widthPx = width;
  params_.heightPx = height;
  terrain::SelectionStats sel;
  if (timer_ != nullptr) timer_->mark("terrain selection");
  const auto tiles = terrain::selectTiles(cache_, view, params_, &sel);
  for (const std::uint64_t key : cache_.takeEvicted()) gpu_.erase(key);
  const std::vector<const terrain::Tile*> drawn = tilesToDraw(view, tiles);
  if (imagery_ != nullptr) prepareImagery(drawn);

  if (timer_ != nullptr) timer_->mark("terrain shadows");
  // Casters: tiles that reach above the sea. Deep sea-floor tiles shadow nothing seen, so
  // over the open ocean no shadow map is drawn at all.
  std::vector<const terrain::Tile*> casters;
  for (const terrain::Tile* t : tiles)
    if (!t->coveredBySea()) casters.push_back(t);
  renderShadowMap(view, casters, sunDirectionEcef);
  if (timer_ != nullptr) timer_->mark("terrain");
  const unsigned frameBits = prepareFrame(view, tiles, drawn, sunDirectionEcef, seaFromGlobe);
  const auto drawAll = [&] { drawFrameTiles(view, drawn, frameBits, sunDirectionEcef, seaFromGlobe); };
  stats_.samplesPassed = 0;
  if (countSamples_)
    stats_.samplesPassed = gl::queryResult(GL_SAMPLES_PASSED, drawAll);
  else
    drawAll();
  stats_.tiles = static_cast<int>(tiles.size());
  stats_.drawnTiles = static_cast<int>(drawn.size());
  stats_.landTiles = static_cast<int>(casters.size());
  stats_.aerialBufferTiles = (frameBits & kAerialBuffer) != 0 ? static_cast<int>(drawn.size()) : 0;
  if ((frameBits & kAerialBuffer) == 0) stats_.aerialVertices = 0;
  stats_.finestLevel = sel.finestLevel;
  stats_.tilesPending = sel.pending;
  stats_.cpuBytes = cache_.bytes();
  stats_.gpuBytes = gpu_.size() * terrain::kTileVertices * sizeof(terrain::TileVertex);
  gl::checkErrors("TerrainRenderer::draw");
}

unsigned TerrainRenderer::prepareFrame(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                                       const std::vector<const terrain::Tile*>& drawn,
                                       const glm::dvec3& sunDirectionEcef, bool seaFromGlobe) {
  stats_.maxHeightM = tiles.empty() ? 0.0 : -1e30;
  for (const terrain::Tile* t : tiles) stats_.maxHeightM = std::max(stats_.maxHeightM, t->maxHeightM);
  // (Above the ceiling the globe draws the sea: no water volume to decide.)
  stats_.seaSeenMaxHeightM = seaFromGlobe   ? -1e30
                             : seaSightTest_ ? seaSeenMaxHeightM(view, tiles)
                                             : stats_.maxHeightM;
  const double highestM = std::max(stats_.maxHeightM, 0.0);  // seen farthest beyond the horizon
  const bool nightInView =
      geo::sunMayBeDownInView(view.enu.up, view.position.heightM, glm::normalize(sunDirectionEcef), highestM);
  const bool imageryLayers = imagery_ != nullptr && imagery_->layerCount() > 0;
  const bool aerialTable =
      aerialTableOn_ && atmosphere_ != nullptr && !drawn.empty() && view.position.heightM < kAerialTableMaxHeightM;
  if (aerialTable) aerialTable_.update(*atmosphere_, view, sunDirectionEcef);
  // The exact path per vertex is ten lookups into the 4D tables: on every core instead (the
  // table's three lookups cost the compute's dispatches and reads more than they save).
  const bool aerialBuffer = tileAerialBufferOn_ && atmosphere_ != nullptr && !drawn.empty() && !aerialTable;
  const unsigned frameBits = (shadows_.on ? 0u : kShadowsOff) | (nightInView ? 0u : kNoNight) |
                             (imageryLayers ? 0u : kNoImageryLayers) | (coarseMask_ ? kCoarseMask : 0u) |
                             (filteredMask_ ? kFilteredMask : 0u) | (pyramid_ ? kPyramid : 0u) |
                             (aerialTable ? kAerialTable : 0u) | (aerialBuffer ? kAerialBuffer : 0u) |
                             (skipDetail(view, drawn) ? kNoDetail : 0u);
  stats_.pixelDetail = !drawn.empty() && (frameBits & kNoDetail) == 0;
  if (aerialBuffer) computeTileAerial(view, drawn, sunDirectionEcef);
  // (Above the grid's ceiling: no floor clip and no coverage pass, whose clip distances and
  // discards would then come from different heights.)
  coarseThisFrame_ = coarseStridesOn_ && seaFromGlobe && aerialBuffer && !shadows_.on;
  stats_.coarseTiles = 0;
  stats_.globeLandTiles = 0;
  stats_.dayTiles = 0;
  stats_.onePassBeyondHorizon = 0;
  // Single-sampled only: with samples the clip would cut each sample where the discard cuts
  // the pixel (an edge anti-aliased along the -1 m contour: another picture).
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  floorClip_ = seaFromGlobe || samples > 1 ? FloorClip{} : floorClip(view, params_.heightPx);
  // No cone for an eye at or under the sea (a view not made by geo::makeCameraView, which keeps
  // the eye 0.1 m up at least).
  seaHorizonClip_.reset();
  if (seaHorizonClipOn_ && !seaFromGlobe && view.position.heightM > 0.0 && cache_.heights().coastFromMask())
    seaHorizonClip_ = terrain::seaHorizonCone(view, seaCrestM_);
  return frameBits;
}

void TerrainRenderer::drawFrameTiles(const geo::CameraView& view, const std::vector<const terrain::Tile*>& drawn,
                                     unsigned frameBits, const glm::dvec3& sunDirectionEcef, bool seaFromGlobe) {
  waterBits_ = frameBits;
  waterSunDirection_ = sunDirectionEcef;
  waterView_ = view;
  // Tiles all above the sea and away from the poles need none of terrain.frag's discards and
  // coast test (their skirts may hang under the sea, where the grid's surface hides them but
  // for a pixel at the horizon): drawn without them (kLandOnly), since llvmpipe runs the test's
  // lookups even where a uniform turns it off (~13 % of the pass at mountain-15km). Above
  // 20 km they also pass the depth test before the shader with the stencil on (llvmpipe tests
  // late in a shader that may discard) and set kLandTilesStencilBit, so the globe's parts skip
  // what they cover (GlobeRenderer::shadeGlobe); the other tiles then wait for
  // drawWaterTiles(), after the globe, over which they draw (over its land class alone where
  // their relief moves a point by at most kGlobeLandShiftPx; the depth test decides between
  // them and these).
  waterTiles_.clear();
  std::vector<const terrain::Tile*> landTiles, otherTiles;
  for (const terrain::Tile* t : drawn) {
    const int lastRow = (1 << t->key.level) - 1;
    const bool landOnly = t->minHeightM > 0.0 && t->key.y > 0 && t->key.y < lastRow;
    (landOnly ? landTiles : seaFromGlobe ? waterTiles_ : otherTiles).push_back(t);
  }
  if (seaFromGlobe) {  // (only the bit: the tiles with water still read the globe's class under it)
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, kLandTilesStencilBit, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glStencilMask(kLandTilesStencilBit);
  }
  if (!landTiles.empty())  // (the variant is compiled on first use: none over the open sea)
    drawTiles(view, landTiles, (frameBits & ~kLandMaskBits) | kLandOnly, sunDirectionEcef, seaFromGlobe);  // (no mask)
  glStencilMask(0xff);
  glDisable(GL_STENCIL_TEST);
  drawCovered(view, otherTiles, frameBits, sunDirectionEcef, seaFromGlobe);
}

}  // namespace og::render
