#pragma once
// Above the grid's ceiling, the globe's open deep sea (render/OpenSeaMap: no land or shallow
// floor within reach) has no resolved waves, no coast and no water column: its radiance is the
// whole sea's BRDF under the local wind, the sky and the aerial perspective, which vary over
// tens of pixels, not one. So it is shaded at a lattice every kLatticePx pixels and
// interpolated (render/open_sea_lattice.frag), block by block where the lattice shows that
// interpolation holds (render/open_sea_lattice.comp); the rest stays per pixel
// (render/GlobeRenderer::shadeGlobe, the open sea's part). The lattice's points are those of the
// blocks of 8 x 8 pixels the CPU classed open sea (render/GlobeBlocks), each shaded by
// render/globe.frag compiled as a compute shader (GLOBE_LATTICE) as a pixel centred there.
// At offshore-40km (1280 x 720) ~4 points a block instead of 64 pixels.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::render {

struct GlobeBlocks;

class OpenSeaLattice {
 public:
  static constexpr int kLatticePx = 4;  ///< the lattice's spacing, pixels (globe.frag's OPEN_SEA_LATTICE_PX)
  static constexpr int kBlockPx = 8;    ///< a block's side (render/GlobeBlocks' kGlobeBlockPx)
  /// The largest difference, in display levels (0-255 after the frame's exposure, tone curve
  /// and sRGB), between a block's lattice points and what its four corners interpolate there
  /// for the block to be interpolated: the lattice's own interpolation, at half that spacing,
  /// is then off by about a quarter of it.
  static constexpr float kMaxLevels = 0.5f;

  /// Lists the lattice points and the blocks of `blocks`' open-sea class in a frame of
  /// `width` x `height` pixels (none: empty()).
  void prepare(const GlobeBlocks& blocks, int width, int height);
  /// Lists nothing (a frame without the open sea's blocks).
  void clear() { blocks_.clear(), points_.clear(); }
  [[nodiscard]] bool empty() const { return blocks_.empty(); }
  /// Shades the listed points with `shade` (globe.frag's GLOBE_LATTICE, in use with its
  /// uniforms set), then flags the blocks it may interpolate at the frame's `exposure`.
  void shade(const gl::Program& shade, double exposure);
  /// Draws the flagged blocks' pixels that pass the caller's stencil test, and zeroes their
  /// stencil values so the open sea's part leaves them (the stencil test must be on). Leaves
  /// the program and the stencil operation changed.
  void drawInterpolated();
  /// The blocks prepare listed, and how many of them shade flagged (reads them back: tests).
  [[nodiscard]] std::size_t listedBlocks() const { return blocks_.size(); }
  [[nodiscard]] std::size_t interpolatedBlocks() const;

 private:
  void ensureTargets(int width, int height);
  std::vector<std::uint32_t> points_, blocks_;  ///< x | y << 16: lattice points, blocks
  std::vector<std::uint8_t> listed_;            ///< prepare's flags, a lattice point each
  gl::Texture lattice_, flags_;
  int latticeColumns_ = 0, latticeRows_ = 0, blockColumns_ = 0, blockRows_ = 0;
  gl::Buffer pointsBuffer_, blocksBuffer_;
  std::size_t pointsBytes_ = 0, blocksBytes_ = 0;
  gl::Program check_, interpolate_;
};

}  // namespace og::render
