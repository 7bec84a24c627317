#include "render/OceanRenderer.hpp"

#include <algorithm>
#include <numbers>
#include <limits>
#include <optional>
#include <cmath>
#include <cstdlib>
#include <cassert>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "gl/DriverProfile.hpp"
#include "gl/ShaderContract.hpp"
#include "render/WaterVolume.hpp"

namespace og::render {
namespace {
glm::vec3 toFloat(const glm::dvec3& v) { return glm::vec3(v); }

/// Where the ray `dir` from an eye `heightM` above the sphere of the semi-major axis (`up` its
/// vertical) meets that sphere, m along the ray; nothing where it misses (above the horizon).
/// The smaller root t of t² - 2 b t + (r + h)² - r² = 0, b = (r + h) cos(angle below the
/// horizontal).
std::optional<double> seaSphereHitM(double heightM, const glm::dvec3& up, const glm::dvec3& dir) {
  const double r = geo::kWgs84SemiMajorM, h = heightM;
  const double b = (r + h) * -glm::dot(dir, up);
  const double disc = b * b - h * (2.0 * r + h);
  if (b <= 0.0 || disc < 0.0) return std::nullopt;
  return b - std::sqrt(disc);
}

/// Where a ray of the view meets the sea (seaSphereHitM): m along it, and the cosine of its
/// incidence there.
struct SeaHit {
  double distanceM = 0.0, cosIncidence = 0.0;
};
/// The view's rays through its corners, its edges' middles and its centre (rows bottom to top,
/// each left to right: the centre is [4]) where they meet the sea; nothing for one that misses.
std::array<std::optional<SeaHit>, 9> seaHitsOfView(const geo::CameraView& view) {
  const double r = geo::kWgs84SemiMajorM, h = std::max(view.position.heightM, 0.1);
  const glm::dvec3 eye = (r + h) * view.enu.up;
  std::array<std::optional<SeaHit>, 9> hits;
  std::size_t k = 0;
  for (const double sy : {-1.0, 0.0, 1.0})
    for (const double sx : {-1.0, 0.0, 1.0}) {
      const glm::dvec3 dir = view.rayDirection(sx, sy);
      if (const std::optional<double> t = seaSphereHitM(h, view.enu.up, dir))
        hits[k] = SeaHit{*t, -glm::dot(dir, (eye + *t * dir) / r)};
      ++k;
    }
  return hits;
}

/// Whether the point straight below the eye is on the screen.
bool nadirInView(const geo::CameraView& view) {
  const glm::dvec3 down = -view.enu.up;
  const double ahead = glm::dot(down, view.forward), tanY = std::tan(0.5 * view.verticalFovRad);
  return ahead > 0.0 && std::abs(glm::dot(down, view.right)) <= tanY * view.aspect * ahead &&
         std::abs(glm::dot(down, view.up)) <= tanY * ahead;
}

// The classic model's textures (seed 002): a tileable ripple normal map (sum of sines with
// integer frequencies over the tile, so it repeats seamlessly) and the 1D Fresnel ramp.
gl::Texture makeBumpMap() {
  constexpr int kSize = 256;
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(kSize * kSize * 2));
  const int freqs[6][2] = {{3, 1}, {-2, 4}, {5, -3}, {7, 2}, {-4, -6}, {9, 5}};
  const double amps[6] = {1.0, 0.8, 0.6, 0.45, 0.35, 0.25};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double dx = 0, dy = 0;
      for (int i = 0; i < 6; ++i) {
        const double ph = 2 * 3.14159265358979 * (freqs[i][0] * x + freqs[i][1] * y) / kSize + i;
        const double c = amps[i] * std::cos(ph) * 0.12;
        dx += c * freqs[i][0] / 4.0;
        dy += c * freqs[i][1] / 4.0;
      }
      const auto idx = static_cast<std::size_t>(2 * (y * kSize + x));
      texels[idx] = static_cast<std::uint8_t>(std::clamp(127.5 + 127.5 * dx, 0.0, 255.0));
      texels[idx + 1] = static_cast<std::uint8_t>(std::clamp(127.5 + 127.5 * dy, 0.0, 255.0));
    }
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 9, GL_RG8, kSize, kSize);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.id(), 0, 0, 0, kSize, kSize, GL_RG, GL_UNSIGNED_BYTE, texels.data());
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return t;
}

gl::Texture makeFresnelRamp() {
  constexpr int kSize = 64;
  std::vector<float> texels;
  for (int i = 0; i < kSize; ++i) {
    const double cosV = (i + 0.5) / kSize;
    const double f = 0.02 + 0.98 * std::pow(1.0 - cosV, 5.0);
    // Greenish looking down, bluish at grazing angles (the paper's ramp), per unit irradiance.
    const glm::dvec3 down{0.004, 0.010, 0.008}, edge{0.002, 0.005, 0.010};
    const glm::dvec3 c = glm::mix(edge, down, cosV);
    texels.insert(texels.end(), {static_cast<float>(c.x), static_cast<float>(c.y),
                                 static_cast<float>(c.z), static_cast<float>(f)});
  }
  gl::Texture t = gl::createTexture(GL_TEXTURE_1D);
  glTextureStorage1D(t.id(), 1, GL_RGBA16F, kSize);
  glTextureSubImage1D(t.id(), 0, 0, kSize, GL_RGBA, GL_FLOAT, texels.data());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  return t;
}

std::vector<std::string> skyDefines(const Atmosphere* atmosphere) {
  return atmosphere ? std::vector<std::string>{} : std::vector<std::string>{"OCEAN_SIMPLE_SKY"};
}

// The validation variants' defines (shaders/ocean/patterns.glsl, lighting.glsl, ocean.frag);
// OCEAN_LIGHTING_TERMS: the terms' weights uLightingTerms (lighting.glsl).
std::vector<std::string> oceanDefines(const Atmosphere* atmosphere, ValidationMode mode) {
  std::vector<std::string> d = skyDefines(atmosphere);
  for (const std::string& define : OceanPatterns::shaderDefines()) d.push_back(define);
  for (const std::string& define : waterVolumeDefines()) d.push_back(define);
  d.emplace_back("OCEAN_LIGHTING_TERMS");
  if (mode == ValidationMode::Reference) d.emplace_back("OCEAN_VALIDATION_REFERENCE");
  if (mode == ValidationMode::ConstantBrdf) d.emplace_back("OCEAN_VALIDATION_CONSTANT_BRDF");
  if (mode == ValidationMode::BrdfOnly) d.emplace_back("OCEAN_VALIDATION_BRDF_ONLY");
  return d;
}
// OCEANGLOBE_SEA: unset (""), "forward" (for comparisons), "deferred" or "compute" (deferred,
// its classes shaded by compute shaders), "split" (forward, the grid's triangles in classes:
// OceanRenderer::drawForwardSplit).
std::string seaPathAsked() {
  const char* e = std::getenv("OCEANGLOBE_SEA");
  const std::string asked = e != nullptr ? e : "";
  if (asked.empty() || asked == "forward" || asked == "deferred" || asked == "compute" || asked == "split") return asked;
  throw InputError("OCEANGLOBE_SEA: '" + asked + "' is not forward, deferred, compute or split");
}

// OCEANGLOBE_SEA_SURFACE: what the deferred sea's surface pass writes where the frame's sea has
// one class: "buffer" (the surface buffer; multisampled frames then draw the sea forward) or
// "visibility" (each pixel's grid triangle, ocean/sea_visibility.glsl, at any sample count);
// unset (""), the driver profile's choice (gl::DriverProfile::seaByVisibility).
std::string seaSurfaceAsked() {
  const char* e = std::getenv("OCEANGLOBE_SEA_SURFACE");
  const std::string asked = e != nullptr ? e : "";
  if (asked.empty() || asked == "buffer" || asked == "visibility") return asked;
  throw InputError("OCEANGLOBE_SEA_SURFACE: '" + asked + "' is not buffer or visibility");
}

// Whether the sea may be drawn deferred (OceanRenderer::setDeferred): unless it is asked forward.
bool deferredAllowed() { return seaPathAsked() != "forward" && seaPathAsked() != "split"; }

// The sea's classes' passes in `bench --breakdown`.
constexpr std::array<const char*, OceanRenderer::kSeaClasses> kClassPass{
    "ocean open sea", "ocean shadows", "ocean floor", "ocean floor shadows", "ocean coast"};
}  // namespace

OceanRenderer::OceanRenderer(const Atmosphere* atmosphere, ValidationMode mode)
    : atmosphere_(atmosphere),
      mode_(mode),
      defines_(oceanDefines(atmosphere, mode)),
      deferred_(deferredAllowed()),
      deferredWithoutExport_(seaPathAsked() == "deferred" || seaPathAsked() == "compute"),
      computeShading_(seaPathAsked() == "compute"),
      visibility_(seaSurfaceAsked() == "visibility" || (seaSurfaceAsked().empty() && gl::driverProfile().seaByVisibility)),
      forwardSplit_(seaPathAsked() == "split" || (seaPathAsked().empty() && !gl::driverProfile().stencilExport)),
      computeForFloors_(seaPathAsked().empty() && !gl::driverProfile().software && !gl::driverProfile().stencilExport),
      vao_(gl::createVertexArray()),
      indices_(gl::createBuffer()) {}

