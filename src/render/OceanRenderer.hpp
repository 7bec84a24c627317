#pragma once
// The near ocean (below 20 km): the projected grid displaced by the FFT wave patterns and
// shaded per pixel with the filtered BRDF (Bruneton 2010) and whitecaps (Dupuy 2012). Draws into the caller's HDR target with the
// reversed-Z depth test, over the globe pass.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geo/Camera.hpp"
#include "gl/PassTimer.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "gl/ShaderContract.hpp"
#include "ocean/OceanFrame.hpp"
#include "render/Atmosphere.hpp"
#include "render/OceanPatterns.hpp"
#include "render/SeaSurfaceBuffer.hpp"
#include "render/TerrainRenderer.hpp"
#include "render/WaterVolume.hpp"
#include "render/WindTextures.hpp"

namespace og::render {

struct OceanLighting {
  glm::dvec3 sunDirectionEcef{0, 0, 1};
  glm::vec3 seaColor{0.0015f, 0.004f, 0.007f};  ///< upwelling radiance per unit irradiance
  // Used without an atmosphere only (tests of the ocean alone): a simple analytic sky.
  glm::vec3 skyZenith{0.02f, 0.045f, 0.11f};
  glm::vec3 skyHorizon{0.07f, 0.09f, 0.12f};
  /// The terrain's Sun shadows to cast on the sea (maps bound to gl::kUnitShadowMap), or none.
  const SunShadows* shadows = nullptr;
  /// Whether land may be in view: false compiles the per-pixel coast test out (ocean/coast.glsl).
  bool landInView = true;
  /// Whether a sea floor within the water's reach (ocean::waterMaxPathM) may be in view: false
  /// compiles the water volume out (ocean/water_volume.glsl): the open ocean's colour is exact.
  bool floorInReach = true;
  /// Whether the sea may be drawn in classes (OceanRenderer's stencil split); false draws every
  /// pixel with the program of the whole frame's features (the reference of the split's test).
  bool classes = true;
  /// Whether every terrain tile in view reaches above the sea (TerrainStats::landTiles ==
  /// tiles, e.g. the Himalaya from 15 km): the sea may be hidden altogether. The deferred sea
  /// then first asks the forward path's lean classifying draw (an occlusion query, the price of
  /// its vertices: 20-26 ms there) whether any of it shows, where its surface pass would pay
  /// the grid's whole vertex shader (110-140 ms).
  bool landEverywhere = false;
  /// Whether a pixel may look the caustics up (ocean/water_volume.glsl's causticCurvature: only
  /// where the floor's footprint, at least the sea's, is under the tile of a caustic pattern);
  /// false leaves their curvature map unmade this frame.
  bool causticsSeen = true;
};

enum class OceanModel {
  Bruneton,  ///< filtered waves + BRDF, Bruneton et al. 2010 (the default)
  Classic,   ///< four sines + scrolling bump maps + Fresnel ramp (ShaderX), the baseline
};

/// Variants of the Bruneton model for its validation (paper §7.2, docs/validation.md), built
/// from compile-time defines of shaders/ocean/*; everything but Filtered is for `validate`.
enum class ValidationMode {
  Filtered,      ///< the normal model (geometry, normals and BRDF by footprint)
  Reference,     ///< every pattern at full resolution, mirror reflection: supersample it
  ConstantBrdf,  ///< the paper's baseline: filtered geometry and normals, the BRDF held at the
                 ///< unresolved tail's variance at every distance
  BrdfOnly,      ///< flat sea, the whole slope variance in the BRDF
};

class OceanRenderer {
 public:
  /// Needs a current GL 4.5 context. With an atmosphere the sea reflects its sky maps and gets
  /// its aerial perspective; without (nullptr) a simple analytic sky lights it.
  explicit OceanRenderer(const Atmosphere* atmosphere = nullptr,
                         ValidationMode mode = ValidationMode::Filtered);

  /// The elevation layer's mapping (see render/elevation.glsl); its texture must be bound to
  /// gl::kUnitElevation when drawing. Without it the sea is drawn everywhere.
  void setElevationLayer(const glm::vec4& map, const glm::vec2& size, int wraps) {
    elevationMap_ = map;
    elevationSize_ = size;
    elevationWraps_ = wraps;
  }

  /// The layer's steepest slope (m/m, render/WaterVolume's layerMaxSlope): how far from land
  /// the sea's classes need the coast test where no land mask decides the coast.
  void setLayerMaxSlope(double slope) { layerMaxSlope_ = static_cast<float>(slope); }

