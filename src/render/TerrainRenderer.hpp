#pragma once
// The terrain pass: the tiles chosen for the view (terrain/Selection), drawn into the caller's
// HDR target with the reversed-Z depth test after the globe pass and before the ocean, which is
// then depth-tested against it (the shoreline is where sea surface and ground meet). Tiles are
// mirrored on the GPU as one vertex buffer each, dropped when the CPU cache evicts them.
#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "data/LatLonGrid.hpp"
#include "geo/Camera.hpp"
#include "gl/Objects.hpp"
#include "gl/PassTimer.hpp"
#include "gl/Shader.hpp"
#include "render/AerialTable.hpp"
#include "render/Atmosphere.hpp"
#include "render/ImageryTextures.hpp"
#include "render/ShadowReceivers.hpp"
#include "terrain/Selection.hpp"
#include "terrain/TileCache.hpp"

namespace og::render {

/// The terrain's Sun shadow maps of the last frame, for other passes to look up
/// (terrain/shadow.glsl's uniforms; the maps stay bound to gl::kUnitShadowMap).
struct SunShadows {
  static constexpr int kCascades = 2;  // SHADOW_CASCADES in terrain/shadow.glsl
  bool on = false;
  std::array<glm::mat4, kCascades> matrices{};
  std::array<float, kCascades> texelM{};
  /// The part of each cascade's map that its lookups may read, (u0, v0, u1, v1) of the map's
  /// uv: within its first texels (shadowCascadeTexels), over the receivers the screen shows
  /// (shadowReceiverRect); outside it every point is lit. Empty (u1 < u0) when nothing casts.
  std::array<glm::vec4, kCascades> cropUv{};
  float splitM = 0.0f;
  /// The highest point of the tiles drawn into the maps, m above sea level: bounds how far
  /// from land their shadows fall (the sea's classes, render/OceanRenderer).
  double casterMaxHeightM = -1e30;
  /// Sets terrain/shadow.glsl's uniforms on `p`.
  void apply(const gl::Program& p) const;
};

struct TerrainStats {
  int tiles = 0;                ///< selected in the last frame
  int drawnTiles = 0;           ///< of those, drawn (not under the sea nor beyond its horizon)
  int finestLevel = 0;
  std::size_t cpuBytes = 0;     ///< tile cache (CPU), bytes
  std::size_t gpuBytes = 0;     ///< vertex buffers, bytes
  std::size_t tilesPending = 0; ///< being built in the background (selection().wait = false)
  int landTiles = 0;            ///< drawn tiles reaching above the sea (-1 m); 0: open ocean
  /// Drawn tiles whose vertices' aerial perspective the compute pass made (setTileAerialBuffer).
  int aerialBufferTiles = 0;
  /// Of their vertices, those it made: the ones the eye may see (the others' triangles lie
  /// beyond its horizon; TerrainRenderer::computeTileAerial).
  int aerialVertices = 0;
  /// Whether the last frame's tiles were shaded with the detail octaves per pixel (false where
  /// no pixel resolves one: detailUnresolved).
  bool pixelDetail = false;
  /// Drawn tiles drawn from the coarser mesh (every 2nd vertex: tileStrideIndex) in the last frame.
  int coarseTiles = 0;
  /// Tiles with water drawn over the globe's land class alone in the last frame
  /// (drawWaterTiles: kGlobeLand).
  int globeLandTiles = 0;
  /// Drawn tiles shaded without the night lights' lookup in the last frame (the Sun up on all
  /// of each, or in all of the view: tileBits).
  int dayTiles = 0;
  /// Drawn tiles the sea's horizon may hide, drawn in one pass without the coverage pass in the
  /// last frame (drawCovered).
  int onePassBeyondHorizon = 0;
  double maxHeightM = 0.0;      ///< highest point of the selected tiles, m (0 when none)
  /// Samples the last frame's tile draws passed (both draws of a tile drawn twice; above the
  /// grid's ceiling not those drawWaterTiles draws after the globe), with setCountSamples(true);
  /// else 0.
  std::uint64_t samplesPassed = 0;
  /// Below the grid's ceiling, the highest the floor can be (a vertex's height, risen at a 45°
  /// slope over 1.5 vertex spacings) around the vertices of the selected tiles with water over
  /// which the sea's surface can be seen a pixel or more below the horizon, in the frustum (its
  /// crests and troughs setSeaCrestM from sea level), m; -1e30 when none or above the ceiling;
  /// maxHeightM with setSeaSightTest(false): whether the sea's floor may show through it
  /// (render/GlobeRenderer's floorInReach).
  double seaSeenMaxHeightM = -1e30;
  /// Tile draws into the shadow maps' cascades in the last frame, and those of them from the
  /// coarser mesh (every 2nd vertex: TerrainRenderer::setShadowStrides).
  int shadowTileDraws = 0;
  int shadowCoarseTileDraws = 0;
};

class TerrainRenderer {
 public:
  /// Needs a current GL 4.5 context. Shares the elevation layer.
  TerrainRenderer(std::shared_ptr<const data::LatLonGrid> elevation, const Atmosphere* atmosphere);