const gl::Program& OceanRenderer::program(unsigned features) {
  gl::Program& p = programs().variants.at(features);
  if (p.id() != 0) return p;
  // The radiance terms' and the split's vertices come from the compute pass (computeGridVertices).
  const char* vertex =
      (features & (kFeatureRadianceTerms | kFeatureCachedVertices)) != 0 ? "ocean/grid_cached.vert" : "ocean/grid.vert";
  p = gl::Program({{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, "ocean/ocean.frag"}}, featureDefines(features));
  return p;
}

std::vector<std::string> OceanRenderer::featureDefines(unsigned features) const {
  std::vector<std::string> d = patternDefines();
  if ((features & kFeatureWaterVolume) == 0) d.emplace_back("OCEAN_NO_WATER_VOLUME");
  if ((features & kFeatureCoastTest) == 0) d.emplace_back("SEA_NO_COAST_TEST");
  if ((features & kFeatureShadows) == 0) d.emplace_back("SHADOWS_OFF");
  if ((features & kFeatureFrameSky) != 0) d.emplace_back("SKY_FRAME_LAYER");
  // The per-wind bands from the tables (the vertex buffer does not keep the vertices').
  if ((features & kFeatureRadianceTerms) != 0) d.insert(d.end(), {"OCEAN_RADIANCE_TERMS", "PATTERN_BANDS_PER_PIXEL"});
  else if ((features & kFeatureCachedVertices) != 0) d.emplace_back("PATTERN_BANDS_PER_PIXEL");
  if (atmosphere_ != nullptr && atmosphere_->skyFilter().radialSums) d.emplace_back("SKY_RADIAL_SUMS");
  if ((features & kFeatureDisplay) != 0) d.emplace_back("OUTPUT_DISPLAY");
  return d;
}

const gl::Program& OceanRenderer::deferredProgram(unsigned features, bool compute, bool visibility,
                                                  bool multisampled) {
  assert((features & ~kFeatureDisplay) < 16u);  // (the variants' index: the feature bits, then the paths')
  gl::Program& p = programs().deferredVariants.at((features & 15u) + (compute ? 16u : 0u) + (visibility ? 32u : 0u) +
                                                  (multisampled ? 64u : 0u) + ((features & kFeatureDisplay) != 0 ? 128u : 0u));
  if (p.id() != 0) return p;
  // The coast test is the surface pass's. The surface buffer's layers the shading reads are the
  // same in its compact layout and its full one (ocean/sea_surface.glsl): one program for both.
  std::vector<std::string> d = featureDefines(features & ~kFeatureCoastTest);
  d.emplace_back("OCEAN_DEFERRED");
  if (visibility) d.emplace_back("SEA_VISIBILITY");
  if (multisampled) d.emplace_back("SEA_VISIBILITY_MULTISAMPLE");
  if (!compute) {
    p = gl::Program({{GL_VERTEX_SHADER, "render/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ocean/ocean.frag"}}, d);
    return p;
  }
  d.emplace_back("OCEAN_COMPUTE");
  if (!visibility && !gl::driverProfile().stencilExport) d.emplace_back("SEA_CLASS_IN_SURFACE");
  p = gl::Program({{GL_COMPUTE_SHADER, "ocean/ocean.frag"}}, d);
  return p;
}

GLuint OceanRenderer::computeImageOf(GLuint target) {
  if (target == 0) return 0;
  const auto attachment = [target](GLenum a, GLenum what) {
    GLint v = 0;
    glGetNamedFramebufferAttachmentParameteriv(target, a, what, &v);
    return v;
  };
  // A single-sampled RGBA32F texture (the HDR target), without the auxiliary channels (--aov).
  if (attachment(GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) != GL_TEXTURE ||
      attachment(GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) != GL_NONE)
    return 0;
  const auto texture = static_cast<GLuint>(attachment(GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME));
  GLint format = 0, samples = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_SAMPLES, &samples);
  return format == GL_RGBA32F && samples == 0 ? texture : 0;
}

