#pragma once
// Above the grid's ceiling the globe's sea has no resolved waves: its radiance is the whole
// sea's BRDF under the local wind, the sky, the floor through the water where it is within
// reach, and the aerial perspective, which vary over tens of pixels, not one. So the blocks of
// 8 x 8 pixels the CPU classed wholly sea or open deep sea (render/GlobeBlocks, render/
// OpenSeaMap) are shaded at a lattice every kLatticePx pixels and interpolated
// (render/sea_lattice.frag), block by block where the lattice shows that interpolation holds
// (render/sea_lattice.comp); the rest stays per pixel (render/GlobeRenderer::shadeGlobe, the
// sea's and the open sea's parts). Each lattice point is shaded by render/globe.frag compiled as
// a compute shader (GLOBE_LATTICE) as a pixel centred there: by the sea's part where it is a
// corner of a sea block, else by the open sea's (which leaves out the water column, deeper
// than its reach there). About 4 points a block instead of 64 pixels.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::render {

struct GlobeBlocks;

class SeaLattice {
 public:
  static constexpr int kLatticePx = 4;  ///< the lattice's spacing, pixels (globe.frag's SEA_LATTICE_PX)
  static constexpr int kBlockPx = 8;    ///< a block's side (render/GlobeBlocks' kGlobeBlockPx)
  /// The largest difference, in display levels (0-255 after the frame's exposure, tone curve
  /// and sRGB), between a block's lattice points and what its four corners interpolate there
  /// for the block to be interpolated: the lattice's own interpolation, at half that spacing,
  /// is then off by about a quarter of it.
  static constexpr float kMaxLevels = 0.5f;
  /// And the largest relative difference there, of any channel of the radiance (an EXR's
  /// values, which another grade may show): the lattice's own about a quarter of it.
  static constexpr float kMaxRelative = 0.02f;

  /// Lists the lattice points and the blocks of `blocks`' open-sea class, and with `sea` of its
  /// sea class too, in a frame of `width` x `height` pixels (none: empty()).
  void prepare(const GlobeBlocks& blocks, int width, int height, bool sea);
  /// Lists nothing (a frame without such blocks).
  void clear() { blocks_.clear(), points_[0].clear(), points_[1].clear(), shaded_ = false; }
  [[nodiscard]] bool empty() const { return blocks_.empty(); }
  /// Shades the listed points with the programs `program(sea)` returns (globe.frag's
  /// GLOBE_LATTICE for the sea's part or the open sea's, in use with their uniforms set), then
  /// flags the blocks it may interpolate at the frame's `exposure`.
  void shade(const std::function<const gl::Program&(bool sea)>& program, double exposure);
  /// Draws the flagged blocks' pixels that pass the caller's stencil test, and zeroes their
  /// stencil values so the part drawn next leaves them (the stencil test must be on):
  /// `drawBlocks` draws the part's blocks (render/blocks.vert's triangles, its vertex array
  /// bound) with the program in use. Leaves the program changed.
  void drawInterpolated(const std::function<void()>& drawBlocks);
  /// The blocks prepare listed, and how many of them this frame's shade flagged (reads them
  /// back: tests; 0 where it did not run).
  [[nodiscard]] std::size_t listedBlocks() const { return blocks_.size(); }
  [[nodiscard]] std::size_t interpolatedBlocks() const;

 private:
  void ensureTargets(int width, int height);
  void shadePoints(const std::vector<std::uint32_t>& points, const gl::Program& program);
  std::vector<std::uint32_t> blocks_;     ///< x | y << 16, in blocks from the frame's corner
  std::vector<std::uint32_t> points_[2];  ///< x | y << 16: the open sea's points, the sea's
  std::vector<std::uint8_t> pointMarks_;  ///< prepare's, a lattice point each: 1 open sea, 2 sea
  gl::Texture lattice_, flags_;
  int latticeColumns_ = 0, latticeRows_ = 0, blockColumns_ = 0, blockRows_ = 0;
  gl::Buffer pointsBuffer_[2], blocksBuffer_;
  std::size_t pointsBytes_[2] = {0, 0}, blocksBytes_ = 0;
  gl::Program check_, interpolate_;
  bool shaded_ = false;  ///< shade ran since prepare
};

}  // namespace og::render
