#pragma once
// Land and water from real coastlines: the GSHHG shorelines rasterised to a global 2′ grid
// (data/gshhg_landmask_2m.png, see data/README.md), lakes as water. It decides land and sea
// (the globe's sea shading, the terrain's heights at the coast, the ocean passes) where the
// elevation layer is coarser than it, so a 20′ or 5′ DEM still has the right coast; the DEM
// only gives heights. Readers: the terrain (CPU) and render/LandMaskTexture (GPU,
// shaders/terrain/landmask.glsl) — the coastal-water code reads it through either.
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "data/LatLonGrid.hpp"

namespace og::data {

class LandMask {
 public:
  /// A mask from rows of 0/1 bytes (row 0 south), `width` × `height` cells of `cellDeg` from
  /// (westDeg, southDeg) (outer edges). Global when it covers 360° × 180°.
  LandMask(int width, int height, double westDeg, double southDeg, double cellDeg,
           const std::vector<std::uint8_t>& landBytes);
  /// A mask from cells already packed as packedBits() lays them out (8 per byte, rows south
  /// to north, bytesPerRow() bytes a row): no per-cell pass.
  static LandMask fromPackedBits(int width, int height, double westDeg, double southDeg, double cellDeg,
                                 std::vector<std::uint8_t> bits);

  /// The fraction of land around a point, [0, 1]: the quadratic B-spline of the 3 × 3 nearest
  /// cells (1 = land; shaders/terrain/landmask.glsl is its GPU twin). The coast is the 0.5
  /// contour: smooth curves at the cells' scale, no raster staircase.
  [[nodiscard]] float landFraction(double latitudeDeg, double longitudeDeg) const;
  [[nodiscard]] bool isLand(double latitudeDeg, double longitudeDeg) const {
    return landFraction(latitudeDeg, longitudeDeg) >= 0.5f;
  }

  /// A layer height (m) made to agree with the mask: on land at least, on water at most,
  /// kCoastRampM × (fraction − 0.5), so the zero contour is the mask's coast and heights stay
  /// continuous across it. On water that bound is scaled by 1 − `keepDepth` (0-1, the layer's
  /// LatLonGrid::keepDepth there): corrected shallow banks keep their depth (data/ShallowBanks).
  [[nodiscard]] double constrainHeightM(double heightM, double latitudeDeg, double longitudeDeg,
                                        double keepDepth = 0.0) const;
  static constexpr double kCoastRampM = 20.0;

  /// True when the mask should decide the coast for `layer`: a global layer coarser than the
  /// mask whose land and sea agree with it on at least kEarthAgreement of a 1° grid (Earth's
  /// relief; ETOPO20 agrees on 0.95). Regional layers, fine DEMs and synthetic globes keep
  /// their own zero contour.
  [[nodiscard]] bool refines(const LatLonGrid& layer) const;
  static constexpr double kEarthAgreement = 0.85;

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] double westDeg() const { return westDeg_; }
  [[nodiscard]] double southDeg() const { return southDeg_; }
  [[nodiscard]] double cellDeg() const { return cellDeg_; }
  /// The cells packed 8 per byte along a row (bit k of byte b = column 8b + k), rows south to
  /// north, (width + 7) / 8 bytes per row: the GPU texture's layout.
  [[nodiscard]] const std::vector<std::uint8_t>& packedBits() const { return bits_; }
  [[nodiscard]] int bytesPerRow() const { return (width_ + 7) / 8; }
  [[nodiscard]] bool cell(int column, int row) const;

 private:
  LandMask() = default;
  int width_ = 0, height_ = 0;
  double westDeg_ = 0.0, southDeg_ = 0.0, cellDeg_ = 0.0;
  std::vector<std::uint8_t> bits_;
};

/// The embedded GSHHG mask (2′, intermediate-resolution shorelines), decoded once (1-bit PNG
/// straight to packed bits, ~30 ms; thread-safe).
const LandMask& defaultLandMask();

/// Reads a mask from any single-band georeferenced raster GDAL reads in EPSG:4326 (nonzero =
/// land), e.g. a finer GSHHG rasterisation. Throws og::InputError "FILE: problem".
LandMask readLandMask(const std::filesystem::path& file);

}  // namespace og::data