  /// Draws into the bound framebuffer (width x height) with GL_GREATER depth test and writes
  /// (and leaves them so).
  /// `seaFromGlobe`: the globe pass drew the sea (above the projected grid's ceiling), so
  /// fragments under sea level are left to it.
  void draw(const geo::CameraView& view, int width, int height, const glm::dvec3& sunDirectionEcef,
            bool seaFromGlobe);
  /// With `seaFromGlobe`, draw() draws only the tiles all above the sea (setting
  /// kLandTilesStencilBit where they draw: GlobeRenderer's parts, which test the whole stencil
  /// value, then skip those pixels); this draws the rest of that frame's tiles, after the
  /// globe's parts but its land's (GlobeRenderer's frameLandLast_). Without, draw() drew them
  /// all and this does nothing. `landClassStencil` > 0: the stencil value (in the bits under
  /// kLandTilesStencilBit) of the globe's land class, the pixels whose samples it found all on
  /// land; the tiles whose relief moves on screen by at most kGlobeLandShiftPx
  /// (reliefShiftPx) are drawn only over those, which then decide the coast
  /// (TERRAIN_GLOBE_LAND: no coast test of their own), the others as before.
  void drawWaterTiles(int landClassStencil);
  /// The stencil bit the tiles all above the sea set above the grid's ceiling (draw()): above
  /// the globe's classes' counts (0-6).
  static constexpr int kLandTilesStencilBit = 8;
  /// The most a water tile's relief may move a point on screen off the ellipsoid's point
  /// behind it, whose class the globe found, for the tile to draw over the land's class
  /// alone, pixels.
  static constexpr double kGlobeLandShiftPx = 0.5;

  [[nodiscard]] const TerrainStats& stats() const { return stats_; }

