#pragma once
// Renders one frame of the globe into off-screen targets: an HDR radiance target (linear,
// float, alpha = coverage, reversed-Z depth; multisampled) and a display target (tone-mapped
// sRGB, 8-bit).
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "atmosphere/Parameters.hpp"
#include "core/Time.hpp"
#include "data/LandFractionMips.hpp"
#include "data/LandMaskPyramid.hpp"
#include "data/LatLonGrid.hpp"
#include "geo/Camera.hpp"
#include "geo/Wind.hpp"
#include "gl/Objects.hpp"
#include "gl/PassTimer.hpp"
#include "gl/Shader.hpp"
#include "io/Image.hpp"
#include "io/SceneSchema.hpp"
#include "ocean/OceanFrame.hpp"
#include "render/AerialTable.hpp"
#include "render/Atmosphere.hpp"
#include "render/GlobeBlocks.hpp"
#include "render/ImageryTextures.hpp"
#include "render/LandMaskTexture.hpp"
#include "render/OceanPatterns.hpp"
#include "render/OceanRenderer.hpp"
#include "render/OpenSeaMap.hpp"
#include "render/SeaLattice.hpp"
#include "render/TerrainRenderer.hpp"
#include "render/UncoveredPixels.hpp"
#include "render/WindTextures.hpp"

namespace og::render {

/// FrameInput::samples: 4 on a GPU; 1 on a software renderer (4 samples cost llvmpipe 1.6-5x
/// a frame: gl::DriverProfile::autoSamples).
inline constexpr int kAutoSamples = io::kAutoSamples;

struct FrameInput {
  geo::CameraPose camera;
  glm::dvec3 sunDirectionEcef{1.0, 0.0, 0.0};  ///< unit, towards the Sun
  /// Multiplies radiance (Sun-irradiance units) before tone mapping. The default is a fixed,
  /// physically based exposure for sunlit scenes (docs/atmosphere.md): daylight at sea level
  /// and the day side seen from orbit share it, as both are lit by the same Sun.
  double exposure = 6.0;
  int width = 256;
  int height = 256;
  double simulationTimeS = 0.0;  ///< seconds since the start of the sequence (wave animation)
  /// The UTC instant the frame shows: wind layers with a time axis are sampled at it
  /// (WindTextures::setTime); nullopt keeps them at the time they were loaded for.
  std::optional<UtcTime> utcTime;
  OceanModel oceanModel = OceanModel::Bruneton;
  /// The 10 m wind, [0, 50] m/s, everywhere unless GlobeRenderer::setWindLayers gave local
  /// winds (the fallback of render::WindTextures).
  geo::Wind wind;
  /// The ocean frame carried from earlier frames (waves fixed to the Earth while the camera
  /// moves); nullptr starts a fresh frame under the camera.
  const ocean::OceanFrame* oceanFrame = nullptr;
  int oceanCellPixels = 8;         ///< projected-grid cell size, pixels
  /// The grid's sea drawn in classes, each pixel by a program with only the code it needs
  /// (render/OceanRenderer, docs/coast.md); false: one program for all (the tests' reference).
  bool oceanClasses = true;
  std::uint64_t waveSeed = 1;      ///< the waves' random amplitudes and phases
  /// Samples per pixel of the HDR target: 1, 2, 4 or 8 (clamped, with a warning, to what the
  /// GL device offers), or kAutoSamples. Shaders still run once per pixel; the extra samples
  /// anti-alias the edges of triangles and of the depth test (terrain silhouettes, shorelines).
  int samples = kAutoSamples;
  /// Also render the auxiliary outputs (whitecap coverage) for GlobeRenderer::whitecap():
  /// an extra float target, for EXR outputs that ask for them (--aov).
  bool auxiliaryOutputs = false;
  /// The caller reads only the display of this frame (display(), depth(), viewDistance(); not
  /// radiance(), which then throws): below the grid's ceiling with no land in view,
  /// single-sampled and with no auxiliary outputs, the sea's pass may write the display itself
  /// (OceanRenderer::setDisplayTarget) and the tone map's pass then reads only the rest (the
  /// globe's pixels), or is left out where the sea covers the screen. False for EXR outputs.
  bool displayOnly = false;
};

/// The sample counts FrameInput::samples accepts (the scene schema's list).
using io::isValidSampleCount;

/// Below this camera height the sea is the projected grid with waves; above, the ellipsoid with
/// the BRDF of the whole slope distribution. The grid's waves fade out towards it
/// (kOceanFadeStartM), so the two agree at the switch.
inline constexpr double kOceanGridMaxHeightM = 20000.0;
inline constexpr double kOceanFadeStartM = 12000.0;

/// The screen rectangle (x, y, width, height in pixels, lower-left origin) outside which the
/// globe pass colours nothing above the atmosphere: the projections of the cones from the eye
/// around the ellipsoid, around the atmosphere's sphere under the eye (render/globe.frag's sky)
/// and around the Sun's disc, with two pixels of margin; the whole screen when the eye is
/// within 1 % of either sphere's radius or a cone reaches behind it.
std::array<int, 4> globeScissor(const geo::CameraView& view, int width, int height,
                                const atmosphere::Parameters& atmosphere,
                                const glm::dvec3& sunDirectionEcef);

/// Two screen rectangles (x, y, width, height in pixels, lower-left origin). `hits` holds every
/// pixel a ray of which can meet the ellipsoid: below the grid's ceiling the globe's
/// classifying draw finds nothing to class elsewhere (its sky has count 0). `sky` holds every
/// pixel a ray of which can miss it (below the grid's ceiling the sky part's, stencil count 0,
/// which also takes any pixel that hits outside `hits`). From rays every kHitScanPx pixels
/// over the screen against the ellipsoid, each box widened by that step and two pixels; each
/// empty (width 0) when none of its rays is found. Every pixel lies in one or both.
struct RayScissors {
  std::array<int, 4> hits, sky;
};
RayScissors rayScissors(const geo::CameraView& view, int width, int height);
/// The box (x, y, width, height, pixels, lower-left origin) holding every pixel whose centre ray
/// lies within the Sun's disc (angular radius `sunRadiusRad`) plus a pixel's largest angle:
/// where render/globe.frag's sky part below the grid's ceiling adds the disc. Empty (width 0)
/// when the Sun is behind the eye; none when the cone around it reaches behind the eye.
std::optional<std::array<int, 4>> sunDiscScissor(const geo::CameraView& view, int width, int height,
                                                 const glm::dvec3& sunDirectionEcef, double sunRadiusRad);
inline constexpr int kHitScanPx = 8;

class GlobeRenderer {
 public:
  /// Needs a current GL 4.5 context. Uploads the elevation layer once and prepares the
  /// atmosphere (precomputed tables, from the on-disk cache when available).
  /// The layer is shared (the terrain keeps it), not copied.
  explicit GlobeRenderer(std::shared_ptr<const data::LatLonGrid> elevation,
                         const atmosphere::Parameters& atmosphere = atmosphere::earth());
  /// Shares an atmosphere already prepared on the current context.
  GlobeRenderer(std::shared_ptr<const data::LatLonGrid> elevation, std::shared_ptr<const Atmosphere> atmosphere);
  /// The same with a copy of `elevation`.
  explicit GlobeRenderer(const data::LatLonGrid& elevation,
                         const atmosphere::Parameters& atmosphere = atmosphere::earth())
      : GlobeRenderer(std::make_shared<const data::LatLonGrid>(elevation), atmosphere) {}
  GlobeRenderer(const data::LatLonGrid& elevation, std::shared_ptr<const Atmosphere> atmosphere)
      : GlobeRenderer(std::make_shared<const data::LatLonGrid>(elevation), std::move(atmosphere)) {}

