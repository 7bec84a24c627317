#include "render/GlobeRenderer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <string_view>
#include <memory>
#include <cstdint>
#include <future>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "core/HalfFloat.hpp"
#include "core/Log.hpp"
#include "core/StartupTrace.hpp"
#include "gl/DriverProfile.hpp"
#include "gl/Readback.hpp"
#include "gl/ShaderContract.hpp"
#include "ocean/WaterOptics.hpp"
#include "render/GlobeBlocks.hpp"
#include "render/WaterVolume.hpp"

namespace og::render {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

glm::vec3 toFloat(const glm::dvec3& v) { return glm::vec3(v); }

/// Grows `box` (pixels: x0, y0, x1, y1, lower-left origin) to hold the cone of directions within
/// `halfAngleRad` of `axis` (unit, ECEF) as the view projects it, sampled on its rim; false
/// when the cone reaches behind the eye (`box` is then the whole screen's business).
bool addCone(const geo::CameraView& view, int width, int height, const glm::dvec3& axis,
             double halfAngleRad, glm::dvec4& box) {
  const glm::dvec3 u = glm::normalize(glm::cross(axis, std::abs(axis.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
  const glm::dvec3 v = glm::cross(axis, u);
  const double tanY = std::tan(0.5 * view.verticalFovRad), tanX = tanY * view.aspect;
  constexpr int kRim = 96;
  for (int i = 0; i < kRim; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / kRim;
    const glm::dvec3 d = std::cos(halfAngleRad) * axis +
                         std::sin(halfAngleRad) * (std::cos(phi) * u + std::sin(phi) * v);
    const double z = glm::dot(d, view.forward);
    if (z <= 1e-6) return false;
    const double x = (glm::dot(d, view.right) / (z * tanX) + 1.0) * 0.5 * width;
    const double y = (glm::dot(d, view.up) / (z * tanY) + 1.0) * 0.5 * height;
    box = glm::dvec4(std::min(box.x, x), std::min(box.y, y), std::max(box.z, x), std::max(box.w, y));
  }
  return true;
}

/// `box` (pixels: x0, y0, x1, y1) with two pixels of margin, clamped to the screen (clamped in
/// double first: a cone's rim just in front of the eye projects arbitrarily far), as a scissor
/// rectangle (x, y, width, height).
std::array<int, 4> scissorOf(const glm::dvec4& box, int width, int height) {
  auto clamped = [](double v, int lo, int hi) { return static_cast<int>(std::clamp(v, double(lo), double(hi))); };
  const int x0 = clamped(std::floor(box.x) - 2.0, 0, width), y0 = clamped(std::floor(box.y) - 2.0, 0, height);
  const int x1 = clamped(std::ceil(box.z) + 2.0, x0, width), y1 = clamped(std::ceil(box.w) + 2.0, y0, height);
  return {x0, y0, x1 - x0, y1 - y0};
}
}  // namespace

std::array<int, 4> globeScissor(const geo::CameraView& view, int width, int height,
                                const atmosphere::Parameters& atmosphere,
                                const glm::dvec3& sunDirectionEcef) {
  const std::array<int, 4> screen{0, 0, width, height};
  glm::dvec4 box(1e30, 1e30, -1e30, -1e30);
  // The ellipsoid lies within the sphere of radius a (+1 km); the sky is the atmosphere's
  // sphere under the eye (globe.frag: radius top, centre R + h below the eye along the normal).
  const double eyeM = glm::length(view.positionEcef);
  const double r = atmosphere.bottomRadiusM + view.position.heightM;
  const double sinGlobe = (geo::kWgs84SemiMajorM + 1000.0) / eyeM;
  const double sinSky = (atmosphere.topRadiusM() + 1000.0) / r;
  if (sinGlobe >= 0.99 || sinSky >= 0.99) return screen;
  // 1 % wider: the rim's samples are chords of the projected ellipse.
  if (!addCone(view, width, height, -view.positionEcef / eyeM, 1.01 * std::asin(sinGlobe), box) ||
      !addCone(view, width, height, -view.enu.up, 1.01 * std::asin(sinSky), box))
    return screen;
  // The Sun's disc in space (globe.frag's sky part paints it there too), when in front.
  const glm::dvec3 sun = glm::normalize(sunDirectionEcef);
  if (glm::dot(sun, view.forward) > 0.0 &&
      !addCone(view, width, height, sun, 2.0 * atmosphere.sunAngularRadiusRad, box))
    return screen;
  // Two pixels of margin, clamped to the screen (an empty box draws nothing: no globe in view).
  return scissorOf(box, width, height);
}

RayScissors rayScissors(const geo::CameraView& view, int width, int height) {
  // (x0, y0, x1, y1) of the rays that hit, then of those that miss.
  std::array<std::array<int, 4>, 2> box{};
  box.fill({width, height, -1, -1});
  for (int y = 0; y <= height + kHitScanPx - 1; y += kHitScanPx)
    for (int x = 0; x <= width + kHitScanPx - 1; x += kHitScanPx) {
      const int px = std::min(x, width), py = std::min(y, height);
      const glm::dvec3 dir = view.rayDirection(2.0 * px / width - 1.0, 2.0 * py / height - 1.0);
      std::array<int, 4>& b = box.at(geo::intersectEllipsoid(view.positionEcef, dir) ? 0 : 1);
      b = {std::min(b[0], px), std::min(b[1], py), std::max(b[2], px), std::max(b[3], py)};
    }
  constexpr int kMargin = kHitScanPx + 2;
  const auto widened = [&](const std::array<int, 4>& b) -> std::array<int, 4> {
    if (b[2] < 0) return {0, 0, 0, 0};
    const int x0 = std::max(b[0] - kMargin, 0), y0 = std::max(b[1] - kMargin, 0);
    return {x0, y0, std::min(b[2] + kMargin, width) - x0, std::min(b[3] + kMargin, height) - y0};
  };
  return {widened(box[0]), widened(box[1])};
}

namespace {
/// The layer as an RG16F texture: height (m) and keepDepth (the land mask leaves corrected
/// banks' depth alone: data/ShallowBanks) per texel; missing values (NaN) read as sea (-1 m).
/// Missing or unrepresentable values (NaN, beyond ±65504 m) read as sea (-1 m), as NaN did in
/// RG32F. Half floats: 1/1024 of the value (0.06 m at 100 m, 4 m at 8000 m), 4 bytes a texel
/// fewer than RG32F to clear, fill and copy at start-up (the default's 9.3 million: 71 -> 36 MiB).
gl::Texture elevationTexture(const data::LatLonGrid& elevation) {
  static_assert(std::endian::native == std::endian::little, "RG16F texels packed as R | G << 16");
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, GL_RG16F, elevation.width, elevation.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Converted and uploaded a band of rows at a time through one small buffer (a whole-layer
  // copy costs its page faults: ~20 ms for the default's 36 MiB).
  const auto width = static_cast<std::size_t>(elevation.width);
  const int bandRows = std::max(1, static_cast<int>((std::size_t{1} << 18) / width));
  std::vector<std::uint16_t> heights(width * static_cast<std::size_t>(bandRows)), keep(heights.size());
  std::vector<std::uint32_t> texels(heights.size());
  for (int row = 0; row < elevation.height; row += bandRows) {
    const int rows = std::min(bandRows, elevation.height - row);
    const std::size_t first = static_cast<std::size_t>(row) * width, n = static_cast<std::size_t>(rows) * width;
    core::floatsToHalves(elevation.values.data() + first, heights.data(), n);
    if (!elevation.keepDepth.empty()) core::floatsToHalves(elevation.keepDepth.data() + first, keep.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint16_t h = core::isHalfFinite(heights[i]) ? heights[i] : core::kHalfMinusOne;
      // R in the low half, G in the high (little-endian, as GL reads two GL_HALF_FLOATs).
      texels[i] = h | (elevation.keepDepth.empty() ? 0u : static_cast<std::uint32_t>(keep[i]) << 16);
    }
    glTextureSubImage2D(t.id(), 0, 0, row, elevation.width, rows, GL_RG, GL_HALF_FLOAT, texels.data());
  }
  return t;
}
}  // namespace

GlobeRenderer::GlobeRenderer(std::shared_ptr<const data::LatLonGrid> elevation,
                             const atmosphere::Parameters& atmosphere)
    : GlobeRenderer(std::move(elevation), std::make_shared<const Atmosphere>(atmosphere)) {}

GlobeRenderer::GlobeRenderer(std::shared_ptr<const data::LatLonGrid> layer,
                             std::shared_ptr<const Atmosphere> atmosphere)
    : atmosphere_(std::move(atmosphere)),
      tonemap_({{GL_VERTEX_SHADER, "render/fullscreen.vert"},
                {GL_FRAGMENT_SHADER, "render/tonemap.frag"}}),
      emptyVao_(gl::createVertexArray()),
      ocean_(std::make_unique<OceanRenderer>(atmosphere_.get())),
      wind_(std::make_unique<WindTextures>()) {
  if (!layer) throw InternalError("GlobeRenderer: no elevation layer");
  const data::LatLonGrid& elevation = *layer;
  if (elevation.width < 2 || elevation.height < 2)
    throw InternalError("elevation layer '" + elevation.name + "' is too small to render");
  // What the set-up needs of the layer on the CPU alone, on another core meanwhile.
  auto maxSlope = std::async(std::launch::async, [layer] { return layerMaxSlope(*layer); });
  const double reachM = ocean::waterMaxPathM(ocean::jerlovWater(ocean::kDefaultWater).attenuationPerM,
                                             ocean::kWaterEpsilon);
  // The open-sea map from the layer and the land mask where it decides the coast (as
  // LandMaskTexture below), with its texels: made on a helper thread, uploaded by the first
  // frame that needs it (bindOpenSeaMap). The open sea's floor must lie beyond the water's
  // reach (shallow.glsl's prepareWaterColumn), with a margin for the shader's float arithmetic.
  openSeaFuture_ = std::async(std::launch::async, [layer, reachM] {
    const data::LandMask& mask = data::defaultLandMask();
    auto map = std::make_unique<OpenSeaMap>(
        makeRendererOpenSeaMap(blockedByLayer(*layer, 1.5 * reachM), mask.refines(*layer) ? &mask : nullptr));
    std::vector<std::uint16_t> texels = openSeaTexels(*map);
    map->blocked = {};  // (20 MiB the renderer does not read: the texture holds the land's)
    map->landClearanceRad = {};
    return std::pair{std::move(map), std::move(texels)};
  });
  std::optional<core::startup::Scope> stage(std::in_place, "renderer: elevation texture");
  elevation_ = elevationTexture(elevation);
  glTextureParameteri(elevation_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(elevation_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(elevation_.id(), GL_TEXTURE_WRAP_S,
                      elevation.wrapsLongitude ? GL_REPEAT : GL_CLAMP_TO_EDGE);
  glTextureParameteri(elevation_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  elevationMap_ = glm::vec4(elevation.lon0Deg * kDeg, elevation.lat0Deg * kDeg,
                            elevation.dLonDeg * kDeg, elevation.dLatDeg * kDeg);
  elevationSize_ = glm::vec2(elevation.width, elevation.height);
  elevationWraps_ = elevation.wrapsLongitude ? 1 : 0;
  ocean_->setElevationLayer(elevationMap_, elevationSize_, elevationWraps_);
  stage.emplace("renderer: terrain set-up");
  terrain_ = std::make_unique<TerrainRenderer>(layer, atmosphere_.get());
  stage.emplace("renderer: imagery textures");
  imagery_ = std::make_unique<ImageryTextures>();
  terrain_->setImagery(imagery_.get());
  // The same rule as the terrain's heights (terrain::Heightfield): the mask decides the coast
  // of a global layer coarser than it.
  stage.emplace("renderer: land mask texture");
  const data::LandMask& mask = data::defaultLandMask();
  landMask_ = std::make_unique<LandMaskTexture>(mask.refines(elevation) ? &mask : nullptr);
  if (landMask_->active()) {  // (on helper threads from here on)
    maskPyramidFuture_ = std::async(std::launch::async, [&mask] { return std::make_unique<data::LandMaskPyramid>(mask); });
    fractionMipsFuture_ = std::async(std::launch::async, [&mask] { return std::make_unique<data::LandFractionMips>(mask); });
  }
  stage.emplace("renderer: layer's steepest slope (waiting)");
  ocean_->setLayerMaxSlope(maxSlope.get());  // the sea's classes (OceanRenderer)
  stage.reset();
  maxSamples_ = gl::maxSamples(GL_RGBA32F);
  blocksOn_ = gl::driverProfile().software;
  scatteredListed_ = gl::driverProfile().software;
  partGateOn_ = partsOverBlocks_ = gl::driverProfile().multisampleShadesEveryBlock;
  gl::checkErrors("GlobeRenderer setup");
}

void GlobeRenderer::ensureTargets(int width, int height, int requested, bool auxiliary) {
  if (hdr_.width == width && hdr_.height == height && requestedSamples_ == requested &&
      auxiliary_ == auxiliary)
    return;
  if (!isValidSampleCount(requested))
    throw InternalError("FrameInput::samples must be 0 (auto), 1, 2, 4 or 8, not " + std::to_string(requested));
  const int wanted = requested == kAutoSamples ? gl::driverProfile().autoSamples : requested;
  const int samples = std::min(wanted, maxSamples_);
  if (samples < wanted && warnedSamples_ != requested) {
    log::warn(std::to_string(wanted) + " samples per pixel asked for, but this OpenGL device "
              "offers at most " + std::to_string(maxSamples_) + ": using " + std::to_string(samples));
    warnedSamples_ = requested;
  }
  hdr_ = gl::createRenderTarget(width, height, GL_RGBA32F, true, samples, auxiliary ? GL_R32F : 0);
  auxiliary_ = auxiliary;
  // sRGB-encoded bytes: the tone map has the store encode them (below); read back and blitted
  // through a GL_RGBA8 view of them, which no driver decodes.
  ldr_ = gl::createRenderTarget(width, height, GL_SRGB8_ALPHA8, false);
  ldrBytes_ = gl::createViewTarget(ldr_, GL_RGBA8);
  displayOverDepth_ = hdr_.samples == 1 ? gl::createFramebufferOver(ldr_, hdr_) : gl::Framebuffer{};
  resolved_ = {};
  requestedSamples_ = requested;
  if (hdr_.samples != samples)
    log::info("the OpenGL device made " + std::to_string(hdr_.samples) + " samples per pixel of " +
              std::to_string(samples) + " asked for");
}

const gl::RenderTarget& GlobeRenderer::singleSampleHdr() const {
  if (hdr_.samples == 1) return hdr_;
  if (!resolvedCurrent_) {
    if (resolved_.width != hdr_.width || resolved_.height != hdr_.height)
      resolved_ = gl::createRenderTarget(hdr_.width, hdr_.height, GL_RGBA32F, true, 1, auxiliary_ ? GL_R32F : 0);
    // Colour: the mean of the samples, linear (the radiance an EXR should hold). Depth must
    // use GL_NEAREST; GL leaves its resolve to the driver (a value between the samples').
    glBlitNamedFramebuffer(hdr_.fbo.id(), resolved_.fbo.id(), 0, 0, hdr_.width, hdr_.height, 0,
                           0, hdr_.width, hdr_.height, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
                           GL_NEAREST);
    if (auxiliary_) {  // the auxiliary outputs: the mean of the samples too
      glNamedFramebufferReadBuffer(hdr_.fbo.id(), GL_COLOR_ATTACHMENT1);
      glNamedFramebufferDrawBuffer(resolved_.fbo.id(), GL_COLOR_ATTACHMENT1);
      glBlitNamedFramebuffer(hdr_.fbo.id(), resolved_.fbo.id(), 0, 0, hdr_.width, hdr_.height, 0, 0,
                             hdr_.width, hdr_.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      glNamedFramebufferReadBuffer(hdr_.fbo.id(), GL_COLOR_ATTACHMENT0);
      const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
      glNamedFramebufferDrawBuffers(resolved_.fbo.id(), 2, buffers);
    }
    gl::checkErrors("GlobeRenderer resolve");
    resolvedCurrent_ = true;
  }
  return resolved_;
}

const OceanPatterns& GlobeRenderer::patternsFor(double referenceWindMs, std::uint64_t seed) {
  if (patterns_ == nullptr || patterns_->patterns().params.seed != seed ||
      patterns_->requestedWindMs() != referenceWindMs) {
    ocean::WavePatternParams p;
    p.referenceWindMs = std::clamp(referenceWindMs, 0.0, 50.0);
    p.seed = seed;
    patterns_ = std::make_unique<OceanPatterns>(
        std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p)), referenceWindMs);
  }
  return *patterns_;
}

void GlobeRenderer::render(const FrameInput& f) {
  ensureTargets(f.width, f.height, f.samples, f.auxiliaryOutputs);
  resolvedCurrent_ = false;
  lastDisplayOnly_ = f.displayOnly;
  lastSeaWroteDisplay_ = false;
  const geo::CameraView view = geo::makeCameraView(f.camera, f.width, f.height);
  lastView_ = view;
  if (timer_ != nullptr) timer_->beginFrame();
  ocean_->beginFrame();
  partsGated_.clear();
  if (countPartSamples_) partSamples_.clear();  // (a frame that draws no globe part counts none)
  // The waves hold the strongest wind of the scene; every point scales and turns them to its
  // own wind (ocean/patterns.glsl).
  wind_->setConstantWind(f.wind);
  wind_->setTime(f.utcTime);  // layers that follow the clock (uploads only on a change)
  patternsFor(std::max(f.wind.speedMs, wind_->maxLayerSpeedMs()), f.waveSeed);
  const bool grid = view.position.heightM < kOceanGridMaxHeightM;
  aerialTableFrame_ = aerialTableOn_ && !grid && view.position.heightM < kAerialTableMaxHeightM;
  coarseMaskFrame_ = coarseMaskVariants_ && landMask_->fineLevelUnresolved(view, f.height);
  prepareFractionMips(view, f.height);
  constantWindFrame_ = constantWindVariants_ && !wind_->hasLayers();
  floorInReachFrame_ = false;  // (drawOcean's, below the ceiling)
  landInViewFrame_ = false;
  causticsSeenFrame_ = false;
  terrain_->setSeaCrestM(patterns_->amplitudeBoundM() + 1.0);  // (+ 1 m: the morph's and chords' rounding)
  terrain_->setCoarseLandMask(coarseMaskFrame_);
  terrain_->setFilteredLandMask(filteredMaskFrame_);
  terrain_->setLandFractionPyramid(fractionMipsFrame_);
  // Above the ceiling the globe's sea reads the Sun layers' radial sums: made once, before any of
  // its programs is bound (Atmosphere::bind sets their uniforms).
  if (!grid) atmosphere_->prepareSunLayerSums();

  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glBindFramebuffer(GL_FRAMEBUFFER, hdr_.fbo.id());
  glViewport(0, 0, f.width, f.height);
  const float clearColor[] = {0, 0, 0, 0};
  const float clearDepth = 0.0f;  // reversed-Z: 0 is infinitely far
  glClearNamedFramebufferfv(hdr_.fbo.id(), GL_COLOR, 0, clearColor);
  if (auxiliary_) glClearNamedFramebufferfv(hdr_.fbo.id(), GL_COLOR, 1, clearColor);
  glClearNamedFramebufferfi(hdr_.fbo.id(), GL_DEPTH_STENCIL, 0, clearDepth, 0);
  glEnable(GL_DEPTH_TEST);
  // gl::kUnitLandMask, its fine level and (in frames that read it) the pyramid, for every pass
  // (render/elevation.glsl)
  landMask_->bind(fractionMipsFrame_);
  if (!grid) classifyGlobe(view, f, grid);

  // Terrain over the globe's land (its far fallback), depth-tested; the ocean below is then
  // depth-tested against it, so the shoreline is where sea surface and ground meet. Above
  // 20 km its tiles all above the sea come first and mark the stencil where they draw, so the
  // globe's parts leave those pixels alone, and the tiles with water come after the globe,
  // over it (over its land class alone where their relief allows: setTilesOverLandClass),
  // but for the land's part, which comes after them where it can (frameLandLast_); below, the
  // globe comes last, shading only what the two left empty.
  terrain_->draw(view, f.width, f.height, f.sunDirectionEcef, !grid);
  glBindTextureUnit(gl::kUnitElevation, elevation_.id());
  glBindVertexArray(emptyVao_.id());
  if (grid) {
    drawOcean(view, f);
    if (!ocean_->lastDrawCoversScreen()) {  // else no pixel is left for the globe
      glDepthMask(GL_FALSE);
      classifyGlobe(view, f, grid);
      shadeGlobe(view, f, grid);
      glDepthMask(GL_TRUE);
    }
  } else {
    shadeGlobe(view, f, grid, frameLandLast_ ? GlobeParts::allButLand : GlobeParts::all);
    // The tiles with water over the land's class alone where their relief stays within half a
    // pixel of the ellipsoid's points the classes are of (setTilesOverLandClass).
    terrain_->drawWaterTiles(frameLandLast_ && tilesOverLandClass_ ? partStencilCount(kGlobePart0 + 4, grid) : 0);
    if (frameLandLast_) {
      shadeGlobe(view, f, grid, GlobeParts::land);
      glDepthFunc(GL_ALWAYS);  // as the other parts leave it
    }
  }

  if (timer_ != nullptr) timer_->mark("tone mapping");
  glDisable(GL_DEPTH_TEST);
  if (!(lastSeaWroteDisplay_ && ocean_->lastDrawCoversScreen())) toneMap(f, grid);  // (else no pixel but the sea's)
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (timer_ != nullptr) timer_->endFrame();
  gl::checkErrors("GlobeRenderer::render");
}

void GlobeRenderer::toneMap(const FrameInput& f, bool grid) {
  glBindFramebuffer(GL_FRAMEBUFFER, lastSeaWroteDisplay_ ? displayOverDepth_.id() : ldr_.fbo.id());
  // Above the ceiling nothing was drawn outside the globe's box (scissorToGlobe): the radiance
  // there is the clear's 0, black once tone mapped. Only the box is tone mapped (orbit: 40 % of
  // the screen), the rest cleared to black.
  const bool toneBoxed = !grid && scissorGlobe_ && globeBox_ != std::array<int, 4>{0, 0, f.width, f.height};
  if (toneBoxed) {
    const float black[] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(ldr_.fbo.id(), GL_COLOR, 0, black);
    glEnable(GL_SCISSOR_TEST);
    glScissor(globeBox_[0], globeBox_[1], globeBox_[2], globeBox_[3]);
  }
  if (hdr_.samples > 1 && tonemapMs_.id() == 0)  // compiled on first use (start-up)
    tonemapMs_ = gl::Program({{GL_VERTEX_SHADER, "render/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "render/tonemap.frag"}},
                             {"TONEMAP_MULTISAMPLE"});
  const gl::Program& tonemap = hdr_.samples > 1 ? tonemapMs_ : tonemap_;
  tonemap.set("uExposure", static_cast<float>(f.exposure));
  glBindTextureUnit(gl::kUnitToneRadiance, hdr_.color.id());
  tonemap.use();
  // The store encodes sRGB (llvmpipe's vector code: the shader's pow() was 3.3 ms of 9.3 at
  // 1280 x 720, one thread). Off again after: read-backs and blits take the bytes as stored.
  glEnable(GL_FRAMEBUFFER_SRGB);
  if (lastSeaWroteDisplay_)
    toneMapGlobePixels(f);
  else
    glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_SCISSOR_TEST);
}

void GlobeRenderer::toneMapGlobePixels(const FrameInput& f) {
  // Where the sea wrote the display, only the pixels it left without a depth remain, the
  // globe's (below the ceiling it shades only those and writes none): the depth test, equal
  // to the clear's 0 before the shader, leaves the sea's alone. They lie in the sky's box and,
  // where the rays hit the ellipsoid, in the blocks the classifying draw listed (those of the
  // uncovered pixels: listsUncoveredBlocks); without that list, anywhere.
  GLint depthFunc = GL_GREATER;
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  if (!listsUncoveredBlocks(true)) {
    glDrawArrays(GL_TRIANGLES, 0, 3);
  } else {
    glEnable(GL_SCISSOR_TEST);
    glScissor(frameSkyBox_[0], frameSkyBox_[1], frameSkyBox_[2], frameSkyBox_[3]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
    if (tonemapBlocks_.id() == 0)  // compiled on first use (start-up)
      tonemapBlocks_ = gl::Program({{GL_VERTEX_SHADER, "render/blocks.vert"}, {GL_FRAGMENT_SHADER, "render/tonemap.frag"}});
    tonemapBlocks_.set("uExposure", static_cast<float>(f.exposure));
    tonemapBlocks_.use();
    glBeginConditionalRender(uncovered_.query(), GL_QUERY_WAIT);  // (a frame with none lists none)
    uncovered_.drawBlocks();
    glEndConditionalRender();
    glBindVertexArray(emptyVao_.id());
  }
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(static_cast<GLenum>(depthFunc));
  glDepthMask(GL_TRUE);
}

void GlobeRenderer::prepareFractionMips(const geo::CameraView& view, int heightPx) {
  const bool weighed = fractionMipsOn_ && landMask_->fractionMipsWeighed(view, heightPx);
  if (weighed && !landMask_->fractionMipsUploaded()) {
    if (fractionMipsFuture_.valid()) fractionMips_ = fractionMipsFuture_.get();
    if (fractionMips_ != nullptr) landMask_->uploadFractionMips(*fractionMips_);
  }
  fractionMipsFrame_ = weighed && landMask_->fractionMipsUploaded();
  filteredMaskFrame_ = fractionMipsFrame_ && coarseMaskFrame_ && filteredMaskVariants_ &&
                       landMask_->fractionMipsOnly(view, heightPx);
}

int GlobeRenderer::programSet(bool behind, int variant) const {
  // Sets of variants: above 20 km with the aerial table, without it, below 20 km, and above
  // 20 km without the table nor the land mask's fine level (a frame from ~2100 km up at 720p,
  // where no pixel resolves it: LANDMASK_COARSE_ONLY), and with the land fraction's pyramid
  // alone (from ~11 000 km up: LANDMASK_FILTERED_ONLY); the first four again with the pyramid
  // where some pixel may weigh it (LANDMASK_PYRAMID); the variants that shade the sea again
  // with the constant wind's uniforms (PATTERN_CONSTANT_WIND), the others whatever the wind.
  const bool tableReader = variant > kClassifyExportLandSea && variant != kBlockFill;  // (classifying: no table)
  const int set = behind                              ? 2
                  : aerialTableFrame_ && tableReader ? 0
                  : filteredMaskFrame_               ? 4
                  : coarseMaskFrame_                 ? 3
                                                     : 1;
  return fractionMipsFrame_ && set != 4 ? set + 5 : set;
}

const gl::Program& GlobeRenderer::globeProgram(bool behind, int variant) {
  const int set = programSet(behind, variant), baseSet = set > 4 ? set - 5 : set;
  const int partOf = variant > kGlobePartOverBlocks0 ? variant - kGlobePartOverBlocks0 + kGlobePart0 : variant;
  const bool shadesSea = partOf == kGlobePart0 + 2 || partOf == kGlobePart0 + 3 || partOf == kGlobePart0 + 5 ||
                         partOf == kGlobePart0 + 6 || variant == kListedPixels ||
                         variant == kOpenSeaLatticePoints ||
                         variant == kSeaLatticePoints;  // the edge, the surface, the seas, the listed, the lattice's
  const int windSet = constantWindFrame_ && shadesSea ? kGlobeProgramSets : 0;
  gl::Program& p = globePrograms_[static_cast<std::size_t>((windSet + set) * kGlobeVariants + variant)];
  if (p.id() == 0) {
    // Variants 0-5: GLOBE_PART_CLASSIFY (4) with its step; 6-7: all steps in one draw; 8-10:
    // the parts 1-3, 11: the land (GLOBE_PART_LAND, 7), 12: the sea (GLOBE_PART_SEA, 6), 13: the
    // open sea (GLOBE_PART_OPEN_SEA, 5) (render/globe.frag); 21-26 the parts again, over blocks.
    std::vector<std::string> defines = OceanPatterns::shaderDefines();
    if (variant <= kClassifyExportLandSea) {
      defines.emplace_back("GLOBE_PART 4");
      defines.push_back(variant >= kClassifyExport ? std::string("GLOBE_CLASSIFY_EXPORT")
                                                   : "GLOBE_CLASSIFY_STEP " + std::to_string(variant));
      if (variant == kClassifyExportLandSea) defines.emplace_back("GLOBE_LAND_SEA");
    } else if (variant == kBlockFill) {
      defines.emplace_back("GLOBE_PART 9");
    } else if (variant == kListedPixels) {
      defines.insert(defines.end(), {"GLOBE_PART 2", "GLOBE_COMPUTE"});
    } else if (variant == kOpenSeaLatticePoints || variant == kSeaLatticePoints) {
      defines.insert(defines.end(), {variant == kSeaLatticePoints ? "GLOBE_PART 6" : "GLOBE_PART 5", "GLOBE_COMPUTE",
                                     "GLOBE_LATTICE"});
    } else if (variant == kSkyLowPass) {
      defines.emplace_back("GLOBE_PART 8");
    } else if (variant == kSkyLowPart || variant == kSkyLowSunPart) {
      defines.insert(defines.end(), {"GLOBE_PART 1", "GLOBE_SKY_LOW"});
      if (variant == kSkyLowSunPart) defines.emplace_back("GLOBE_SKY_SUN_DISC");
    } else {
      static constexpr std::array<int, 6> kPart{1, 2, 3, 7, 6, 5};
      defines.push_back("GLOBE_PART " + std::to_string(kPart.at(static_cast<std::size_t>(partOf - kGlobePart0 - 1))));
    }
    if (behind) defines.emplace_back("GLOBE_BEHIND");  // (baseSet 2)
    if (baseSet == 0) defines.emplace_back("AERIAL_TABLE");
    if (baseSet == 3) defines.emplace_back("LANDMASK_COARSE_ONLY");
    if (baseSet == 4) defines.emplace_back("LANDMASK_FILTERED_ONLY");
    if (set > 4) defines.emplace_back("LANDMASK_PYRAMID");
    if (maskCoastVariants_ && landMask_->active()) defines.emplace_back("GLOBE_MASK_COAST");  // (setMaskCoastVariants remakes the programs)
    if (windSet != 0) defines.emplace_back("PATTERN_CONSTANT_WIND");
    // Above the ceiling the sea's sky filter as the grid's (the 20 km switch): the Sun layers'
    // radial sums. Below it the globe shades only the horizon's sea samples, with the probes:
    // the sums of every Sun layer would cost a first frame at sea level ~60 ms.
    if (atmosphere_->skyFilter().radialSums && !behind) defines.emplace_back("SKY_RADIAL_SUMS");
    // Above the ceiling the classifying draws cover blocks of pixels (render/GlobeBlocks), below
    // it the one draw the uncovered ones (render/UncoveredPixels); so do the parts' variants
    // 21-26 with several samples a pixel (drawPartOverBlocks; below, the edge's and the surface's).
    const bool blocks = variant > kGlobePartOverBlocks0 ||
                        (behind ? variant >= kClassifyExport && variant <= kClassifyExportLandSea
                                : variant <= kClassifyExportLandSea || variant == kBlockFill);
    if (variant == kListedPixels || variant == kOpenSeaLatticePoints || variant == kSeaLatticePoints)
      p = gl::Program({{GL_COMPUTE_SHADER, "render/globe.frag"}}, defines);
    else
      p = gl::Program({{GL_VERTEX_SHADER, blocks ? "render/blocks.vert" : "render/fullscreen.vert"},
                       {GL_FRAGMENT_SHADER, "render/globe.frag"}},
                      defines);
  }
  return p;
}

// The ray-cast ellipsoid with the atmosphere: sky, the land's far fallback and the sea from
// orbit (or, below the grid's ceiling, the sea the grid leaves uncovered). llvmpipe skips a
// fragment shader only for fragments that fail the depth or stencil test before it runs, so
// three cheap classifying draws count into the stencil what each pixel needs (globe.frag's
// header), and each part is then drawn over only its own pixels. Above 20 km the classifying
// draws come before the terrain (their first writes the globe's depth, which the terrain is
// tested against) and the parts after it, skipping what the terrain's land-only tiles covered
// (they set a stencil bit where they draw); below, both come after the terrain and the grid.
void GlobeRenderer::classifyGlobe(const geo::CameraView& view, const FrameInput& f, bool grid) {
  if (timer_ != nullptr) timer_->mark("globe");
  const std::array<int, 4> box = grid ? std::array<int, 4>{0, 0, f.width, f.height} : scissorToGlobe(view, f);
  glBindVertexArray(emptyVao_.id());
  glDepthFunc(grid ? GL_GEQUAL : GL_ALWAYS);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the query's and the steps' draws
  // One draw writing the count where the driver allows it, else one draw per step counting,
  // each only over the pixels that passed every step before it (the classes nest: a pixel in
  // the open sea's class is in the sea's, and so on), as the one draw counts.
  const bool oneDraw = gl::driverProfile().stencilExport;
  // Below the ceiling the one draw covers only the blocks of pixels the terrain and the grid left.
  const bool listedBlocks = listsUncoveredBlocks(grid);
  frameHasSky_ = false;
  if (grid) {  // the classifying draws run on every pixel: skip them when nothing is left
    // The sky (every ray misses the ellipsoid) has count 0 below the ceiling: the draws skip it
    // (the query must see it where the parts' draws are conditional on it: frameHasSky_).
    const std::array<int, 4> whole{0, 0, f.width, f.height};
    const RayScissors boxes = ellipsoidScissorOn_ ? rayScissors(view, f.width, f.height) : RayScissors{whole, whole};
    const std::array<int, 4>& hits = boxes.hits;
    frameSkyBox_ = boxes.sky;
    // A ray that misses the ellipsoid is the sky's pixel, which the globe shades unless the
    // terrain or a wave covers it: with one, the globe's parts are drawn without the query's
    // condition, and the query answers for the hits' box alone (the classifying draws), its
    // draw cut to it (the sky's pixels cost it ~1-3 ms of process CPU at 1280 x 720).
    frameHasSky_ = ellipsoidScissorOn_ && boxes.sky[2] > 0 && boxes.sky[3] > 0;
    uncovered_.find(f.width, f.height, hits, listedBlocks, !uncoveredBlocksOn_, frameHasSky_);
    glBindVertexArray(emptyVao_.id());
    glBeginConditionalRender(uncovered_.query(), GL_QUERY_WAIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(hits[0], hits[1], hits[2], hits[3]);
  }
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, oneDraw ? GL_REPLACE : GL_INCR);
  if (!grid) bindOpenSeaMap();
  const bool blocks = uploadClassifyingBlocks(view, f, box, grid);
  // With blocks the land and the sea are mostly classed on the CPU: their split always pays.
  frameLandSea_ = !grid && landSeaParts_ && (blocks || landSeaSplitPays(view));
  frameLandLast_ = frameLandSea_ && oneDraw && landAfterTiles_;
  const std::vector<int> steps =
      oneDraw ? std::vector<int>{frameLandSea_ ? kClassifyExportLandSea : kClassifyExport} : classifyingSteps(grid);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const int step = steps[i];
    glStencilFunc(oneDraw ? GL_ALWAYS : GL_EQUAL, static_cast<GLint>(i), 0xff);
    // Above 20 km the first draw writes the depth.
    glDepthMask(!grid && step == steps.front() ? GL_TRUE : GL_FALSE);
    const gl::Program& classify = globeProgram(grid, step);
    setGlobeUniforms(classify, view, f);
    if (!grid) classify.set("uOpenSeaOn", openSeaPart_ ? 1 : 0);
    if (!grid) classify.set("uLandAtFarPlane", frameLandLast_ ? 1 : 0);
    classify.use();
    if (grid) {
      if (listedBlocks)
        uncovered_.drawBlocks();
      else
        glDrawArrays(GL_TRIANGLES, 0, 3);
      continue;
    }
    glBindVertexArray(blocksVao_.id());
    glDrawArrays(GL_TRIANGLES, blockRanges_.perPixel.first, blockRanges_.perPixel.second);
    // The sky's blocks: the steps up to "all four rays hit", or the one draw without the
    // land's and the sea's tests and without the open sea (no pixel there has four hits).
    if (blockRanges_.miss.second == 0 || (!oneDraw && step > 2)) continue;
    const gl::Program& sky = oneDraw ? globeProgram(false, kClassifyExport) : classify;
    if (oneDraw) {
      setGlobeUniforms(sky, view, f);
      sky.set("uOpenSeaOn", 0);
      sky.use();
    }
    glDrawArrays(GL_TRIANGLES, blockRanges_.miss.first, blockRanges_.miss.second);
  }
  if (blocks) drawBlockFill(view, f);
  glBindVertexArray(emptyVao_.id());
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(grid ? GL_FALSE : GL_TRUE);  // as the caller had it
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_SCISSOR_TEST);
  if (grid) glEndConditionalRender();
}

// Above 20 km the globe pass runs only within the screen rectangle that can hold the globe, its
// atmosphere or the Sun's disc: llvmpipe rasterises no fragment outside the scissor box, so
// the classifying draw (a full-screen triangle) skips the space around a distant globe.
bool GlobeRenderer::landSeaSplitPays(const geo::CameraView& view) const {
  if (openSeaMap_ == nullptr || !openSeaPart_) return true;
  constexpr int kRays = 8;
  int hits = 0, open = 0;
  for (int j = 0; j < kRays; ++j)
    for (int i = 0; i < kRays; ++i) {
      const glm::dvec3 dir = view.rayDirection(-1.0 + (2.0 * i + 1.0) / kRays, -1.0 + (2.0 * j + 1.0) / kRays);
      const std::optional<double> t = geo::intersectEllipsoid(view.positionEcef, dir);
      if (!t) continue;
      ++hits;
      const geo::Geodetic g = geo::ecefToGeodetic(view.positionEcef + *t * dir);
      open += openSeaMap_->clearanceAt(g.latitudeDeg, g.longitudeDeg) > 0.0f ? 1 : 0;
    }
  return 2 * open < hits;
}

std::vector<int> GlobeRenderer::classifyingSteps(bool grid) const {
  std::vector<int> steps;
  for (int step = firstClassifyingStep(grid); step <= 2; ++step) steps.push_back(step);
  if (!grid && frameLandSea_) steps.insert(steps.end(), {3, 4});
  if (!grid && openSeaPart_) steps.push_back(5);
  return steps;
}

int GlobeRenderer::partStencilCount(int part, bool grid) const {
  const std::vector<int> parts = globeParts(grid);
  const auto at = std::find(parts.begin(), parts.end(), part);
  return static_cast<int>(at - parts.begin()) + 1 - firstClassifyingStep(grid);
}

std::vector<int> GlobeRenderer::globeParts(bool grid) const {
  std::vector<int> parts{kGlobePart0 + 1, kGlobePart0 + 2, kGlobePart0 + 3};
  if (!grid && frameLandSea_) parts.insert(parts.end(), {kGlobePart0 + 4, kGlobePart0 + 5});
  if (!grid && openSeaPart_) parts.push_back(kGlobePart0 + 6);
  return parts;
}

std::array<int, 4> GlobeRenderer::scissorToGlobe(const geo::CameraView& view, const FrameInput& f) {
  if (!scissorGlobe_) return {0, 0, f.width, f.height};
  const std::array<int, 4> box = globeScissor(view, f.width, f.height, atmosphere_->parameters(),
                                              f.sunDirectionEcef);
  globeBox_ = box;
  glEnable(GL_SCISSOR_TEST);
  glScissor(box[0], box[1], box[2], box[3]);
  return box;
}

bool GlobeRenderer::uploadClassifyingBlocks(const geo::CameraView& view, const FrameInput& f,
                                            const std::array<int, 4>& box, bool grid) {
  if (blocksBuffer_.id() == 0) {
    blocksBuffer_ = gl::createBuffer();
    blocksVao_ = gl::createVertexArray();
    glVertexArrayVertexBuffer(blocksVao_.id(), 0, blocksBuffer_.id(), 0, 2 * sizeof(float));
    glEnableVertexArrayAttrib(blocksVao_.id(), 0);
    glVertexArrayAttribFormat(blocksVao_.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(blocksVao_.id(), 0, 0);
  }
  blockRanges_ = {};
  blockCounts_ = {};
  seaLattice_.clear();
  if (grid) return false;
  if (maskPyramidFuture_.valid()) maskPyramid_ = maskPyramidFuture_.get();
  std::vector<float> vertices;
  const bool blocks = blocksOn_ && maskPyramid_ != nullptr;
  if (blocks) {
    // Blocks in space get no draw: the clear colour is what the classifying draw leaves there.
    const atmosphere::Parameters& a = atmosphere_->parameters();
    const GlobeSkyOutline sky{a.bottomRadiusM, a.topRadiusM(), glm::normalize(f.sunDirectionEcef), a.sunAngularRadiusRad};
    const GlobeBlocks b = classifyGlobeBlocks(view, f.width, f.height, box, *maskPyramid_,
                                              openSeaPart_ ? openSeaMap_.get() : nullptr, &sky,
                                              fractionMipsFrame_ ? fractionMips_.get() : nullptr);
    auto append = [&](GlobeBlockClass c) {
      const std::vector<float> t = b.triangles(c, f.width, f.height);
      const std::pair<int, int> range{static_cast<int>(vertices.size() / 2), static_cast<int>(t.size() / 2)};
      vertices.insert(vertices.end(), t.begin(), t.end());
      return range;
    };
    for (const GlobeBlockClass c : b.classes) ++blockCounts_[static_cast<std::size_t>(c)];
    blockRanges_.perPixel = append(GlobeBlockClass::PerPixel);
    blockRanges_.miss = append(GlobeBlockClass::Miss);
    blockRanges_.fills = {append(GlobeBlockClass::Land), append(GlobeBlockClass::Sea), append(GlobeBlockClass::OpenSea)};
    // The sea's blocks only where the frame splits the land's and the sea's parts off (with
    // blocks, landSeaParts_ alone decides: frameLandSea_, set after this). Not with the
    // auxiliary outputs, whose whitecaps the check does not weigh.
    if (seaLatticeOn_ && !auxiliary_) seaLattice_.prepare(b, f.width, f.height, landSeaParts_);
  } else {
    vertices = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};  // fullscreen.vert's triangle
    blockRanges_.perPixel = {0, 3};
  }
  glNamedBufferData(blocksBuffer_.id(), static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
                    GL_STREAM_DRAW);
  return blocks;
}

// The blocks classed on the CPU: their class's stencil count (the parts' numbering: 3 the
// surface, then the land 4, the sea 5 and the open sea 6 where the frame splits them off; the
// per-pixel draws' own but where the CPU's open-sea test, as strict, says sea) and the depth
// (globe.frag's GLOBE_PART_BLOCK_FILL; the land's stays the far plane with frameLandLast_).
void GlobeRenderer::drawBlockFill(const geo::CameraView& view, const FrameInput& f) {
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glDepthMask(GL_TRUE);
  const gl::Program& fill = globeProgram(false, kBlockFill);
  setGlobeUniforms(fill, view, f);
  fill.use();
  glBindVertexArray(blocksVao_.id());
  for (std::size_t k = 0; k < blockRanges_.fills.size(); ++k) {
    const auto [first, count] = blockRanges_.fills[k];
    if (count == 0) continue;
    fill.set("uBlockLand", k == 0 ? 1 : 0);
    glStencilFunc(GL_ALWAYS, fillStencilCount(k), 0xff);
    glDepthMask(k == 0 && frameLandLast_ ? GL_FALSE : GL_TRUE);  // the land's: the far plane, as cleared
    glDrawArrays(GL_TRIANGLES, first, count);
  }
  glDepthMask(GL_TRUE);
}

int GlobeRenderer::fillStencilCount(std::size_t k) const {
  const int open = k == 2 && openSeaPart_ ? 1 : 0;
  return frameLandSea_ ? (k == 0 ? 4 : 5) + open : 3 + open;
}

void GlobeRenderer::bindOpenSeaMap() {
  if (openSeaTexture_ == nullptr) {
    // Made on a helper thread since the constructor, uploaded on the first frame that needs it.
    const core::startup::Scope stage("renderer: open sea and land clearance maps (waiting, upload)");
    if (!openSeaFuture_.valid()) throw InternalError("the open-sea map failed on an earlier frame");
    auto [map, texels] = openSeaFuture_.get();
    openSeaTexture_ = std::make_unique<OpenSeaTexture>(texels);
    openSeaMap_ = std::move(map);
  }
  openSeaTexture_->bind();
}

void GlobeRenderer::shadeGlobe(const geo::CameraView& view, const FrameInput& f, bool grid, GlobeParts which) {
  if (timer_ != nullptr) timer_->mark("globe");
  const bool landOnly = which == GlobeParts::land;
  glBindVertexArray(emptyVao_.id());
  // The land after the tiles: where none drew, its class's depth is still the far plane (0),
  // the full-screen triangle's own depth; a tile's fragment fails it before the shader.
  glDepthFunc(grid ? GL_GEQUAL : landOnly ? GL_EQUAL : GL_ALWAYS);
  if (partsOnUncovered(grid)) glBeginConditionalRender(uncovered_.query(), GL_QUERY_WAIT);
  glEnable(GL_STENCIL_TEST);
  glDepthMask(GL_FALSE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  if (aerialTableFrame_ && !landOnly) aerialTable_.update(*atmosphere_, view, f.sunDirectionEcef);
  if (!grid) scissorToGlobe(view, f);
  lastSkyLowFactor_ = 1;
  if (grid && timer_ != nullptr) timer_->mark("globe sky");  // (its low-resolution draw)
  const bool skyLow = grid && drawSkyLow(view, f);
  // Sky, edge, surface, land, sea, open sea: the stencil counts 1-6 (one lower below 20 km).
  const std::vector<int> parts = globeParts(grid);
  if (countPartSamples_ && !landOnly) partSamples_.clear();
  const bool listed = listsScatteredParts();
  std::vector<int> listedCounts;
  bool latticeShaded = false;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const int count = partStencilCount(parts[k], grid);
    if ((parts[k] == kGlobePart0 + 4) != landOnly && which != GlobeParts::all) continue;
    if (listed && (parts[k] == kGlobePart0 + 2 || parts[k] == kGlobePart0 + 3)) {  // the edge, the surface
      listedCounts.push_back(count);
      continue;
    }
    // The part's pass in the breakdown, apart from the classifying draws ("globe"); without
    // "globe ", its name in partSamples_.
    static constexpr std::array<const char*, 6> kPassNames{"globe sky",  "globe edge", "globe surface",
                                                           "globe land", "globe sea",  "globe open sea"};
    const char* pass = kPassNames.at(static_cast<std::size_t>(parts[k] - kGlobePart0 - 1));
    glStencilFunc(GL_EQUAL, count, 0xff);
    // Below the ceiling the sky's pixels lie in the box of the rays that miss the ellipsoid:
    // its triangle's fragments elsewhere would cost their rasterising and tests (~6 ns each on
    // llvmpipe, 70 % of sea-4m's screen).
    const bool skyBoxed = grid && parts[k] == kGlobePart0 + 1;
    if (skyBoxed) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(frameSkyBox_[0], frameSkyBox_[1], frameSkyBox_[2], frameSkyBox_[3]);
    }
    if (parts[k] == kGlobePart0 + 5 || parts[k] == kGlobePart0 + 6) {
      drawSeaLattice(view, f, !latticeShaded, parts[k] == kGlobePart0 + 5);
      latticeShaded = true;
    }
    if (timer_ != nullptr) timer_->mark(pass);
    const bool readsSkyLow = skyLow && parts[k] == kGlobePart0 + 1;
    // Below 20 km the edge's and the surface's pixels lie in the blocks the classifying draw
    // covered (uncovered_'s, where listed); the sky's beyond them.
    const bool overBlocks = partsOverBlocks_ && hdr_.samples > 1 &&
                            (!grid || (listsUncoveredBlocks(grid) && parts[k] != kGlobePart0 + 1));
    const gl::Program& globe =
        globeProgram(grid, readsSkyLow ? kSkyLowPart : overBlocks ? parts[k] - kGlobePart0 + kGlobePartOverBlocks0 : parts[k]);
    setGlobeUniforms(globe, view, f);
    if (readsSkyLow) {
      globe.set("uSkyLowScale", skyLowScale_);
      glBindTextureUnit(gl::kUnitSkyLow, skyLow_.color.id());
    }
    globe.use();
    const std::function<void()> draw = [&, part = parts[k]] {
      if (overBlocks && grid) {
        uncovered_.drawBlocks();
        glBindVertexArray(emptyVao_.id());
      } else if (overBlocks) {
        drawPartOverBlocks(part, count);
      } else {
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
    };
    if (!countPartSamples_) {
      if (grid && partGateOn_ && hdr_.samples > 1)
        drawPartGated(globe, draw);
      else
        draw();
    } else {
      partSamples_.emplace_back(std::string(pass).substr(std::string_view("globe ").size()),
                                gl::queryResult(GL_SAMPLES_PASSED, draw));
    }
    if (skyBoxed) glDisable(GL_SCISSOR_TEST);
    if (readsSkyLow) drawSunDisc(view, f, grid);  // over the sky just drawn without it
  }
  if (!listedCounts.empty()) {
    if (timer_ != nullptr) timer_->mark("globe edge and surface (listed)");
    shadeScatteredParts(view, f, grid, listedCounts);
  }
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(grid ? GL_FALSE : GL_TRUE);  // as the caller had it
  if (partsOnUncovered(grid)) glEndConditionalRender();
}

void GlobeRenderer::drawPartGated(const gl::Program& part, const std::function<void()>& draw) {
  if (partGate_.id() == 0) {
    partGate_ = gl::Program({{GL_VERTEX_SHADER, "render/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "render/uncovered.frag"}});
    partGateQuery_ = gl::createQuery(GL_ANY_SAMPLES_PASSED);
  }
  // The frame's triangle under the part's depth and stencil tests, nothing written. Inside the
  // frame's condition (a discarded draw passes no sample), which conditional renders cannot nest.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  partGate_.use();
  glBeginQuery(GL_ANY_SAMPLES_PASSED, partGateQuery_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  if (recordPartGate_) {
    GLuint any = 0;
    glGetQueryObjectuiv(partGateQuery_.id(), GL_QUERY_RESULT, &any);
    partsGated_.push_back(any != 0);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // (shadeGlobe's)
  part.use();
  if (partsOnUncovered(true)) glEndConditionalRender();
  glBeginConditionalRender(partGateQuery_.id(), GL_QUERY_WAIT);
  draw();
  glEndConditionalRender();
  if (partsOnUncovered(true)) glBeginConditionalRender(uncovered_.query(), GL_QUERY_WAIT);
}

void GlobeRenderer::drawPartOverBlocks(int part, int count) const {
  glBindVertexArray(blocksVao_.id());
  const auto drawRange = [](std::pair<int, int> range) {
    if (range.second > 0) glDrawArrays(GL_TRIANGLES, range.first, range.second);
  };
  drawRange(blockRanges_.perPixel);  // (without blocks: the frame's triangle)
  if (part == kGlobePart0 + 1) drawRange(blockRanges_.miss);
  for (std::size_t k = 0; k < blockRanges_.fills.size(); ++k)
    if (fillStencilCount(k) == count) drawRange(blockRanges_.fills[k]);
  glBindVertexArray(emptyVao_.id());
}

void GlobeRenderer::drawSeaLattice(const geo::CameraView& view, const FrameInput& f, bool first, bool seaPart) {
  if (seaLattice_.empty()) return;
  if (timer_ != nullptr) timer_->mark("globe sea lattice");
  if (first)
    seaLattice_.shade(
        [&](bool sea) -> const gl::Program& {
          const gl::Program& p = globeProgram(false, sea ? kSeaLatticePoints : kOpenSeaLatticePoints);
          setGlobeUniforms(p, view, f);
          return p;
        },
        f.exposure);
  // Over the part's blocks the CPU classed (its other pixels have no flag), not the whole box.
  const auto [firstVertex, vertices] = blockRanges_.fills.at(seaPart ? 1 : 2);
  const auto draw = [&] {
    seaLattice_.drawInterpolated([&] {
      glBindVertexArray(blocksVao_.id());
      glDrawArrays(GL_TRIANGLES, firstVertex, vertices);
      glBindVertexArray(emptyVao_.id());
    });
  };
  if (!countPartSamples_)
    draw();
  else
    partSamples_.emplace_back(seaPart ? "sea lattice" : "open sea lattice", gl::queryResult(GL_SAMPLES_PASSED, draw));
}

std::optional<std::array<int, 4>> sunDiscScissor(const geo::CameraView& view, int width, int height,
                                                 const glm::dvec3& sunDirectionEcef, double sunRadiusRad) {
  // globe.frag's sky part adds the disc where a pixel's centre ray lies within the disc's
  // radius plus a pixel's diagonal at the frame's centre (its largest): that cone, widened by
  // half, plus two pixels of margin (scissorOf).
  const double tanY = std::tan(0.5 * view.verticalFovRad), tanX = tanY * view.aspect;
  const double pixelRad = std::hypot(2.0 * tanX / width, 2.0 * tanY / height);
  const double coneRad = 1.5 * (sunRadiusRad + pixelRad);
  const glm::dvec3 sun = glm::normalize(sunDirectionEcef);
  if (glm::dot(sun, view.forward) < -std::sin(coneRad)) return std::array<int, 4>{0, 0, 0, 0};  // behind
  glm::dvec4 box(1e30, 1e30, -1e30, -1e30);
  if (!addCone(view, width, height, sun, coneRad, box)) return std::nullopt;  // reaches behind the eye
  return scissorOf(box, width, height);
}

void GlobeRenderer::drawSunDisc(const geo::CameraView& view, const FrameInput& f, bool grid) {
  const std::optional<std::array<int, 4>> box =
      sunDiscBoxOn_ ? sunDiscScissor(view, f.width, f.height, f.sunDirectionEcef, atmosphere_->parameters().sunAngularRadiusRad)
                    : std::nullopt;
  if (box && ((*box)[2] == 0 || (*box)[3] == 0)) return;
  const gl::Program& p = globeProgram(grid, kSkyLowSunPart);
  setGlobeUniforms(p, view, f);
  p.set("uSkyLowScale", skyLowScale_);
  p.use();
  if (box) {
    glEnable(GL_SCISSOR_TEST);
    glScissor((*box)[0], (*box)[1], (*box)[2], (*box)[3]);
  }
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_SCISSOR_TEST);  // (below the ceiling nothing else scissors)
}

std::uint32_t GlobeRenderer::listedPixelCount() const {
  GLuint count = 0;
  if (scatteredPixels_.id() != 0) glGetNamedBufferSubData(scatteredPixels_.id(), 0, sizeof count, &count);
  return count;
}

bool GlobeRenderer::partsOnUncovered(bool grid) const { return grid && !frameHasSky_; }

bool GlobeRenderer::listsUncoveredBlocks(bool grid) { return grid && gl::driverProfile().stencilExport; }

bool GlobeRenderer::listsScatteredParts() const {
  return scatteredListed_ && hdr_.samples == 1 && !auxiliary_ && !countPartSamples_;
}

void GlobeRenderer::shadeScatteredParts(const geo::CameraView& view, const FrameInput& f, bool grid,
                                        const std::vector<int>& counts) {
  // The block: count, the dispatch's three group counts, then a pixel each (globe_pixels.glsl).
  const std::size_t bytes = (4 + static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height)) * sizeof(GLuint);
  gl::ensureBufferCapacity(scatteredPixels_, scatteredPixelsBytes_, bytes, GL_DYNAMIC_STORAGE_BIT);
  // The parts' counts lie only in some blocks: below the ceiling those the classifying draw
  // covered (listsUncoveredBlocks), above it the per-pixel blocks and the fills of the count
  // (drawPartOverBlocks). Over those, not the frame, whose rejected pixels cost llvmpipe ~6 ns
  // each (two counts: sea-4m 7 ms of process CPU, orbit 4).
  const bool overBlocks = !grid || listsUncoveredBlocks(grid);
  gl::Program& list = overBlocks ? scatteredListBlocks_ : scatteredList_;
  if (list.id() == 0)
    list = gl::Program({{GL_VERTEX_SHADER, overBlocks ? "render/blocks.vert" : "render/fullscreen.vert"},
                        {GL_FRAGMENT_SHADER, "render/globe_list.frag"}});
  if (scatteredArgs_.id() == 0) scatteredArgs_ = gl::Program({{GL_COMPUTE_SHADER, "render/globe_list_args.comp"}});
  const GLuint zero = 0;
  glNamedBufferSubData(scatteredPixels_.id(), 0, sizeof zero, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kGlobePixelsBinding, scatteredPixels_.id());
  // The list: the parts' pixels, as their draws would pass the depth and stencil tests.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  list.use();
  for (const int count : counts) {
    glStencilFunc(GL_EQUAL, count, 0xff);
    if (!grid)
      drawPartOverBlocks(0, count);
    else if (overBlocks)
      uncovered_.drawBlocks();
    else
      glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindVertexArray(emptyVao_.id());
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // (Below the ceiling, unless the frame has sky, the draws above are conditional on the
  // uncovered query; the dispatch is not, and finds the count they left: 0 when they were
  // skipped.)
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scatteredArgs_.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  const gl::Program& shade = globeProgram(grid, kListedPixels);
  setGlobeUniforms(shade, view, f);
  shade.use();
  glBindImageTexture(0, hdr_.color.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, scatteredPixels_.id());
  glDispatchComputeIndirect(sizeof(GLuint));  // uArgs
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  // The target's next users, and the count's next update (listedPixelCount, the next frame's reset).
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
}

bool GlobeRenderer::drawSkyLow(const geo::CameraView& view, const FrameInput& f) {
  const double pixelRad = 2.0 * std::tan(0.5 * view.verticalFovRad) / f.height;
  const int factor = skyLowOn_ ? std::min(static_cast<int>(kSkyLowTexelRad / pixelRad), kSkyLowMaxFactor) : 1;
  // The pass covers the sky's box, the sky a part of the frame (29 % of sea-4m): below 3 x 3
  // pixels a texel it saves too little (640 x 360, 2 x 2: no gain measured).
  if (factor < kSkyLowMinFactor) return false;
  lastSkyLowFactor_ = factor;
  const int width = (f.width + factor - 1) / factor, height = (f.height + factor - 1) / factor;
  if (width != skyLow_.width || height != skyLow_.height)
    skyLow_ = gl::createRenderTarget(width, height, GL_RGBA16F, false);
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, skyLow_.fbo.id());
  glViewport(0, 0, width, height);
  const gl::Program& sky = globeProgram(true, kSkyLowPass);
  setGlobeUniforms(sky, view, f);
  sky.set("uSkyLowFactor", static_cast<float>(factor));
  sky.set("uFrameSize", glm::vec2(static_cast<float>(f.width), static_cast<float>(f.height)));
  sky.use();
  // Only the texels the sky's pixels read (frameSkyBox_, classifyGlobe's), two more each side
  // for their bilinear lookups; the others keep what they held.
  const std::array<int, 4>& box = frameSkyBox_;
  const int x0 = std::max(box[0] / factor - 2, 0), y0 = std::max(box[1] / factor - 2, 0);
  const int x1 = std::min((box[0] + box[2] + factor - 1) / factor + 2, width);
  const int y1 = std::min((box[1] + box[3] + factor - 1) / factor + 2, height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0, y0, x1 - x0, y1 - y0);
  if (box[2] > 0 && box[3] > 0) glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(0, 0, f.width, f.height);
  skyLowScale_ = 1.0f / (glm::vec2(static_cast<float>(width), static_cast<float>(height)) * static_cast<float>(factor));
  return true;
}

void GlobeRenderer::setGlobeUniforms(const gl::Program& globe, const geo::CameraView& view,
                                     const FrameInput& f) {
  // Eye in the ellipsoid's scaled space; C = |o|² - 1 in double (see geo/ellipsoid.glsl).
  const glm::dvec3 o = view.positionEcef /
                       glm::dvec3(geo::kWgs84SemiMajorM, geo::kWgs84SemiMajorM,
                                  geo::kWgs84SemiMinorM);
  const double tanY = std::tan(0.5 * view.verticalFovRad);
  globe.set("uRight", toFloat(view.right));
  globe.set("uUp", toFloat(view.up));
  globe.set("uForward", toFloat(view.forward));
  globe.set("uTanHalfFov", glm::vec2(static_cast<float>(tanY * view.aspect), static_cast<float>(tanY)));
  globe.set("uPixelNdc", glm::vec2(2.0f / static_cast<float>(f.width), 2.0f / static_cast<float>(f.height)));
  globe.set("uNear", static_cast<float>(view.nearM));
  globe.set("uGlobeDepthPushM", static_cast<float>(kGlobeDepthPushM));
  globe.set("uSunDir", toFloat(glm::normalize(f.sunDirectionEcef)));
  globe.set("uEyeScaled", toFloat(o));
  globe.set("uEyeC", static_cast<float>(glm::dot(o, o) - 1.0));
  globe.set("uCamUp", toFloat(view.enu.up));
  globe.set("uCamAltitude", static_cast<float>(view.position.heightM));
  wind_->bind(globe);
  patterns_->bind();
  patterns_->setUniforms(globe, nullptr, 0.0);
  if (constantWindFrame_)  // (the patterns' bins are not the globe's: any field rotation; unread by programs without)
    patterns_->setConstantWind(globe, wind_->constantSpeedMs(), glm::radians(wind_->constantTowardsDeg()), 0.0);
  globe.set("uSeaColor", OceanLighting{}.seaColor);
  setWaterOptics(globe, ocean::jerlovWater(ocean::kDefaultWater));
  globe.set("uElevationMap", elevationMap_);
  globe.set("uElevationSize", elevationSize_);
  globe.set("uElevationWraps", elevationWraps_);
  glBindTextureUnit(gl::kUnitElevation, elevation_.id());
  imagery_->bind(globe);
  atmosphere_->bind(globe);
  atmosphere_->bindSkyMaps();
}

// The near sea: the projected grid over the globe's sea holes, depth-tested against land.
void GlobeRenderer::drawOcean(const geo::CameraView& view, const FrameInput& f) {
  ocean::OceanFrame fresh;
  if (f.oceanFrame == nullptr) fresh.reset(view.position);
  const ocean::OceanFrame& frame = f.oceanFrame ? *f.oceanFrame : fresh;
  OceanLighting lighting;
  lighting.sunDirectionEcef = f.sunDirectionEcef;
  lighting.shadows = &terrain_->shadows();
  // Over the open ocean (every tile in view deep under the sea) no pixel needs the coast test.
  const TerrainStats& ts = terrain_->stats();
  lighting.landInView = ts.landTiles > 0 || ts.tiles == 0;
  landInViewFrame_ = lighting.landInView;
  lighting.landEverywhere = ts.tiles > 0 && ts.landTiles == ts.tiles;
  // The water volume only where a floor its light can come back from is under sea the eye
  // sees (TerrainStats::seaSeenMaxHeightM): the floor's light goes down and back up, at least
  // twice its depth through the water, so below half the reach d_max (the path that leaves
  // every channel less than kWaterEpsilon) it returns less than that: the deep colour, within
  // a level. (The pixels' classes keep the floor down to d_max: conservative per pixel.)
  const double reachM = ocean::waterMaxPathM(ocean::jerlovWater(ocean::kDefaultWater).attenuationPerM,
                                             ocean::kWaterEpsilon);
  lighting.floorInReach = ts.tiles == 0 || ts.seaSeenMaxHeightM > -0.5 * reachM;
  floorInReachFrame_ = lighting.floorInReach;
  lighting.classes = f.oceanClasses;
  // Waves fade out on the way up so the grid meets the orbit model at the switch.
  const double h = view.position.heightM;
  const double x = std::clamp((h - kOceanFadeStartM) / (kOceanGridMaxHeightM - kOceanFadeStartM), 0.0, 1.0);
  const double amplitude = 1.0 - x * x * (3.0 - 2.0 * x);
  if (f.oceanModel == OceanModel::Bruneton) {
    if (timer_ != nullptr) timer_->mark("ocean waves");
    // Only the patterns some pixel resolves (the finest footprint of the CPU's rays, half a
    // level of margin: OceanPatterns::resolvedPatternCount). The caustics are looked up at a
    // blur of at least twice the floor's footprint, itself at least the sea's (ocean/
    // water_volume.glsl's causticGain), only where that is under their patterns' tiles: a
    // subset of those patterns, and none from a km or two up in the demo's views at 1280x720,
    // where their map is left unmade (9.3 ms of one thread in its 1-20 km frames,
    // docs/performance.md). As the patterns' count, the rule takes the sea's footprint on
    // the undisplaced surface: wave faces seen at a few degrees' grazing, which shrink it
    // beyond the margin, may then read a pattern or a caustic map left from an earlier frame.
    const ocean::WavePatternParams& params = patterns_->patterns().params;
    const double finestM = OceanPatterns::finestSeaFootprintM(view, f.height);
    lighting.causticsSeen = lighting.floorInReach &&
                            (causticsAlwaysMade_ || OceanPatterns::resolvedPatternCount(params, 2.0 * finestM) >
                                                        ocean::kPatternCount - kCausticPatterns);
    causticsSeenFrame_ = lighting.causticsSeen;
    patterns_->update(f.simulationTimeS,
                      causticsAlwaysMade_ ? ocean::kPatternCount : OceanPatterns::resolvedPatternCount(params, finestM));
  }
  if (timer_ != nullptr) timer_->mark("ocean");
  glDepthFunc(GL_GREATER);
  if (landMask_->active()) bindOpenSeaMap();  // its land clearance: the sea's classes
  ocean_->setCellPixels(f.oceanCellPixels);
  // A display-only frame with no tile drawn (no land in view): where one pass shades the whole
  // sea, it writes the display itself; the tone map then reads only the globe's pixels, or
  // none where the sea covers the screen.
  // (Set in every frame, so that no earlier frame's request outlives it.)
  const bool seaDisplay = f.displayOnly && seaWritesDisplay_ && !auxiliary_ && displayOverDepth_.id() != 0 &&
                          ts.drawnTiles == 0;
  ocean_->setDisplayTarget(seaDisplay ? displayOverDepth_.id() : 0, static_cast<float>(f.exposure));
  ocean_->draw(view, f.width, f.height, *patterns_, frame, f.simulationTimeS, lighting, amplitude,
               f.oceanModel, *wind_);
  lastSeaWroteDisplay_ = ocean_->lastDrawWroteDisplay();
}

io::ImageRgbaF GlobeRenderer::radiance() const {
  if (lastDisplayOnly_) throw InternalError("GlobeRenderer::radiance after a FrameInput::displayOnly frame");
  const gl::RenderTarget& t = singleSampleHdr();
  return {t.width, t.height, gl::readRgbaF(t.fbo.id(), t.width, t.height)};
}

io::ImageRgba8 GlobeRenderer::display() const {
  return {ldrBytes_.width, ldrBytes_.height, gl::readRgba8(ldrBytes_.fbo.id(), ldrBytes_.width, ldrBytes_.height)};
}

std::vector<float> GlobeRenderer::depth() const {
  const gl::RenderTarget& t = singleSampleHdr();
  return gl::readDepth(t.fbo.id(), t.width, t.height);
}

std::vector<float> GlobeRenderer::whitecap() const {
  if (!auxiliary_) throw InternalError("GlobeRenderer::whitecap needs FrameInput::auxiliaryOutputs");
  const gl::RenderTarget& t = singleSampleHdr();
  return gl::readRedF(t.fbo.id(), t.width, t.height, 1);
}

std::vector<float> GlobeRenderer::viewDistance() const {
  // Reversed-Z depth = near / (distance along the view axis); along the pixel's ray the
  // distance is longer by |forward + x tan right + y tan up| (the ray's unnormalised length).
  std::vector<float> d = depth();
  const int w = hdr_.width, h = hdr_.height;
  const double tanY = std::tan(0.5 * lastView_.verticalFovRad), tanX = tanY * lastView_.aspect;
  // Above the grid's ceiling the globe pass's depth over land stands kGlobeDepthPushM behind the
  // ellipsoid (or at the far plane where its land part comes last); the terrain keeps no
  // fragment under the sea up there, the deepest land is ~0.4 km under it and a tile's chord
  // ~0.5 km, which puts a terrain pixel half the push behind the ellipsoid only at grazing
  // incidence near the limb (a tile's skirt there too): those read the ellipsoid's distance,
  // some kilometres short at a thousand.
  const bool globeDepthPushed = lastView_.position.heightM >= kOceanGridMaxHeightM;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float& z = d[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)];
      const double ndcX = 2.0 * (x + 0.5) / w - 1.0, ndcY = 1.0 - 2.0 * (y + 0.5) / h;
      const glm::dvec3 dir = lastView_.rayDirection(ndcX, ndcY);
      const std::optional<double> t =
          globeDepthPushed ? geo::intersectEllipsoid(lastView_.positionEcef, dir) : std::nullopt;
      if (z <= 0.0f) {
        // The sky; or, above the ceiling, land the globe's part shaded where no tile drew (its
        // depth is the far plane: frameLandLast_).
        z = t ? static_cast<float>(*t) : kSkyDistanceM;
        continue;
      }
      const double nx = ndcX * tanX, ny = ndcY * tanY;
      const double axial = lastView_.nearM / static_cast<double>(z);
      z = static_cast<float>(axial * std::sqrt(1.0 + nx * nx + ny * ny));
      if (t && axial > *t * glm::dot(dir, lastView_.forward) + 0.5 * kGlobeDepthPushM) z = static_cast<float>(*t);
    }
  return d;
}

void GlobeRenderer::finish() { glFinish(); }

}  // namespace og::render