  /// Marks the shadow and tile passes on `timer` while drawing (nullptr: none).
  void setPassTimer(gl::PassTimer* timer) { timer_ = timer; }
  /// The shadow maps drawn by the last draw() (off when there were none).
  [[nodiscard]] const SunShadows& shadows() const { return shadows_; }
  /// The imagery draped as the terrain's albedo (nullptr: the stand-in materials). Not owned.
  void setImagery(ImageryTextures* imagery) { imagery_ = imagery; }
  /// Selection settings; `wait = false` (progressive) never stalls a frame on tile builds.
  terrain::SelectionParams& selection() { return params_; }
  /// Whether tiles wholly beyond the sea's horizon are left undrawn where the land mask decides
  /// the coast (terrain::aboveSeaHorizon; default on). Off: only the deep occluder culls them
  /// (terrain::aboveHorizon), as the selection does: for tests that compare the two.
  void setSeaHorizonCulling(bool on) { seaHorizonCulling_ = on; }
  /// Whether, below the grid's ceiling where the land mask decides the coast, the drawn tiles'
  /// points beyond the sea's horizon at the waves' depth (terrain::seaHorizonCone) are clipped
  /// before any fragment (default on). Off: for tests that compare the two.
  void setSeaHorizonClip(bool on) { seaHorizonClipOn_ = on; }
  /// Whether draw() counts the samples its tile draws pass (TerrainStats::samplesPassed; an
  /// occlusion query that waits for them: for tests).
  void setCountSamples(bool on) { countSamples_ = on; }
  /// Whether a shadow cascade draws only as many texels as the screen resolves at its nearest
  /// receivers (shadowCascadeTexels; the default) or always kShadowMapSize: for tests that
  /// compare the two.
  void setShadowTexelsFitted(bool on) { shadowTexelsFitted_ = on; }
  /// Whether a shadow cascade draws only the part of its map over the receivers the screen
  /// shows in its distances (shadowReceiverRect; the default) or all of it: for tests that
  /// compare the two.
  void setShadowCropped(bool on) { shadowCropped_ = on; }
  /// Whether a tile is drawn into a shadow cascade from every 2nd vertex where that mesh's part
  /// above the sea lies within half a texel of the full grid's, less at a low Sun (shadowStride;
  /// the default), or always from the full grid: for tests that compare the two. Why: the
  /// maps' cost on llvmpipe is their triangles' set-up (sea-2m-horizon, the strait's coasts into
  /// a 2048² cascade: 29 ms of one thread, 13 with every caster from every 2nd vertex), and a
  /// caster's outline moving by under half a texel moves the shadows' edges within the lookups'
  /// own 2 x 2 filter.
  void setShadowStrides(bool on) { shadowStridesOn_ = on; }
  /// Cascade `cascade`'s shadow map as drawn in the last frame: kShadowMapSize² depths in
  /// [0, 1], row-major from its first texel (1 where nothing was drawn; only the frame's crop,
  /// SunShadows::cropUv, was cleared). For tests; waits for the GPU.
  [[nodiscard]] std::vector<float> shadowMapDepths(int cascade) const;
  /// Whether the tiles the sea's horizon may hide get the coverage pass too (drawCovered;
  /// default off: the horizon's clip leaves them few fragments): for tests that compare.
  void setCoverageBeyondHorizon(bool on) { coverageBeyondHorizon_ = on; }
  /// Whether the next frames draw with the programs that leave the land mask's fine level out
  /// (no pixel resolves it: render::LandMaskTexture::fineLevelUnresolved; the globe renderer
  /// sets it each frame).
  void setCoarseLandMask(bool on) { coarseMask_ = on; }
  /// Whether this frame's every pixel weighs only the land fraction's pyramid
  /// (LANDMASK_FILTERED_ONLY: GlobeRenderer sets it with setCoarseLandMask).
  void setFilteredLandMask(bool on) { filteredMask_ = on; }
  /// Whether this frame's programs read the land fraction's pyramid where a pixel spans several
  /// 2′ cells (LANDMASK_PYRAMID: GlobeRenderer sets it where some pixel may).
  void setLandFractionPyramid(bool on) { pyramid_ = on; }
  /// Whether tiles with water draw first their coast's discards alone, then their shading where
  /// those left the depth (drawCovered; on by default), or in one pass (off: the tests' reference).
  void setCoveragePass(bool on) { coveragePassOn_ = on; }
  /// How far this frame's waves reach above and below sea level, m (TerrainStats's
  /// seaSeenMaxHeightM; the globe renderer sets it each frame).
  void setSeaCrestM(double m) { seaCrestM_ = m; }
  /// Whether TerrainStats::seaSeenMaxHeightM keeps only the vertices around which the sea is
  /// seen (the default) or takes every selected tile's highest point (the tests' reference).
  void setSeaSightTest(bool on) { seaSightTest_ = on; }
  /// Below the grid's ceiling, whether the floor deeper than a metre that terrain.frag would
  /// discard is clipped before its fragments where the land mask holds no land around the eye
  /// (floorClip; the default), or every fragment of it is tested (the tests' reference).
  void setFloorClip(bool on) { floorClipOn_ = on; }
  /// The floor a frame clips (setFloorClip, terrain.vert; single-sampled frames): deeper than
  /// a metre, its view ray crossing sea level within clipM (m) across the eye's vertical, and
  /// no farther than farM from the eye. The land mask holds no land within clipM of the eye's
  /// foot (plus a margin for the shader's crossing) at the level that decides terrain.frag's
  /// coast test there: the fine one out to where the pixels' footprints stop resolving it,
  /// both levels beyond, out to kFloorClipFarM. 1e9 for both where no mask decides the coast
  /// (every such fragment is discarded); 0 (none) above the ceiling, with the eye at or
  /// under the sea, and when off.
  struct FloorClip {
    double clipM = 0.0, farM = 0.0;
  };
  [[nodiscard]] FloorClip floorClip(const geo::CameraView& view, int heightPx) const;
  /// The farthest floorClip looks for land.
  static constexpr double kMaxFloorClipM = 65536.0;
  /// The farthest from the eye floorClip clips (FloorClip::farM at most).
  static constexpr double kFloorClipFarM = 60000.0;
  /// Whether the vertices' aerial perspective comes from a table made each frame (three lookups
  /// instead of ten into the 4D tables: llvmpipe shades vertices on one thread) up to
  /// kAerialTableMaxHeightM, or is computed per vertex (the tests' reference).
  void setAerialTable(bool on) { aerialTableOn_ = on; }
  /// Farther out the terminator crosses the view and changes faster across the table's entries
  /// than it resolves (as GlobeRenderer's own table), and the tiles are few: per vertex there.
  static constexpr double kAerialTableMaxHeightM = 5.0e5;
  /// Whether, where no table serves (above kAerialTableMaxHeightM), the vertices' aerial
  /// perspective is computed for the frame's tiles' vertices the eye may see by a compute pass
  /// (terrain/tile_aerial.comp, on every core) and read by the vertex shader from its buffer
  /// (default on), or computed by the vertex shader itself (on llvmpipe's one vertex thread:
  /// orbit's 23 tiles took ~5 ms of it).
  void setTileAerialBuffer(bool on) { tileAerialBufferOn_ = on; }
  /// When the tiles are shaded without the detail octaves' code (TERRAIN_NO_DETAIL; llvmpipe runs
  /// the octaves' loop's first trip for every pixel): where no pixel resolves one
  /// (detailUnresolved; the default), never, or always (for tests: what the detail adds).
  enum class DetailSkip { never, whereUnresolved, always };
  void setDetailSkip(DetailSkip skip) { detailSkip_ = skip; }
  /// Whether tiles are drawn from a coarser mesh (every 2nd vertex) where it lies within
  /// kStrideDeviationPx of the full grid (tileStrideIndex; the default), or always from the full
  /// grid (the tests' reference). Where drawn so, the fragments still take their normal,
  /// height, detail amplitude and aerial perspective from the full grid (TERRAIN_COARSE), so
  /// only the picture's place moves, by under kStrideDeviationPx. Why: llvmpipe shades a
  /// triangle's fragments in blocks of 4 x 4 pixels, and orbit's tiles are quads of 7-10
  /// pixels (docs/performance.md, twenty-first session).
  void setCoarseStrides(bool on) { coarseStridesOn_ = on; }
  /// Whether a tile with the Sun up everywhere on it leaves the night lights' lookup out where
  /// the frame has night elsewhere (tileBits; the default), or only frames all in daylight do
  /// (the tests' reference).
  void setDayTiles(bool on) { dayTilesOn_ = on; }
  /// The farthest on screen a coarser mesh may lie from the full grid, pixels.
  static constexpr double kStrideDeviationPx = 0.5;
  /// Texels per side of each shadow cascade's map (shadowMapDepths).
  static constexpr int kShadowMapSize = 2048;

