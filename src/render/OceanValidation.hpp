#pragma once
// Validation of the filtered ocean as Bruneton et al. 2010 §7.2 (docs/validation.md): each view
// is rendered by OceanRenderer alone (no atmosphere: the analytic sky of lighting.glsl) as
//   reference: every pattern at full resolution as geometry and normal, a mirror per sample (the
//              Sun a true disc), supersampled S x S and averaged down (the brute force),
//   filtered:  the model as it renders (ValidationMode::Filtered),
//   constant:  the paper's baseline: the same filtered geometry and normals, the BRDF held at
//              the unresolved tail's variance at every distance (ValidationMode::ConstantBrdf),
//   brdf_only: a flat sea with the whole slope variance in the BRDF (ValidationMode::BrdfOnly),
// once per lighting term (Sun, sky, refracted light; whitecaps off), and the mean luminance of
// every image row of each model is compared with the reference's, per term and in total.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "geo/Wgs84.hpp"
#include "io/Image.hpp"
#include "render/OceanPatterns.hpp"
#include "render/OceanRenderer.hpp"
#include "render/WindTextures.hpp"

namespace og::render {

struct ValidationView {
  std::string name;
  double heightM = 2.0;
  double headingDeg = 0.0;
  double pitchDeg = -15.0;
  double sunElevationDeg = 10.0;
  double sunAzimuthDeg = 0.0;
};

/// The fixed views of `oceanglobe validate`: 2, 20 and 200 m, looking into a low Sun and away.
std::vector<ValidationView> defaultValidationViews();

struct ValidationSettings {
  int width = 160, height = 90;     ///< the compared images
  int supersample = 8;              ///< reference samples per pixel: supersample² (box filter)
  int referenceCellPixels = 2;      ///< reference grid cell, in supersampled pixels
  int cellPixels = 8;               ///< the models' grid cell (the renderer's default)
  double verticalFovDeg = 45.0;
  double timeS = 10.0;
  double windSpeedMs = 8.0;
  double windDirectionDeg = 70.0;   ///< blowing towards, clockwise from north
  std::uint64_t seed = 1;
  geo::Geodetic where{30.0, -40.0, 0.0};  ///< open Atlantic; height from the view
};

/// The compared models and lighting terms, in the order of the arrays below.
inline constexpr int kValidationModels = 3;  ///< filtered, constant, brdf_only
inline constexpr int kValidationTerms = 4;   ///< total, sun, sky, refracted
inline constexpr std::array<const char*, kValidationModels> kValidationModelNames{"filtered", "constant",
                                                                                  "brdf_only"};
inline constexpr std::array<const char*, kValidationTerms> kValidationTermNames{"total", "sun", "sky",
                                                                                "refracted"};
using PerModel = std::array<double, kValidationModels>;

/// One image row: mean luminance (linear, units of the Sun's irradiance per sr) per term.
struct RowError {
  int row = 0;               ///< from the top
  double distanceM = 0.0;    ///< eye to the sea along the row's central ray (spherical Earth)
  std::array<double, kValidationTerms> reference{};
  std::array<PerModel, kValidationTerms> model{};
  /// (model - reference) / reference total, per term: the terms' errors add up to the total's.
  std::array<PerModel, kValidationTerms> error{};
};

/// |row error| over a band of rows, per term and model.
struct BandError {
  std::string name;
  int rows = 0;
  double nearM = 0.0, farM = 0.0;
  std::array<PerModel, kValidationTerms> mean{}, max{};
};

struct ValidationResult {
  ValidationView view;
  std::vector<RowError> rows;     ///< rows entirely covered by sea in all images
  std::array<BandError, 3> bands; ///< near (bottom third of the rows), mid, far (at the horizon)
  BandError all;
  io::ImageRgbaF reference;       ///< linear radiance (all terms), width x height
  std::array<io::ImageRgbaF, kValidationModels> models;
};

class OceanValidator {
 public:
  /// Needs a current GL 4.5 context.
  explicit OceanValidator(const ValidationSettings& settings = {});
  ~OceanValidator();
  OceanValidator(const OceanValidator&) = delete;
  OceanValidator& operator=(const OceanValidator&) = delete;

  [[nodiscard]] ValidationResult run(const ValidationView& view);
  [[nodiscard]] const ValidationSettings& settings() const { return settings_; }

 private:
  io::ImageRgbaF render(OceanRenderer& renderer, const ValidationView& view, int width, int height);

  /// The term images (sun, sky, refracted) of one renderer at s x s the size; `weighted`: the
  /// reference's weighted samples, averaged down by s.
  std::array<io::ImageRgbaF, 3> renderTerms(OceanRenderer& renderer, const ValidationView& view, int s,
                                            bool weighted);

  ValidationSettings settings_;
  std::unique_ptr<OceanPatterns> patterns_;
  std::unique_ptr<OceanRenderer> reference_;
  std::array<std::unique_ptr<OceanRenderer>, kValidationModels> models_;
  std::unique_ptr<WindTextures> wind_;
};

/// Tone maps linear radiance for viewing: exposure, then sRGB (clamped), sea-less pixels black.
io::ImageRgba8 validationPreview(const io::ImageRgbaF& image, double exposure);

/// The four images side by side (reference | filtered | constant | brdf_only) with 2-px gaps.
io::ImageRgba8 validationStrip(const ValidationResult& result, double exposure);

/// Exposure putting the reference's mean sea luminance at 0.18.
double validationExposure(const ValidationResult& result);

}  // namespace og::render
