#include "render/Atmosphere.hpp"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <optional>
#include <sstream>
#include <vector>

#include "core/CacheFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/StartupTrace.hpp"
#include "gl/Probe.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Pass numbers of shaders/atmosphere/precompute.comp.
enum Pass : int {
  kTransmittance = 1,
  kDirectIrradiance = 2,
  kSingleScattering = 3,
  kScatteringDensity = 4,
  kIndirectIrradiance = 5,
  kMultipleScattering = 6,
  kSkyMaps = 7,
  kSkyIrradiance = 8,
};

gl::Program passProgram(int pass) {
  return gl::Program({{GL_COMPUTE_SHADER, "atmosphere/precompute.comp"}},
                     {"PASS " + std::to_string(pass)});
}

gl::Texture texture2D(int w, int h, GLenum format = GL_RGBA32F) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, w, h);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

gl::Texture texture3D(const atmosphere::TableSizes& s) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_3D);
  glTextureStorage3D(t.id(), 1, GL_RGBA32F, s.scatteringNu * s.scatteringMuS, s.scatteringMu,
                     s.scatteringR);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  return t;
}

void clear(const gl::Texture& t) {
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, zero);
}

GLuint groups(int n) { return static_cast<GLuint>((n + 7) / 8); }

void dispatch(const gl::Program& p, int w, int h, int d) {
  p.use();
  glUniform3i(p.location("uSize"), w, h, d);
  glDispatchCompute(groups(w), groups(h), static_cast<GLuint>(d));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void bindImage(GLuint unit, const gl::Texture& t, GLenum access, GLenum format = GL_RGBA32F) {
  glBindImageTexture(unit, t.id(), 0, GL_TRUE, 0, access, format);
}

std::vector<float> download(const gl::Texture& t, std::size_t texels) {
  std::vector<float> v(texels * 4);
  glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(v.size() * sizeof(float)),
                    v.data());
  return v;
}

std::uint64_t fnv(const void* data, std::size_t n, std::uint64_t h = 14695981039346656037ull) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= b[i];
    h *= 1099511628211ull;
  }
  return h;
}

// The text of the code that computes the tables: part of the cache key.
std::string tableCodeSalt() {
  return gl::readShaderFile("atmosphere/functions.glsl") +
         gl::readShaderFile("atmosphere/precompute.comp");
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << v;
  return s.str();
}

// The text of the code that computes the sky maps from the tables: part of their key.
std::string skyMapCodeSalt() {
  return gl::readShaderFile("atmosphere/definitions.glsl") + gl::readShaderFile("atmosphere/skymap_common.glsl");
}

// Cache files (core/CacheFile's format): `atmosphere-KIND-CODE-PARAMS.bin`, KIND tables or
// skymaps, CODE hashing the code that computes them, PARAMS the parameters and sizes. A file of
// another CODE was made by another build and is superseded (removed when the new one is
// written, as are the files of the older one-key format); one of other PARAMS is another
// scene's and stays.
std::filesystem::path cacheFileOf(const std::filesystem::path& dir, const std::string& kind, std::uint64_t code,
                                  std::uint64_t params) {
  return dir / ("atmosphere-" + kind + "-" + core::hex16(code) + "-" + core::hex16(params) + ".bin");
}

std::function<bool(const std::string&)> supersededBy(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  const std::string kind = name.substr(0, name.find('-', std::string("atmosphere-").size()) + 1);
  const std::string current = name.substr(0, kind.size() + 17);  // atmosphere-KIND-CODE-
  return [kind, current](const std::string& f) {
    if (f.rfind("atmosphere-", 0) != 0 || f.size() < 4 || f.substr(f.size() - 4) != ".bin") return false;
    const bool oldFormat = f.rfind("atmosphere-tables-", 0) != 0 && f.rfind("atmosphere-skymaps-", 0) != 0;
    return oldFormat || (f.rfind(kind, 0) == 0 && f.rfind(current, 0) != 0);
  };
}

