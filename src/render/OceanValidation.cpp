#include "render/OceanValidation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geo/Camera.hpp"
#include "geo/Sun.hpp"
#include "gl/Objects.hpp"
#include "gl/Readback.hpp"
#include "ocean/OceanFrame.hpp"

namespace og::render {
namespace {
double luminance(const float* rgba) {
  return 0.2126 * double(rgba[0]) + 0.7152 * double(rgba[1]) + 0.0722 * double(rgba[2]);
}

// Box filter of the reference's (width*s) x (height*s) samples down to width x height. Each
// sample holds its radiance premultiplied by its projected-area weight, the weight in alpha
// (ocean.frag, OCEAN_VALIDATION_REFERENCE): the pixel is the weighted mean, its alpha the
// fraction of samples that hit the sea.
io::ImageRgbaF weightedDownsample(const io::ImageRgbaF& big, int s) {
  io::ImageRgbaF out;
  out.width = big.width / s;
  out.height = big.height / s;
  out.pixels.assign(static_cast<std::size_t>(4 * out.width * out.height), 0.0f);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      double sum[3] = {0, 0, 0}, weight = 0.0;
      int hits = 0;
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const float* p = &big.pixels[static_cast<std::size_t>(4 * ((y * s + j) * big.width + x * s + i))];
          if (p[3] <= 0.0f) continue;
          for (int c = 0; c < 3; ++c) sum[c] += double(p[c]);
          weight += double(p[3]);
          ++hits;
        }
      float* o = &out.pixels[static_cast<std::size_t>(4 * (y * out.width + x))];
      for (int c = 0; c < 3; ++c) o[c] = weight > 0.0 ? static_cast<float>(sum[c] / weight) : 0.0f;
      o[3] = static_cast<float>(double(hits) / double(s * s));
    }
  return out;
}

// Distance from the eye to the ellipsoid along `dir` (-1: misses).
double seaDistance(const geo::CameraView& view, const glm::dvec3& dir) {
  return geo::intersectEllipsoid(view.positionEcef, dir, 0.0).value_or(-1.0);
}

std::uint8_t toSrgb8(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  const double s = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(255.0 * s));
}
// The camera of a validation view.
geo::CameraPose poseOf(const ValidationSettings& settings, const ValidationView& v) {
  geo::CameraPose pose;
  pose.position = settings.where;
  pose.position.heightM = v.heightM;
  pose.headingDeg = v.headingDeg;
  pose.pitchDeg = v.pitchDeg;
  pose.verticalFovDeg = settings.verticalFovDeg;
  return pose;
}

}  // namespace

std::vector<ValidationView> defaultValidationViews() {
  // Sun 10° high in the west (azimuth 270°); "sun" views look at it, "away" views turn round.
  std::vector<ValidationView> v;
  for (const double h : {2.0, 20.0, 200.0}) {
    const std::string hs = std::to_string(static_cast<int>(h)) + "m";
    v.push_back({hs + "_sun", h, 270.0, -15.0, 10.0, 270.0});
    v.push_back({hs + "_away", h, 90.0, -15.0, 10.0, 270.0});
  }
  return v;
}

OceanValidator::OceanValidator(const ValidationSettings& settings) : settings_(settings) {
  ocean::WavePatternParams p;
  p.referenceWindMs = settings.windSpeedMs;
  p.seed = settings.seed;
  patterns_ = std::make_unique<OceanPatterns>(std::make_shared<const ocean::WavePatterns>(ocean::makeWavePatterns(p)));
  patterns_->update(settings.timeS);
  reference_ = std::make_unique<OceanRenderer>(nullptr, ValidationMode::Reference);
  reference_->setCellPixels(settings.referenceCellPixels);
  reference_->setCellGrowth(false);  // validation measures the models at the cells it names
  const ValidationMode modes[kValidationModels] = {ValidationMode::Filtered, ValidationMode::ConstantBrdf,
                                                   ValidationMode::BrdfOnly};
  for (int m = 0; m < kValidationModels; ++m) {
    models_[static_cast<std::size_t>(m)] = std::make_unique<OceanRenderer>(nullptr, modes[m]);
    models_[static_cast<std::size_t>(m)]->setCellPixels(settings.cellPixels);
    models_[static_cast<std::size_t>(m)]->setCellGrowth(false);
  }
  wind_ = std::make_unique<WindTextures>();
  wind_->setConstantWind(geo::Wind::blowingTowards(settings.windSpeedMs, settings.windDirectionDeg));
}