  /// Weights of the Bruneton model's lighting terms (Sun, sky, refracted light, whitecaps), 1
  /// each by default; `validate` renders them one at a time (paper §7.2).
  void setLightingTerms(const glm::vec4& weights) { lightingTerms_ = weights; }
  /// Largest angle at the Earth's centre (rad) between the camera's nadir and the sea in view:
  /// where the screen's top corners' and top centre's rays meet the sphere of the semi-major
  /// axis, or the horizon where one misses it. Decides the sky maps' frame layer.
  [[nodiscard]] static double farthestSeaAngleRad(const geo::CameraView& view);
  /// The highest NDC y in [bottomNdc, topNdc] at which a ray of `view` with its NDC x in
  /// [leftNdc, rightNdc] (kSeaTopColumns + 1 of them, evenly) meets the WGS84 ellipsoid (the
  /// projected grid's sea: its rays above that are lowered onto the horizon), exactly per x (a
  /// quadratic in y: the rays of one x are linear in it); below bottomNdc when none does, topNdc
  /// when the eye is not above the ellipsoid.
  [[nodiscard]] static double seaTopNdc(const geo::CameraView& view, double leftNdc, double rightNdc, double bottomNdc,
                                        double topNdc);
  static constexpr int kSeaTopColumns = 64;
  /// Fine rows the grid keeps above the sea's top (seaTopNdc): the shader's float rays, and the
  /// horizon's curve between the columns seaTopNdc tries.
  static constexpr int kGridRowsOverSeaTop = 2;
  /// Vertex rows the last frame computed and drew (of the grid's: those up to the sea's top and
  /// kGridRowsOverSeaTop more, in whole bands of kGridBlockRows).
  [[nodiscard]] int lastGridRowsDrawn() const { return gridRowsDrawn_; }
  /// Whether the filtered model's grid stops at the band holding the sea's top (the default)
  /// or draws every row up to the screen's top: for tests that compare the two.
  void setGridToSeaTop(bool on) { gridToSeaTop_ = on; }
  [[nodiscard]] int lastGridRows() const { return gridRows_; }
  /// Up to this farthestSeaAngleRad the grid reads the sky maps' frame layer (1°, under a third
  /// of the Sun layers' spacing; sea-8km's 0.70° changes its image by at most 1 level).
  static constexpr double kFrameSkyMaxAngleRad = 0.0175;
  /// Times the sea's own steps within the caller's "ocean" pass (`bench --breakdown`): the
  /// caustics' update ("ocean caustics") and the classifying draw ("ocean classify"); nullptr: none.
  void setPassTimer(gl::PassTimer* timer) { timer_ = timer; }
  /// The sea's classes (shaders/ocean/sea_classify.frag): open sea, shadows, floor, floor with
  /// shadows, coast.
  static constexpr std::size_t kSeaClasses = 5;
  // (Without stencil export the classes take gl::kSeaClassBits: ocean/sea_surface.glsl's
  // SEA_CLASS_BITS, classesIntoStencil's three passes.)
  static_assert(kSeaClasses <= gl::kSeaClassBits, "a pixel's class fits three bits");
  /// Which of the sea's classes (sea_classify.frag) the last draw drew: bit k for class k + 1
  /// (open sea, shadows, floor, floor with shadows, coast), where the classifying draw found
  /// fragments of them; 0 when it drew the sea in one program.
  [[nodiscard]] unsigned classesDrawn() const { return classesDrawn_; }
  /// With `on`, each class's draw counts the samples it shades (an occlusion query read back at
  /// once: for tests and measurements, not for frames that must not wait).
  void setCountClassSamples(bool on) { countClassSamples_ = on; }
  /// Starts a frame (GlobeRenderer::render): forgets the last frame's classes, and their sample
  /// counts when counting (a frame above the grid's ceiling draws no sea here).
  void beginFrame() {
    classesDrawn_ = 0;
    if (countClassSamples_) classSamples_ = {};
  }
  /// The samples each class shaded in the last classified draw of the last frame that counted
  /// them (setCountClassSamples).
  [[nodiscard]] const std::array<std::uint64_t, kSeaClasses>& classSamples() const { return classSamples_; }
  /// Whether the filtered sea may be drawn deferred (drawDeferred) where the target allows it
  /// (single-sampled, a depth-stencil texture; stencil export, or OCEANGLOBE_SEA=deferred or compute); on by default. Off, the grid's
  /// fragments shade the sea themselves (as under multisampling and in `validate`).
  void setDeferred(bool on) { deferred_ = on; }
  /// Cells of this many pixels or more (grown: geometryIsSubPixel) are drawn forward: their
  /// triangles shade few blocks twice, and a pixel shaded from the surface buffer costs more
  /// than one with its varyings (sea-8km at 640x360, process CPU: forward 110 ms, deferred
  /// 140-155 ms; sea-4m with 8-px cells: 160-170 against 110-140).
  static constexpr int kDeferredMaxCellPixels = 16;
  /// Whether a wind blowing towards `towardsRad` (radians clockwise from north) lies along one
  /// of the wave patterns' 8 direction bins in a field turned by `fieldRotationRad`
  /// (ocean/patterns.glsl's windBins): the other bin's weight under 1e-3. The shader takes a
  /// point's angle in the field's axes from its local azimuth and the frame's rotation alone,
  /// so a constant wind has the same bins and weights at every point: the decision holds for
  /// the whole sea (a wind 0.2° off a bin, weight 7e-3, already moves the glitter by 2 % on
  /// average: the threshold is not loose). A constant wind (no
  /// wind layers) along one reads one bin's patterns instead of two (PATTERN_ONE_BIN), and the
  /// wind, its bin and the per-wind tables' values from uniforms the CPU sets once
  /// (PATTERN_CONSTANT_WIND, OceanPatterns::setConstantWind): the
  /// default westerly, towards 90°, lies along bin 0; a wind layer or a wind between bins, two.
  [[nodiscard]] static bool windAlongOneBin(double towardsRad, double fieldRotationRad);
  /// Whether a wind along one bin may read one bin's patterns (default on); off: two always.
  void setOneBinAllowed(bool on) { oneBinAllowed_ = on; }
  /// Whether the last draw read one bin's patterns.
  [[nodiscard]] bool lastDrawOneBin() const { return programSet_ == 1; }
  /// Whether the last draw was deferred.
  [[nodiscard]] bool lastDrawDeferred() const { return lastDeferred_; }
  /// Whether the last draw was forward with its triangles in classes (OCEANGLOBE_SEA=split).
  [[nodiscard]] bool lastDrawForwardSplit() const { return lastForwardSplit_; }
  /// Whether the last deferred draw shaded its classes by compute shaders (OCEANGLOBE_SEA=compute).
  [[nodiscard]] bool lastClassesByCompute() const { return lastClassesByCompute_; }
  /// The default of GPUs without stencil export (computeForFloors_: on there unless OCEANGLOBE_SEA
  /// is set), for tests on llvmpipe with OCEANGLOBE_STENCIL_EXPORT=0.
  void setComputeForFloors(bool on) { computeForFloors_ = on; }
  /// Whether the last deferred draw wrote a visibility buffer instead of the surface buffer
  /// (OCEANGLOBE_SEA_SURFACE=visibility, a frame whose sea has one class).
  [[nodiscard]] bool lastSurfaceByVisibility() const { return lastSurfaceByVisibility_; }
  /// Whether the last deferred draw's surface buffer had the compact layout (SEA_SURFACE_COMPACT).
  [[nodiscard]] bool lastSurfaceCompact() const { return lastSurfaceCompact_; }
  /// Grid cell size in pixels (the paper's ~8 px); smaller = finer geometry, slower.
  void setCellPixels(int pixels) { cellPixels_ = pixels; }
  /// Whether the grid's cells may grow (2 or kGrownCellFactor-fold, to at most kGrownCellMaxRad
  /// across) where the waves' geometry is sub-pixel and no sea is seen near grazing
  /// (geometryIsSubPixel); on by default.
  void setCellGrowth(bool on) { cellGrowth_ = on; }
  /// The cell size (pixels) the last draw used.
  [[nodiscard]] int lastCellPixels() const { return frameCellPixels_; }
  /// Whether the grid's vertices may hand the pixels of grown cells their radiance as a
  /// quadratic in the pixel's mean slope and slope covariance (ocean/radiance_terms.glsl,
  /// OCEAN_RADIANCE_TERMS); on by default. Where they do, the cells grow only to
  /// kRadianceTermsMaxCellLobes of the glint's width, and only for the forward draw's open sea:
  /// the filtered model's picture (not a validation variant), neither the water volume nor the
  /// terrain's shadows (terms per pixel the quadratic does not carry), no sea classes.
  void setRadianceTerms(bool on) { radianceTerms_ = on; }
  /// Whether the last draw's pixels took their radiance from the vertices' quadratic.
  [[nodiscard]] bool lastRadianceTerms() const { return lastRadianceTerms_; }
  /// Whether the last draw's sea covered every pixel of the screen: the grid laid over it
  /// whole (layOutGridOnBlocks: the radiance terms' cells, no horizon in view) and no coast
  /// test to discard samples. Then nothing is left for the globe to draw.
  [[nodiscard]] bool lastDrawCoversScreen() const { return lastCoversScreen_; }
  /// For the next draw only: where one pass shades the whole sea by fragments (the forward
  /// grid; the deferred sea of one class through the visibility buffer, single-sampled), that
  /// pass writes the display itself into `displayFbo` (the display target's sRGB colour over
  /// the bound target's depth-stencil: gl::createFramebufferOver), tone mapped with `exposure`
  /// as render/tonemap.frag does (OUTPUT_DISPLAY), in every pixel where it leaves a depth, so
  /// no tone map pass need read those pixels' radiance (llvmpipe: sea-8km's whole pass, 5-6 ms
  /// of its wall at 1280x720). The bound target's colour is left as it was there. 0 (after
  /// every draw): the radiance, as always.
  void setDisplayTarget(GLuint displayFbo, float exposure) {
    displayFbo_ = displayFbo;
    displayExposure_ = exposure;
  }
  /// Whether the last draw wrote the display (setDisplayTarget) rather than the radiance, in
  /// every pixel where it left a depth.
  [[nodiscard]] bool lastDrawWroteDisplay() const { return lastWroteDisplay_; }
  /// Whether a grid of larger cells draws the same sea: the waves displace no point by more
  /// than kSubPixelDisplacementPx on the screen (displacementBoundM at the nearest sea point in
  /// view, where the screen magnifies most), and the corners and edges of the view meet the
  /// sea at least kGrownCellMinGrazingRad above grazing (no horizon: the terms the vertices
  /// carry, the aerial perspective above all, vary fast there). Then a cell only interpolates smooth
  /// terms: sea-8km at 1280x720 with 32-px cells differs from 8-px ones by at most 2 levels
  /// (mean 0.03) for a third of the ocean pass (llvmpipe shades every 4 x 2 block a
  /// triangle touches: small triangles shade many pixels twice).
  [[nodiscard]] static bool geometryIsSubPixel(const geo::CameraView& view, int height, double displacementBoundM);
  /// Of the displacement bound (6 sigma of the waves' heights, OceanPatterns::amplitudeBoundM):
  /// the displacement itself is within a tenth of a pixel nearly everywhere.
  static constexpr double kSubPixelDisplacementPx = 0.5;
  static constexpr double kGrownCellMinGrazingRad = 0.087;  // 5°
  static constexpr int kGrownCellFactor = 4;
  /// The largest grown cell, rad: 4.2° (32 px at 640x360, 45° tall) draws the same sea (OceanCell
  /// tests); 8.4° cells (32 px at 320x180) move the far sea by up to 5 levels.
  static constexpr double kGrownCellMaxRad = 0.075;
  /// The largest cell whose pixels take their radiance from the vertices' quadratic
  /// (setRadianceTerms), in widths of the glint's lobe across the view
  /// (radianceTermsMaxCellRad): the triangles interpolate the quadratic's coefficients, which
  /// curve over the screen as fast as the lobe is narrow.
  static constexpr double kRadianceTermsMaxCellLobes = 0.23;