  [[nodiscard]] const Atmosphere& atmosphere() const { return *atmosphere_; }
  [[nodiscard]] std::shared_ptr<const Atmosphere> sharedAtmosphere() const { return atmosphere_; }

  /// Local winds from data layers for every following frame (nullptr: each frame's constant
  /// wind everywhere). The sea's slopes, glint and waves then follow the wind point by point.
  void setWindLayers(std::shared_ptr<const data::WindLayers> layers) { wind_->setLayers(std::move(layers)); }

  /// The wind on the GPU (its uploads count tells how often a time-varying wind changed).
  [[nodiscard]] const WindTextures& wind() const { return *wind_; }

  /// Draws a frame into the internal targets (resized as needed).
  void render(const FrameInput& frame);

  /// Whether the sea's pass may write the display itself in FrameInput::displayOnly frames
  /// (default on; off: the tone map's pass always, to compare in tests).
  void setSeaWritesDisplay(bool on) { seaWritesDisplay_ = on; }
  /// Whether the last render()'s sea wrote the display where it drew (the tone map's pass then
  /// read only the rest, the globe's pixels, or ran not at all where the sea covered the screen).
  [[nodiscard]] bool lastSeaWroteDisplay() const { return lastSeaWroteDisplay_; }

  /// Results of the last render(). With multisampling, radiance is the mean of each pixel's
  /// samples and depth one sample's value (the driver's resolve). radiance() throws
  /// og::InternalError after a FrameInput::displayOnly frame.
  [[nodiscard]] io::ImageRgbaF radiance() const;
  [[nodiscard]] io::ImageRgba8 display() const;
  [[nodiscard]] std::vector<float> depth() const;
  /// Whitecap coverage of every pixel of the last render(), [0, 1], top row first; needs
  /// FrameInput::auxiliaryOutputs (else throws og::InternalError).
  [[nodiscard]] std::vector<float> whitecap() const;
  /// Distance from the eye to the surface seen in every pixel of the last render(), metres
  /// along the pixel's ray, top row first; kSkyDistanceM where no surface is seen. Where the
  /// globe pass's own depth stands (kGlobeDepthPushM), the ellipsoid's exact distance.
  [[nodiscard]] std::vector<float> viewDistance() const;
  static constexpr float kSkyDistanceM = 1e10f;  ///< what compositors' Z passes use for the sky
  /// Above the grid's ceiling the globe pass writes the depth of its pixel-centre ray this far
  /// behind the ellipsoid (metres along the view axis), so that no terrain tile, whose chords
  /// sag up to ~0.5 km below it, ever falls behind it (render/globe.frag).
  static constexpr double kGlobeDepthPushM = 20000.0;

  /// Samples per pixel of the last render() (after clamping; the driver may round up).
  [[nodiscard]] int samples() const { return hdr_.samples; }

  /// The tone-mapped display target of the last render(), its sRGB-encoded bytes (a GL_RGBA8
  /// view: for blitting to a window or reading back, not for drawing into, which would store
  /// unencoded values).
  [[nodiscard]] GLuint displayFramebuffer() const { return ldrBytes_.fbo.id(); }