OceanValidator::~OceanValidator() = default;

io::ImageRgbaF OceanValidator::render(OceanRenderer& renderer, const ValidationView& v, int width,
                                      int height) {
  const geo::CameraPose pose = poseOf(settings_, v);
  const geo::CameraView view = geo::makeCameraView(pose, width, height);
  ocean::OceanFrame frame;
  frame.reset(pose.position);
  OceanLighting light;
  light.sunDirectionEcef = geo::sunDirectionFromHorizontal(pose.position, v.sunElevationDeg, v.sunAzimuthDeg);
  gl::RenderTarget target = gl::createRenderTarget(width, height, GL_RGBA32F, true);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
  glViewport(0, 0, width, height);
  const float zero = 0.0f, clear[] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(target.fbo.id(), GL_COLOR, 0, clear);
  glClearNamedFramebufferfv(target.fbo.id(), GL_DEPTH, 0, &zero);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  renderer.draw(view, width, height, *patterns_, frame, settings_.timeS, light, 1.0, OceanModel::Bruneton,
                *wind_);
  io::ImageRgbaF image;
  image.width = width;
  image.height = height;
  image.pixels = gl::readRgbaF(target.fbo.id(), width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return image;
}

std::array<io::ImageRgbaF, 3> OceanValidator::renderTerms(OceanRenderer& renderer,
                                                          const ValidationView& view, int s,
                                                          bool weighted) {
  const glm::vec4 weights[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};  // whitecaps off
  std::array<io::ImageRgbaF, 3> out;
  for (std::size_t t = 0; t < 3; ++t) {
    renderer.setLightingTerms(weights[t]);
    out[t] = render(renderer, view, settings_.width * s, settings_.height * s);
    if (weighted) out[t] = weightedDownsample(out[t], s);
  }
  renderer.setLightingTerms(glm::vec4(1.0f));
  return out;
}

namespace {
// The sum of the term images (alpha: the first's coverage).
io::ImageRgbaF sumOfTerms(const std::array<io::ImageRgbaF, 3>& terms) {
  io::ImageRgbaF sum = terms[0];
  for (std::size_t i = 0; i < sum.pixels.size(); ++i)
    if (i % 4 != 3) sum.pixels[i] = terms[0].pixels[i] + terms[1].pixels[i] + terms[2].pixels[i];
  return sum;
}

// |error| statistics of rows [begin, end) (stored far first).
void summarize(const std::vector<RowError>& rows, BandError& b, std::size_t begin, std::size_t end) {
  b.rows = static_cast<int>(end - begin);
  if (b.rows == 0) return;
  b.nearM = rows[end - 1].distanceM;
  b.farM = rows[begin].distanceM;
  for (std::size_t i = begin; i < end; ++i)
    for (std::size_t t = 0; t < kValidationTerms; ++t)
      for (std::size_t m = 0; m < kValidationModels; ++m) {
        const double e = std::abs(rows[i].error[t][m]);
        b.mean[t][m] += e / b.rows;
        b.max[t][m] = std::max(b.max[t][m], e);
      }
}
}  // namespace

ValidationResult OceanValidator::run(const ValidationView& v) {
  const int w = settings_.width, h = settings_.height, s = std::max(1, settings_.supersample);
  ValidationResult r;
  r.view = v;
  std::array<std::array<io::ImageRgbaF, 3>, kValidationModels> modelTerms;
  for (std::size_t m = 0; m < kValidationModels; ++m) {
    modelTerms[m] = renderTerms(*models_[m], v, 1, false);
    r.models[m] = sumOfTerms(modelTerms[m]);
  }
  const std::array<io::ImageRgbaF, 3> referenceTerms = renderTerms(*reference_, v, s, true);
  r.reference = sumOfTerms(referenceTerms);

  const geo::CameraPose pose = poseOf(settings_, v);
  const geo::CameraView view = geo::makeCameraView(pose, w, h);
  for (int y = 0; y < h; ++y) {
    RowError e;
    e.row = y;
    double cover = 1.0;
    for (int x = 0; x < w; ++x) {
      const auto i = static_cast<std::size_t>(4 * (y * w + x));
      cover = std::min(cover, double(r.reference.pixels[i + 3]));
      for (std::size_t m = 0; m < kValidationModels; ++m) cover = std::min(cover, double(r.models[m].pixels[i + 3]));
      for (std::size_t t = 1; t < kValidationTerms; ++t) {
        e.reference[t] += luminance(&referenceTerms[t - 1].pixels[i]) / w;
        for (std::size_t m = 0; m < kValidationModels; ++m)
          e.model[t][m] += luminance(&modelTerms[m][t - 1].pixels[i]) / w;
      }
    }
    for (std::size_t t = 1; t < kValidationTerms; ++t) {
      e.reference[0] += e.reference[t];
      for (std::size_t m = 0; m < kValidationModels; ++m) e.model[0][m] += e.model[t][m];
    }
    // Only rows all sea in all images: at the horizon the models' coverage differs by design.
    if (cover < 0.999 || e.reference[0] <= 0.0) continue;
    for (std::size_t t = 0; t < kValidationTerms; ++t)
      for (std::size_t m = 0; m < kValidationModels; ++m)
        e.error[t][m] = (e.model[t][m] - e.reference[t]) / e.reference[0];
    e.distanceM = seaDistance(view, view.rayDirection(0.0, 1.0 - 2.0 * (y + 0.5) / h));
    r.rows.push_back(e);
  }
  // Bands by row: the bottom third of the sea rows is "near", the third at the horizon "far".
  const std::size_t n = r.rows.size();
  const char* names[3] = {"near", "mid", "far"};
  for (int b = 0; b < 3; ++b) {
    BandError& band = r.bands[static_cast<std::size_t>(b)];
    band.name = names[b];
    // Rows are stored top (far) first: band b covers the (2 - b)-th third.
    summarize(r.rows, band, n * static_cast<std::size_t>(2 - b) / 3, n * static_cast<std::size_t>(3 - b) / 3);
  }
  r.all.name = "all";
  summarize(r.rows, r.all, 0, n);
  return r;
}

io::ImageRgba8 validationPreview(const io::ImageRgbaF& image, double exposure) {
  io::ImageRgba8 out;
  out.width = image.width;
  out.height = image.height;
  out.pixels.resize(static_cast<std::size_t>(4 * image.width * image.height));
  for (std::size_t i = 0; i < out.pixels.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) out.pixels[i + c] = toSrgb8(exposure * double(image.pixels[i + c]));
    out.pixels[i + 3] = 255;
  }
  return out;
}

io::ImageRgba8 validationStrip(const ValidationResult& result, double exposure) {
  const io::ImageRgbaF* parts[4] = {&result.reference, &result.models[0], &result.models[1],
                                    &result.models[2]};
  const int w = result.reference.width, h = result.reference.height, gap = 2;
  io::ImageRgba8 out;
  out.width = 4 * w + 3 * gap;
  out.height = h;
  out.pixels.assign(static_cast<std::size_t>(4 * out.width * out.height), 255);
  for (int k = 0; k < 4; ++k) {
    const io::ImageRgba8 p = validationPreview(*parts[k], exposure);
    for (int y = 0; y < h; ++y)
      std::copy_n(p.pixels.begin() + 4 * y * w, 4 * w,
                  out.pixels.begin() + 4 * (y * out.width + k * (w + gap)));
  }
  return out;
}

double validationExposure(const ValidationResult& result) {
  double sum = 0.0;
  for (const RowError& e : result.rows) sum += e.reference[0];
  const double mean = result.rows.empty() ? 0.0 : sum / double(result.rows.size());
  return mean > 0.0 ? 0.18 / mean : 1.0;
}

}  // namespace og::render
