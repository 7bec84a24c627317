#pragma once
// Validation of the filtered ocean in the spirit of Bruneton et al. 2010 §7.2 (docs/validation.md):
// each view is rendered three times, alone (no atmosphere: the analytic sky of lighting.glsl) -
//   reference: every pattern at full resolution as geometry and normal, a mirror per sample, supersampled S x S and
//              box-filtered down (the brute force that filtering should reproduce),
//   filtered:  the model as it renders (OceanRenderer, ValidationMode::Filtered),
//   constant:  a flat sea with the whole slope variance in the BRDF ("BRDF only"),
// and the mean radiance of every image row of the two models is compared with the reference's.
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

/// One image row's mean luminance (linear, units of the Sun's irradiance per sr).
struct RowError {
  int row = 0;               ///< from the top
  double distanceM = 0.0;    ///< eye to the sea along the row's central ray (spherical Earth)
  double reference = 0.0, filtered = 0.0, constant = 0.0;
  double errorFiltered = 0.0, errorConstant = 0.0;  ///< (model - reference) / reference
};

/// |relative error| over a band of rows.
struct BandError {
  std::string name;
  int rows = 0;
  double nearM = 0.0, farM = 0.0;
  double meanFiltered = 0.0, maxFiltered = 0.0;
  double meanConstant = 0.0, maxConstant = 0.0;
};

struct ValidationResult {
  ValidationView view;
  std::vector<RowError> rows;     ///< rows entirely covered by sea in all three images
  std::array<BandError, 3> bands; ///< near (bottom third of the rows), mid, far (at the horizon)
  BandError all;
  io::ImageRgbaF reference, filtered, constant;  ///< linear radiance, width x height
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

  ValidationSettings settings_;
  std::unique_ptr<OceanPatterns> patterns_;
  std::unique_ptr<OceanRenderer> filtered_, reference_, constant_;
  std::unique_ptr<WindTextures> wind_;
};

/// Tone maps linear radiance for viewing: exposure, then sRGB (clamped), sea-less pixels black.
io::ImageRgba8 validationPreview(const io::ImageRgbaF& image, double exposure);

/// The three images side by side (reference | filtered | constant) with 2-px gaps.
io::ImageRgba8 validationStrip(const ValidationResult& result, double exposure);

/// Exposure putting the reference's mean sea luminance at 0.18.
double validationExposure(const ValidationResult& result);

}  // namespace og::render