  /// Blocks until the GPU has finished the last frame (for timing).
  static void finish();

  /// Times the passes of every following frame on `timer` (nullptr: none): "globe" (its
  /// classifying draws and set-up), its parts ("globe sky", "globe land", "globe sea", "globe
  /// open sea", "globe edge", "globe surface", or the last two as "globe edge and surface
  /// (listed)"), "globe sea lattice" (render/SeaLattice's points, check and draws), "terrain
  /// shadows", "terrain", "ocean waves" (the FFTs), "ocean" and the sea's steps, "tone mapping".
  void setPassTimer(gl::PassTimer* timer) {
    timer_ = timer;
    terrain_->setPassTimer(timer);
    ocean_->setPassTimer(timer);
  }

  /// The wave patterns of the last frame (nullptr before the first).
  [[nodiscard]] const OceanPatterns* oceanPatterns() const { return patterns_.get(); }

  /// The sea's pass (which of its classes the last frame drew).
  [[nodiscard]] const OceanRenderer& ocean() const { return *ocean_; }
  OceanRenderer& ocean() { return *ocean_; }

  /// The terrain pass (tile counts and memory of the last frame).
  [[nodiscard]] const TerrainRenderer& terrain() const { return *terrain_; }
  TerrainRenderer& terrain() { return *terrain_; }

  /// The imagery draped over the land (day colour, night lights, `--imagery-layer`s).
  [[nodiscard]] const ImageryTextures& imagery() const { return *imagery_; }
  ImageryTextures& imagery() { return *imagery_; }
  /// The GSHHG land mask deciding the coast (active for global layers coarser than it).
  [[nodiscard]] const LandMaskTexture& landMask() const { return *landMask_; }

