#include "render/SeaLattice.hpp"

#include <algorithm>
#include <array>

#include "gl/ShaderContract.hpp"
#include "render/GlobeBlocks.hpp"

namespace og::render {

static_assert(SeaLattice::kBlockPx == kGlobeBlockPx, "the lattice's blocks are GlobeBlocks'");
static_assert(SeaLattice::kBlockPx == 2 * SeaLattice::kLatticePx, "a block spans two lattice spacings");

namespace {
constexpr std::uint32_t packed(int x, int y) {
  return static_cast<std::uint32_t>(x) | static_cast<std::uint32_t>(y) << 16;
}
constexpr GLuint kGroup = gl::kGlobePixelsGroup;       // the shaders' work groups
constexpr GLuint kGroupsARow = gl::kGlobePixelsRow;     // render/globe_pixels.glsl's rows of groups

// Uploads a list as the shaders' storage block: a count, three words (globe_pixels.glsl's
// dispatch arguments, unused here), then the entries.
void upload(gl::Buffer& buffer, std::size_t& capacity, const std::vector<std::uint32_t>& entries) {
  const std::array<std::uint32_t, 4> head{static_cast<std::uint32_t>(entries.size()), 0, 0, 0};
  const std::size_t entryBytes = entries.size() * sizeof(std::uint32_t);
  gl::ensureBufferCapacity(buffer, capacity, sizeof head + entryBytes, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferSubData(buffer.id(), 0, sizeof head, head.data());
  glNamedBufferSubData(buffer.id(), sizeof head, static_cast<GLsizeiptr>(entryBytes), entries.data());
}
}  // namespace

void SeaLattice::prepare(const GlobeBlocks& blocks, int width, int height, bool sea) {
  clear();
  ensureTargets(width, height);
  std::fill(pointMarks_.begin(), pointMarks_.end(), std::uint8_t{0});
  const auto markAt = [&](int x, int y) -> std::uint8_t& {
    return pointMarks_[static_cast<std::size_t>(y) * static_cast<std::size_t>(latticeColumns_) + static_cast<std::size_t>(x)];
  };
  const int x0 = blocks.rect[0] / kBlockPx, y0 = blocks.rect[1] / kBlockPx;  // (multiples of the block)
  for (int j = 0; j < blocks.rows; ++j)
    for (int i = 0; i < blocks.columns; ++i) {
      const GlobeBlockClass c =
          blocks.classes[static_cast<std::size_t>(j) * static_cast<std::size_t>(blocks.columns) + static_cast<std::size_t>(i)];
      if (c != GlobeBlockClass::OpenSea && (c != GlobeBlockClass::Sea || !sea)) continue;
      const int bx = x0 + i, by = y0 + j;
      blocks_.push_back(packed(bx, by));
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) markAt(2 * bx + a, 2 * by + b) |= c == GlobeBlockClass::Sea ? 2 : 1;
    }
  for (int y = 0; y < latticeRows_; ++y)
    for (int x = 0; x < latticeColumns_; ++x)
      if (const std::uint8_t m = markAt(x, y); m != 0) points_[m >= 2 ? 1 : 0].push_back(packed(x, y));
}

void SeaLattice::ensureTargets(int width, int height) {
  const int columns = (width + kBlockPx - 1) / kBlockPx, rows = (height + kBlockPx - 1) / kBlockPx;
  if (columns == blockColumns_ && rows == blockRows_) return;
  blockColumns_ = columns, blockRows_ = rows;
  latticeColumns_ = 2 * columns + 1, latticeRows_ = 2 * rows + 1;
  pointMarks_.assign(static_cast<std::size_t>(latticeColumns_) * static_cast<std::size_t>(latticeRows_), 0);
  lattice_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(lattice_.id(), 1, GL_RGBA32F, latticeColumns_, latticeRows_);
  glTextureParameteri(lattice_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(lattice_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(lattice_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(lattice_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  flags_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(flags_.id(), 1, GL_R8UI, blockColumns_, blockRows_);
  glTextureParameteri(flags_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // (an integer texture is
  glTextureParameteri(flags_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // incomplete otherwise)
}

void SeaLattice::shadePoints(const std::vector<std::uint32_t>& points, const gl::Program& program) {
  // As globe.frag's listed pixels: rows of at most kGroupsARow groups.
  const auto groups = static_cast<GLuint>((points.size() + kGroup - 1) / kGroup);
  program.use();
  glDispatchCompute(std::min(groups, kGroupsARow), (groups + kGroupsARow - 1) / kGroupsARow, 1);
}

void SeaLattice::shade(const std::function<const gl::Program&(bool sea)>& program, double exposure) {
  if (empty()) return;
  for (const bool sea : {false, true}) {
    const std::vector<std::uint32_t>& points = points_[sea ? 1 : 0];
    if (points.empty()) continue;
    const gl::Program& p = program(sea);
    upload(pointsBuffer_[sea ? 1 : 0], pointsBytes_[sea ? 1 : 0], points);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kGlobePixelsBinding, pointsBuffer_[sea ? 1 : 0].id());
    glBindImageTexture(0, lattice_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    shadePoints(points, p);
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  upload(blocksBuffer_, blocksBytes_, blocks_);
  // The blocks' flags: 0 (per pixel) unless the check passes one.
  if (check_.id() == 0) {  // (compiled on first use, as the globe's variants are)
    check_ = gl::Program({{GL_COMPUTE_SHADER, "render/sea_lattice.comp"}});
    interpolate_ = gl::Program({{GL_VERTEX_SHADER, "render/blocks.vert"}, {GL_FRAGMENT_SHADER, "render/sea_lattice.frag"}});
  }
  const GLubyte zero = 0;
  glClearTexImage(flags_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::kSeaLatticeBlocksBinding, blocksBuffer_.id());
  glBindImageTexture(0, lattice_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(1, flags_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
  check_.set("uExposure", static_cast<float>(exposure));
  check_.set("uMaxLevels", kMaxLevels);
  check_.set("uMaxRelative", kMaxRelative);
  check_.use();
  glDispatchCompute(static_cast<GLuint>((blocks_.size() + kGroup - 1) / kGroup), 1, 1);
  // (The fragments' lookups, and interpolatedBlocks' read-back.)
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  shaded_ = true;
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
}

void SeaLattice::drawInterpolated(const std::function<void()>& drawBlocks) {
  if (empty()) return;
  glBindTextureUnit(gl::kUnitSeaLattice, lattice_.id());
  glBindTextureUnit(gl::kUnitSeaLatticeBlocks, flags_.id());
  GLint writeMask = 0;
  glGetIntegerv(GL_STENCIL_WRITEMASK, &writeMask);
  glStencilMask(0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
  interpolate_.use();
  drawBlocks();
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(static_cast<GLuint>(writeMask));
}

std::size_t SeaLattice::interpolatedBlocks() const {
  if (empty() || !shaded_) return 0;
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(blockColumns_) * static_cast<std::size_t>(blockRows_));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(flags_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, static_cast<GLsizei>(flags.size()), flags.data());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  return static_cast<std::size_t>(std::count(flags.begin(), flags.end(), std::uint8_t{1}));
}

}  // namespace og::render