  /// Draws the sea into the bound framebuffer (width x height), depth-tested. `patterns` must
  /// hold the sea at `timeS` (OceanPatterns::update). `amplitudeScale` in [0, 1] fades the
  /// resolved waves (1 = as the spectrum says).
  void draw(const geo::CameraView& view, int width, int height, const OceanPatterns& patterns,
            const ocean::OceanFrame& frame, double timeS, const OceanLighting& lighting,
            double amplitudeScale, OceanModel model, const WindTextures& wind);

 private:
  void ensureGrid(int columns, int rows);

  void setCommon(const gl::Program& p, const geo::CameraView& view, int height,
                 const ocean::OceanFrame& frame, const OceanLighting& lighting, unsigned features) const;
  /// The filtered model's program with `features` (bits of kFeature*) compiled in, compiled
  /// on first use. llvmpipe pays for code no pixel runs (it evaluates both sides of an `if`
  /// and a loop's first trip, masked), so what a frame does not need is left out of it.
  const gl::Program& program(unsigned features);
  /// Sets everything a program of the filtered model reads for this frame.
  void prepare(const gl::Program& p, const geo::CameraView& view, int height, const OceanPatterns& patterns,
               const ocean::OceanFrame& frame, const OceanLighting& lighting, double amplitudeScale,
               const WindTextures& wind, unsigned features, const glm::vec4& margin) const;
  void drawGrid(const gl::Program& p) const;
  /// The grid's triangle rows firstRow ... lastRow (row r between vertex rows r and r + 1),
  /// widened to whole bands of kGridBlockRows.
  void drawGridRows(const gl::Program& p, int firstRow, int lastRow) const;
  static constexpr GLint kNoRow = 1 << 30;
  static constexpr GLuint kClassRowsBinding = 3;  ///< ocean/sea_classify.frag's SeaClassRows
  /// ocean/grid_vertex_buffer.glsl's GridVertices and its vec4s per vertex.
  static constexpr GLuint kGridVerticesBinding = 4;
  /// The vertices' near-land and floor flags (gl::kGlobePixelsBinding's too: each pass binds its own).
  static constexpr GLuint kGridNearLandBinding = 2;
  static constexpr int kGridVertexVec4s = 10;
  /// ocean/grid_vertex_buffer.glsl's GridRadianceTerms and its vec4s per vertex
  /// (ocean/radiance_terms.glsl's SEA_RADIANCE_VEC4S).
  static constexpr GLuint kGridRadianceTermsBinding = 7;  ///< kNearLandIndicesBinding's too (GL 4.5 guarantees 0-7): each pass binds its own
  static constexpr int kGridRadianceTermsVec4s = 10;
  /// All the grid's vertices by `compute` (ocean/grid_vertices.comp, its uniforms set) into
  /// gridVertices_, and with `radianceTerms` their radiance terms into gridRadianceTerms_:
  /// llvmpipe shades a draw's vertices on one thread, a dispatch on every core.
  void computeGridVertices(const gl::Program& compute, bool radianceTerms);
  /// The deferred sea's surface pass: its program (the variant for `key`: kFeatureWaterVolume,
  /// kFeatureCoastTest and kSurfaceClasses bits, compiled on first use) and, before its draw,
  /// all the grid's vertices computed by the matching compute pass into gridVertices_ (llvmpipe
  /// shades a draw's vertices on one thread, a dispatch on every core). `prepareProgram` sets a
  /// program's uniforms for the frame.
  const gl::Program& prepareSurfacePass(unsigned key, const std::function<void(const gl::Program&)>& prepareProgram);
  /// prepareSurfacePass's vertices alone (also drawForwardSplit's): the compute variant for
  /// `key`, its uniforms set by `prepareProgram`, run into gridVertices_ (and the classes'
  /// per-vertex flags with kSurfaceClasses).
  void computeSurfaceVertices(unsigned key, const std::function<void(const gl::Program&)>& prepareProgram);
  /// The surface pass's key bit for the sea's classes (OCEAN_SEA_CLASSIFY).
  static constexpr unsigned kSurfaceClasses = 4;
  /// The defines of the surface pass's programs for `key` (as prepareSurfacePass).
  [[nodiscard]] std::vector<std::string> surfaceDefines(unsigned key) const;
  /// Whether a surface pass of key `surfaceKey` writes the compact layout (SEA_SURFACE_COMPACT).
  static bool surfaceCompact(unsigned surfaceKey);
  /// The surface pass's program for `key` (as prepareSurfacePass), compiled on first use.
  const gl::Program& surfaceProgram(unsigned key);
  /// The visibility buffer's surface pass (ocean/sea_visibility.vert/.frag), compiled on first
  /// use; with `classes` the deep triangles' of a frame in classes (SEA_VISIBILITY_CLASSES).
  const gl::Program& visibilityProgram(bool classes = false);
  /// The stencil's class of the deep triangles' open-sea pixels drawn through the visibility
  /// buffer in a frame in classes (drawDeferred), + 1 for their shadows' (after kSeaClasses').
  static constexpr int kVisibilityClass = 6;
  /// classRows_'s ints: each class's first and last row, then whether each of the visibility
  /// buffer's two classes has a pixel (ocean/sea_visibility.frag).
  static constexpr std::size_t kClassRowsInts = 2 * kSeaClasses + 2;
  /// Whether the grid's vertex records fit one buffer texture (bindGridTexels).
  [[nodiscard]] bool gridTexelsFit() const;
  class ClassDispatches;
  /// A deferred class's pass with `program()` (taken after the pass's timer mark;
  /// `prepareProgram` sets its uniforms) over the stencil's `stencilClass`, timed as class
  /// `pass` (0-based), drawn and counted as class `counted` (kSeaClasses: not counted, as a
  /// frame without classes); by `dispatches` where given, else by a full-screen draw.
  void shadeClass(const std::function<const gl::Program&()>& program, int stencilClass, std::size_t pass,
                  std::size_t counted, const std::function<void(const gl::Program&)>& prepareProgram,
                  const ClassDispatches* dispatches = nullptr);
  /// Its draw alone, `p` in use (its samples added to classSamples_ where counted, `counted`
  /// < kSeaClasses).
  void shadeClassPixels(int stencilClass, std::size_t counted);
  /// The grid's index list split in three copies by ocean/grid_near_land.comp (after the surface
  /// pass's vertices): nearLandIndices_ with only the triangles where land may be near (the others
  /// degenerate), floorIndices_ with the others that have a floor within the water's reach, and
  /// deepIndices_ with the rest, so that only the near-land draw pays for the coast test and the
  /// deep draw writes the compact layout (llvmpipe runs a fragment shader's every line whatever
  /// its conditions). `key`: the surface pass's, with classes.
  void splitNearLand(unsigned key);
  /// Without stencil export (gl::DriverProfile::stencilExport): copies the surface pass's
  /// classes from the surface buffer into the bound framebuffer's stencil, a pass per bit
  /// (ocean/sea_class_stencil.frag).
  void classesIntoStencil();
  /// drawGrid with another index list of the same layout (splitNearLand's).
  void drawGridIndices(const gl::Program& p, const gl::Buffer& indices) const;
  /// The forward sea with the grid's triangles in three classes (forwardSplit_): near land
  /// with every feature, over a floor within reach without the coast test, the rest without
  /// the water volume too; the vertices from the compute pass (computeGridVertices,
  /// splitNearLand).
  void drawForwardSplit(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                        const ocean::OceanFrame& frame, const OceanLighting& lighting, double amplitudeScale,
                        const WindTextures& wind, unsigned features, const glm::vec4& margin);
  /// ocean/grid_near_land.comp's buffers: the grid's indices, its three copies (the deep list's
  /// binding is kClassRowsBinding's: drawDeferred binds the class rows there after the split).
  static constexpr GLuint kGridIndicesBinding = 5, kFloorIndicesBinding = 6, kNearLandIndicesBinding = 7,
                          kDeepIndicesBinding = 3;
  static constexpr int kFoldRows = 2;
  /// The index buffer's blocks of cells (ensureGrid): rows, columns.
  static constexpr int kGridBlockRows = 16, kGridBlockColumns = 16;
  /// The sea in classes (shaders/ocean/sea_classify.frag): one cheap draw of the grid writes
  /// each pixel's class into the stencil, then each class is drawn by the program with only the
  /// `features` it needs (the open sea without the water volume, the coast test and the shadows;
  /// the shadows' reach without the water volume and the coast test; the floor within reach
  /// without the coast test and the shadows; the floor within the shadows' reach without the
  /// coast test; land near with all), stencil-tested before its
  /// shader runs. The stencil is left 0. Needs a stencil buffer in the bound framebuffer.
  void drawClassified(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                      const ocean::OceanFrame& frame, const OceanLighting& lighting,
                      double amplitudeScale, const WindTextures& wind, unsigned features,
                      const glm::vec4& margin);
  /// The sea deferred: one draw of the grid writes, per pixel, its nearest fragment's values into
  /// the surface buffer (shaders/ocean/sea_surface.frag; the coast test there) and its class
  /// into the stencil; then each class present is shaded by a full-screen pass of its program
  /// (ocean.frag with OCEAN_DEFERRED), stencil-tested: every pixel is shaded once, where the
  /// grid's own fragments shade the blocks along every triangle's edges twice on llvmpipe.
  /// `depthStencil`: the bound framebuffer's (SeaSurfaceBuffer::boundDepthStencil;
  /// multisampled, the visibility buffer's frames only: deferredServes). The stencil is left 0.
  void drawDeferred(const geo::CameraView& view, int width, int height, const OceanPatterns& patterns,
                    const ocean::OceanFrame& frame, const OceanLighting& lighting, double amplitudeScale,
                    const WindTextures& wind, unsigned features, const glm::vec4& margin,
                    SeaSurfaceBuffer::DepthStencil depthStencil);
  /// drawDeferred's arguments, for its two steps.
  struct DeferredSea {
    const geo::CameraView& view;
    int width, height;
    const OceanPatterns& patterns;
    const ocean::OceanFrame& frame;
    const OceanLighting& lighting;
    double amplitudeScale;
    const WindTextures& wind;
    unsigned features;
    glm::vec4 margin;
    SeaSurfaceBuffer::DepthStencil depthStencil;
    /// prepare() for `p` with `programFeatures`.
    void prepare(const OceanRenderer& r, const gl::Program& p, unsigned programFeatures) const {
      r.prepare(p, view, height, patterns, frame, lighting, amplitudeScale, wind, programFeatures, margin);
    }
  };
  /// What drawDeferred's surface pass left for its shading.
  struct SeaSurfaceDrawn {
    bool classes = false;           ///< the surface pass wrote classes (surfaceClasses)
    bool visibility = false;        ///< the visibility buffer holds the whole sea (visibilityServes)
    bool deepByVisibility = false;  ///< in classes, the deep triangles' in the visibility buffer
    bool seaVisible = false;        ///< any sample of sea was drawn
    unsigned routedShadows = 0;     ///< setClassUniforms'
    std::array<GLint, 2 * kSeaClasses> rows{};  ///< each class's first and last row (noClassRows)
    std::array<GLint, 2> seen{};    ///< the visibility buffer's open sea and shadows have a pixel
    GLint target = 0;               ///< the draw framebuffer the shading writes to
  };
  /// drawDeferred's step 1: the surface pass into the surface or visibility buffer, the classes
  /// into the stencil; the draw framebuffer is left the surface buffer's.
  SeaSurfaceDrawn drawSeaSurface(const DeferredSea& sea);
  /// drawDeferred's step 2: each class present shaded into `drawn.target` by full-screen
  /// passes or compute dispatches (multisampled: into the single-sampled image that
  /// copySeaRadiance copies to the samples after). `display`: kFeatureDisplay where the one
  /// class's pass writes the display (the bound framebuffer then its: ScopedDisplayTarget), else 0.
  void shadeSeaClasses(const DeferredSea& sea, const SeaSurfaceDrawn& drawn, unsigned display);
  /// Sets the classifying uniforms of sea_class.glsl on `p`; returns the shadows routed to
  /// classes (kFeatureShadows or 0).
  unsigned setClassUniforms(const gl::Program& p, const geo::CameraView& view, const OceanPatterns& patterns,
                            const OceanLighting& lighting, double amplitudeScale, unsigned features) const;
  /// Each class's features (sea_classify.frag's list) given the frame's and the routed shadows.
  static std::array<unsigned, kSeaClasses> classFeatures(unsigned features, unsigned routedShadows);
  /// Per class, no row yet (first kNoRow, last -1): the classes' row bounds before a draw.
  static std::array<GLint, 2 * kSeaClasses> noClassRows();
  /// Clears the classes' row bounds and binds their buffer.
  void resetClassRows();
  /// The classifying program (ocean/sea_classify.frag, compiled on first use) prepared for this
  /// frame, its row bounds cleared; returns the shadows routed to classes (setClassUniforms).
  unsigned prepareClassify(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                           const ocean::OceanFrame& frame, const OceanLighting& lighting, double amplitudeScale,
                           const WindTextures& wind, unsigned features, const glm::vec4& margin);
  /// Whether any of the grid's sea passes the depth test (the classifying draw in an occlusion
  /// query, writing nothing).
  bool seaShows(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                const ocean::OceanFrame& frame, const OceanLighting& lighting, double amplitudeScale,
                const WindTextures& wind, unsigned features, const glm::vec4& margin);
  /// The filtered model's defines with `features` (bits of kFeature*) compiled in.
  [[nodiscard]] std::vector<std::string> featureDefines(unsigned features) const;
  /// The frame's features (kFeature* bits) for `model`: the sea floor, land and the terrain's
  /// shadows as `lighting` has them, the sky's frame layer where it serves (prepared here), and
  /// the caustics updated where the floor is in reach.
  unsigned frameFeatures(const geo::CameraView& view, const OceanPatterns& patterns, double timeS,
                         const OceanLighting& lighting, OceanModel model);
  /// Whether the filtered model's forward draw with `features` goes through the sea's classes
  /// (drawClassified).
  [[nodiscard]] static bool drawsClassified(const OceanLighting& lighting, unsigned features);
  /// The smallest of the whole sea's slope variances along and across the wind (per-wind
  /// tables, bands and tail) at the winds the frame may meet: the constant wind's two table
  /// columns, or every column up to the wind layers' fastest.
  [[nodiscard]] static double slopeVarianceFloor(const OceanPatterns& patterns, const WindTextures& wind);
  /// The smallest and largest zenith angles (rad) at which the view's rays (corners, edges'
  /// middles, centre) meet the sea (the sphere of the semi-major axis): 0 for the smallest with
  /// the nadir in view, pi/2 for the largest if a ray misses it.
  [[nodiscard]] static glm::dvec2 seaZenithRangeRad(const geo::CameraView& view);
  /// The largest cell (rad) for the vertices' radiance quadratic: kRadianceTermsMaxCellLobes
  /// of the glint's narrowest lobe across the view, 2 sigma cos(theta), sigma² the
  /// slopeVarianceFloor and theta the view's zenith angle where the Sun's glint lies (90° less
  /// its elevation at the camera), within seaZenithRangeRad; and kGrownCellMaxRad at most.
  [[nodiscard]] static double radianceTermsMaxCellRad(const geo::CameraView& view, const glm::dvec3& sunDirectionEcef,
                                                      const OceanPatterns& patterns, const WindTextures& wind);
  /// The cell size (pixels) grown kGrownCellFactor- or 2-fold, the largest no wider than
  /// `maxCellRad` (rad), or cellPixels_ if none is.
  [[nodiscard]] int grownCellPixels(const geo::CameraView& view, int height, double maxCellRad) const;
  /// The grid's rows for frameCellPixels_ (gridRowsNdc_, gridCoarseRows_) and its buffers.
  void layOutGrid(const geo::CameraView& view, int width, int height, double side, double bottom, OceanModel model);
  /// The grid of the radiance terms' cells (frameCellPixels_: 16 or 32 with the default 8-px
  /// cells; the blocks' edges are met when it is a multiple of 4): its vertices on
  /// whole pixels every frameCellPixels_ from the screen's corner, where ocean/grid_vertex.glsl
  /// keeps them (OCEAN_RADIANCE_TERMS: the waves move no point by half a pixel there), so that
  /// the cells' edges lie between llvmpipe's 4 x 4 pixel blocks: a block an edge crosses is
  /// shaded by the triangles on both sides (sea-8km at 1280x720: 1.60 fragment shader
  /// invocations a pixel with the grid's usual layout, 1.19 on the blocks). Returns the grid's
  /// margin (uGridMarginNdc: left, right, bottom, top).
  glm::vec4 layOutGridOnBlocks(int width, int height);
  /// The deferred sea's shading program for `features` (coast test excluded), compiled on first
  /// use: a full-screen fragment pass, or with `compute` ocean.frag as a compute shader
  /// (OCEAN_COMPUTE: ClassDispatches).
  /// With `visibility` (and `compute`), the pixels' values from the visibility buffer
  /// (SEA_VISIBILITY: ocean/sea_visibility.glsl).
  /// (`multisampled`: SEA_VISIBILITY_MULTISAMPLE, with `compute` only).
  const gl::Program& deferredProgram(unsigned features, bool compute, bool visibility = false,
                                     bool multisampled = false);
  /// Whether the frame's surface pass writes the sea's classes (a floor or a coast to route).
  [[nodiscard]] static bool surfaceClasses(const OceanLighting& lighting, unsigned features);
  /// Whether a frame of `features` may be drawn deferred over a depth-stencil texture of
  /// `samples` a pixel (its sea with `classes` or not; `computeFloors`: computeForFloors_'s frame).
  [[nodiscard]] bool deferredServes(int samples, unsigned features, bool classes, bool computeFloors) const;
  /// Whether a frame's deferred sea (`features`, with `classes` or not) goes through the
  /// visibility buffer: visibility_, one class, no coast test, the grid's records within a
  /// buffer texture.
  [[nodiscard]] bool visibilityServes(unsigned features, bool classes) const;
  /// The texture of framebuffer `target`'s colour if compute shaders can write it (a
  /// single-sampled RGBA32F texture, no auxiliary channels), else 0.
  [[nodiscard]] static GLuint computeImageOf(GLuint target);
  /// A frame's class dispatches (drawDeferred) into `image`, the classes read from
  /// `depthStencil`'s stencil (with stencil export) or the surface buffer: the bindings and the
  /// stencil's texture state set once for all and put back by the destructor.
  class ClassDispatches {
   public:
    ClassDispatches(GLuint image, GLuint depthStencil);
    ~ClassDispatches();
    ClassDispatches(const ClassDispatches&) = delete;
    ClassDispatches& operator=(const ClassDispatches&) = delete;
    /// Shades class `seaClass` (1..kSeaClasses) with `p` (deferredProgram's compute one, in use).
    void dispatch(const gl::Program& p, int seaClass) const;