template <class T>
void appendBytes(std::vector<std::uint8_t>& out, const std::vector<T>& v) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
  out.insert(out.end(), p, p + v.size() * sizeof(T));
}

// A cached payload of `bytes` bytes whose float32 part (from byte `floatsFrom` on) is finite and
// ≥ 0; nullopt (with a warning naming the file and the reason, none when it is missing) else.
std::optional<core::CachePayload> readPayload(const std::filesystem::path& file, std::uint64_t key,
                                              std::size_t bytes, std::size_t floatsFrom, const char* what) {
  std::string why;
  auto payload = core::readCacheFile(file, key, &why);
  if (payload && payload->size() != bytes) why = "wrong size";
  for (std::size_t at = floatsFrom; payload && why.empty() && at + 4 <= payload->size(); at += 4) {
    float v = 0.0f;
    std::memcpy(&v, payload->data() + at, 4);
    if (!std::isfinite(v) || v < 0.0f) why = "invalid values";
  }
  if (payload && why.empty()) return payload;
  if (why != "missing")
    log::warn(std::string("atmosphere: ignoring ") + what + " " + file.string() + " (" + why + "); recomputing");
  return std::nullopt;
}

}  // namespace

std::filesystem::path Atmosphere::defaultCacheDirectory() {
  return core::cacheDirectory();
}

SkyFilter Atmosphere::chooseSkyFilter() {
  std::string forced;
  if (const char* e = std::getenv("OCEANGLOBE_SKY_FILTER"); e && *e) forced = e;
  if (!forced.empty() && forced != "hardware" && forced != "probes" && forced != "radial" && forced != "single" &&
      forced != "probes9")
    throw InputError("OCEANGLOBE_SKY_FILTER: '" + forced + "' is not hardware, radial, probes, probes9 or single");
  const bool software = gl::isSoftwareRenderer();
  if (forced == "single") return {1, false, 1.0f, "forced single lookup (OCEANGLOBE_SKY_FILTER)"};
  if (forced == "radial" || (forced.empty() && software))
    // Two lookups a layer in the layers' radial sums (render/SkyRadialSums); for the globe's
    // horizon pixels below 20 km up to 4 lookups along the ellipse (at most 4: the paper's 9
    // are less than a level apart at 8 bits, docs/performance.md).
    return {4, true, 1.0f, forced.empty() ? "CPU rasteriser: radial sums of the sky maps' layers (the globe's horizon below 20 km: up to 4 isotropic lookups, Bruneton 2010 7.3)"
                                          : "forced radial sums, else up to 4 lookups (OCEANGLOBE_SKY_FILTER)"};
  if (forced == "probes") return {4, false, 1.0f, "forced up to 4 lookups (OCEANGLOBE_SKY_FILTER)"};
  if (forced == "probes9") return {9, false, 1.0f, "forced up to 9 lookups, the paper's (OCEANGLOBE_SKY_FILTER)"};
  GLfloat most = 1.0f;
  glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &most);
  glGetError();  // a driver without the (GL 4.6 / EXT) anisotropy leaves `most` at 1
  return {1, false, std::clamp(most, 1.0f, 16.0f), "GPU: hardware anisotropic filtering"};
}

