#include "render/OceanRenderer.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/ShaderContract.hpp"
#include "render/WaterVolume.hpp"

namespace og::render {
namespace {
glm::vec3 toFloat(const glm::dvec3& v) { return glm::vec3(v); }

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
}  // namespace

OceanRenderer::OceanRenderer(const Atmosphere* atmosphere, ValidationMode mode)
    : atmosphere_(atmosphere),
      defines_(oceanDefines(atmosphere, mode)),
      classic_({{GL_VERTEX_SHADER, "ocean/classic.vert"}, {GL_FRAGMENT_SHADER, "ocean/classic.frag"}},
               skyDefines(atmosphere)),
      bumpMap_(makeBumpMap()),
      fresnelRamp_(makeFresnelRamp()),
      vao_(gl::createVertexArray()),
      indices_(gl::createBuffer()) {}

const gl::Program& OceanRenderer::program(unsigned features) {
  gl::Program& p = variants_.at(features);
  if (p.id() != 0) return p;
  std::vector<std::string> d = defines_;
  if ((features & kFeatureWaterVolume) == 0) d.emplace_back("OCEAN_NO_WATER_VOLUME");
  if ((features & kFeatureCoastTest) == 0) d.emplace_back("SEA_NO_COAST_TEST");
  if ((features & kFeatureShadows) == 0) d.emplace_back("SHADOWS_OFF");
  if ((features & kFeatureFrameSky) != 0) d.emplace_back("SKY_FRAME_LAYER");
  p = gl::Program({{GL_VERTEX_SHADER, "ocean/grid.vert"}, {GL_FRAGMENT_SHADER, "ocean/ocean.frag"}}, d);
  return p;
}

double OceanRenderer::farthestSeaAngleRad(const geo::CameraView& view) {
  const double r = geo::kWgs84SemiMajorM, h = std::max(view.position.heightM, 0.0);
  const double tanY = std::tan(0.5 * view.verticalFovRad), tanX = tanY * view.aspect;
  const double horizon = std::acos(r / (r + h));
  double most = 0.0;
  for (const double sx : {-1.0, 0.0, 1.0}) {
    const glm::dvec3 dir = glm::normalize(view.forward + sx * tanX * view.right + tanY * view.up);
    // The ray from (r + h) up meets the sphere of radius r at the smaller root t of
    // t² - 2 b t + (r + h)² - r² = 0, b = (r + h) cos(angle below the horizontal).
    const double b = (r + h) * -glm::dot(dir, view.enu.up);
    const double disc = b * b - h * (2.0 * r + h);
    if (b <= 0.0 || disc < 0.0) return horizon;
    const double t = b - std::sqrt(disc);
    // Angle at the centre: cos = ((r + h) - t cos(down)) / r, the hit's height along up over r.
    most = std::max(most, std::acos(std::clamp((r + h - t * b / (r + h)) / r, -1.0, 1.0)));
  }
  return std::min(most, horizon);
}

void OceanRenderer::ensureGrid(int columns, int rows) {
  if (columns == gridColumns_ && rows == gridRows_) return;
  std::vector<GLuint> idx;
  idx.reserve(static_cast<std::size_t>(6 * (columns - 1) * (rows - 1)));
  for (int y = 0; y + 1 < rows; ++y)
    for (int x = 0; x + 1 < columns; ++x) {
      const auto i = static_cast<GLuint>(y * columns + x);
      const auto c = static_cast<GLuint>(columns);
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
  p.set("uCellAngle", static_cast<float>(2.0 * tanY / height * cellPixels_));
  p.set("uCellPixels", static_cast<float>(cellPixels_));
  // Patterns whose texels span 2 cells or more are looked up per vertex (ocean/patterns.glsl).
  p.set("uPatternVertexLod", static_cast<float>(-std::log2(static_cast<double>(cellPixels_))));
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
  const glm::vec4 margin(static_cast<float>(side), static_cast<float>(side),
                         static_cast<float>(bottom), 0.1f);  // left, right, bottom, top
  ensureGrid(std::max(2, static_cast<int>(std::ceil(width * (1 + side) / cellPixels_)) + 1),
             std::max(2, static_cast<int>(std::ceil(height * (1 + 0.5 * (bottom + 0.1)) / cellPixels_)) + 1));

  unsigned features = 0;
  if (model == OceanModel::Classic) {
    features = kFeatureCoastTest | kFeatureShadows;  // classic.frag has no variants: its uniforms
  } else {
    if (lighting.floorInReach) features |= kFeatureWaterVolume;
    if (lighting.landInView) features |= kFeatureCoastTest;
    if (lighting.shadows != nullptr && lighting.shadows->on) features |= kFeatureShadows;
    if (atmosphere_ != nullptr && farthestSeaAngleRad(view) <= kFrameSkyMaxAngleRad) {
      features |= kFeatureFrameSky;
      const double cosSun = glm::dot(glm::normalize(lighting.sunDirectionEcef), view.enu.up);
      atmosphere_->prepareFrameSkyLayer(std::acos(std::clamp(cosSun, -1.0, 1.0)));
    }
  }
  const gl::Program& p = model == OceanModel::Classic ? classic_ : program(features);
  setCommon(p, view, height, frame, lighting, features);
  p.set("uGridMarginNdc", margin);
  if (model == OceanModel::Classic) {
    // The classic pattern repeats every 800 m (see classic.vert/.frag): fold the offset there.
    const glm::dvec2 off = frame.fieldOffsetM();
    p.set("uFieldOffset", glm::vec2(static_cast<float>(std::fmod(off.x, 800.0)),
                                    static_cast<float>(std::fmod(off.y, 800.0))));
    p.set("uTime", static_cast<float>(std::fmod(timeS, 1000.0)));
    glBindTextureUnit(gl::kUnitBumpMap, bumpMap_.id());
    glBindTextureUnit(gl::kUnitFresnelRamp, fresnelRamp_.id());
  } else {
    if ((features & kFeatureWaterVolume) != 0) {
      caustics_.update(patterns, timeS);
      caustics_.bind();
    }
    patterns.bind();
    patterns.setUniforms(p, &frame, amplitudeScale);
    p.set("uLightingTerms", lightingTerms_);
    wind.bind(p);
  }
  p.use();
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  gl::checkErrors("OceanRenderer::draw");
}

}  // namespace og::render
