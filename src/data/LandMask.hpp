#pragma once
// Land and water from real coastlines: the GSHHG shorelines rasterised to a global 2′ grid
// (data/gshhg_landmask_2m.png, see data/README.md), lakes as water, with a fine level of 15″
// cells (the high-resolution shorelines, 8 × 8 per 2′ cell) stored only for the 2′ cells whose
// own fine cells are not all one class (the coasts). It decides land and sea
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
  /// The fraction of land as seen by a footprint of `footprintDeg` (degrees of arc on the
  /// ground, ≥ 0): the fine level's B-spline (fineFraction) where the footprint resolves its
  /// cells, the coarse one (above) where it does not, blended by fineWeight between, so the
  /// coast neither aliases from orbit nor pops on the way down. Without a fine level: the
  /// coarse one. landmask.glsl's landFraction(latLon, footprintRad) is its GPU twin.
  [[nodiscard]] float landFraction(double latitudeDeg, double longitudeDeg, double footprintDeg) const;
  /// The quadratic B-spline of the 3 × 3 fine cells around a point, [0, 1]; a cell of a 2′ cell
  /// that is not refined is that cell's own class. Needs hasFineLevel().
  [[nodiscard]] float fineFraction(double latitudeDeg, double longitudeDeg) const;
  /// A pixel's footprint on the ground for the coast, degrees of arc: its view distance
  /// `distanceM` times the angle `pixelRad` a pixel subtends, widened at grazing incidence
  /// (`cosIncidence`: the view's cosine to the vertical, counted from 0.2). The CPU twin of
  /// terrain/landmask.glsl's coastFootprintRad, which every pass drawing a side of the coast uses.
  [[nodiscard]] static double coastFootprintDeg(double distanceM, double pixelRad, double cosIncidence);
  /// The fine level's weight for a footprint (degrees of arc): 1 up to one fine cell, 0 from
  /// three, smooth between; 0 without a fine level.
  [[nodiscard]] double fineWeight(double footprintDeg) const;

  /// Whether the mask holds no land within `radiusM` (metres on the ground, any direction) of a
  /// point, so that landFraction is 0 there: every cell of the box around that circle and the
  /// B-spline's reach (the 3 × 3 cells about a point's nearest centre) is water — the 2′
  /// level's land bits (`fine` false) or the fine cells (`fine` true; a cell that is not
  /// refined as its own class; needs hasFineLevel()). False within a degree of a pole, and
  /// on a regional mask where the box leaves it.
  [[nodiscard]] bool waterAround(double latitudeDeg, double longitudeDeg, double radiusM, bool fine) const;
  /// The classes among fine cells fc0 ... fc1 × fr0 ... fr1 (fine cells from the west and south
  /// edges; rows within the mask; columns wrap on a global mask and count as water outside a
  /// regional one): bit 0 water, bit 1 land (LandMaskPyramid::Content's values), both as soon as
  /// both are found. A cell that is not refined holds its own class. Needs hasFineLevel().
  [[nodiscard]] std::uint8_t fineClasses(int fc0, int fc1, int fr0, int fr1) const;

  /// A layer height (m) made to agree with the mask: on land at least, on water at most,
  /// kCoastRampM × (fraction − 0.5), so the zero contour is the mask's coast and heights stay
  /// continuous across it. On water that bound is scaled by 1 − `keepDepth` (0-1, the layer's
  /// LatLonGrid::keepDepth there): corrected shallow banks keep their depth (data/ShallowBanks).
  /// The fraction is landFraction's for a footprint of `footprintDeg` (0: the finest level).
  [[nodiscard]] double constrainHeightM(double heightM, double latitudeDeg, double longitudeDeg,
                                        double keepDepth = 0.0, double footprintDeg = 0.0) const;
  static constexpr double kCoastRampM = 20.0;

  /// True when the mask should decide the coast for `layer`: a global layer coarser than the
  /// mask whose land and sea agree with it on at least kEarthAgreement of a 1° grid (Earth's
  /// relief; ETOPO20 agrees on 0.95). Regional layers, fine DEMs and synthetic globes keep
  /// their own zero contour.
  [[nodiscard]] bool refines(const LatLonGrid& layer) const;
  static constexpr double kEarthAgreement = 0.85;

  [[nodiscard]] int width() const { return width_; }
  /// Whether the mask covers 360° of longitude (its columns wrap).
  [[nodiscard]] bool global() const { return width_ * cellDeg_ >= 359.999; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] double westDeg() const { return westDeg_; }
  [[nodiscard]] double southDeg() const { return southDeg_; }
  [[nodiscard]] double cellDeg() const { return cellDeg_; }
  /// The cells packed 8 per byte along a row (bit k of byte b = column 8b + k), rows south to
  /// north, (width + 7) / 8 bytes per row: the GPU texture's layout.
  [[nodiscard]] const std::vector<std::uint8_t>& packedBits() const { return bits_; }
  [[nodiscard]] int bytesPerRow() const { return (width_ + 7) / 8; }
  [[nodiscard]] bool cell(int column, int row) const;

  /// Fine cells per cell along each axis (15″ in a 2′ cell).
  static constexpr int kFinePerCell = 8;
  /// fineClasses' bits.
  static constexpr std::uint8_t kFineWater = 1, kFineLand = 2;
  /// Adds the fine level to a global mask: `refinedBits` packed as packedBits() (1 = the
  /// cell's fine cells are not all one class), `blocks` one 64-bit word per refined cell in
  /// row-major order (rows south to north, then columns west to east); bit 8 j + i of a word =
  /// the fine cell i columns east of the cell's west edge and j rows north of its south edge.
  /// Throws InternalError on sizes that do not agree.
  void setFineLevel(std::vector<std::uint8_t> refinedBits, std::vector<std::uint64_t> blocks);
  [[nodiscard]] bool hasFineLevel() const { return !refined_.empty(); }
  [[nodiscard]] bool refined(int column, int row) const;
  /// The 8 × 8 fine cells of a cell as 64 bits (layout as setFineLevel's): the refined block,
  /// or all ones / all zeros from the cell's own class.
  [[nodiscard]] std::uint64_t block(int column, int row) const;
  [[nodiscard]] const std::vector<std::uint8_t>& refinedBits() const { return refined_; }
  [[nodiscard]] const std::vector<std::uint64_t>& blocks() const { return blocks_; }

 private:
  LandMask() = default;
  int width_ = 0, height_ = 0;
  double westDeg_ = 0.0, southDeg_ = 0.0, cellDeg_ = 0.0;
  std::vector<std::uint8_t> bits_;
  // The fine level: refined cells' bits (as bits_), their blocks, and the number of refined
  // cells before each row's 64-cell chunks (row-major), for a block's index.
  std::vector<std::uint8_t> refined_;
  std::vector<std::uint64_t> blocks_;
  std::vector<std::uint32_t> refinedBefore_;
};

/// The embedded GSHHG mask (2′, with the 15″ fine level at the coasts, both from the
/// high-resolution shorelines), decoded once (1-bit PNGs straight to packed bits and the
/// gzipped blocks, cached on disk; thread-safe).
const LandMask& defaultLandMask();

/// Reads a mask from any single-band georeferenced raster GDAL reads in EPSG:4326 (nonzero =
/// land), e.g. a finer GSHHG rasterisation. Throws og::InputError "FILE: problem".
LandMask readLandMask(const std::filesystem::path& file);

}  // namespace og::data