 private:
  static constexpr int kMaxDetailOctaves = 24;  // MAX_DETAIL_OCTAVES in terrain.frag
  static constexpr int kShadowMinTexels = 256;  // the least a cascade draws (shadowCascadeTexels)
  /// Texels drawn around a cascade's receivers: the lookups' offset along the normal (1.5
  /// texels), their filter's texel beyond it and the rounding.
  static constexpr int kShadowCropMarginTexels = 4;
  /// The most a caster's coarser mesh may lie off the full grid's, above the sea, in texels of
  /// the cascade it is drawn into (shadowStride: less at a low Sun).
  static constexpr double kShadowStrideTexels = 0.5;
  /// Metres added below and above the tiles' heights for the receivers' slab: the sea's waves
  /// and the raised ellipsoids' departure from constant heights.
  static constexpr double kShadowSlabMarginM = 100.0;
  static constexpr int kShadowCascades = SunShadows::kCascades;
  void setDetailUniforms(const gl::Program& p, const geo::CameraView& view) const;
  /// Draws `tiles` with variant(bits) and each tile's own bits on top (tileBits), the frame's
  /// uniforms (setFrameUniforms), the depth test `depthFunc` (GL_GREATER, writing the depth, or
  /// GL_EQUAL, not writing it).
  void drawTiles(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles, unsigned bits,
                 const glm::dvec3& sunDirectionEcef, bool seaFromGlobe, GLenum depthFunc = GL_GREATER);
  /// The frame's state before its tiles are drawn (statistics, the aerial table or buffer,
  /// whether tiles may be coarser, the floor's clip) and its variant bits.
  unsigned prepareFrame(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                        const std::vector<const terrain::Tile*>& drawn, const glm::dvec3& sunDirectionEcef,
                        bool seaFromGlobe);
  /// Draws `drawn`: the tiles all above the sea without the coast test (setting
  /// kLandTilesStencilBit above the ceiling), then the others, or above the ceiling leaves them
  /// to drawWaterTiles.
  void drawFrameTiles(const geo::CameraView& view, const std::vector<const terrain::Tile*>& drawn, unsigned frameBits,
                      const glm::dvec3& sunDirectionEcef, bool seaFromGlobe);
  /// drawTiles' tiles of one variant (`bits`, each tile's own included).
  void drawTileGroup(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles, unsigned bits,
                     const glm::dvec3& sunDirectionEcef, bool seaFromGlobe, GLenum depthFunc);
  /// Tiles whose fragments may be discarded (under the sea, the coast test): below the grid's
  /// ceiling and single-sampled, their depth by the kCoverage program, then their shading by
  /// variant(frameBits | kAfterCoverage) (sea-2m-horizon's terrain pass -18 %; mountain-15km,
  /// whose tiles are land, unchanged); otherwise variant(frameBits) alone (each tile's own
  /// bits on top: drawTiles).
  void drawCovered(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                   unsigned frameBits, const glm::dvec3& sunDirectionEcef, bool seaFromGlobe);
  /// Whether the sea's horizon may hide part of tile `t` (this frame's cone: terrain::
  /// seaHorizonMayHide): its draws then clip at the cone (GL_CLIP_DISTANCE1), in one pass.
  [[nodiscard]] bool seaHorizonMayHide(const terrain::Tile& t, const geo::CameraView& view) const;
  /// What the vertices' aerial perspective reads (terrain/tile_vertex.glsl): the Sun, the eye's
  /// vertical and height, the atmosphere's tables.
  void setAerialUniforms(const gl::Program& p, const geo::CameraView& view, const glm::dvec3& sunDirectionEcef) const;
  /// Everything terrain.frag/vert read that is the same for every tile of a frame.
  void setFrameUniforms(const gl::Program& p, const geo::CameraView& view,
                        const glm::dvec3& sunDirectionEcef, bool seaFromGlobe) const;
  /// Renders the Sun's depth map over the tiles in view and sets the terrain program's shadow
  /// uniforms (uShadowOn = 0 when there is none this frame).
  void renderShadowMap(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                       const glm::dvec3& sunDirectionEcef);
  /// Clears the part `crop` (texels x0, y0, x1, y1) of cascade `cascade` of the shadow map and
  /// draws `casting` into it, the cascade's first `texels` texels on the viewport (lightClip:
  /// camera-relative ECEF to its clip space), each from the mesh shadowStride chooses for the
  /// cascade's texels of `texelM` (m) and the Sun (`sunDirectionEcef`, unit); nothing when
  /// `casting` is empty.
  void drawShadowCascade(const geo::CameraView& view, int cascade, const glm::mat4& lightClip,
                         const std::vector<const terrain::Tile*>& casting, int texels, const glm::ivec4& crop,
                         double texelM, const glm::dvec3& sunDirectionEcef);
  /// The index into kTileStrides of the mesh tile `t` is drawn from into a cascade of texels
  /// `texelM` (m) wide under the Sun `sunDirectionEcef` (unit): 1 (every 2nd vertex) where that mesh's part above the sea lies off the
  /// full grid's (terrain::Tile::StrideDeviation's aboveSea*, along the verticals plus across)
  /// by at most half the room the lookups leave a surface before it shades itself at the Sun's
  /// lowest over the tile, and by kShadowStrideTexels of a texel at most; else 0.
  [[nodiscard]] std::size_t shadowStride(const terrain::Tile& t, const glm::dvec3& sunDirectionEcef, double texelM) const;
  /// The texels (x0, y0, x1, y1) of a cascade of `texels` over the box mid +- half (m, across
  /// the Sun's rays) that hold `receivers` and kShadowCropMarginTexels around them, clamped to
  /// the cascade; all 0 when none.
  [[nodiscard]] static glm::ivec4 shadowCropTexels(const LightRect& receivers, const glm::dvec2& mid, double half, int texels);
  /// The tiles whose bounding spheres reach over `rect` (across the Sun's rays lx, ly).
  [[nodiscard]] static std::vector<const terrain::Tile*> tilesOver(const std::vector<const terrain::Tile*>& tiles,
                                                                   const glm::dvec3& eyeEcef, const glm::dvec3& lx,
                                                                   const glm::dvec3& ly, const LightRect& rect);
  /// Texels per side a cascade of `half` (m) over `casting` draws: fewer than kShadowMapSize,
  /// halving down to kShadowMinTexels, while one, laid on level ground along the Sun's rays,
  /// spans at most half the ground a screen pixel covers at the nearest point it can shadow
  /// (beyond `nearestServedM` from the eye, where the cascade takes over, and no nearer than a
  /// caster less its longest shadow): a far coast's map need not be finer than the screen
  /// resolves it.
  int shadowCascadeTexels(const geo::CameraView& view, const std::vector<const terrain::Tile*>& casting,
                          double half, double nearestServedM, const glm::dvec3& sunDirectionEcef) const;
  /// Creates the shadow map and its framebuffer on first use (none over the open ocean).
  void ensureShadowMap();
  void bindTile(const terrain::Tile& tile);
  /// The selected tiles this frame draws: not under the sea, not beyond its horizon.
  [[nodiscard]] std::vector<const terrain::Tile*> tilesToDraw(const geo::CameraView& view,
                                                             const std::vector<const terrain::Tile*>& tiles) const;
  /// Streams the imagery tiles the land tiles to draw want (ImageryTextures::prepareTiles).
  void prepareImagery(const std::vector<const terrain::Tile*>& tiles);
  /// terrain/tile_vertex.glsl's uniforms for a tile: uTileOffset, uMorphScale.
  void setTileUniforms(const gl::Program& p, const terrain::Tile& tile, const geo::CameraView& view) const;
  /// Their values as (uTileOffset, uMorphScale) (also tile_aerial.comp's per-tile vec4).
  [[nodiscard]] glm::vec4 tileUniforms(const terrain::Tile& tile, const geo::CameraView& view) const;
  /// terrain.vert's uMorphScale for a tile.
  [[nodiscard]] float morphScale(const terrain::Tile& tile, const geo::CameraView& view) const;
  struct GpuTile {
    gl::Buffer vertices;
  };

