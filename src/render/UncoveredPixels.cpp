#include "render/UncoveredPixels.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "gl/ShaderContract.hpp"

namespace og::render {

void UncoveredPixels::find(int width, int height, const std::array<int, 4>& box, bool listBlocks, bool everyBlock,
                           bool onlyInBox) {
  static const std::vector<std::pair<GLenum, std::string>> stages{{GL_VERTEX_SHADER, "render/fullscreen.vert"},
                                                                  {GL_FRAGMENT_SHADER, "render/uncovered.frag"}};
  if (find_.id() == 0) {
    find_ = gl::Program(stages);
    query_ = gl::createQuery(GL_ANY_SAMPLES_PASSED);
  }
  if (listBlocks && findBlocks_.id() == 0) {
    findBlocks_ = gl::Program(stages, {"UNCOVERED_BLOCKS"});
    list_ = gl::Program({{GL_COMPUTE_SHADER, "render/uncovered_blocks.comp"}});
    vao_ = gl::createVertexArray();
    glEnableVertexArrayAttrib(vao_.id(), 0);
    glVertexArrayAttribFormat(vao_.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_.id(), 0, 0);
  }
  const gl::Program& program = listBlocks ? findBlocks_ : find_;
  if (listBlocks) {
    blocksPerRow_ = (width + kBlockPx - 1) / kBlockPx;
    const int rows = (height + kBlockPx - 1) / kBlockPx;
    const std::size_t blocks = static_cast<std::size_t>(blocksPerRow_) * static_cast<std::size_t>(rows);
    gl::ensureBufferCapacity(blocks_, blocksBytes_, (4 + blocks) * sizeof(GLuint), GL_DYNAMIC_STORAGE_BIT);
    gl::ensureBufferCapacity(triangles_, trianglesBytes_, 6 * blocks * 2 * sizeof(float));
    // The arguments (no vertices yet, one instance) and no block flagged.
    const std::array<GLuint, 4> args{0, 1, 0, 0};
    glNamedBufferSubData(blocks_.id(), 0, sizeof args, args.data());
    glClearNamedBufferSubData(blocks_.id(), GL_R32UI, sizeof args, blocks * sizeof(GLuint), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, nullptr);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kUncoveredBlocksBinding, blocks_.id());
    program.set("uBox", glm::ivec4(box[0], box[1], box[0] + box[2], box[1] + box[3]));
    program.set("uBlocksPerRow", blocksPerRow_);
  }
  program.use();
  if (onlyInBox) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(box[0], box[1], box[2], box[3]);
  }
  glBeginQuery(GL_ANY_SAMPLES_PASSED, query_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  if (onlyInBox) glDisable(GL_SCISSOR_TEST);
  if (listBlocks) listFlagged(width, height, box, everyBlock);
}

void UncoveredPixels::listFlagged(int width, int height, const std::array<int, 4>& box, bool everyBlock) {
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const int x0 = box[0] / kBlockPx, y0 = box[1] / kBlockPx;
  const int x1 = (box[0] + box[2] + kBlockPx - 1) / kBlockPx, y1 = (box[1] + box[3] + kBlockPx - 1) / kBlockPx;
  list_.set("uBlockBox", glm::ivec4(x0, y0, x1, y1));
  list_.set("uBlocksPerRow", blocksPerRow_);
  list_.set("uEveryBlock", everyBlock ? 1 : 0);
  list_.set("uBlockNdc", 2.0f * kBlockPx / glm::vec2(static_cast<float>(width), static_cast<float>(height)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kUncoveredTrianglesBinding, triangles_.id());
  list_.use();
  const auto groups = [](int blocks) { return static_cast<GLuint>(std::max(blocks, 0) + 7) / 8; };  // 8 x 8 a group
  glDispatchCompute(groups(x1 - x0), groups(y1 - y0), 1);
  // The draw's arguments and vertices; the next frame's reset and the tests' read-back.
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void UncoveredPixels::drawBlocks() const {
  // (The buffer may have been remade since: bound again each time.)
  glVertexArrayVertexBuffer(vao_.id(), 0, triangles_.id(), 0, 2 * sizeof(float));
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, blocks_.id());
  glDrawArraysIndirect(GL_TRIANGLES, nullptr);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

int UncoveredPixels::listedBlocks() const {
  if (blocks_.id() == 0) return 0;
  GLuint vertices = 0;
  glGetNamedBufferSubData(blocks_.id(), 0, sizeof vertices, &vertices);
  return static_cast<int>(vertices / 6);
}

}  // namespace og::render
