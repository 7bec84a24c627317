#pragma once
// The GSHHG land mask on the GPU (shaders/terrain/landmask.glsl): data::LandMask's packed bits
// as an R32UI texture on gl::kUnitLandMask, texel x of a row holding columns 8x − 4 … 8x + 11,
// their land bits in the low half and their refined bits (the fine level's) in the high half
// (1350 × 5400 texels, 28 MiB for the 2′ default), bound only
// where the mask decides the coast (a global elevation layer coarser than it); a 1×1 texture
// there otherwise, which landmask.glsl reads as "no mask". The fine level (15″ blocks at the
// coasts, data::LandMask::setFineLevel) in one RGBA32UI texture on gl::kUnitLandMaskFine,
// 4096 texels wide, read as a list: first the rank index, one texel per 96 cells of a row
// (x, y, z: those cells' refined bits; w: the refined cells before them, row-major), then the
// blocks, two a texel (xy, zw: low and high 32 bits); ~14 MiB for the default.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "data/LandFractionMips.hpp"
#include "data/LandMask.hpp"
#include "geo/Camera.hpp"
#include "gl/Objects.hpp"

namespace og::render {

class LandMaskTexture {
 public:
  /// Needs a current GL context. `mask` nullptr: no mask (the elevation layer's zero contour).
  explicit LandMaskTexture(const data::LandMask* mask);
  /// Binds the mask (or the 1×1 stand-in) to gl::kUnitLandMask, its fine level (or a 1×1
  /// stand-in) to gl::kUnitLandMaskFine, and the land fraction's pyramid where uploaded and
  /// `fractionMips` (else a 1×1 stand-in: the B-spline at every footprint) to
  /// gl::kUnitLandFraction.
  void bind(bool fractionMips) const;
  [[nodiscard]] bool active() const { return active_; }
  /// Whether the fine level weighs nothing anywhere in `view` (`heightPx` pixels tall): every
  /// pixel's footprint on the ground (landmask.glsl's coastFootprintRad, at least
  /// geo::smallestGroundFootprintRad) spans kFineCellsUnweighted fine cells or more, or there is
  /// no fine level. Such a frame's programs compile the fine level out (LANDMASK_COARSE_ONLY).
  [[nodiscard]] bool fineLevelUnresolved(const geo::CameraView& view, int heightPx) const;
  /// The footprint, in fine cells, from which the fine level's weight is 0 (landMaskFineWeight).
  static constexpr double kFineCellsUnweighted = 3.0;
  /// Uploads the land fraction's pyramid (R8, its levels as mip levels, on gl::kUnitLandFraction:
  /// landmask.glsl's landFractionFiltered); until then bind() binds a 1×1 stand-in there, which
  /// landmask.glsl reads as "no pyramid" (the B-spline at every footprint).
  void uploadFractionMips(const data::LandFractionMips& mips);
  [[nodiscard]] bool fractionMipsUploaded() const { return mipsUploaded_; }
  /// Whether some pixel of `view` (`heightPx` pixels tall) may weigh the pyramid: a footprint
  /// (coastFootprintRad, from a view distance at most to the horizon of the highest ground) of
  /// more than one 2′ cell. Such a frame needs uploadFractionMips first.
  [[nodiscard]] bool fractionMipsWeighed(const geo::CameraView& view, int heightPx) const;
  /// Whether every pixel's footprint spans two 2′ cells or more (the pyramid's weight is 1
  /// everywhere) and the pyramid is uploaded: such a frame's programs compile the B-spline and
  /// the fine level out (LANDMASK_FILTERED_ONLY).
  [[nodiscard]] bool fractionMipsOnly(const geo::CameraView& view, int heightPx) const;
  [[nodiscard]] std::size_t gpuBytes() const { return bytes_; }
  /// landmask.glsl's landFraction at (latitude, longitude, footprint) radians, evaluated on the
  /// GPU (for tests against data::LandMask::landFraction with a footprint).
  [[nodiscard]] std::vector<float> probeLandFraction(const std::vector<glm::vec3>& latLonFootprintRad) const;

 private:
  // The fine level's texture: kFineWidth RGBA32UI texels a row (landmask.glsl's
  // landMaskFineTexel assumes 4096), `height` rows.
  static constexpr int kFineWidth = 4096;
  struct FineTexels {
    std::vector<std::uint32_t> texels;
    int height = 0;
  };
  static FineTexels fineTexels(const data::LandMask& mask);
  void uploadFineLevel(const FineTexels& f);

  gl::Texture texture_;
  gl::Texture fine_;
  gl::Texture mips_, noMips_;
  bool active_ = false, mipsUploaded_ = false;
  double cellRad_ = 0.0;      ///< a 2′ cell's side, radians of arc; 0 without a mask
  double fineCellRad_ = 0.0;  ///< a fine cell's side, radians of arc; 0 without a fine level
  std::size_t bytes_ = 0;
};

}  // namespace og::render