  const Atmosphere* atmosphere_;
  ImageryTextures* imagery_ = nullptr;
  terrain::TileCache cache_;
  terrain::SelectionParams params_;
  bool seaHorizonCulling_ = true;
  bool seaHorizonClipOn_ = true;
  bool countSamples_ = false;  ///< setCountSamples
  bool shadowTexelsFitted_ = true;
  bool shadowCropped_ = true;
  bool coverageBeyondHorizon_ = false;  ///< setCoverageBeyondHorizon
  double floorShadowReachM_ = 0.0;  ///< the crops' margin for the floor's shadows (constructor)
  bool shadowStridesOn_ = true;     ///< setShadowStrides
  /// terrain.vert/frag variants by bits, built on first use: llvmpipe runs every branch, so
  /// a frame draws with only the code it needs. kLandOnly: without the discards and the coast
  /// test, for tiles all above the sea and away from the poles; kNoNight: no city lights (the
  /// Sun is up everywhere in view, geo::sunMayBeDownInView, or on the tile: tileBits); kShadowsOff: no shadow maps this
  /// frame; kNoImageryLayers: no user imagery layer loaded (terrain/imagery.glsl's loops
  /// compiled out); kCoarseMask: no pixel resolves the land mask's fine level
  /// (LANDMASK_COARSE_ONLY, setCoarseLandMask); kFilteredMask: every pixel reads only the land
  /// fraction's pyramid (LANDMASK_FILTERED_ONLY, setFilteredLandMask); kPyramid: the pyramid is
  /// compiled in (LANDMASK_PYRAMID, setLandFractionPyramid); kAerialTable: the vertices' aerial perspective
  /// from this frame's table (TERRAIN_AERIAL_TABLE, render/AerialTable); kAerialBuffer: from
  /// the tile aerial buffer (TERRAIN_AERIAL_BUFFER, computeTileAerial); kNoDetail: no pixel of
  /// these tiles resolves a detail octave their vertex normals leave out (TERRAIN_NO_DETAIL,
  /// detailUnresolved); kGlobeLand: over the globe's land class only, with no coast test
  /// (TERRAIN_GLOBE_LAND, drawWaterTiles).
  /// kCoverage: only the discards, writing the depth of what survives them (its colour writes
  /// masked off); kAfterCoverage: the shading after it, the depth test (equal) before the
  /// shader and no discards (drawCovered).
  enum VariantBits : unsigned {
    kLandOnly = 1u,
    kNoNight = 2u,
    kShadowsOff = 4u,
    kNoImageryLayers = 8u,
    kCoverage = 16u,
    kAfterCoverage = 32u,
    kCoarseMask = 64u,
    kAerialTable = 128u,
    kAerialBuffer = 256u,
    kNoDetail = 512u,
    kCoarse = 1024u,
    kGlobeLand = 2048u,
    kFilteredMask = 4096u,
    kPyramid = 8192u
  };
  /// The bits that choose the land mask's code (the coast's tests read it; tiles all above the
  /// sea drop them).
  static constexpr unsigned kLandMaskBits = kCoarseMask | kFilteredMask | kPyramid;
  const gl::Program& variant(unsigned bits);
  std::unordered_map<unsigned, gl::Program> variants_;  ///< by bits (a few dozen are ever used)
  /// The stride of the mesh `tile` is drawn from, as an index into terrain::kTileStrides: the
  /// coarsest that lies within kStrideDeviationPx of the full grid, in the smallest pixel the
  /// tile can reach at its nearest point. Its own skirts must also be deeper than its vertical
  /// offset (so they hang below the full grid's edge; where a neighbour's edge lies under
  /// its chord, the neighbour's skirts close the gap, as at any T-junction). Only where no
  /// vertex of the tile morphs (a morphing vertex leaves the full grid:
  /// terrain/tile_vertex.glsl), above the grid's ceiling (no floor clip, no coverage pass), in
  /// frames with the tile aerial buffer (the fragments read the full grid's aerial
  /// perspective from it) and no shadow map (whose depths are the full grid's); 0 (the full
  /// grid) elsewhere.
  [[nodiscard]] std::size_t tileStrideIndex(const terrain::Tile& tile, const geo::CameraView& view) const;
  /// How a vertical offset on `tile` moves a point on screen at most: the sine of the largest
  /// angle between a vertical on the tile and a ray to it (across), and the pixels a metre
  /// spans in the smallest pixel the tile can reach at its nearest point; and the distance from
  /// the eye to the tile's bounding sphere's centre, m. nullopt with the eye within that sphere.
  struct ScreenScale {
    double across = 1.0, pixelsPerM = 0.0, centreM = 0.0;
  };
  [[nodiscard]] std::optional<ScreenScale> tileScreenScale(const terrain::Tile& tile, const geo::CameraView& view) const;
  /// tileStrideIndex with the tile's screen scale `scale` (tileScreenScale) already at hand.
  [[nodiscard]] std::size_t tileStrideIndex(const terrain::Tile& tile, const geo::CameraView& view,
                                            const std::optional<ScreenScale>& scale) const;
  /// How far the tile's relief (its heights above and depths below sea level) can move a point
  /// on screen off the ellipsoid's point behind it, pixels, by its screen scale `scale`
  /// (infinite with the eye within the tile's bounding sphere: nullopt).
  [[nodiscard]] static double reliefShiftPx(const terrain::Tile& tile, const std::optional<ScreenScale>& scale);
  /// Variant bits of one tile on top of a draw's `bits`: kCoarse (tileStrideIndex), kGlobeLand
  /// (drawWaterTiles: within kGlobeLandShiftPx) and kNoNight where the Sun is up everywhere on
  /// the tile (a shading draw's only).
  [[nodiscard]] unsigned tileBits(const terrain::Tile& tile, const geo::CameraView& view, unsigned bits,
                                  const glm::dvec3& sunDirectionEcef) const;
  /// The first index and the grid's and the skirts' counts of each stride's mesh in indices_.
  struct StrideIndices {
    int first = 0, grid = 0, skirts = 0;
  };
  std::array<StrideIndices, std::size(terrain::kTileStrides)> strideIndices_{};
  /// Fills the tile aerial buffer for `tiles` (kAerialBuffer's frames): the transmittance and
  /// in-scatter of each tile's vertices at its slots (tileFirstVertex_), of those the eye may
  /// see (listTileAerialVertices).
  void computeTileAerial(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles,
                         const glm::dvec3& sunDirectionEcef);
  /// Lists in tileAerialListed_ the vertices of `tiles` (their indices among the frame's, tile k's
  /// from k x terrain::kTileVertices) that a fragment the eye sees may read: within the cap of the
  /// globe the eye can see, widened by how far beyond it a point of the tile can be seen and by
  /// a cell of its grid (a seen fragment reads its triangle's vertices). The others lie on
  /// triangles beyond the horizon, which the globe's nearer tiles hide where they are drawn at
  /// all.
  void listTileAerialVertices(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles);
  /// Whether no pixel of `tiles` resolves the first detail octave its vertex normals leave out
  /// (terrain.frag's pixelDetailGradient adds nothing): each tile's nearest point is far enough
  /// that a pixel's footprint there, at its smallest (the pixel farthest off the axis the tile
  /// can reach, the surface seen square on, the ellipsoid's largest radius of curvature), spans
  /// kDetailUnresolvedCells of that octave's lattice cells or more, where the octave's weight
  /// is 0 from 0.5. The shader's footprint is its foot point's move across the pixel, the
  /// larger of the screen's two axes: a facet seen square on but sloping shortens it along its
  /// slope by the slope's cosine, and the larger of two axes at 45° to it keeps at least 1/√2.
  [[nodiscard]] bool detailUnresolved(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles) const;
  static constexpr double kDetailUnresolvedCells = 0.71;
  /// Whether this frame's tiles are shaded without the detail (setDetailSkip).
  [[nodiscard]] bool skipDetail(const geo::CameraView& view, const std::vector<const terrain::Tile*>& tiles) const;
  /// A tile's vertex buffer, uploaded on first use.
  const gl::Buffer& tileBuffer(const terrain::Tile& tile);
  /// TerrainStats::seaSeenMaxHeightM of `tiles`.
  [[nodiscard]] double seaSeenMaxHeightM(const geo::CameraView& view,
                                         const std::vector<const terrain::Tile*>& tiles) const;
  /// This frame's aerial perspective to altitudes (kAerialTable's frames).
  AerialTable aerialTable_{AerialTable::Kind::terrain};
  bool aerialTableOn_ = true;  ///< setAerialTable
  bool tileAerialBufferOn_ = true;  ///< setTileAerialBuffer
  DetailSkip detailSkip_ = DetailSkip::whereUnresolved;  ///< setDetailSkip
  bool coarseStridesOn_ = true;     ///< setCoarseStrides
  bool dayTilesOn_ = true;          ///< setDayTiles
  bool coarseThisFrame_ = false;    ///< whether this frame's tiles may be drawn coarser (tileStrideIndex)
  int landClassStencil_ = 0;        ///< drawWaterTiles' while it draws, else 0
  gl::Program tileAerialProgram_;     ///< terrain/tile_aerial.comp
  gl::Buffer tileAerial_;             ///< two vec4s a vertex of the frame's tiles
  std::size_t tileAerialBytes_ = 0;
  gl::Buffer tileAerialVertices_, tileAerialTiles_;  ///< tile_aerial.comp's copy of the tiles' vertices, their uniforms
  std::size_t tileAerialVerticesBytes_ = 0, tileAerialTilesBytes_ = 0;
  gl::Buffer tileAerialList_;  ///< tile_aerial.comp's vertices to do, their indices among the frame's
  std::size_t tileAerialListBytes_ = 0;
  std::vector<std::int32_t> tileAerialListed_;  ///< listTileAerialVertices' list
  std::unordered_map<const terrain::Tile*, int> tileFirstVertex_;  ///< this frame's slots in tileAerial_
  bool coarseMask_ = false;  ///< setCoarseLandMask
  bool filteredMask_ = false;  ///< setFilteredLandMask
  bool pyramid_ = false;       ///< setLandFractionPyramid
  bool coveragePassOn_ = true;  ///< setCoveragePass
  double seaCrestM_ = 30.0;  ///< setSeaCrestM
  bool seaSightTest_ = true;  ///< setSeaSightTest
  bool floorClipOn_ = true;   ///< setFloorClip
  FloorClip floorClip_;       ///< this frame's (none above the ceiling)
  std::optional<terrain::SeaHorizonCone> seaHorizonClip_;  ///< this frame's (setSeaHorizonClip)
  unsigned waterBits_ = 0;  ///< drawWaterTiles()' variant bits this frame
  glm::dvec3 waterSunDirection_{1.0, 0.0, 0.0};
  std::vector<const terrain::Tile*> waterTiles_;  ///< left by draw() for drawWaterTiles()
  geo::CameraView waterView_;
  gl::Program shadowProgram_;  ///< id 0 until ensureShadowMap()
  gl::Texture shadowMap_;      ///< id 0 until ensureShadowMap()
  gl::Framebuffer shadowFbo_;
  gl::VertexArray vao_;
  gl::Buffer indices_;
  std::unordered_map<std::uint64_t, GpuTile> gpu_;
  TerrainStats stats_;
  gl::PassTimer* timer_ = nullptr;
  SunShadows shadows_;
};

}  // namespace og::render