   private:
    GLuint depthStencil_;  ///< 0 without stencil export
    GLint width_ = 0, height_ = 0, mode_ = 0, minFilter_ = 0, magFilter_ = 0;
  };
  /// How far from land (m along the sea) the terrain's shadows can fall on the sea's surface or
  /// on the floor seen through it: the casters' height over the tangent of the Sun's elevation
  /// (the longest shadow on the sea), plus, with the water volume, how far from its pixel the
  /// floor's shadow is looked up (ocean/water_volume.glsl's floorSunVisibility: the refracted
  /// view ray's horizontal run to a floor within the water's reach `waterReachM`, at most
  /// waterReachM, and the refracted Sun ray's back up, at most its depth x tan 48.3°, the
  /// critical angle: 1.13 waterReachM); 0 when no caster rises above the sea. Negative where
  /// the shadows are not routed (no shadow maps, the Sun within 1° of the horizon).
  /// `towardsSunM` (if given) receives the casters' part alone, the distance from a sea point
  /// towards the Sun within which a caster can shade it, and `casterHeightM` the casters'
  /// height it divides (0 where not routed).
  [[nodiscard]] static double shadowReachM(const OceanLighting& lighting, const geo::CameraView& view,
                                           bool volume, double waterReachM, double* towardsSunM = nullptr,
                                           double* casterHeightM = nullptr);
  /// Whether the bound draw framebuffer has a stencil buffer.
  [[nodiscard]] static bool drawTargetHasStencil();
  /// Whether the bound draw framebuffer has --aov's second colour attachment.
  [[nodiscard]] static bool drawTargetHasAuxiliary();
  /// A multisampled deferred frame's single-sampled sea radiance, for its compute shading
  /// (seaRadiance_, `width` x `height`, made on first use; a full-screen pass per pixel cost
  /// llvmpipe twice as much, every pixel shaded: docs/performance.md, "Thirty-fifth session").
  GLuint seaRadianceImage(int width, int height);
  /// Binds gridVertices_ (and with `radianceTerms` gridRadianceTerms_) as the buffer textures
  /// the passes after computeGridVertices read (gl::kUnitSeaGridVertices, kUnitSeaGridTerms).
  void bindGridTexels(bool radianceTerms);
  /// Binds the visibility buffer and indices_ (gl::kUnitSeaGridIndices) for the shading passes.
  void bindVisibilityForShading();
  /// While alive, draws go to the display (setDisplayTarget's framebuffer) with the sRGB store
  /// on, for OUTPUT_DISPLAY variants; then the draw framebuffer bound before is bound again.
  class ScopedDisplayTarget {
   public:
    explicit ScopedDisplayTarget(GLuint displayFbo);
    ~ScopedDisplayTarget();
    ScopedDisplayTarget(const ScopedDisplayTarget&) = delete;
    ScopedDisplayTarget& operator=(const ScopedDisplayTarget&) = delete;

