#pragma once
// Below the grid's ceiling, what the terrain and the grid leave for the globe
// (render/GlobeRenderer::classifyGlobe): whether any pixel at all (an occlusion query of
// shaders/render/uncovered.frag, on which the globe's draws are conditional; in frames with
// sky, any within the box of rays that meet the ellipsoid, and only its classifying draws are)
// and which blocks of 8 x 8 pixels hold one, as triangles for the classifying draw that writes
// the stencil from its shader (GLOBE_CLASSIFY_EXPORT). llvmpipe tests the depth after a shader that writes the
// stencil, so drawn over its whole box that draw ran in full for every pixel the grid covers
// (7 of sea-4m's 185 ms of one thread at 1280 x 720); over the listed blocks it runs for the
// horizon's gaps and the sky near them.
#include <array>
#include <cstddef>

#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::render {

class UncoveredPixels {
 public:
  static constexpr int kBlockPx = 8;  ///< a block's side, pixels (shaders/render/uncovered_blocks.glsl)

  /// Draws uncovered.frag over a `width` x `height` frame in the query (the caller's depth test
  /// passes what is left; the caller turns the colour writes off); with `listBlocks`, flags the
  /// blocks holding such a pixel within `box` (x, y, width, height, pixels) and lists them for
  /// drawBlocks (`everyBlock`: every block within it, the tests' reference); with `onlyInBox`,
  /// draws over `box` alone, so that the query answers for it alone. Leaves the program, the
  /// storage bindings and the scissor test changed.
  void find(int width, int height, const std::array<int, 4>& box, bool listBlocks, bool everyBlock = false,
            bool onlyInBox = false);
  /// The query find drew in (GL_ANY_SAMPLES_PASSED).
  [[nodiscard]] GLuint query() const { return query_.id(); }
  /// The blocks find listed, two triangles each (shaders/render/blocks.vert's input), with the
  /// bound program (the classifying draw's, and with several samples a pixel the globe's edge
  /// and surface parts': GlobeRenderer::shadeGlobe); binds its own vertex array.
  void drawBlocks() const;
  /// The blocks find listed last (reads them back: for tests; a frame whose grid left no pixel
  /// lists none and leaves the count as it was).
  [[nodiscard]] int listedBlocks() const;

 private:
  void listFlagged(int width, int height, const std::array<int, 4>& box, bool everyBlock);
  gl::Program find_, findBlocks_, list_;
  gl::Query query_;
  gl::Buffer blocks_;     ///< uncovered_blocks.glsl's block: the draw's arguments, a flag a block
  gl::Buffer triangles_;  ///< the listed blocks' vertices (vec2, normalised device coordinates)
  std::size_t blocksBytes_ = 0, trianglesBytes_ = 0;
  gl::VertexArray vao_;
  int blocksPerRow_ = 0;
};

}  // namespace og::render