Atmosphere::Atmosphere(const atmosphere::Parameters& parameters, const AtmosphereOptions& options)
    : parameters_(parameters), skyFilter_(chooseSkyFilter()) {
  if (auto problem = atmosphere::validate(parameters_))
    throw InputError("atmosphere: " + *problem);
  const auto t0 = Clock::now();
  allocate();
  std::filesystem::path file;
  if (options.useCache) {
    const std::filesystem::path dir =
        options.cacheDirectory.empty() ? defaultCacheDirectory() : options.cacheDirectory;
    file = cacheFileOf(dir, "tables", fnv(tableCodeSalt().data(), tableCodeSalt().size()),
                       atmosphere::cacheKey(parameters_, ""));
    timing_.fromCache = loadCache(file);
  }
  if (!timing_.fromCache) {
    precompute();
    if (!file.empty()) {
      try {
        saveCache(file);
      } catch (const std::exception& e) {
        log::warn(std::string("atmosphere: tables not cached: ") + e.what());
        file.clear();
      }
    }
  }
  glFinish();
  timing_.tablesMs = msSince(t0);
  core::startup::add(timing_.fromCache ? "atmosphere: cached tables (load + upload)"
                                       : "atmosphere: tables precomputed (cache miss)",
                     t0, timing_.tablesMs);
  timing_.cacheFile = file;
  const auto t1 = Clock::now();
  allocateSkyMaps();
  // The sky maps are cached beside the tables they derive from (start-up: no compute passes,
  // no mip-map generation, whose shaders llvmpipe compiles at first use).
  const atmosphere::TableSizes& s = parameters_.tables;
  const std::string skyCode = tableCodeSalt() + skyMapCodeSalt();
  const std::string skySizes = std::to_string(s.skyMapSize) + " " + std::to_string(s.skyMapLayers) + " " +
                               std::to_string(s.skyIrradianceEntries);
  const std::filesystem::path skyFile =
      file.empty() ? file
                   : cacheFileOf(file.parent_path(), "skymaps", fnv(skyCode.data(), skyCode.size()),
                                 fnv(skySizes.data(), skySizes.size(), atmosphere::cacheKey(parameters_, "")));
  const bool skyCached = !skyFile.empty() && loadSkyMaps(skyFile);
  if (!skyCached) {
    computeSkyMaps();
    if (!skyFile.empty()) saveSkyMaps(skyFile);
  }
  glFinish();
  timing_.skyMapsMs = msSince(t1);
  core::startup::add(skyCached ? "atmosphere: cached sky maps (load + upload)"
                               : "atmosphere: sky maps + sea-level irradiance computed",
                     t1, timing_.skyMapsMs);
  gl::checkErrors("Atmosphere");
  log::debug("atmosphere: sky filter: " + skyFilter_.reason);
  log::debug("atmosphere: tables " + std::to_string(timing_.tablesMs) + " ms" +
             (timing_.fromCache ? " (cached)" : "") + ", sky maps " +
             std::to_string(timing_.skyMapsMs) + " ms");
}

void Atmosphere::allocate() {
  const atmosphere::TableSizes& s = parameters_.tables;
  transmittance_ = texture2D(s.transmittanceWidth, s.transmittanceHeight);
  irradiance_ = texture2D(s.irradianceWidth, s.irradianceHeight);
  scattering_ = texture3D(s);
  singleMie_ = texture3D(s);
}

void Atmosphere::setParameters(const gl::Program& g, const atmosphere::Parameters& p) {
  auto v3 = [](const glm::dvec3& v) { return glm::vec3(v); };
  auto f = [](double v) { return static_cast<float>(v); };
  g.set("uAtmosphere.solarIrradiance", v3(p.solarIrradiance));
  g.set("uAtmosphere.sunAngularRadius", f(p.sunAngularRadiusRad));
  g.set("uAtmosphere.bottomRadius", f(p.bottomRadiusM));
  g.set("uAtmosphere.topRadius", f(p.topRadiusM()));
  g.set("uAtmosphere.rayleighScattering", v3(p.rayleighScattering));
  g.set("uAtmosphere.rayleighScaleHeight", f(p.rayleighScaleHeightM));
  g.set("uAtmosphere.mieScattering", v3(p.mieScattering));
  g.set("uAtmosphere.mieExtinction", v3(p.mieExtinction));
  g.set("uAtmosphere.mieScaleHeight", f(p.mieScaleHeightM));
  g.set("uAtmosphere.miePhaseG", f(p.miePhaseG));
  g.set("uAtmosphere.ozoneAbsorption", v3(p.ozoneAbsorption));
  g.set("uAtmosphere.ozoneCenterAltitude", f(p.ozoneCenterAltitudeM));
  g.set("uAtmosphere.ozoneHalfWidth", f(p.ozoneHalfWidthM));
  g.set("uAtmosphere.groundAlbedo", v3(p.groundAlbedo));
  g.set("uAtmosphere.muSMin", f(p.muSMin));
  const atmosphere::TableSizes& t = p.tables;
  g.set("uAtmosphere.transmittanceWidth", t.transmittanceWidth);
  g.set("uAtmosphere.transmittanceHeight", t.transmittanceHeight);
  g.set("uAtmosphere.irradianceWidth", t.irradianceWidth);
  g.set("uAtmosphere.irradianceHeight", t.irradianceHeight);
  g.set("uAtmosphere.scatteringR", t.scatteringR);
  g.set("uAtmosphere.scatteringMu", t.scatteringMu);
  g.set("uAtmosphere.scatteringMuS", t.scatteringMuS);
  g.set("uAtmosphere.scatteringNu", t.scatteringNu);
  g.set("uAtmosphere.sphereSamples", t.sphereSamples);
}