  /// Above 20 km, pixels in the open deep sea (render/OpenSeaMap) go to a part of their own
  /// (render/globe.frag); false shades them with the rest of the surface (the tests' reference).
  void setOpenSeaPart(bool on) { openSeaPart_ = on; }
  /// Above 20 km, the sea's and the open sea's blocks shaded at a lattice every 4 pixels and
  /// interpolated where that holds (render/SeaLattice; default on); off: per pixel (the tests'
  /// reference).
  void setSeaLattice(bool on) { seaLatticeOn_ = on; }
  /// The sea's blocks the last frame listed for the lattice and how many it interpolated
  /// (reads the flags back: tests).
  [[nodiscard]] std::pair<std::size_t, std::size_t> seaLatticeBlocks() const {
    return {seaLattice_.listedBlocks(), seaLattice_.interpolatedBlocks()};
  }
  /// From 20 km to kAerialTableMaxHeightM the globe's parts read the aerial perspective to sea
  /// level from a table made per frame (render/AerialTable; default on); off: from the
  /// atmosphere's tables per pixel (tests).
  void setAerialTable(bool on) { aerialTableOn_ = on; }
  /// Farther out the terminator and the limb change faster across the table's entries than it
  /// resolves (docs/atmosphere.md), and the globe covers fewer pixels: per pixel there.
  static constexpr double kAerialTableMaxHeightM = 5.0e5;
  /// Above 20 km, pixels whose four samples are all on land go to a part without the sea's
  /// code, those all on the sea to one without the land's (render/globe.frag); false shades
  /// them with the rest of the surface (the tests' reference).
  void setLandSeaParts(bool on) { landSeaParts_ = on; }
  /// Above 20 km with the land's part split off (and one classifying draw, stencil export), the
  /// land's part comes after the terrain's tiles with water and shades only the pixels they
  /// left, instead of all before them (frameLandLast_); false: before (the tests' reference).
  void setLandAfterTiles(bool on) { landAfterTiles_ = on; }
  /// With the land's part after the tiles, the tiles with water whose relief moves a point on
  /// screen by at most TerrainRenderer::kGlobeLandShiftPx draw only over the land's class (every
  /// sample of the pixel on land), which then decides their coast: the coast's mixed pixels
  /// stay the globe's surface part, anti-aliased by its four samples, and those tiles need no
  /// coast test per fragment (terrain.frag's TERRAIN_GLOBE_LAND). false: the tiles test the
  /// land mask themselves over every class (the reference of tests).
  void setTilesOverLandClass(bool on) { tilesOverLandClass_ = on; }
  /// With `on`, each of the globe's parts counts the samples it shades (an occlusion query read
  /// back at once: for tests and `bench --breakdown`, not for frames that must not wait).
  void setCountPartSamples(bool on) { countPartSamples_ = on; }
  /// The globe parts of the last frame that counted them and the samples each shaded
  /// (setCountPartSamples; none where the frame drew no globe part), in the order they were drawn: "sky", "edge", "surface", "land",
  /// "sea lattice", "sea", "open sea lattice", "open sea" (the lattice's: render/SeaLattice's
  /// interpolated pixels of the part after it).
  [[nodiscard]] const std::vector<std::pair<std::string, std::uint64_t>>& partSamples() const { return partSamples_; }
  /// Above 20 km the globe pass is scissored to the rectangle around the globe, its atmosphere
  /// and the Sun (globeScissor); false draws it over the whole screen (the tests' reference).
  void setGlobeScissor(bool on) { scissorGlobe_ = on; }
  /// Below 20 km the classifying draws are scissored to the pixels whose rays can meet the
  /// ellipsoid, the sky's part to those whose rays can miss it (rayScissors); false: the whole
  /// screen for both (the tests' reference).
  void setEllipsoidScissor(bool on) { ellipsoidScissorOn_ = on; }
  /// Below the ceiling, the classifying draw that writes the stencil from its shader covers only
  /// the blocks of pixels the terrain and the grid left (render/UncoveredPixels); false: every
  /// block of the ellipsoid's box (the tests' reference).
  void setUncoveredBlocks(bool on) { uncoveredBlocksOn_ = on; }
  /// The blocks of pixels the last frame below the ceiling listed (reads them back: tests).
  [[nodiscard]] int uncoveredBlocksListed() const { return uncovered_.listedBlocks(); }
  /// Above 20 km, blocks of pixels that are wholly land or wholly sea are classed on the CPU
  /// (render/GlobeBlocks) and spared the per-pixel classifying draw; false classes every pixel
  /// on the GPU (the tests' reference). On by default on software renderers (llvmpipe), where
  /// the per-pixel classification was a third of the globe pass; a GPU's is not measured yet.
  void setGlobeBlocks(bool on) { blocksOn_ = on; }
  /// The last frame's blocks of each GlobeBlockClass (in its order; all 0 without blocks).
  [[nodiscard]] const std::array<int, kGlobeBlockClasses>& globeBlockCounts() const { return blockCounts_; }
  /// Below 20 km the sky is drawn at a lower resolution and read back per pixel where a pixel
  /// is finer than kSkyLowTexelRad / 3 (drawSkyLow: 1280 x 720 and up at the usual fields of
  /// view); false computes it per pixel (the tests' reference).
  void setSkyLow(bool on) { skyLowOn_ = on; }
  /// Below 20 km the sky part leaves the Sun's disc out and draws it again only over
  /// sunDiscScissor's box (drawSunDisc); false: over the whole screen (the tests' reference).
  void setSunDiscBox(bool on) { sunDiscBoxOn_ = on; }
  /// The globe's edge and surface parts (the limb, the horizon, the coasts: scattered pixels)
  /// listed and shaded by a compute shader (shadeScatteredParts) instead of by fragments, which
  /// on llvmpipe pay a vector of lanes for a lone pixel. On by default on software renderers
  /// with one sample per pixel and no auxiliary outputs; false: fragments (the tests' reference).
  void setScatteredPartsListed(bool on) { scatteredListed_ = on; }
  /// Whether a multisampled frame below 20 km draws each of the globe's parts only where a lean
  /// draw's occlusion query found samples of it (drawPartGated; on by default where
  /// gl::DriverProfile::multisampleShadesEveryBlock; off: the tests' reference).
  void setPartGate(bool on) { partGateOn_ = on; }
  /// Whether a multisampled frame draws each of the globe's parts over the blocks of pixels that
  /// may hold it (above 20 km drawPartOverBlocks; below, the edge's and the surface's over the
  /// blocks the grid and the terrain left: UncoveredPixels; on by default where
  /// gl::DriverProfile::multisampleShadesEveryBlock; off: the tests' reference).
  void setPartsOverBlocks(bool on) { partsOverBlocks_ = on; }
  /// With `on`, each gated part's query is read back at once (a stall: for tests) into
  /// partsGated(): whether the last frame's gated parts had samples, in their order (none where
  /// the frame gated none).
  void setRecordPartGate(bool on) { recordPartGate_ = on; }
  [[nodiscard]] const std::vector<bool>& partsGated() const { return partsGated_; }
  /// Whether frames in which no pixel resolves the land mask's fine level draw with programs
  /// that leave it out (LANDMASK_COARSE_ONLY; on by default, off for comparisons).
  void setCoarseMaskVariants(bool on) { coarseMaskVariants_ = on; }
  /// Whether the last frame drew with them.
  [[nodiscard]] bool lastFrameCoarseMask() const { return coarseMaskFrame_; }
  /// Whether frames in which every pixel's footprint spans two of the land mask's 2′ cells or
  /// more draw with programs that read only the land fraction's pyramid (LANDMASK_FILTERED_ONLY,
  /// data::LandFractionMips; on by default, off for comparisons).
  void setFilteredMaskVariants(bool on) { filteredMaskVariants_ = on; }
  /// Whether the last frame drew with them.
  [[nodiscard]] bool lastFrameFilteredMask() const { return filteredMaskFrame_; }
  /// Whether footprints over a 2′ cell see the land fraction's pyramid (data::LandFractionMips;
  /// on by default), or the B-spline of the cells at every scale (off: the tests' reference).
  void setFractionMipsOn(bool on) { fractionMipsOn_ = on; }
  /// Whether the last frame's programs read the pyramid (it was on, and some pixel may weigh it:
  /// LandMaskTexture::fractionMipsWeighed).
  [[nodiscard]] bool lastFrameFractionMips() const { return fractionMipsFrame_; }
  /// Whether, where the land mask decides the coast, the globe's samples are classed by its
  /// fraction alone (GLOBE_MASK_COAST; on by default), or also read the layer's heights, which
  /// change the class only at a fraction of exactly 0.5 (off: for comparisons; the programs
  /// are made again).
  void setMaskCoastVariants(bool on) {
    if (on != maskCoastVariants_) globePrograms_ = {};
    maskCoastVariants_ = on;
  }
  /// Whether frames with the constant wind (no wind layers) draw the globe's sea with its
  /// values as uniforms (PATTERN_CONSTANT_WIND; on by default, off for comparisons).
  void setConstantWindVariants(bool on) { constantWindVariants_ = on; }
  /// Whether the last frame drew with them.
  [[nodiscard]] bool lastFrameConstantWind() const { return constantWindFrame_; }
  /// Whether the last frame drew the sea with its water volume (a floor within the water's
  /// reach under sea in view: TerrainStats::seaSeenMaxHeightM; false above 20 km).
  [[nodiscard]] bool lastFrameFloorInReach() const { return floorInReachFrame_; }
  /// Whether the last frame drew the sea with its coast test (land may be in view:
  /// TerrainStats::landTiles; false above 20 km).
  [[nodiscard]] bool lastFrameLandInView() const { return landInViewFrame_; }
  /// Whether the last frame made the caustics' map (a floor in reach, and its footprint under
  /// the caustic patterns' tiles somewhere: OceanLighting::causticsSeen).
  [[nodiscard]] bool lastFrameCausticsSeen() const { return causticsSeenFrame_; }
  /// Whether the caustics' map is made wherever a floor is in reach, seen or not (off by
  /// default; on: the reference of the tests).
  void setCausticsAlwaysMade(bool on) { causticsAlwaysMade_ = on; }
  /// The pixels the last frame listed (setScatteredPartsListed; reads the count back: for tests).
  [[nodiscard]] std::uint32_t listedPixelCount() const;
  /// The last frame's pixels per sky texel along a side (1: the sky per pixel).
  [[nodiscard]] int lastSkyLowFactor() const { return lastSkyLowFactor_; }
  /// The open-sea map, its clearanceRad alone (its blocked cells and land clearance are
  /// dropped after the upload); nullptr before the first frame that binds it.
  [[nodiscard]] const OpenSeaMap* openSeaMap() const { return openSeaMap_.get(); }