   private:
    GLint bound_ = 0;
  };
  /// Binds `target` and writes seaRadiance_ into its samples with sea (the stencil's class 1:
  /// ocean/sea_radiance_copy.frag).
  void copySeaRadiance(GLuint target);

  static constexpr unsigned kFeatureWaterVolume = 1, kFeatureCoastTest = 2, kFeatureShadows = 4;
  /// The sky maps' frame layer alone (Atmosphere::prepareFrameSkyLayer) instead of two layers
  /// blended per pixel: where every sea point in view is within kFrameSkyMaxAngleRad of the
  /// camera's nadir (angle at the Earth's centre, farthestSeaAngleRad), so that the Sun's zenith
  /// angle varies by no more than that across the sea in view: the sea from a few metres (the
  /// horizon 7 km away at 4 m: 0.06°), or looking down from a few km (sea-8km: 0.70°).
  static constexpr unsigned kFeatureFrameSky = 8;
  /// The radiance from the vertices' quadratic (OCEAN_RADIANCE_TERMS, setRadianceTerms).
  static constexpr unsigned kFeatureRadianceTerms = 16;
  /// The vertices from the compute pass (ocean/grid_cached.vert), the bands per pixel
  /// (drawForwardSplit).
  static constexpr unsigned kFeatureCachedVertices = 32;
  /// The display's tone-mapped colour instead of the radiance (OUTPUT_DISPLAY, setDisplayTarget).
  static constexpr unsigned kFeatureDisplay = 64;
  const Atmosphere* atmosphere_;
  ValidationMode mode_;
  std::vector<std::string> defines_;        ///< the filtered model's, whatever the features
  bool deferred_;                           ///< setDeferred
  /// Deferred in every frame where the driver cannot export stencil values (NVIDIA's): only when
  /// asked, OCEANGLOBE_SEA=deferred or compute (computeForFloors_ otherwise); where compute
  /// cannot serve (--aov, counted samples) the classes then go into the stencil by the copy passes.
  bool deferredWithoutExport_;
  /// The deferred classes shaded by compute shaders (OCEANGLOBE_SEA=compute; frameComputeImage_):
  /// for GPUs whose pixel shaders are few (the H200's: docs/performance.md, "Thirty-second session");
  /// slower on llvmpipe (sea-4m's open sea 105 -> 175 ms of one thread).
  bool computeShading_;
  /// Where a deferred frame's sea has one class, the surface pass writes each pixel's grid
  /// triangle alone (a visibility buffer, ocean/sea_visibility.frag) and the shading
  /// interpolates the triangle's vertices; multisampled frames' open sea, otherwise forward,
  /// goes deferred so too, each pixel shaded once by compute shaders and its radiance written
  /// to its samples with sea. As the driver profile says (gl::DriverProfile::seaByVisibility:
  /// llvmpipe), or OCEANGLOBE_SEA_SURFACE.
  bool visibility_;
  gl::Program visibilityProgram_, visibilityClassesProgram_;  ///< visibilityProgram's; id() 0 until first used
  gl::Texture seaRadiance_;  ///< seaRadianceImage's
  gl::Texture gridVertexTexels_, gridTermsTexels_, gridIndexTexels_;  ///< bindGridTexels's views of the buffers
  int seaRadianceWidth_ = 0, seaRadianceHeight_ = 0;
  gl::Program seaRadianceCopy_;    ///< ocean/sea_radiance_copy.frag; id() 0 until first used
  /// A forward frame with a floor or a coast to route draws the grid's triangles in three
  /// classes (drawForwardSplit), each program with only what they need, where the pixels cannot
  /// be classed (that needs stencil export): by default without stencil export (NVIDIA's: its
  /// multisampled frames, the GPU default, and its single-sampled ones without a floor), with
  /// OCEANGLOBE_SEA=split also where export exists but the frame is drawn forward without the
  /// classified path (a target without stencil). Measured on llvmpipe without
  /// export: sea-2m-horizon 208 -> 157 ms, coast-2m-bank 432 -> 344 (1280x720, one sample);
  /// not yet on a GPU (docs/performance.md, "Thirty-third session").
  bool forwardSplit_;
  /// A GPU without stencil export (NVIDIA's), OCEANGLOBE_SEA unset: the frames whose sea has a
  /// floor within reach (the water volume) drawn deferred, their classes shaded by compute
  /// shaders; the others forward. Measured on the H200 at 1080p, forward against by compute:
  /// coast-2m-bank 22.9 against 11.4 ms; sea-4m 6.6 against 7.3, coast-2m-deep (the coast
  /// test) 7.2 against 8.2, sea-2m-horizon 11.9 against 12.0 (docs/performance.md,
  /// "Thirty-third session").
  bool computeForFloors_;
  /// This frame's target's texture where its deferred classes are shaded by compute shaders
  /// (computeShading_ or computeForFloors_'s; computeImageOf, the classes' samples not
  /// counted: draw); 0: by full-screen draws.
  GLuint frameComputeImage_ = 0;
  /// The programs that read the wave patterns, each compiled on first use: set 1 with
  /// PATTERN_ONE_BIN and PATTERN_CONSTANT_WIND (a constant wind along one of the patterns'
  /// direction bins: one bin's lookups, the wind, its bin and the tables' values as uniforms;
  /// windAlongOneBin), set 0
  /// without.
  struct PatternPrograms {
    std::array<gl::Program, 128> variants;   ///< by feature bits
    gl::Program classify;                    ///< ocean/sea_classify.frag
    /// ocean.frag OCEAN_DEFERRED, by feature bits, + 16 with OCEAN_COMPUTE, + 32 with
    /// SEA_VISIBILITY, + 64 with SEA_VISIBILITY_MULTISAMPLE, + 128 with OUTPUT_DISPLAY
    std::array<gl::Program, 256> deferredVariants;
    std::array<gl::Program, 8> surfaceVariants;    ///< sea_surface.frag: volume, coast, classes bits
    std::array<gl::Program, 8> gridComputeVariants;  ///< grid_vertices.comp, as surfaceVariants
    /// grid_vertices.comp with the radiance terms, by feature bits (kFeatureRadianceTerms's aside)
    std::array<gl::Program, 16> termsComputeVariants;
    gl::Program nearLandSplit;  ///< ocean/grid_near_land.comp
  };
  std::array<PatternPrograms, 2> programSets_;
  std::size_t programSet_ = 0;  ///< this frame's (draw)
  PatternPrograms& programs() { return programSets_.at(programSet_); }
  /// defines_ with this frame's set's (PATTERN_ONE_BIN, PATTERN_CONSTANT_WIND).
  [[nodiscard]] std::vector<std::string> patternDefines() const;
  bool oneBinAllowed_ = true;
  gl::Buffer gridVertices_;  ///< the surface pass's vertices (ocean/grid_vertex_buffer.glsl)
  gl::Program classStencil_;   ///< ocean/sea_class_stencil.frag; id() 0 until first used
  gl::Buffer floorIndices_, nearLandIndices_, deepIndices_;  ///< splitNearLand's copies of indices_
  std::size_t floorIndicesBytes_ = 0, nearLandIndicesBytes_ = 0, deepIndicesBytes_ = 0;
  std::size_t gridVerticesBytes_ = 0;
  gl::Buffer gridRadianceTerms_;  ///< the radiance terms' vertices' (ocean/grid_vertex_buffer.glsl)
  std::size_t gridRadianceTermsBytes_ = 0;
  gl::Buffer gridNearLand_;  ///< flags a vertex for the split (near land, floor: ocean/grid_vertex_buffer.glsl)
  std::size_t gridNearLandBytes_ = 0;
  SeaSurfaceBuffer surface_;
  bool lastDeferred_ = false;
  bool lastForwardSplit_ = false;  ///< lastDrawForwardSplit
  bool lastClassesByCompute_ = false;  ///< lastClassesByCompute
  bool lastSurfaceCompact_ = false;
  bool lastSurfaceByVisibility_ = false;  ///< lastSurfaceByVisibility
  unsigned classesDrawn_ = 0;  ///< classesDrawn()
  bool countClassSamples_ = false;
  std::array<std::uint64_t, kSeaClasses> classSamples_{};
  gl::Buffer classRows_;  ///< per class, the first and last grid row of its fragments (kClassRowsInts)
  CausticCurvature caustics_;  ///< the water volume's caustics (render/WaterVolume)
  gl::Program classic_;      ///< id() 0 until first used, as the next two
  gl::Texture bumpMap_;      ///< classic: tileable ripple normals, mip-mapped
  gl::Texture fresnelRamp_;  ///< classic: water colour and Fresnel by N.V
  gl::VertexArray vao_;
  gl::Buffer indices_;
  int gridColumns_ = 0, gridRows_ = 0;
  /// Vertex rows this frame computes and draws: from the bottom up to the band of kGridBlockRows
  /// that holds the sea's top (layOutGrid; all of them for the classic model).
  int gridRowsDrawn_ = 0;
  bool gridToSeaTop_ = true;  ///< setGridToSeaTop
  int indexCount_ = 0;
  int cellPixels_ = 8;
  /// Rows below the screen deeper than this (NDC) are coarse: only waves lifting a point by
  /// more than that (180 px at 720p, 45° tall) bring them into view.
  static constexpr double kGridFineBottomNdc = 0.5;
  static constexpr int kGridCoarseFactor = 4;  ///< coarse rows' height in fine rows
  glm::vec4 gridRowsNdc_{0.0f};  ///< grid.vert's uGridRowsNdc
  int gridCoarseRows_ = 0;       ///< grid.vert's uGridCoarseRows
  int frameCellPixels_ = 8;  ///< this frame's: cellPixels_, or grown (geometryIsSubPixel)
  bool cellGrowth_ = true;
  bool radianceTerms_ = true;
  bool lastRadianceTerms_ = false;
  bool lastCoversScreen_ = false;
  GLuint displayFbo_ = 0;  ///< setDisplayTarget's, for the next draw
  GLuint frameDisplayFbo_ = 0;  ///< this draw's
  float displayExposure_ = 1.0f;
  bool lastWroteDisplay_ = false;
  glm::vec4 lightingTerms_{1.0f};
  glm::vec4 elevationMap_{0.0f};
  glm::vec2 elevationSize_{0.0f};
  int elevationWraps_ = 0;
  float layerMaxSlope_ = 1e6f;  ///< unknown: any layer height is near land
  gl::PassTimer* timer_ = nullptr;
};

}  // namespace og::render