void Atmosphere::precompute() {
  const atmosphere::TableSizes& s = parameters_.tables;
  const int sw = s.scatteringNu * s.scatteringMuS, sh = s.scatteringMu, sd = s.scatteringR;
  gl::Texture deltaIrradiance = texture2D(s.irradianceWidth, s.irradianceHeight);
  gl::Texture deltaRayleigh = texture3D(s), deltaMie = texture3D(s), deltaMultiple = texture3D(s),
              deltaDensity = texture3D(s);
  clear(irradiance_);
  clear(deltaMultiple);

  // Transmittance (Eq. 5).
  gl::Program transmittance = passProgram(kTransmittance);
  setParameters(transmittance, parameters_);
  bindImage(0, transmittance_, GL_WRITE_ONLY);
  dispatch(transmittance, s.transmittanceWidth, s.transmittanceHeight, 1);
  glBindTextureUnit(0, transmittance_.id());

  // Direct irradiance E[L0] (kept in the delta table only: rendering adds it analytically).
  gl::Program direct = passProgram(kDirectIrradiance);
  setParameters(direct, parameters_);
  bindImage(0, deltaIrradiance, GL_WRITE_ONLY);
  dispatch(direct, s.irradianceWidth, s.irradianceHeight, 1);

  // Single scattering.
  gl::Program single = passProgram(kSingleScattering);
  setParameters(single, parameters_);
  bindImage(2, deltaRayleigh, GL_WRITE_ONLY);
  bindImage(3, deltaMie, GL_WRITE_ONLY);
  dispatch(single, sw, sh, sd);
  glCopyImageSubData(deltaRayleigh.id(), GL_TEXTURE_3D, 0, 0, 0, 0, scattering_.id(), GL_TEXTURE_3D,
                     0, 0, 0, 0, sw, sh, sd);
  glCopyImageSubData(deltaMie.id(), GL_TEXTURE_3D, 0, 0, 0, 0, singleMie_.id(), GL_TEXTURE_3D, 0, 0,
                     0, 0, sw, sh, sd);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);

  if (parameters_.scatteringOrders >= 2) {
    gl::Program density = passProgram(kScatteringDensity);
    gl::Program indirect = passProgram(kIndirectIrradiance);
    gl::Program multiple = passProgram(kMultipleScattering);
    for (const gl::Program* p : {&density, &indirect, &multiple}) setParameters(*p, parameters_);
    glBindTextureUnit(1, deltaRayleigh.id());
    glBindTextureUnit(2, deltaMie.id());
    for (int order = 2; order <= parameters_.scatteringOrders; ++order) {
      // Scattering density J of this order, from L_{order-1} and E_{order-2}.
      density.set("uOrder", order);
      glBindTextureUnit(3, deltaMultiple.id());
      glBindTextureUnit(4, deltaIrradiance.id());
      bindImage(2, deltaDensity, GL_WRITE_ONLY);
      dispatch(density, sw, sh, sd);
      // Indirect irradiance E_{order-1}, accumulated into the final table.
      indirect.set("uOrder", order - 1);
      bindImage(0, deltaIrradiance, GL_WRITE_ONLY);
      bindImage(1, irradiance_, GL_READ_WRITE);
      dispatch(indirect, s.irradianceWidth, s.irradianceHeight, 1);
      // Multiple scattering L_order from J, accumulated into the final table.
      glBindTextureUnit(3, deltaDensity.id());
      bindImage(2, deltaMultiple, GL_WRITE_ONLY);
      bindImage(4, scattering_, GL_READ_WRITE);
      dispatch(multiple, sw, sh, sd);
      glFinish();  // bounds the driver's queue on llvmpipe; each pass is long anyway
    }
  }
  for (GLuint unit = 0; unit < 5; ++unit) glBindTextureUnit(unit, 0);
  gl::checkErrors("Atmosphere::precompute");
}