 private:
  void ensureTargets(int width, int height, int samples, bool auxiliary);
  /// The globe pass's two halves (render/globe.frag): the classifying draws, then the parts.
  void classifyGlobe(const geo::CameraView& view, const FrameInput& f, bool grid);
  /// Which of the globe's parts a shadeGlobe() call draws: above 20 km, where the land's class
  /// is left at the far plane (frameLandLast_), the land comes after the tiles with water.
  enum class GlobeParts { all, allButLand, land };
  void shadeGlobe(const geo::CameraView& view, const FrameInput& f, bool grid, GlobeParts which = GlobeParts::all);
  /// Below 20 km no pixel sees pure space, and the depth test already leaves out what the
  /// terrain and the grid cover: step 0 is skipped and the counts start at 0 for the sky.
  static int firstClassifyingStep(bool grid) { return grid ? 1 : 0; }
  void drawOcean(const geo::CameraView& view, const FrameInput& f);
  /// The HDR target, resolved to one sample per pixel when multisampled (on first use after
  /// each render()).
  const gl::RenderTarget& singleSampleHdr() const;
  /// The wave patterns for the scene's winds: made for the strongest wind of the layers and the
  /// constant wind (never the wind under the camera), rebuilt only when that or the seed changes.
  const OceanPatterns& patternsFor(double referenceWindMs, std::uint64_t seed);