OceanRenderer::ClassDispatches::ClassDispatches(GLuint image, GLuint depthStencil)
    : depthStencil_(gl::driverProfile().stencilExport ? depthStencil : 0) {
  glGetTextureLevelParameteriv(image, 0, GL_TEXTURE_WIDTH, &width_);
  glGetTextureLevelParameteriv(image, 0, GL_TEXTURE_HEIGHT, &height_);
  if (depthStencil_ != 0) {
    // The classes from the stencil: the depth-stencil texture read as its stencil, unfiltered
    // (an integer texture is incomplete otherwise); its state put back after. (Without stencil
    // export they are read from the surface buffer.)
    glGetTextureParameteriv(depthStencil_, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode_);
    glGetTextureParameteriv(depthStencil_, GL_TEXTURE_MIN_FILTER, &minFilter_);
    glGetTextureParameteriv(depthStencil_, GL_TEXTURE_MAG_FILTER, &magFilter_);
    glTextureParameteri(depthStencil_, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    glTextureParameteri(depthStencil_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(depthStencil_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTextureUnit(gl::kUnitSeaStencil, depthStencil_);
  }
  glBindImageTexture(0, image, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  // The surface pass's writes and the stencil before the reads. (The classes write disjoint
  // pixels and read none of the image: no barrier between them.)
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

OceanRenderer::ClassDispatches::~ClassDispatches() {
  // The image's writes before the target's next users.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  if (depthStencil_ == 0) return;
  glBindTextureUnit(gl::kUnitSeaStencil, 0);
  glTextureParameteri(depthStencil_, GL_DEPTH_STENCIL_TEXTURE_MODE, mode_);
  glTextureParameteri(depthStencil_, GL_TEXTURE_MIN_FILTER, minFilter_);
  glTextureParameteri(depthStencil_, GL_TEXTURE_MAG_FILTER, magFilter_);
}

void OceanRenderer::ClassDispatches::dispatch(const gl::Program& p, int seaClass) const {
  p.set("uSeaClass", seaClass);
  glDispatchCompute(static_cast<GLuint>((width_ + 7) / 8), static_cast<GLuint>((height_ + 7) / 8), 1);
}

double OceanRenderer::farthestSeaAngleRad(const geo::CameraView& view) {
  const double r = geo::kWgs84SemiMajorM, h = std::max(view.position.heightM, 0.0);
  const double horizon = std::acos(r / (r + h));
  double most = 0.0;
  for (const double sx : {-1.0, 0.0, 1.0}) {
    const glm::dvec3 dir = view.rayDirection(sx, 1.0);
    const std::optional<double> t = seaSphereHitM(h, view.enu.up, dir);
    if (!t) return horizon;
    // Angle at the centre: cos = ((r + h) - t cos(down)) / r, the hit's height along up over r.
    most = std::max(most, std::acos(std::clamp((r + h + *t * glm::dot(dir, view.enu.up)) / r, -1.0, 1.0)));
  }
  return std::min(most, horizon);
}

double OceanRenderer::seaTopNdc(const geo::CameraView& view, double leftNdc, double rightNdc, double bottomNdc,
                                double topNdc) {
  // In the space scaled so that the ellipsoid is the unit sphere, the eye o (|o|² - 1 = c, in
  // double: a metre above the sea) and a ray d = a + y b of one x: it meets the sphere ahead
  // where (o.d)² >= c |d|² and o.d < 0. The first is a quadratic in y, the second linear: the
  // hits of one x are intervals whose ends lie among the roots, -p/q and the range's ends.
  const double ea = geo::kWgs84SemiMajorM, eb = geo::kWgs84SemiMinorM;
  const auto scaled = [&](const glm::dvec3& v) { return glm::dvec3(v.x / ea, v.y / ea, v.z / eb); };
  const glm::dvec3 o = scaled(view.positionEcef);
  const double c = glm::dot(o, o) - 1.0;
  if (c <= 0.0) return topNdc;
  double highest = bottomNdc - 1.0;
  if (!(bottomNdc <= topNdc)) return highest;  // an empty range (or NaN): no ray in it meets the sea
  const double tanY = std::tan(0.5 * view.verticalFovRad), tanX = tanY * view.aspect;
  const glm::dvec3 b = scaled(tanY * view.up);
  for (int k = 0; k <= kSeaTopColumns; ++k) {
    const double x = leftNdc + (rightNdc - leftNdc) * k / kSeaTopColumns;
    const glm::dvec3 a = scaled(view.forward + x * tanX * view.right);
    const double p = glm::dot(o, a), q = glm::dot(o, b);
    const auto hits = [&](double y) {
      const double along = p + y * q;
      const glm::dvec3 d = a + y * b;
      return along < 0.0 && along * along >= c * glm::dot(d, d);
    };
    // (q² - c b.b) y² + 2 (p q - c a.b) y + (p² - c a.a) = 0
    const double qa = q * q - c * glm::dot(b, b), qb = p * q - c * glm::dot(a, b), qc = p * p - c * glm::dot(a, a);
    // The range's ends, -p/q and the two roots, in a fixed array (the unused ends last, +inf).
    constexpr double kUnused = std::numeric_limits<double>::infinity();
    std::array<double, 5> ends{bottomNdc, topNdc, kUnused, kUnused, kUnused};
    std::size_t n = 2;
    const auto add = [&](double y) {
      if (y >= bottomNdc && y <= topNdc) ends.at(n++) = y;  // (NaN and outside the range left out)
    };
    if (q != 0.0) add(-p / q);
    const double disc = qb * qb - qa * qc;
    if (qa != 0.0 && disc >= 0.0) {
      add((-qb - std::sqrt(disc)) / qa);
      add((-qb + std::sqrt(disc)) / qa);
    }
    std::sort(ends.begin(), ends.end());
    for (std::size_t i = 0; i + 1 < n; ++i)
      if (ends[i + 1] > highest && hits(0.5 * (ends[i] + ends[i + 1]))) highest = ends[i + 1];
  }
  return highest;
}

bool OceanRenderer::geometryIsSubPixel(const geo::CameraView& view, int height, double displacementBoundM) {
  const double tanY = std::tan(0.5 * view.verticalFovRad), tanX = tanY * view.aspect;
  // The sea in view, from the rays of the corners and the edges' middles (seen from the sphere
  // of the semi-major axis): every one must meet it kGrownCellMinGrazingRad above grazing,
  // and the nearest gives the nearest sea point, unless the nadir is in view (the eye's height).
  double nearestM = std::numeric_limits<double>::infinity();
  const std::array<std::optional<SeaHit>, 9> hits = seaHitsOfView(view);
  for (std::size_t k = 0; k < hits.size(); ++k) {
    if (k == 4) continue;  // (the centre)
    if (!hits[k]) return false;  // the ray misses: the horizon is in view
    if (hits[k]->cosIncidence < std::sin(kGrownCellMinGrazingRad)) return false;
    nearestM = std::min(nearestM, hits[k]->distanceM);
  }
  if (nadirInView(view)) nearestM = std::max(view.position.heightM, 0.1);
  // The waves move no point by more than displacementBoundM: its largest angle, at the nearest
  // sea point, in pixels where the screen magnifies most (a corner: a rectilinear projection's
  // pixels per radian grow as 1 + tan² of the angle off its axis).
  const double pixelsPerRad = height / (2.0 * tanY) * (1.0 + tanX * tanX + tanY * tanY);
  return displacementBoundM / nearestM * pixelsPerRad <= kSubPixelDisplacementPx;
}

void OceanRenderer::ensureGrid(int columns, int rows) {
  if (columns == gridColumns_ && rows == gridRows_) return;
  // Cells in blocks of kGridBlockRows x kGridBlockColumns, the blocks row band by row band:
  // llvmpipe shades the vertices of a draw in segments of a thousand-odd indices with a small
  // cache of recent ones, so row by row every vertex was shaded twice (once per cell row it
  // touches); blocks share their inner rows: 1.2 shadings a vertex (sea-4m at 1280x720: 78 540
  // vertex shader invocations -> 47 797 for 39 283 vertices, GL_VERTEX_SHADER_INVOCATIONS).
  std::vector<GLuint> idx;
  idx.reserve(static_cast<std::size_t>(6 * (columns - 1) * (rows - 1)));
  const auto c = static_cast<GLuint>(columns);
  for (int y0 = 0; y0 + 1 < rows; y0 += kGridBlockRows)
    for (int x0 = 0; x0 + 1 < columns; x0 += kGridBlockColumns)
      for (int y = y0; y < std::min(y0 + kGridBlockRows, rows - 1); ++y)
        for (int x = x0; x < std::min(x0 + kGridBlockColumns, columns - 1); ++x) {
          const auto i = static_cast<GLuint>(y * columns + x);
          idx.insert(idx.end(), {i, i + 1, i + c, i + 1, i + c + 1, i + c});
        }
  indices_ = gl::createBuffer();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(idx.size() * sizeof(GLuint)), idx.data(), 0);
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  gridColumns_ = columns;
  gridRows_ = rows;
  indexCount_ = static_cast<int>(idx.size());
}

void OceanRenderer::setCommon(const gl::Program& p, const geo::CameraView& view, int height,
                              const ocean::OceanFrame& frame, const OceanLighting& lighting,
                              unsigned features) const {
  const geo::EnuFrame& axes = frame.axes();
  // Rows east, north, up: ECEF vector -> ocean frame components.
  const glm::mat3 ecefToOcean = glm::transpose(
      glm::mat3(glm::vec3(axes.east), glm::vec3(axes.north), glm::vec3(axes.up)));
  // The eye's height above the frame's tangent plane (the frame sits under the eye).
  const double eyeHeight = glm::dot(view.positionEcef - frame.originEcef(), axes.up);
  const glm::dvec3 o = view.positionEcef / glm::dvec3(geo::kWgs84SemiMajorM, geo::kWgs84SemiMajorM,
                                                     geo::kWgs84SemiMinorM);
  const double tanY = std::tan(0.5 * view.verticalFovRad);
  p.set("uGridSize", glm::ivec2(gridColumns_, gridRows_));
  p.set("uRight", toFloat(view.right));
  p.set("uUp", toFloat(view.up));
  p.set("uForward", toFloat(view.forward));
  p.set("uTanHalfFov", glm::vec2(static_cast<float>(tanY * view.aspect), static_cast<float>(tanY)));
  p.set("uViewProjection", glm::mat4(view.viewProjection()));
  p.set("uEcefToOcean", ecefToOcean);
  p.set("uEyeHeight", static_cast<float>(eyeHeight));
  p.set("uCellAngle", static_cast<float>(2.0 * tanY / height * frameCellPixels_));
  p.set("uCellPixels", static_cast<float>(frameCellPixels_));
  // Patterns whose texels span 2 cells or more are looked up per vertex (ocean/patterns.glsl).
  p.set("uPatternVertexLod", static_cast<float>(-std::log2(static_cast<double>(frameCellPixels_))));
  p.set("uEyeScaled", toFloat(o));
  p.set("uEyeC", static_cast<float>(glm::dot(o, o) - 1.0));
  p.set("uSunDirOcean", ecefToOcean * toFloat(glm::normalize(lighting.sunDirectionEcef)));
  p.set("uSunDirEcef", toFloat(glm::normalize(lighting.sunDirectionEcef)));
  p.set("uSeaColor", lighting.seaColor);
  if ((features & kFeatureWaterVolume) != 0) {
    setWaterOptics(p, ocean::jerlovWater(ocean::kDefaultWater));
    setFloorDetail(p, view);
  }
  p.set("uElevationMap", elevationMap_);
  p.set("uElevationSize", elevationSize_);
  p.set("uElevationWraps", elevationWraps_);
  if ((features & kFeatureCoastTest) != 0) p.set("uCoastTest", lighting.landInView ? 1 : 0);
  p.set("uCamUp", toFloat(view.enu.up));
  p.set("uCamAltitude", static_cast<float>(view.position.heightM));
  if ((features & kFeatureShadows) != 0) {
    if (lighting.shadows != nullptr)
      lighting.shadows->apply(p);
    else
      p.set("uShadowOn", 0);
  }
  if (atmosphere_ != nullptr) {
    atmosphere_->bind(p);
    atmosphere_->bindSkyMaps();
  } else {
    p.set("uSkyZenith", lighting.skyZenith);
    p.set("uSkyHorizon", lighting.skyHorizon);
  }
}

unsigned OceanRenderer::frameFeatures(const geo::CameraView& view, const OceanPatterns& patterns, double timeS,
                                      const OceanLighting& lighting, OceanModel model) {
  if (model == OceanModel::Classic) return kFeatureCoastTest | kFeatureShadows;  // classic.frag has no variants: its uniforms
  unsigned features = 0;
  if (lighting.floorInReach) features |= kFeatureWaterVolume;
  if (lighting.landInView) features |= kFeatureCoastTest;
  if (lighting.shadows != nullptr && lighting.shadows->on) features |= kFeatureShadows;
  if (atmosphere_ != nullptr && farthestSeaAngleRad(view) <= kFrameSkyMaxAngleRad) {
    features |= kFeatureFrameSky;
    const double cosSun = glm::dot(glm::normalize(lighting.sunDirectionEcef), view.enu.up);
    atmosphere_->prepareFrameSkyLayer(std::acos(std::clamp(cosSun, -1.0, 1.0)));
  } else if (atmosphere_ != nullptr) {
    atmosphere_->prepareSunLayerSums();  // (once: the Sun layers' radial sums, where used)
  }
  if ((features & kFeatureWaterVolume) != 0 && lighting.causticsSeen) {
    if (timer_ != nullptr) timer_->mark("ocean caustics");
    caustics_.update(patterns, timeS);
    if (timer_ != nullptr) timer_->mark("ocean");
  }
  return features;
}

bool OceanRenderer::drawsClassified(const OceanLighting& lighting, unsigned features) {
  return lighting.classes && (features & (kFeatureWaterVolume | kFeatureCoastTest)) != 0 && drawTargetHasStencil() &&
         gl::driverProfile().stencilExport;
}

double OceanRenderer::slopeVarianceFloor(const OceanPatterns& patterns, const WindTextures& wind) {
  const double low = wind.hasLayers() ? 0.0 : wind.constantSpeedMs();
  const double high = wind.hasLayers() ? wind.maxLayerSpeedMs() : wind.constantSpeedMs();
  const int last = ocean::PatternTables::kSpeeds - 1;
  double floor = std::numeric_limits<double>::infinity();
  for (int speed = std::clamp(static_cast<int>(std::floor(low)), 0, last);
       speed <= std::clamp(static_cast<int>(std::ceil(high)), 0, last); ++speed) {
    const ocean::SlopeVariance v = patterns.tables().totalSlopeVariance(speed);
    floor = std::min({floor, v.up, v.cross});
  }
  return floor;
}

glm::dvec2 OceanRenderer::seaZenithRangeRad(const geo::CameraView& view) {
  glm::dvec2 range(0.5 * std::numbers::pi, 0.0);
  for (const std::optional<SeaHit>& hit : seaHitsOfView(view)) {
    if (!hit) return {range.x, 0.5 * std::numbers::pi};
    const double zenith = std::acos(std::clamp(hit->cosIncidence, -1.0, 1.0));
    range = {std::min(range.x, zenith), std::max(range.y, zenith)};
  }
  if (nadirInView(view)) range.x = 0.0;
  return range;
}

double OceanRenderer::radianceTermsMaxCellRad(const geo::CameraView& view, const glm::dvec3& sunDirectionEcef,
                                              const OceanPatterns& patterns, const WindTextures& wind) {
  // The glint's lobe seen across the view at zenith angle theta: a facet tilted sideways by
  // sigma turns the reflected ray's azimuth by ~2 sigma cot(theta), on the screen 2 sigma
  // cos(theta). It lies where the view's zenith angle is 90° less the Sun's elevation, taken
  // within the zenith angles of the sea in view.
  const double sunElevation = std::asin(std::clamp(glm::dot(glm::normalize(sunDirectionEcef), view.enu.up), -1.0, 1.0));
  const glm::dvec2 range = seaZenithRangeRad(view);
  const double zenith = std::clamp(0.5 * std::numbers::pi - std::max(sunElevation, 0.0), range.x, range.y);
  const double lobeRad = 2.0 * std::sqrt(slopeVarianceFloor(patterns, wind)) * std::cos(zenith);
  return std::min(kRadianceTermsMaxCellLobes * lobeRad, kGrownCellMaxRad);
}

int OceanRenderer::grownCellPixels(const geo::CameraView& view, int height, double maxCellRad) const {
  const double pixelRad = 2.0 * std::tan(0.5 * view.verticalFovRad) / height;
  for (int k = kGrownCellFactor; k > 1; k /= 2)
    if (k * cellPixels_ * pixelRad <= maxCellRad) return k * cellPixels_;
  return cellPixels_;
}

void OceanRenderer::layOutGrid(const geo::CameraView& view, int width, int height, double side, double bottom,
                               OceanModel model) {
  // The rows (ocean/grid.vert's gridNdc): the uniform rows' layout from the grid's bottom to
  // its top, fine from kGridFineBottomNdc below the screen up (the same rows as all fine), the
  // filtered model's rows below that merged kGridCoarseFactor to one.
  const double span = 2.0 + bottom + 0.1;
  const int rows = std::max(1, static_cast<int>(std::ceil(span * height / (2.0 * frameCellPixels_))));
  const double step = span / rows;
  const int fineRows = std::min(rows, static_cast<int>(std::ceil((2.1 + kGridFineBottomNdc) / step)));
  const int merged = model == OceanModel::Bruneton ? rows - fineRows : 0;
  const int coarseRows = merged >= kGridCoarseFactor ? (merged + kGridCoarseFactor - 1) / kGridCoarseFactor : 0;
  const int below = coarseRows > 0 ? merged : 0;  // uniform rows the coarse ones stand for
  gridRowsNdc_ = glm::vec4(static_cast<float>(-1.0 - bottom), coarseRows > 0 ? static_cast<float>(below * step / coarseRows) : 0.0f,
                           static_cast<float>(-1.0 - bottom + below * step), static_cast<float>(step));
  gridCoarseRows_ = coarseRows;
  ensureGrid(std::max(2, static_cast<int>(std::ceil(width * (1 + side) / frameCellPixels_)) + 1),
             coarseRows + rows - below + 1);
  // The rows above the sea's top all lie on the horizon (their rays lowered onto it): their
  // vertices and triangles drew nothing (sea-2m-horizon: over half the fine rows). The filtered
  // model's rows stop at the first fine row over the sea's top, kGridRowsOverSeaTop more, in
  // whole bands; the rows kept lie where they lay. (The classic model spaces its rows by their
  // count: all of them.)
  gridRowsDrawn_ = gridRows_;
  if (model != OceanModel::Bruneton || !gridToSeaTop_) return;
  const double fineStart = -1.0 - bottom + below * step, gridTop = -1.0 - bottom + rows * step;
  const double seaTop = seaTopNdc(view, -1.0 - side, 1.0 + side, -1.0 - bottom, gridTop);
  const int overTop = coarseRows + std::max(static_cast<int>(std::ceil((seaTop - fineStart) / step)), 0) +
                      kGridRowsOverSeaTop;  // the vertex row
  const int bands = (overTop + kGridBlockRows - 1) / kGridBlockRows;
  gridRowsDrawn_ = std::clamp(bands * kGridBlockRows + 1, 2, gridRows_);
}

glm::vec4 OceanRenderer::layOutGridOnBlocks(int width, int height) {
  const int cell = frameCellPixels_;
  const int columns = (width + cell - 1) / cell, rows = (height + cell - 1) / cell;
  gridRowsNdc_ = glm::vec4(-1.0f, 0.0f, -1.0f, static_cast<float>(2.0 * cell / height));
  gridCoarseRows_ = 0;
  ensureGrid(columns + 1, rows + 1);
  gridRowsDrawn_ = gridRows_;
  // Whole cells from the screen's bottom-left corner: past the right and top edges, not below.
  return {0.0f, static_cast<float>(2.0 * columns * cell / width - 2.0), 0.0f,
          static_cast<float>(2.0 * rows * cell / height - 2.0)};
}

void OceanRenderer::draw(const geo::CameraView& view, int width, int height,
                         const OceanPatterns& patterns, const ocean::OceanFrame& frame, double timeS,
                         const OceanLighting& lighting, double amplitudeScale, OceanModel model,
                         const WindTextures& wind) {
  // The grid overshoots the screen (NDC) so displaced edges stay covered: waves displace
  // vertices by up to their amplitude, which is a large angle seen from a few metres.
  const double amplitude = model == OceanModel::Classic ? 0.76 : patterns.amplitudeBoundM();  // classic: its four sines
  const double eyeAbove = std::max(view.position.heightM, 0.1);
  const double side = std::clamp(amplitudeScale * amplitude / eyeAbove, 0.1, 1.0);
  const double bottom = std::clamp(3.0 * amplitudeScale * amplitude / eyeAbove, 0.1, 3.0);
  glm::vec4 margin(static_cast<float>(side), static_cast<float>(side), static_cast<float>(bottom),
                   0.1f);  // left, right, bottom, top
  unsigned features = frameFeatures(view, patterns, timeS, lighting, model);
  const bool classified = model == OceanModel::Bruneton && drawsClassified(lighting, features);
  // Grown cells where the geometry is sub-pixel: small enough for the vertices' radiance
  // quadratic where that may serve (the forward draw's open sea), else up to kGrownCellMaxRad.
  frameCellPixels_ = cellPixels_;
  bool termsCells = false;
  if (model == OceanModel::Bruneton && cellGrowth_ && geometryIsSubPixel(view, height, amplitudeScale * amplitude)) {
    if (radianceTerms_ && mode_ == ValidationMode::Filtered && (features & (kFeatureWaterVolume | kFeatureShadows)) == 0 &&
        !classified) {
      frameCellPixels_ = grownCellPixels(view, height, radianceTermsMaxCellRad(view, lighting.sunDirectionEcef, patterns, wind));
      termsCells = frameCellPixels_ > cellPixels_ && frameCellPixels_ >= kDeferredMaxCellPixels;  // grown
    }
    if (!termsCells) frameCellPixels_ = grownCellPixels(view, height, kGrownCellMaxRad);
  }
  if (termsCells)
    margin = layOutGridOnBlocks(width, height);
  else
    layOutGrid(view, width, height, side, bottom, model);

  // A constant wind along one of the patterns' bins: the programs that read one bin.
  programSet_ = model == OceanModel::Bruneton && oneBinAllowed_ && !wind.hasLayers() &&
                        windAlongOneBin(glm::radians(wind.constantTowardsDeg()), frame.fieldRotationRad())
                    ? 1
                    : 0;
  // The deferred classes by compute shaders (OCEANGLOBE_SEA=compute; on a GPU without stencil
  // export, the frames with a floor within reach), where they can serve: into the target's
  // image (not --aov's targets), the classes' samples not counted. The bound framebuffer is
  // drawDeferred's target.
  const bool floorsByCompute = computeForFloors_ && lighting.classes && (features & kFeatureWaterVolume) != 0;
  frameComputeImage_ = 0;
  if ((computeShading_ || floorsByCompute) && !countClassSamples_) {
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    frameComputeImage_ = computeImageOf(static_cast<GLuint>(target));
  }
  const bool computeFloors = floorsByCompute && frameComputeImage_ != 0;
  lastDeferred_ = false;
  lastForwardSplit_ = false;
  lastClassesByCompute_ = false;
  lastSurfaceCompact_ = false;
  lastSurfaceByVisibility_ = false;
  lastRadianceTerms_ = false;
  lastCoversScreen_ = false;
  lastWroteDisplay_ = false;
  frameDisplayFbo_ = std::exchange(displayFbo_, 0);  // (for this draw only)
  if (model == OceanModel::Classic) {
    if (classic_.id() == 0) {  // made on first use (start-up: bench --startup)
      classic_ = gl::Program({{GL_VERTEX_SHADER, "ocean/classic.vert"}, {GL_FRAGMENT_SHADER, "ocean/classic.frag"}},
                             skyDefines(atmosphere_));
      bumpMap_ = makeBumpMap();
      fresnelRamp_ = makeFresnelRamp();
    }
    const gl::Program& p = classic_;
    setCommon(p, view, height, frame, lighting, features);
    p.set("uGridMarginNdc", margin);
    // The classic pattern repeats every 800 m (see classic.vert/.frag): fold the offset there.
    const glm::dvec2 off = frame.fieldOffsetM();
    p.set("uFieldOffset", glm::vec2(static_cast<float>(std::fmod(off.x, 800.0)),
                                    static_cast<float>(std::fmod(off.y, 800.0))));
    p.set("uTime", static_cast<float>(std::fmod(timeS, 1000.0)));
    glBindTextureUnit(gl::kUnitBumpMap, bumpMap_.id());
    glBindTextureUnit(gl::kUnitFresnelRamp, fresnelRamp_.id());
    drawGrid(p);
  } else if (const SeaSurfaceBuffer::DepthStencil depthStencil =
                 deferred_ ? SeaSurfaceBuffer::boundDepthStencil() : SeaSurfaceBuffer::DepthStencil{};
             deferred_ && mode_ == ValidationMode::Filtered && frameCellPixels_ < kDeferredMaxCellPixels &&
             depthStencil.texture != 0 && deferredServes(depthStencil.samples, features, surfaceClasses(lighting, features), computeFloors)) {
    lastDeferred_ = true;
    drawDeferred(view, width, height, patterns, frame, lighting, amplitudeScale, wind, features, margin, depthStencil);
  } else if (classified) {  // sea_classify.frag
    drawClassified(view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
  } else {
    lastRadianceTerms_ = termsCells;
    lastCoversScreen_ = termsCells && (features & kFeatureCoastTest) == 0;
    if (!termsCells && forwardSplit_ && mode_ == ValidationMode::Filtered && lighting.classes &&
        (features & (kFeatureWaterVolume | kFeatureCoastTest)) != 0) {
      drawForwardSplit(view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
      gl::checkErrors("OceanRenderer::draw");
      return;
    }
    if (termsCells) features |= kFeatureRadianceTerms;
    if (termsCells) {  // the vertices first, on every core
      gl::Program& compute = programs().termsComputeVariants.at(features & ~kFeatureRadianceTerms);
      if (compute.id() == 0) compute = gl::Program({{GL_COMPUTE_SHADER, "ocean/grid_vertices.comp"}}, featureDefines(features));
      prepare(compute, view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
      computeGridVertices(compute, true);
      if (timer_ != nullptr) timer_->mark("ocean");
    }
    // (The forward grid writes its colour and depth in one fragment: the display wherever
    // the depth shows sea.)
    lastWroteDisplay_ = frameDisplayFbo_ != 0;
    if (lastWroteDisplay_) features |= kFeatureDisplay;
    const gl::Program& p = program(features);
    prepare(p, view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
    std::optional<ScopedDisplayTarget> display;
    if (lastWroteDisplay_) display.emplace(frameDisplayFbo_);
    drawGrid(p);
  }
  gl::checkErrors("OceanRenderer::draw");
}

OceanRenderer::ScopedDisplayTarget::ScopedDisplayTarget(GLuint displayFbo) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, displayFbo);
  glEnable(GL_FRAMEBUFFER_SRGB);  // the store encodes sRGB, as for render/tonemap.frag
}

OceanRenderer::ScopedDisplayTarget::~ScopedDisplayTarget() {
  glDisable(GL_FRAMEBUFFER_SRGB);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(bound_));
}

bool OceanRenderer::surfaceClasses(const OceanLighting& lighting, unsigned features) {
  return lighting.classes && (features & (kFeatureWaterVolume | kFeatureCoastTest)) != 0;
}

bool OceanRenderer::deferredServes(int samples, unsigned features, bool classes, bool computeFloors) const {
  // Multisampled: only by the visibility buffer (one class: a sample's class is its triangle's),
  // without --aov's channels (copySeaRadiance writes the radiance alone).
  if (samples > 1) {
    static const GLint maxIntegerSamples = [] {  // (the visibility buffer's R32UI samples)
      GLint n = 0;
      glGetIntegerv(GL_MAX_INTEGER_SAMPLES, &n);
      return n;
    }();
    return visibilityServes(features, classes) && samples <= maxIntegerSamples && !drawTargetHasAuxiliary();
  }
  return gl::driverProfile().stencilExport || deferredWithoutExport_ || computeFloors || visibilityServes(features, classes);
}

bool OceanRenderer::visibilityServes(unsigned features, bool classes) const {
  // (The coast test is the surface pass's, which the visibility buffer's has not.)
  return visibility_ && !classes && (features & kFeatureCoastTest) == 0 && gridTexelsFit();
}

bool OceanRenderer::gridTexelsFit() const {
  static const GLint maxTexels = [] {
    GLint n = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &n);
    return n;
  }();
  // (GL guarantees 65536 texels, drivers offer 2^27.)
  return static_cast<std::int64_t>(gridColumns_) * gridRows_ * kGridVertexVec4s <= maxTexels;
}

void OceanRenderer::shadeClass(const std::function<const gl::Program&()>& program, int stencilClass, std::size_t pass,
                               std::size_t counted, const std::function<void(const gl::Program&)>& prepareProgram,
                               const ClassDispatches* dispatches) {
  if (timer_ != nullptr) timer_->mark(kClassPass.at(pass));
  if (counted < kSeaClasses) classesDrawn_ |= 1u << counted;
  const gl::Program& p = program();  // (after the mark: a variant compiled on first use is its pass's time)
  prepareProgram(p);
  p.use();
  if (dispatches != nullptr)
    dispatches->dispatch(p, stencilClass);
  else
    shadeClassPixels(stencilClass, counted);
}

void OceanRenderer::shadeClassPixels(int stencilClass, std::size_t counted) {
  glStencilFunc(GL_EQUAL, stencilClass, 0xff);
  const auto draw = [] { glDrawArrays(GL_TRIANGLES, 0, 3); };
  if (countClassSamples_ && counted < kSeaClasses)
    classSamples_.at(counted) += gl::queryResult(GL_SAMPLES_PASSED, draw);
  else
    draw();
}

void OceanRenderer::prepare(const gl::Program& p, const geo::CameraView& view, int height,
                            const OceanPatterns& patterns, const ocean::OceanFrame& frame,
                            const OceanLighting& lighting, double amplitudeScale,
                            const WindTextures& wind, unsigned features, const glm::vec4& margin) const {
  setCommon(p, view, height, frame, lighting, features);
  if ((features & kFeatureDisplay) != 0) p.set("uExposure", displayExposure_);
  p.set("uGridMarginNdc", margin);
  p.set("uGridRowsNdc", gridRowsNdc_);
  p.set("uGridCoarseRows", gridCoarseRows_);
  if ((features & kFeatureWaterVolume) != 0) caustics_.bind();
  patterns.bind();
  patterns.setUniforms(p, &frame, amplitudeScale);
  if (programSet_ == 1)
    patterns.setConstantWind(p, wind.constantSpeedMs(), glm::radians(wind.constantTowardsDeg()), frame.fieldRotationRad());
  p.set("uLightingTerms", lightingTerms_);
  wind.bind(p);
}

void OceanRenderer::drawGrid(const gl::Program& p) const { drawGridRows(p, 0, gridRowsDrawn_ - 2); }

void OceanRenderer::drawGridRows(const gl::Program& p, int firstRow, int lastRow) const {
  if (lastRow < firstRow) return;
  // Whole bands of rows (ensureGrid's order): a band's cells are contiguous in the indices.
  const int first = firstRow - firstRow % kGridBlockRows;
  const int last = std::min(lastRow - lastRow % kGridBlockRows + kGridBlockRows - 1, gridRowsDrawn_ - 2);
  const auto perRow = static_cast<std::size_t>(6 * (gridColumns_ - 1));
  p.use();
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(perRow * static_cast<std::size_t>(last - first + 1)),
                 GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(perRow * static_cast<std::size_t>(first) * sizeof(GLuint)));
}

std::vector<std::string> OceanRenderer::patternDefines() const {
  std::vector<std::string> d = defines_;
  if (programSet_ == 1) d.insert(d.end(), {"PATTERN_ONE_BIN", "PATTERN_CONSTANT_WIND"});
  return d;
}

bool OceanRenderer::windAlongOneBin(double towardsRad, double fieldRotationRad) {
  // ocean/patterns.glsl's windBins: the second bin's weight sin(pi/2 f) for the fraction f past
  // the first.
  const double b = OceanPatterns::fieldWind(towardsRad, fieldRotationRad).bin;
  const double f = b - std::floor(b);
  return std::sin(0.5 * std::numbers::pi * std::min(f, 1.0 - f)) < 1e-3;
}

bool OceanRenderer::drawTargetHasAuxiliary() {
  GLint fbo = 0, type = GL_NONE;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  if (fbo == 0) return false;
  glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(fbo), GL_COLOR_ATTACHMENT1,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  return type != GL_NONE;
}

bool OceanRenderer::drawTargetHasStencil() {
  GLint fbo = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  const auto name = static_cast<GLuint>(fbo);
  const GLenum attachment = name == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
  GLint type = GL_NONE;
  glGetNamedFramebufferAttachmentParameteriv(name, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type == GL_NONE) return false;
  GLint bits = 0;
  glGetNamedFramebufferAttachmentParameteriv(name, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &bits);
  return bits >= 2;
}

double OceanRenderer::shadowReachM(const OceanLighting& lighting, const geo::CameraView& view, bool volume,
                                   double waterReachM, double* towardsSunM, double* casterHeightM) {
  if (towardsSunM != nullptr) *towardsSunM = 0.0;
  if (casterHeightM != nullptr) *casterHeightM = 0.0;
  if (lighting.shadows == nullptr || !lighting.shadows->on) return -1.0;
  // The Sun's elevation at the eye; across the sea in view from a few metres up (a few km) the
  // vertical turns by less than the 0.01 rad taken off. From 20 km up the sea reaches ~500 km,
  // where the Sun can stand ~4° lower: the classes take each vertex's own elevation with the
  // casters' height (ocean/water_volume_vertex.glsl); this reach is the eye's.
  const double sinElevation = glm::dot(glm::normalize(lighting.sunDirectionEcef), view.enu.up);
  const double elevation = std::asin(std::clamp(sinElevation, -1.0, 1.0)) - 0.01;
  if (elevation < 0.0175) return -1.0;
  // The maps hold no ground below sea level (terrain/shadow_depth.frag): no caster, no shadow.
  if (lighting.shadows->casterMaxHeightM < 0.0) return 0.0;
  // The casters' meshes with a margin for their morphing between levels.
  const double heightM = 1.05 * std::max(lighting.shadows->casterMaxHeightM, 0.0) + 5.0;
  constexpr double kTanCritical = 1.13;  // tan(asin(1 / 1.34)): a refracted ray's steepest slope
  const double castersM = heightM / std::tan(elevation);
  if (towardsSunM != nullptr) *towardsSunM = castersM;
  if (casterHeightM != nullptr) *casterHeightM = heightM;
  return castersM + (volume ? (1.0 + kTanCritical) * waterReachM : 0.0);
}

unsigned OceanRenderer::setClassUniforms(const gl::Program& p, const geo::CameraView& view,
                                         const OceanPatterns& patterns, const OceanLighting& lighting,
                                         double amplitudeScale, unsigned features) const {
  const bool volume = (features & kFeatureWaterVolume) != 0, coast = (features & kFeatureCoastTest) != 0;
  const double reachM = ocean::waterMaxPathM(ocean::jerlovWater(ocean::kDefaultWater).attenuationPerM,
                                             ocean::kWaterEpsilon);
  p.set("uWaterReachM", volume ? static_cast<float>(reachM) : -1e30f);
  p.set("uCoastClass", coast ? 1 : 0);
  p.set("uLayerMaxSlope", layerMaxSlope_);
  p.set("uWaveReachM", static_cast<float>(amplitudeScale * patterns.amplitudeBoundM()));
  // The terrain's shadows routed to classes 2 and 4 (and 5) where they can reach, if the frame
  // has them.
  double towardsSunM = 0.0, casterHeightM = 0.0;
  const double shadowReach = (features & kFeatureShadows) != 0
                                 ? shadowReachM(lighting, view, volume, reachM, &towardsSunM, &casterHeightM)
                                 : -1.0;
  // A caster shades a sea point only from between it and the Sun: the classes look for land
  // in the disc around the point half the casters' reach towards the Sun, each vertex with its
  // own Sun (ocean/water_volume_vertex.glsl), so they get the casters' height and the rest of
  // the reach apart, the rest with a margin of the maps' soft edge (terrain/shadow.glsl: 4
  // lookups 1 texel apart, 1.5 texels along the normal: 3 of the far cascade's texels).
  const double marginM = 3.0 * double{lighting.shadows != nullptr ? lighting.shadows->texelM[1] : 0.0f};
  p.set("uShadowCasterHeightM", static_cast<float>(casterHeightM));
  p.set("uShadowBesideCastersM", static_cast<float>(shadowReach >= 0.0 ? shadowReach - towardsSunM + marginM : -1.0));
  return shadowReach >= 0.0 ? kFeatureShadows : 0u;
}

std::array<unsigned, OceanRenderer::kSeaClasses> OceanRenderer::classFeatures(unsigned features,
                                                                              unsigned routedShadows) {
  const unsigned routed = kFeatureWaterVolume | kFeatureCoastTest | routedShadows;
  return {features & ~routed, features & ~(kFeatureCoastTest | kFeatureWaterVolume),
          features & ~(kFeatureCoastTest | routedShadows), features & ~kFeatureCoastTest, features};
}

std::array<GLint, 2 * OceanRenderer::kSeaClasses> OceanRenderer::noClassRows() {
  std::array<GLint, 2 * kSeaClasses> none{};
  for (std::size_t k = 0; k < kSeaClasses; ++k) none.at(2 * k) = kNoRow, none.at(2 * k + 1) = -1;
  return none;
}

void OceanRenderer::resetClassRows() {
  if (classRows_.id() == 0) {
    classRows_ = gl::createBuffer();
    glNamedBufferStorage(classRows_.id(), kClassRowsInts * sizeof(GLint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  std::array<GLint, kClassRowsInts> none{};  // (the visibility buffer's classes' flags 0)
  const std::array<GLint, 2 * kSeaClasses> rows = noClassRows();
  std::copy(rows.begin(), rows.end(), none.begin());
  glNamedBufferSubData(classRows_.id(), 0, sizeof none, none.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kClassRowsBinding, classRows_.id());
}

unsigned OceanRenderer::prepareClassify(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                                        const ocean::OceanFrame& frame, const OceanLighting& lighting,
                                        double amplitudeScale, const WindTextures& wind, unsigned features,
                                        const glm::vec4& margin) {
  if (programs().classify.id() == 0) {
    std::vector<std::string> d = patternDefines();
    d.emplace_back("OCEAN_SEA_CLASSIFY");
    if (!gl::driverProfile().stencilExport) d.emplace_back("SEA_CLASS_IN_SURFACE");  // seaShows' query alone
    programs().classify = gl::Program({{GL_VERTEX_SHADER, "ocean/grid.vert"}, {GL_FRAGMENT_SHADER, "ocean/sea_classify.frag"}}, d);
  }
  prepare(programs().classify, view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
  const unsigned routedShadows = setClassUniforms(programs().classify, view, patterns, lighting, amplitudeScale, features);
  resetClassRows();
  return routedShadows;
}

bool OceanRenderer::seaShows(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                             const ocean::OceanFrame& frame, const OceanLighting& lighting, double amplitudeScale,
                             const WindTextures& wind, unsigned features, const glm::vec4& margin) {
  prepareClassify(view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  const bool shows = gl::queryResult(GL_ANY_SAMPLES_PASSED, [&] { drawGrid(programs().classify); }) != 0;
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  return shows;
}

void OceanRenderer::drawClassified(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                                   const ocean::OceanFrame& frame, const OceanLighting& lighting,
                                   double amplitudeScale, const WindTextures& wind, unsigned features,
                                   const glm::vec4& margin) {
  const unsigned routedShadows =
      prepareClassify(view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
  // The classes: the largest of the grid's fragments in a pixel (folds at grazing angles),
  // only where the sea passes the depth test (in front of the terrain).
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xff);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilFunc(GL_GEQUAL, 0, 0xff);  // the reference is the shader's (gl_FragStencilRefARB)
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  if (timer_ != nullptr) timer_->mark("ocean classify");
  // Fragments behind the terrain record their rows too (the shader's side effects come before
  // the depth test); where none passes it (the sea hidden by mountains) nothing is drawn.
  const bool seaVisible = gl::queryResult(GL_ANY_SAMPLES_PASSED, [&] { drawGrid(programs().classify); }) != 0;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::array<GLint, 2 * kSeaClasses> rows = noClassRows();
  if (seaVisible) glGetNamedBufferSubData(classRows_.id(), 0, sizeof rows, rows.data());
  if (timer_ != nullptr) timer_->mark("ocean");
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  // Each class by its program over the grid rows that can make its pixels. No stencil writes:
  // llvmpipe then tests depth and stencil before the shader even where it may discard (the
  // coast test), so a class's shading costs only its pixels, and its vertices only its rows.
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0);
  const std::array<unsigned, kSeaClasses> perClass = classFeatures(features, routedShadows);
  for (std::size_t k = 0; k < kSeaClasses; ++k) {
    const GLint first = rows.at(2 * k), last = rows.at(2 * k + 1);
    if (last < first) continue;  // no fragment of the grid is of this class
    if (timer_ != nullptr) timer_->mark(kClassPass.at(k));
    classesDrawn_ |= 1u << k;
    const gl::Program& p = program(perClass.at(k));
    prepare(p, view, height, patterns, frame, lighting, amplitudeScale, wind, perClass.at(k), margin);
    glStencilFunc(GL_EQUAL, static_cast<GLint>(k + 1), 0xff);
    // Triangle rows r span vertex rows r and r + 1; kFoldRows more each side for the grid's
    // folds (a nearer fragment of another row in a pixel whose class a farther one set).
    const auto draw = [&] {
      drawGridRows(p, std::max(first - 1 - kFoldRows, 0), std::min(last + kFoldRows, gridRowsDrawn_ - 2));
    };
    if (countClassSamples_)
      classSamples_.at(k) = gl::queryResult(GL_SAMPLES_PASSED, draw);
    else
      draw();
  }
  if (timer_ != nullptr) timer_->mark("ocean");
  glStencilMask(0xff);
  glClear(GL_STENCIL_BUFFER_BIT);  // as the caller had it (the globe's parts count from 0)
  glDisable(GL_STENCIL_TEST);
}

bool OceanRenderer::surfaceCompact(unsigned surfaceKey) {
  return (surfaceKey & kFeatureWaterVolume) == 0;  // (the class, without stencil export, in layer 0)
}

std::vector<std::string> OceanRenderer::surfaceDefines(unsigned key) const {
  std::vector<std::string> d = featureDefines(key & (kFeatureWaterVolume | kFeatureCoastTest));
  if ((key & kSurfaceClasses) != 0) d.emplace_back("OCEAN_SEA_CLASSIFY");
  if (!gl::driverProfile().stencilExport) d.emplace_back("SEA_CLASS_IN_SURFACE");
  if (surfaceCompact(key)) d.emplace_back("SEA_SURFACE_COMPACT");
  return d;
}

void OceanRenderer::classesIntoStencil() {
  if (classStencil_.id() == 0)
    classStencil_ = gl::Program({{GL_VERTEX_SHADER, "render/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ocean/sea_class_stencil.frag"}});
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilFunc(GL_ALWAYS, 0xff, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  surface_.bindForReading();
  glBindVertexArray(vao_.id());
  classStencil_.use();
  for (int bit = 0; bit < 3; ++bit) {  // classes 1..kSeaClasses
    glStencilMask(1u << bit);
    classStencil_.set("uClassBit", bit);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

namespace {
// A buffer texture of `format` over `buffer` at `unit`, `view` made on first use. (Re-pointed
// each frame: ensureBufferCapacity and ensureGrid may have made new buffers.)
void bindTexels(gl::Texture& view, GLenum format, const gl::Buffer& buffer, GLuint unit) {
  if (view.id() == 0) view = gl::createTexture(GL_TEXTURE_BUFFER);
  glTextureBuffer(view.id(), format, buffer.id());
  glBindTextureUnit(unit, view.id());
}
}  // namespace

void OceanRenderer::bindGridTexels(bool radianceTerms) {
  // Every reader of the vertices reads them so (ocean/grid_vertex_buffer.glsl): a grid beyond a
  // buffer texture (2^27 texels on the drivers known, 65536 guaranteed) cannot be drawn.
  if (!gridTexelsFit())
    throw InternalError("OceanRenderer: the projected grid's " + std::to_string(gridColumns_) + " x " +
                        std::to_string(gridRows_) + " vertices exceed this driver's buffer textures");
  bindTexels(gridVertexTexels_, GL_RGBA32F, gridVertices_, gl::kUnitSeaGridVertices);
  if (radianceTerms) bindTexels(gridTermsTexels_, GL_RGBA32F, gridRadianceTerms_, gl::kUnitSeaGridTerms);
}

void OceanRenderer::bindVisibilityForShading() {
  surface_.bindVisibilityForReading();
  // The triangles' corners (the vertices' texels bound by computeGridVertices).
  bindTexels(gridIndexTexels_, GL_R32UI, indices_, gl::kUnitSeaGridIndices);
}

GLuint OceanRenderer::seaRadianceImage(int width, int height) {
  if (seaRadiance_.id() == 0 || seaRadianceWidth_ != width || seaRadianceHeight_ != height) {
    seaRadiance_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(seaRadiance_.id(), 1, GL_RGBA32F, width, height);
    seaRadianceWidth_ = width, seaRadianceHeight_ = height;
  }
  return seaRadiance_.id();
}

void OceanRenderer::copySeaRadiance(GLuint target) {
  if (seaRadianceCopy_.id() == 0)
    seaRadianceCopy_ = gl::Program(
        {{GL_VERTEX_SHADER, "render/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ocean/sea_radiance_copy.frag"}});
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  glStencilFunc(GL_EQUAL, 1, 0xff);  // the samples with sea
  glBindTextureUnit(gl::kUnitSeaSurface, seaRadiance_.id());
  seaRadianceCopy_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

const gl::Program& OceanRenderer::visibilityProgram(bool classes) {
  gl::Program& p = classes ? visibilityClassesProgram_ : visibilityProgram_;
  if (p.id() != 0) return p;
  std::vector<std::string> d = featureDefines(0);  // (the vertex records' layout needs the patterns' count)
  if (classes) d.emplace_back("SEA_VISIBILITY_CLASSES");
  p = gl::Program({{GL_VERTEX_SHADER, "ocean/sea_visibility.vert"}, {GL_FRAGMENT_SHADER, "ocean/sea_visibility.frag"}}, d);
  if (classes) p.set("uVisibilityClass", kVisibilityClass);
  return p;
}

const gl::Program& OceanRenderer::surfaceProgram(unsigned key) {
  gl::Program& surface = programs().surfaceVariants.at(key);
  if (surface.id() == 0)
    surface = gl::Program({{GL_VERTEX_SHADER, "ocean/grid_cached.vert"}, {GL_FRAGMENT_SHADER, "ocean/sea_surface.frag"}},
                          surfaceDefines(key));
  return surface;
}

const gl::Program& OceanRenderer::prepareSurfacePass(unsigned key,
                                                  const std::function<void(const gl::Program&)>& prepareProgram) {
  const gl::Program& surface = surfaceProgram(key);
  computeSurfaceVertices(key, prepareProgram);
  prepareProgram(surface);
  return surface;
}

void OceanRenderer::computeSurfaceVertices(unsigned key, const std::function<void(const gl::Program&)>& prepareProgram) {
  gl::Program& compute = programs().gridComputeVariants.at(key);
  if (compute.id() == 0) compute = gl::Program({{GL_COMPUTE_SHADER, "ocean/grid_vertices.comp"}}, surfaceDefines(key));
  prepareProgram(compute);
  computeGridVertices(compute, false);
}

void OceanRenderer::computeGridVertices(const gl::Program& compute, bool radianceTerms) {
  // (Sized for the whole grid, computed for the rows drawn.)
  const auto vertices = static_cast<std::size_t>(gridColumns_) * static_cast<std::size_t>(gridRows_);
  gl::ensureBufferCapacity(gridVertices_, gridVerticesBytes_, vertices * kGridVertexVec4s * 4 * sizeof(float));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGridVerticesBinding, gridVertices_.id());
  // (Written by the classes' variants; bound for every one: a few bytes a vertex.)
  gl::ensureBufferCapacity(gridNearLand_, gridNearLandBytes_, vertices * sizeof(GLuint));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGridNearLandBinding, gridNearLand_.id());
  if (radianceTerms) {
    gl::ensureBufferCapacity(gridRadianceTerms_, gridRadianceTermsBytes_,
                             vertices * kGridRadianceTermsVec4s * 4 * sizeof(float));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGridRadianceTermsBinding, gridRadianceTerms_.id());
  }
  if (timer_ != nullptr) timer_->mark("ocean grid");
  compute.use();
  const auto drawn = static_cast<std::size_t>(gridColumns_) * static_cast<std::size_t>(gridRowsDrawn_);
  glDispatchCompute(static_cast<GLuint>((drawn + 63) / 64), 1, 1);
  // (Read as buffer textures: ocean/grid_vertex_buffer.glsl.)
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  bindGridTexels(radianceTerms);
}

void OceanRenderer::splitNearLand(unsigned key) {
  if (programs().nearLandSplit.id() == 0)
    programs().nearLandSplit = gl::Program({{GL_COMPUTE_SHADER, "ocean/grid_near_land.comp"}}, surfaceDefines(key));
  const std::size_t bytes = static_cast<std::size_t>(indexCount_) * sizeof(GLuint);
  gl::ensureBufferCapacity(floorIndices_, floorIndicesBytes_, bytes);
  gl::ensureBufferCapacity(nearLandIndices_, nearLandIndicesBytes_, bytes);
  gl::ensureBufferCapacity(deepIndices_, deepIndicesBytes_, bytes);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGridIndicesBinding, indices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGridNearLandBinding, gridNearLand_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFloorIndicesBinding, floorIndices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kNearLandIndicesBinding, nearLandIndices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDeepIndicesBinding, deepIndices_.id());
  const int triangles = 2 * (gridColumns_ - 1) * (gridRowsDrawn_ - 1);  // (the rows drawn: whole bands)
  programs().nearLandSplit.set("uTriangleCount", triangles);
  programs().nearLandSplit.use();
  glDispatchCompute(static_cast<GLuint>((triangles + 63) / 64), 1, 1);
  glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT);
}

void OceanRenderer::drawForwardSplit(const geo::CameraView& view, int height, const OceanPatterns& patterns,
                                     const ocean::OceanFrame& frame, const OceanLighting& lighting,
                                     double amplitudeScale, const WindTextures& wind, unsigned features,
                                     const glm::vec4& margin) {
  lastForwardSplit_ = true;
  // The vertices and their flags as the deferred sea's surface pass computes them, the grid's
  // index list split by them (near land, a floor within reach, the rest), each third drawn by
  // the forward program with only what its triangles need.
  const unsigned key = (features & (kFeatureWaterVolume | kFeatureCoastTest)) | kSurfaceClasses;
  computeSurfaceVertices(key, [&](const gl::Program& compute) {
    prepare(compute, view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
    setClassUniforms(compute, view, patterns, lighting, amplitudeScale, features);
  });
  splitNearLand(key);
  if (timer_ != nullptr) timer_->mark("ocean");
  const std::array<std::pair<unsigned, const gl::Buffer*>, 3> draws{
      {{features, &nearLandIndices_},
       {features & ~kFeatureCoastTest, &floorIndices_},
       {features & ~(kFeatureCoastTest | kFeatureWaterVolume), &deepIndices_}}};
  for (const auto& [drawFeatures, indices] : draws) {
    if ((drawFeatures & kFeatureWaterVolume) == 0 && indices == &floorIndices_) continue;  // (empty)
    const gl::Program& p = program(drawFeatures | kFeatureCachedVertices);
    prepare(p, view, height, patterns, frame, lighting, amplitudeScale, wind, drawFeatures, margin);
    drawGridIndices(p, *indices);
  }
}

void OceanRenderer::drawGridIndices(const gl::Program& p, const gl::Buffer& indices) const {
  glVertexArrayElementBuffer(vao_.id(), indices.id());
  drawGrid(p);
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
}

void OceanRenderer::drawDeferred(const geo::CameraView& view, int width, int height, const OceanPatterns& patterns,
                                 const ocean::OceanFrame& frame, const OceanLighting& lighting,
                                 double amplitudeScale, const WindTextures& wind, unsigned features,
                                 const glm::vec4& margin, SeaSurfaceBuffer::DepthStencil depthStencil) {
  if (lighting.landEverywhere) {  // the sea may be hidden by the terrain: ask the lean draw first
    if (timer_ != nullptr) timer_->mark("ocean classify");
    const bool shows = seaShows(view, height, patterns, frame, lighting, amplitudeScale, wind, features, margin);
    if (timer_ != nullptr) timer_->mark("ocean");
    if (!shows) return;
  }
  const DeferredSea sea{view, width, height, patterns, frame, lighting, amplitudeScale, wind, features, margin, depthStencil};
  const SeaSurfaceDrawn drawn = drawSeaSurface(sea);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawn.target));
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  // The display (setDisplayTarget) where one pass by fragments shades the whole sea: over the
  // visibility buffer's pixels, exactly those whose depth the surface pass wrote. (The
  // visibility buffer holds the whole sea only without classes: visibilityServes.)
  lastWroteDisplay_ = frameDisplayFbo_ != 0 && drawn.visibility && depthStencil.samples == 1 && frameComputeImage_ == 0;
  {
    std::optional<ScopedDisplayTarget> display;
    if (lastWroteDisplay_) display.emplace(frameDisplayFbo_);
    shadeSeaClasses(sea, drawn, lastWroteDisplay_ ? kFeatureDisplay : 0u);
  }
  if (timer_ != nullptr) timer_->mark("ocean");
  if (depthStencil.samples > 1 && drawn.seaVisible) copySeaRadiance(static_cast<GLuint>(drawn.target));
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
  glClear(GL_STENCIL_BUFFER_BIT);  // as the caller had it (the globe's parts count from 0)
  glDisable(GL_STENCIL_TEST);
}

OceanRenderer::SeaSurfaceDrawn OceanRenderer::drawSeaSurface(const DeferredSea& sea) {
  SeaSurfaceDrawn d;
  // With classes where the frame has a floor or a coast to route.
  d.classes = surfaceClasses(sea.lighting, sea.features);
  const unsigned surfaceKey = (sea.features & (kFeatureWaterVolume | kFeatureCoastTest)) | (d.classes ? kSurfaceClasses : 0u);
  d.routedShadows = kFeatureShadows;
  const auto prepareSurface = [&](const gl::Program& p) {
    sea.prepare(*this, p, sea.features);
    if (d.classes) d.routedShadows = setClassUniforms(p, sea.view, sea.patterns, sea.lighting, sea.amplitudeScale, sea.features);
  };
  // A visibility buffer where the sea has one class (multisampled frames come only so:
  // deferredServes).
  const bool multisampled = sea.depthStencil.samples > 1;
  d.visibility = visibilityServes(sea.features, d.classes);
  // In classes, the deep triangles (no floor within reach, no land near) through it too, as
  // their own classes (kVisibilityClass: exported, shaded by full-screen passes).
  d.deepByVisibility = d.classes && visibility_ && gl::driverProfile().stencilExport && frameComputeImage_ == 0 &&
                       !multisampled && gridTexelsFit();
  lastSurfaceByVisibility_ = d.visibility || d.deepByVisibility;
  if (d.visibility) computeSurfaceVertices(surfaceKey, prepareSurface);
  const gl::Program& surface = d.visibility ? visibilityProgram() : prepareSurfacePass(surfaceKey, prepareSurface);
  // With classes the coast test runs only where land may be near, and the water's terms only
  // where a floor may be within reach: the grid in three draws (splitNearLand).
  const gl::Program* open = nullptr;
  const gl::Program* deep = nullptr;
  const bool fullLayout = (surfaceKey & kFeatureWaterVolume) != 0;
  if (d.classes) {
    splitNearLand(surfaceKey);
    open = &surfaceProgram(surfaceKey & ~kFeatureCoastTest);
    prepareSurface(*open);
    deep = open;
    if (fullLayout) {
      deep = &surfaceProgram(surfaceKey & ~(kFeatureCoastTest | kFeatureWaterVolume));
      prepareSurface(*deep);
    }
    resetClassRows();  // (binds the class rows at kClassRowsBinding, the split's deep list's)
  }
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &d.target);
  const bool compact = surfaceCompact(surfaceKey);
  lastSurfaceCompact_ = compact && !d.visibility;  // (no surface buffer written)
  if (d.visibility) {
    surface_.bindVisibilityForWriting(sea.width, sea.height, sea.depthStencil.texture, sea.depthStencil.samples);
  } else {
    surface_.bindForWriting(sea.width, sea.height, sea.depthStencil.texture, compact);
    if (!gl::driverProfile().stencilExport) surface_.clearClasses();
  }
  // Each pixel's class is its nearest fragment's (depth-tested, its values in the buffer).
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xff);
  glClear(GL_STENCIL_BUFFER_BIT);
  // The reference is the shader's (gl_FragStencilRefARB); the visibility buffer's one class's.
  glStencilFunc(GL_ALWAYS, d.visibility ? 1 : 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  if (timer_ != nullptr) timer_->mark("ocean surface");
  d.seaVisible = gl::queryResult(GL_ANY_SAMPLES_PASSED, [&] {
                   if (open == nullptr) return drawGrid(surface);
                   if (fullLayout) drawGridIndices(*open, floorIndices_);  // (else empty)
                   drawGridIndices(surface, nearLandIndices_);
                   if (d.deepByVisibility) {
                     surface_.drawVisibility();
                     drawGridIndices(visibilityProgram(true), deepIndices_);
                     return surface_.drawLayers(compact);
                   }
                   if (fullLayout) surface_.drawLayers(true);  // (deep: the compact layout)
                   drawGridIndices(*deep, deepIndices_);
                   if (fullLayout) surface_.drawLayers(false);
                 }) != 0;
  d.rows = noClassRows();
  d.rows.at(0) = 0, d.rows.at(1) = 0;  // without classes, all is class 1
  if (d.classes && d.seaVisible) {     // (one read-back: the rows, then the flags)
    std::array<GLint, kClassRowsInts> recorded{};
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(classRows_.id(), 0, sizeof recorded, recorded.data());
    std::copy_n(recorded.begin(), d.rows.size(), d.rows.begin());
    std::copy_n(recorded.begin() + d.rows.size(), d.seen.size(), d.seen.begin());
  }
  return d;
}

void OceanRenderer::shadeSeaClasses(const DeferredSea& sea, const SeaSurfaceDrawn& drawn, unsigned display) {
  // A full-screen pass per class present, only its pixels; or a compute dispatch into the
  // target's image, which reads the classes where they are. Multisampled, per pixel into a
  // single-sampled image first (copySeaRadiance).
  const bool multisampled = sea.depthStencil.samples > 1;
  const GLuint image = multisampled ? seaRadianceImage(sea.width, sea.height) : frameComputeImage_;
  lastClassesByCompute_ = image != 0;
  if (!gl::driverProfile().stencilExport && !drawn.visibility && drawn.seaVisible && image == 0) classesIntoStencil();
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0);
  if (drawn.visibility)
    bindVisibilityForShading();
  else
    surface_.bindForReading();
  glBindVertexArray(vao_.id());
  if (!drawn.seaVisible) return;
  std::array<unsigned, kSeaClasses> perClass = classFeatures(sea.features, drawn.routedShadows);
  if (!drawn.classes) perClass.at(0) = (sea.features & ~kFeatureCoastTest) | display;  // one class: all but the coast test
  {
    std::optional<ClassDispatches> dispatches;
    if (image != 0) dispatches.emplace(image, drawn.visibility ? 0 : sea.depthStencil.texture);
    for (std::size_t k = 0; k < kSeaClasses; ++k) {
      if (drawn.rows.at(2 * k + 1) < drawn.rows.at(2 * k)) continue;  // no pixel of this class
      shadeClass([&]() -> const gl::Program& { return deferredProgram(perClass.at(k), image != 0, drawn.visibility, multisampled); },
                 static_cast<int>(k + 1), k, drawn.classes ? k : kSeaClasses,
                 [&](const gl::Program& p) { sea.prepare(*this, p, perClass.at(k)); },
                 dispatches ? &*dispatches : nullptr);
    }
  }
  if (drawn.deepByVisibility) {
    bindVisibilityForShading();
    for (std::size_t k = 0; k < 2; ++k)  // open sea, shadows
      if (drawn.seen.at(k) != 0)
        shadeClass([&]() -> const gl::Program& { return deferredProgram(perClass.at(k), false, true); },
                   kVisibilityClass + static_cast<int>(k), k, k,
                   [&](const gl::Program& p) { sea.prepare(*this, p, perClass.at(k)); });
  }
}

}  // namespace og::render