int Atmosphere::skyMapLevels() const {
  return gl::fullMipLevels(parameters_.tables.skyMapSize);
}

void Atmosphere::allocateSkyMaps() {
  const atmosphere::TableSizes& s = parameters_.tables;
  const int levels = skyMapLevels();
  // One layer per Sun zenith angle, plus the frame layer (prepareFrameSkyLayer).
  skyMaps_ = gl::createSquareArray(GL_RGBA16F, s.skyMapSize, s.skyMapLayers + 1, levels, GL_CLAMP_TO_EDGE);
  // Anisotropy per chooseSkyFilter(): hardware on a GPU, 1 on llvmpipe (where skymap.glsl
  // averages up to 4 lookups instead); textureGrad selects the mip level from the gradients.
  if (skyFilter_.maxAnisotropy > 1.0f)
    glTextureParameterf(skyMaps_.id(), GL_TEXTURE_MAX_ANISOTROPY, skyFilter_.maxAnisotropy);
  skyIrradiance_ = gl::createTexture(GL_TEXTURE_1D_ARRAY);
  glTextureStorage2D(skyIrradiance_.id(), 1, GL_RGBA32F, s.skyIrradianceEntries, 2);
  glTextureParameteri(skyIrradiance_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(skyIrradiance_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(skyIrradiance_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
}

void Atmosphere::computeSkyMaps() {
  const atmosphere::TableSizes& s = parameters_.tables;
  glBindTextureUnit(0, transmittance_.id());
  glBindTextureUnit(5, scattering_.id());
  glBindTextureUnit(2, singleMie_.id());
  glBindTextureUnit(6, irradiance_.id());
  gl::Program maps = passProgram(kSkyMaps);
  setParameters(maps, parameters_);
  bindImage(5, skyMaps_, GL_WRITE_ONLY, GL_RGBA16F);
  dispatch(maps, s.skyMapSize, s.skyMapSize, s.skyMapLayers);
  glGenerateTextureMipmap(skyMaps_.id());
  gl::Program irr = passProgram(kSkyIrradiance);
  setParameters(irr, parameters_);
  bindImage(6, skyIrradiance_, GL_WRITE_ONLY);
  dispatch(irr, s.skyIrradianceEntries, 1, 1);
  for (GLuint unit : {0u, 2u, 5u, 6u}) glBindTextureUnit(unit, 0);
  // Each Sun layer's value below the horizon, its corner texel (cold start only: a cached start
  // reads it from the file).
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::vector<float> corners(static_cast<std::size_t>(4 * s.skyMapLayers));
  glGetTextureSubImage(skyMaps_.id(), 0, 0, 0, 0, 1, 1, s.skyMapLayers, GL_RGBA, GL_FLOAT,
                       static_cast<GLsizei>(corners.size() * sizeof(float)), corners.data());
  skyBelowHorizon_.clear();
  for (std::size_t k = 0; k < static_cast<std::size_t>(s.skyMapLayers); ++k)
    skyBelowHorizon_.emplace_back(corners[4 * k], corners[4 * k + 1], corners[4 * k + 2]);
  gl::checkErrors("Atmosphere::computeSkyMaps");
}

void Atmosphere::bind(const gl::Program& program) const {
  setParameters(program, parameters_);
  program.set("uSkyFilterProbes", skyFilter_.probes);
  if (radial_.ready()) {
    radial_.bind();
    radial_.setUniforms(program);
  }
  glBindTextureUnit(gl::kUnitAtmTransmittance, transmittance_.id());
  glBindTextureUnit(gl::kUnitAtmScattering, scattering_.id());
  glBindTextureUnit(gl::kUnitAtmSingleMie, singleMie_.id());
  glBindTextureUnit(gl::kUnitAtmIrradiance, irradiance_.id());
}

void Atmosphere::prepareFrameSkyLayer(double sunZenithRad) const {
  const atmosphere::TableSizes& s = parameters_.tables;
  if (frameLayer_.id() == 0) frameLayer_ = gl::Program({{GL_COMPUTE_SHADER, "atmosphere/skymap_frame.comp"}});
  // The layer coordinate as skymap.glsl computes it.
  const double f = std::clamp(sunZenithRad / kSkyMapMaxZenithRad, 0.0, 1.0) * (s.skyMapLayers - 1);
  const int layer0 = std::min(static_cast<int>(std::floor(f)), s.skyMapLayers - 2);
  frameLayer_.set("uLayer0", layer0);
  frameLayer_.set("uWeight", static_cast<float>(f - layer0));
  glBindTextureUnit(gl::kUnitSkyMap, skyMaps_.id());
  frameLayer_.use();
  for (int level = 0; (s.skyMapSize >> level) > 0; ++level) {
    const int size = s.skyMapSize >> level;
    frameLayer_.set("uLevel", level);
    glBindImageTexture(0, skyMaps_.id(), level, GL_FALSE, s.skyMapLayers, GL_WRITE_ONLY, GL_RGBA16F);
    const auto groups = static_cast<GLuint>((size + 7) / 8);
    glDispatchCompute(groups, groups, 1);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  gl::checkErrors("Atmosphere::prepareFrameSkyLayer");
  if (skyFilter_.radialSums) {
    // As skymap_frame.comp blends the texel, into a half float (the compute subtracts the texel).
    glm::vec3 below = glm::mix(skyBelowHorizon_.at(static_cast<std::size_t>(layer0)),
                               skyBelowHorizon_.at(static_cast<std::size_t>(layer0 + 1)), static_cast<float>(f - layer0));
    for (int c = 0; c < 3; ++c) below[c] = glm::unpackHalf1x16(glm::packHalf1x16(below[c]));
    radial_.updateFrameLayer(skyMaps_.id(), s.skyMapLayers, sunZenithRad, below);
  }
}

void Atmosphere::prepareSunLayerSums() const {
  if (skyFilter_.radialSums) radial_.ensureSunLayers(skyMaps_.id(), skyBelowHorizon_);
}

void Atmosphere::bindSkyMaps() const {
  glBindTextureUnit(gl::kUnitSkyMap, skyMaps_.id());
  glBindTextureUnit(gl::kUnitSkyIrradiance, skyIrradiance_.id());
}

// The tables' payload: the four tables as float32 RGBA, in this order.
void Atmosphere::saveCache(const std::filesystem::path& file) const {
  const atmosphere::TableSizes& s = parameters_.tables;
  const std::size_t n3 = static_cast<std::size_t>(s.scatteringNu * s.scatteringMuS *
                                                  s.scatteringMu * s.scatteringR);
  std::vector<std::uint8_t> payload;
  for (auto [tex, n] : {std::pair{&transmittance_, static_cast<std::size_t>(s.transmittanceWidth * s.transmittanceHeight)},
                        std::pair{&irradiance_, static_cast<std::size_t>(s.irradianceWidth * s.irradianceHeight)},
                        std::pair{&scattering_, n3}, std::pair{&singleMie_, n3}})
    appendBytes(payload, download(*tex, n));
  core::writeCacheFile(file, atmosphere::cacheKey(parameters_, tableCodeSalt()), payload,
                       supersededBy(file));
}

std::uint64_t Atmosphere::skyMapKey() const {
  const atmosphere::TableSizes& s = parameters_.tables;
  const std::string salt = hex(atmosphere::cacheKey(parameters_, tableCodeSalt())) + skyMapCodeSalt() + " " +
                           std::to_string(s.skyMapSize) + " " + std::to_string(s.skyMapLayers) + " " +
                           std::to_string(s.skyIrradianceEntries);
  return fnv(salt.data(), salt.size());
}

std::size_t Atmosphere::skyMapHalfs() const {
  const atmosphere::TableSizes& s = parameters_.tables;
  std::size_t n = 0;
  for (int level = 0; level < skyMapLevels(); ++level) {
    const auto side = static_cast<std::size_t>(std::max(1, s.skyMapSize >> level));
    n += 4 * side * side * static_cast<std::size_t>(s.skyMapLayers + 1);
  }
  return n;
}

// The sky maps' payload: every mip level as half-float RGBA, then the sea-level irradiance
// table as float32 RGBA.
void Atmosphere::saveSkyMaps(const std::filesystem::path& file) const {
  const atmosphere::TableSizes& s = parameters_.tables;
  std::vector<std::uint16_t> halfs(skyMapHalfs());
  std::size_t at = 0;
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  for (int level = 0; level < skyMapLevels(); ++level) {
    const auto side = static_cast<std::size_t>(std::max(1, s.skyMapSize >> level));
    const std::size_t n = 4 * side * side * static_cast<std::size_t>(s.skyMapLayers + 1);
    glGetTextureImage(skyMaps_.id(), level, GL_RGBA, GL_HALF_FLOAT, static_cast<GLsizei>(n * 2), halfs.data() + at);
    at += n;
  }
  std::vector<std::uint8_t> payload;
  appendBytes(payload, halfs);
  appendBytes(payload, download(skyIrradiance_, static_cast<std::size_t>(s.skyIrradianceEntries) * 2));
  try {
    core::writeCacheFile(file, skyMapKey(), payload, supersededBy(file));
  } catch (const std::exception& e) {
    log::warn(std::string("atmosphere: sky maps not cached: ") + e.what());
  }
}

bool Atmosphere::loadSkyMaps(const std::filesystem::path& file) {
  const atmosphere::TableSizes& s = parameters_.tables;
  const std::size_t halfBytes = skyMapHalfs() * 2;
  const std::size_t irradianceFloats = static_cast<std::size_t>(s.skyIrradianceEntries) * 2 * 4;
  const auto payload = readPayload(file, skyMapKey(), halfBytes + irradianceFloats * 4, halfBytes, "sky-map cache");
  if (!payload) return false;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  // Each Sun layer's value below the horizon: its corner texel of level 0.
  skyBelowHorizon_.clear();
  const auto texels0 = static_cast<std::size_t>(s.skyMapSize) * static_cast<std::size_t>(s.skyMapSize);
  for (std::size_t k = 0; k < static_cast<std::size_t>(s.skyMapLayers); ++k) {
    std::uint16_t h[3];
    std::memcpy(h, payload->data() + 8 * texels0 * k, sizeof h);
    skyBelowHorizon_.emplace_back(glm::unpackHalf1x16(h[0]), glm::unpackHalf1x16(h[1]), glm::unpackHalf1x16(h[2]));
  }
  std::size_t at = 0;
  for (int level = 0; level < skyMapLevels(); ++level) {
    const int side = std::max(1, s.skyMapSize >> level);
    glTextureSubImage3D(skyMaps_.id(), level, 0, 0, 0, side, side, s.skyMapLayers + 1, GL_RGBA,
                        GL_HALF_FLOAT, payload->data() + at);
    at += 8 * static_cast<std::size_t>(side) * static_cast<std::size_t>(side) * static_cast<std::size_t>(s.skyMapLayers + 1);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(skyIrradiance_.id(), 0, 0, 0, s.skyIrradianceEntries, 2, GL_RGBA, GL_FLOAT, payload->data() + at);
  gl::checkErrors("Atmosphere::loadSkyMaps");
  return true;
}

bool Atmosphere::loadCache(const std::filesystem::path& file) {
  const atmosphere::TableSizes& s = parameters_.tables;
  const std::size_t nT = static_cast<std::size_t>(s.transmittanceWidth * s.transmittanceHeight);
  const std::size_t nI = static_cast<std::size_t>(s.irradianceWidth * s.irradianceHeight);
  const std::size_t n3 = static_cast<std::size_t>(s.scatteringNu * s.scatteringMuS *
                                                  s.scatteringMu * s.scatteringR);
  const auto payload = readPayload(file, atmosphere::cacheKey(parameters_, tableCodeSalt()),
                                   16 * (nT + nI + 2 * n3), 0, "cache");
  if (!payload) return false;
  const std::uint8_t* p = payload->data();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(transmittance_.id(), 0, 0, 0, s.transmittanceWidth, s.transmittanceHeight,
                      GL_RGBA, GL_FLOAT, p);
  p += 16 * nT;
  glTextureSubImage2D(irradiance_.id(), 0, 0, 0, s.irradianceWidth, s.irradianceHeight, GL_RGBA,
                      GL_FLOAT, p);
  p += 16 * nI;
  const int sw = s.scatteringNu * s.scatteringMuS;
  glTextureSubImage3D(scattering_.id(), 0, 0, 0, 0, sw, s.scatteringMu, s.scatteringR, GL_RGBA,
                      GL_FLOAT, p);
  p += 16 * n3;
  glTextureSubImage3D(singleMie_.id(), 0, 0, 0, 0, sw, s.scatteringMu, s.scatteringR, GL_RGBA,
                      GL_FLOAT, p);
  gl::checkErrors("Atmosphere::loadCache");
  return true;
}

atmosphere::ReferenceTables Atmosphere::readTables() const {
  const atmosphere::TableSizes& s = parameters_.tables;
  auto to2D = [](const gl::Texture& t, int w, int h) {
    const std::vector<float> v = download(t, static_cast<std::size_t>(w * h));
    atmosphere::Table2D out{w, h, {}};
    for (std::size_t i = 0; i < v.size(); i += 4) out.texels.emplace_back(v[i], v[i + 1], v[i + 2], v[i + 3]);
    return out;
  };
  auto to3D = [&](const gl::Texture& t) {
    const int w = s.scatteringNu * s.scatteringMuS, h = s.scatteringMu, d = s.scatteringR;
    const std::vector<float> v = download(t, static_cast<std::size_t>(w * h * d));
    atmosphere::Table3D out{w, h, d, {}};
    for (std::size_t i = 0; i < v.size(); i += 4) out.texels.emplace_back(v[i], v[i + 1], v[i + 2], v[i + 3]);
    return out;
  };
  return {to2D(transmittance_, s.transmittanceWidth, s.transmittanceHeight),
          to2D(irradiance_, s.irradianceWidth, s.irradianceHeight), to3D(scattering_),
          to3D(singleMie_)};
}

std::vector<float> Atmosphere::readSkyMap(int layer) const {
  const int n = parameters_.tables.skyMapSize;
  std::vector<float> v(static_cast<std::size_t>(n * n * 4));
  glGetTextureSubImage(skyMaps_.id(), 0, 0, 0, layer, n, n, 1, GL_RGBA, GL_FLOAT,
                       static_cast<GLsizei>(v.size() * sizeof(float)), v.data());
  return v;
}

std::vector<glm::dvec3> Atmosphere::probeSunIrradiance(const std::vector<double>& zenithRad) const {
  if (zenithRad.empty()) return {};
  std::vector<glm::vec4> values;
  for (const double z : zenithRad) values.emplace_back(static_cast<float>(z), 0.0f, 0.0f, 0.0f);
  gl::Program probe({{GL_COMPUTE_SHADER, "atmosphere/probe.comp"}});
  bind(probe);
  bindSkyMaps();
  gl::runProbe(probe, values, static_cast<int>(values.size()), "Atmosphere::probeSunIrradiance");
  std::vector<glm::dvec3> out;
  for (const glm::vec4& v : values) out.emplace_back(v.x, v.y, v.z);
  return out;
}

}  // namespace og::render