  std::shared_ptr<const Atmosphere> atmosphere_;
  /// globe.frag's variants: six classifying steps (0-5; the last three, land or sea, the sea
  /// and the open sea, above 20 km only), the one-draw classification (6,
  /// GLOBE_CLASSIFY_EXPORT; 7 with the land's and the sea's steps, GLOBE_LAND_SEA: a uniform
  /// would not spare their lookups, llvmpipe runs both sides of an `if`), then six parts (8-13:
  /// sky, edge, surface, land, sea, open sea; see its GLOBE_PART), drawn first above the grid's
  /// ceiling and last (GLOBE_BEHIND, after the terrain and the grid) below; each compiled on
  /// first use; 14 the sky at a lower resolution below the ceiling (GLOBE_PART_SKY_LOW) and 15
  /// the sky part that reads it (GLOBE_SKY_LOW); 16 the depth of blocks classed on the CPU
  /// (GLOBE_PART_BLOCK_FILL); 17 the edge part as a compute shader over listed pixels
  /// (GLOBE_COMPUTE); 18 the sky part with the Sun's disc (GLOBE_SKY_SUN_DISC: 15 leaves it
  /// out), drawn over the Sun's box only (drawSunDisc); 19 and 20 the open sea's and the sea's
  /// parts as compute shaders at the lattice's points (GLOBE_LATTICE, render/SeaLattice); 21-26
  /// the six parts again over triangles of blocks (render/blocks.vert), with several samples a
  /// pixel. `variant` in [0, kGlobeVariants). Above the ceiling the classifying variants and
  /// 21-26 draw the triangles of blocksVao_ (drawPartOverBlocks), below it the one draw (6, 7)
  /// and the edge's and the surface's parts (22, 23) render/UncoveredPixels' blocks.
  static constexpr int kGlobeVariants = 27;
  /// Part k (1 sky ... 6 open sea) over blocks is variant kGlobePartOverBlocks0 + k.
  static constexpr int kGlobePartOverBlocks0 = 20;
  static constexpr int kSkyLowPass = 14, kSkyLowPart = 15, kBlockFill = 16, kListedPixels = 17, kSkyLowSunPart = 18;
  static constexpr int kOpenSeaLatticePoints = 19, kSeaLatticePoints = 20;
  static constexpr int kClassifyExport = 6, kClassifyExportLandSea = 7;
  /// Part k (1 sky ... 6 open sea) is variant kGlobePart0 + k.
  static constexpr int kGlobePart0 = 7;
  /// A frame's classifying steps (0-5) and its parts (variants, in stencil count order): the
  /// land's, the sea's and the open sea's only above 20 km, where they are on.
  [[nodiscard]] std::vector<int> classifyingSteps(bool grid) const;
  [[nodiscard]] std::vector<int> globeParts(bool grid) const;
  /// The stencil count the classifying draws leave on the pixels of `part` (kGlobePart0 + k).
  [[nodiscard]] int partStencilCount(int part, bool grid) const;
  /// Below the ceiling, the sky part's pixels near the Sun's disc again with the disc
  /// (kSkyLowSunPart) over the sky just drawn without it: scissored to sunDiscScissor's box, or
  /// over the whole screen where that has none or setSunDiscBox(false).
  void drawSunDisc(const geo::CameraView& view, const FrameInput& f, bool grid);
  /// Above the ceiling, before the sea's or the open sea's part (its stencil test set): the
  /// lattice's points shaded and its blocks checked (before the first of the two), and the
  /// part's blocks that passed drawn interpolated (render/SeaLattice); `seaPart`: the sea's
  /// part, else the open sea's.
  void drawSeaLattice(const geo::CameraView& view, const FrameInput& f, bool first, bool seaPart);
  /// Whether this frame splits the land and the sea off the surface part (landSeaParts_ and
  /// the split pays): their classifying step costs four elevation lookups a pixel, which a
  /// view mostly of the open deep sea (the limb over the Atlantic) does not win back. From an
  /// 8 x 8 lattice of rays on the CPU: fewer than half of those that hit the globe land in open
  /// sea cells (render/OpenSeaMap). Set by classifyGlobe, read by shadeGlobe; always on with
  /// the blocks (uploadClassifyingBlocks), which class most of those pixels on the CPU.
  [[nodiscard]] bool landSeaSplitPays(const geo::CameraView& view) const;
  bool frameLandSea_ = false;
  /// Whether this frame's land class (count 4) keeps the far plane's depth (0) and its part
  /// comes after the terrain's tiles with water, shading only the pixels they left (depth
  /// equal to 0): above 20 km with frameLandSea_ where one classifying draw writes the count
  /// (the per-step draws write the depth before the land's step). The tiles draw the land at
  /// almost all of those pixels, over the globe's part, which ran for nothing before them.
  bool frameLandLast_ = false;
  bool floorInReachFrame_ = false;  ///< lastFrameFloorInReach
  bool landInViewFrame_ = false;    ///< lastFrameLandInView
  bool causticsSeenFrame_ = false;   ///< lastFrameCausticsSeen
  bool causticsAlwaysMade_ = false;  ///< setCausticsAlwaysMade
  /// The open-sea map on its texture unit (made on a helper thread since the constructor,
  /// uploaded on first use).
  void bindOpenSeaMap();
  /// Enables the scissor test on globeScissor's box (when setGlobeScissor is on); the box (the
  /// whole frame without it).
  std::array<int, 4> scissorToGlobe(const geo::CameraView& view, const FrameInput& f);
  /// Above the ceiling where the land mask decides the coast: the blocks of pixels that are
  /// wholly land, sea or open sea (render/GlobeBlocks) get their stencil count and depth from
  /// drawBlockFill, the per-pixel classifying draws cover the rest, those of the sky without
  /// the land's and the sea's tests. Uploads this frame's triangles to blocksBuffer_ and sets
  /// blockRanges_; false without blocks (one triangle over the frame, per pixel).
  bool uploadClassifyingBlocks(const geo::CameraView& view, const FrameInput& f, const std::array<int, 4>& box,
                               bool grid);
  void drawBlockFill(const geo::CameraView& view, const FrameInput& f);
  gl::Buffer blocksBuffer_;
  gl::VertexArray blocksVao_;
  /// First vertex and count in blocksBuffer_ of each kind of block.
  struct BlockRanges {
    std::pair<int, int> perPixel, miss;
    std::array<std::pair<int, int>, 3> fills;  ///< land, sea, open sea
  };
  BlockRanges blockRanges_{};
  std::array<int, kGlobeBlockClasses> blockCounts_{};
  bool blocksOn_ = false;  ///< set from gl::driverProfile().software by the constructor
  /// The land mask's pyramid (data::LandMaskPyramid), made on a helper thread from the
  /// constructor on.
  std::future<std::unique_ptr<data::LandMaskPyramid>> maskPyramidFuture_;
  std::unique_ptr<data::LandMaskPyramid> maskPyramid_;
  /// The land fraction's pyramid (data::LandFractionMips), likewise; uploaded to landMask_ by
  /// the first frame whose footprints may weigh it (prepareFractionMips).
  std::future<std::unique_ptr<data::LandFractionMips>> fractionMipsFuture_;
  std::unique_ptr<data::LandFractionMips> fractionMips_;
  /// The tone map's pass from hdr_ into the display: over the globe's box above the ceiling,
  /// over the globe's pixels alone where the sea wrote the display (toneMapGlobePixels).
  void toneMap(const FrameInput& f, bool grid);
  /// The tone map (the program in use, its exposure set) over the pixels at the clear's depth
  /// alone; leaves another program in use.
  void toneMapGlobePixels(const FrameInput& f);
  /// Waits for the pyramid and uploads it where `view` may weigh it; sets filteredMaskFrame_.
  void prepareFractionMips(const geo::CameraView& view, int heightPx);
  const gl::Program& globeProgram(bool behind, int variant);
  /// The set of globePrograms_ `variant` draws from this frame (kGlobeProgramSets of them).
  [[nodiscard]] int programSet(bool behind, int variant) const;
  /// Below the grid's ceiling: the sky into skyLow_, one texel per kSkyLowTexelRad of view (at
  /// most kSkyLowMaxFactor pixels a side), for the sky part to read (globe.frag's
  /// GLOBE_PART_SKY_LOW). False, drawing nothing, where a texel would hold fewer than
  /// kSkyLowMinFactor pixels a side (test frames, 640 x 360).
  bool drawSkyLow(const geo::CameraView& view, const FrameInput& f);
  static constexpr double kSkyLowTexelRad = 0.3 * 0.017453292519943295;  // 0.3°
  static constexpr int kSkyLowMinFactor = 3, kSkyLowMaxFactor = 4;
  gl::RenderTarget skyLow_;  ///< drawSkyLow's texels (RGBA16F, bilinear)
  glm::vec2 skyLowScale_{0.0f};  ///< globe.frag's uSkyLowScale for this frame
  bool skyLowOn_ = true;
  bool sunDiscBoxOn_ = true;  ///< setSunDiscBox
  int lastSkyLowFactor_ = 1;
  /// Above 20 km: this frame's aerial perspective to sea level by path length and angle to the
  /// Sun (render/aerial_table.comp), which the globe's parts read (AERIAL_TABLE) instead of the
  /// atmosphere's 4D tables per pixel.
  AerialTable aerialTable_{AerialTable::Kind::seaLevel};
  bool aerialTableOn_ = true;
  bool aerialTableFrame_ = false;  ///< this frame's globe reads the table
  /// This frame's programs leave the land mask's fine level out (LandMaskTexture::fineLevelUnresolved).
  bool coarseMaskFrame_ = false;
  /// This frame's programs read only the land fraction's pyramid (LandMaskTexture::fractionMipsOnly).
  bool filteredMaskFrame_ = false;
  /// This frame's wind is the constant one (no wind layers): the globe's sea reads its values
  /// from uniforms (PATTERN_CONSTANT_WIND) instead of the wind texture and the tables per pixel.
  bool constantWindFrame_ = false;
  bool constantWindVariants_ = true;  ///< setConstantWindVariants
  bool maskCoastVariants_ = true;     ///< setMaskCoastVariants
  bool coarseMaskVariants_ = true;  ///< setCoarseMaskVariants
  bool filteredMaskVariants_ = true;  ///< setFilteredMaskVariants
  bool fractionMipsOn_ = true;        ///< setFractionMipsOn
  /// This frame's globe and terrain read the pyramid (LANDMASK_PYRAMID; prepareFractionMips).
  bool fractionMipsFrame_ = false;
  void setGlobeUniforms(const gl::Program& globe, const geo::CameraView& view, const FrameInput& f);
  /// Whether this frame lists its scattered parts (setScatteredPartsListed, one sample, no
  /// auxiliary outputs, not counting the parts' samples).
  [[nodiscard]] bool listsScatteredParts() const;
  /// The pixels whose stencil count is one of `counts` (the edge's and the surface's), listed by
  /// render/globe_list.frag and shaded by globe.frag's compute variant into the HDR target.
  void shadeScatteredParts(const geo::CameraView& view, const FrameInput& f, bool grid, const std::vector<int>& counts);
  gl::Buffer scatteredPixels_;  ///< render/globe_pixels.glsl's block: count, groups, pixels
  std::size_t scatteredPixelsBytes_ = 0;
  gl::Program scatteredList_, scatteredListBlocks_, scatteredArgs_;
  bool scatteredListed_ = false;  ///< set from gl::driverProfile().software by the constructor
  /// Below 20 km with several samples a pixel: `draw` (a part's full-screen draw, its tests
  /// set) conditional on a lean draw's occlusion query under the same tests. llvmpipe's early
  /// tests skip no block of a multisampled draw, so a part without samples (the edge's and the
  /// surface's, where the grid covers the globe) cost the whole screen's shading. Within the
  /// frame's conditional render on uncovered_ where there is one (partsOnUncovered), which this
  /// suspends around the part's; binds the part's program `part` again after the lean one.
  void drawPartGated(const gl::Program& part, const std::function<void()>& draw);
  /// Above 20 km with several samples a pixel: the part of stencil count `count` (variant
  /// `part`) over the triangles of the blocks that may hold it (blockRanges_: the per-pixel
  /// blocks, the sky's, the fills of that count) instead of the whole frame, with its
  /// blocks.vert variant bound: llvmpipe shaded every block of the frame for the limb's edge
  /// (limb-400km at 1280x720, 4 samples: the edge's and the surface's parts 250 and 230 ms).
  /// With one sample, the listing of the scattered parts (shadeScatteredParts; `part` 0).
  void drawPartOverBlocks(int part, int count) const;
  /// The stencil count drawBlockFill gives fill k (0 land, 1 sea, 2 open sea) this frame.
  [[nodiscard]] int fillStencilCount(std::size_t k) const;
  bool partsOverBlocks_ = false;  ///< setPartsOverBlocks; from gl::DriverProfile::multisampleShadesEveryBlock
  /// Below 20 km: whether the classifying draw covers uncovered_'s listed blocks (its one draw,
  /// with stencil export) rather than the frame.
  [[nodiscard]] static bool listsUncoveredBlocks(bool grid);
  gl::Program partGate_;     ///< render/uncovered.frag: nothing but the tests; id() 0 until first used
  gl::Query partGateQuery_;  ///< GL_ANY_SAMPLES_PASSED
  bool partGateOn_ = false;  ///< setPartGate; from gl::DriverProfile::multisampleShadesEveryBlock
  bool recordPartGate_ = false;  ///< setRecordPartGate
  std::vector<bool> partsGated_;
  bool ellipsoidScissorOn_ = true;
  /// Above 20 km with the aerial table, without, below, above without the mask's fine level,
  /// above with the land fraction's pyramid alone, and the first four again with the pyramid
  /// (LANDMASK_PYRAMID). By set (globeProgram), and again with the constant wind's uniforms
  /// (PATTERN_CONSTANT_WIND).
  static constexpr int kGlobeProgramSets = 9;
  std::array<gl::Program, 2 * kGlobeProgramSets * kGlobeVariants> globePrograms_;
  /// Below 20 km: whether the terrain and the grid left any pixel for the globe (the
  /// classifying draws are conditional on it, the parts' too unless the frame has sky:
  /// partsOnUncovered), and which blocks of pixels hold one.
  UncoveredPixels uncovered_;
  bool uncoveredBlocksOn_ = true;  ///< setUncoveredBlocks
  gl::Program tonemap_;
  gl::Program tonemapMs_;  ///< per-sample tone mapping of a multisampled target; id() 0 until first used
  gl::Program tonemapBlocks_;  ///< the tone map over the uncovered blocks (blocks.vert); id() 0 until first used
  gl::VertexArray emptyVao_;
  gl::Texture elevation_;
  glm::vec4 elevationMap_{};
  glm::vec2 elevationSize_{};
  int elevationWraps_ = 0;
  std::unique_ptr<OceanRenderer> ocean_;
  std::unique_ptr<TerrainRenderer> terrain_;
  std::unique_ptr<ImageryTextures> imagery_;
  std::unique_ptr<LandMaskTexture> landMask_;
  /// The open-sea map (makeRendererOpenSeaMap) and its texels, made on a helper thread from the
  /// constructor on (the layer's blocked cells, two passes over the mask's ~29 M cells, two
  /// distance transforms of 4 M cells).
  std::future<std::pair<std::unique_ptr<OpenSeaMap>, std::vector<std::uint16_t>>> openSeaFuture_;
  std::unique_ptr<OpenSeaMap> openSeaMap_;
  std::unique_ptr<OpenSeaTexture> openSeaTexture_;
  bool openSeaPart_ = true;
  SeaLattice seaLattice_;  ///< this frame's lattice over the sea's blocks
  bool seaLatticeOn_ = true;
  bool landSeaParts_ = true;
  bool landAfterTiles_ = true;
  bool tilesOverLandClass_ = true;  ///< setTilesOverLandClass
  bool countPartSamples_ = false;
  std::vector<std::pair<std::string, std::uint64_t>> partSamples_;
  bool scissorGlobe_ = true;
  std::array<int, 4> globeBox_{};  ///< this frame's box above the ceiling (scissorToGlobe): x, y, width, height
  std::unique_ptr<WindTextures> wind_;
  std::unique_ptr<OceanPatterns> patterns_;
  gl::RenderTarget hdr_;
  gl::RenderTarget ldr_;       ///< the display target, GL_SRGB8_ALPHA8 (the tone map writes it)
  gl::RenderTarget ldrBytes_;  ///< a GL_RGBA8 view of its bytes (read-back, the viewer's blit)
  /// ldr_'s colour over hdr_'s depth-stencil (single-sampled hdr_ only): where the sea's pass
  /// writes the display itself (FrameInput::displayOnly, OceanRenderer::setDisplayTarget).
  gl::Framebuffer displayOverDepth_;
  bool lastDisplayOnly_ = false;     ///< the last render()'s FrameInput::displayOnly
  /// Below the ceiling: this frame's box of the rays that miss the ellipsoid (rayScissors), the
  /// sky part's and, where the sea wrote the display, the tone map's (classifyGlobe's).
  std::array<int, 4> frameSkyBox_{};
  /// Below the ceiling: a ray of the scan missed the ellipsoid (classifyGlobe), so the query
  /// covered only the hits' box (UncoveredPixels::find's `onlyInBox`).
  bool frameHasSky_ = false;
  /// Whether the globe's parts are drawn conditional on uncovered_'s query: below the ceiling,
  /// unless the frame has sky (frameHasSky_), which the query did not look at.
  [[nodiscard]] bool partsOnUncovered(bool grid) const;
  bool lastSeaWroteDisplay_ = false;  ///< its sea's pass wrote the display where it drew
  bool seaWritesDisplay_ = true;      ///< setSeaWritesDisplay
  int maxSamples_ = 1;        ///< what the device offers for the HDR target
  int requestedSamples_ = 0;  ///< FrameInput::samples that hdr_ was made for
  bool auxiliary_ = false;    ///< hdr_ has the auxiliary attachment
  gl::PassTimer* timer_ = nullptr;
  geo::CameraView lastView_;  ///< the camera of the last render()
  int warnedSamples_ = 0;     ///< the request last warned about (once, not every resize)
  mutable gl::RenderTarget resolved_;  ///< hdr_ resolved, for read-back
  mutable bool resolvedCurrent_ = false;
};

}  // namespace og::render
