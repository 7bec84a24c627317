#include "render/TerrainRenderer.hpp"

#include <cmath>
#include <cstddef>

#include "core/Error.hpp"

namespace og::render {

TerrainRenderer::TerrainRenderer(const data::LatLonGrid& elevation, const Atmosphere* atmosphere)
    : atmosphere_(atmosphere),
      cache_(std::make_shared<const terrain::Heightfield>(elevation)),
      program_({{GL_VERTEX_SHADER, "terrain/terrain.vert"},
                {GL_FRAGMENT_SHADER, "terrain/terrain.frag"}}),
      vao_(gl::createVertexArray()),
      indices_(gl::createBuffer()) {
  const auto& idx = terrain::tileIndices();
  indexCount_ = static_cast<int>(idx.size());
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)),
                       idx.data(), 0);
  const GLuint vao = vao_.id();
  glVertexArrayElementBuffer(vao, indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(terrain::TileVertex, position));
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(terrain::TileVertex, normal));
  glVertexArrayAttribFormat(vao, 2, 4, GL_FLOAT, GL_FALSE, offsetof(terrain::TileVertex, heightM));
  for (GLuint a = 0; a < 3; ++a) glVertexArrayAttribBinding(vao, a, 0);
  gl::checkErrors("TerrainRenderer setup");
}

void TerrainRenderer::draw(const geo::CameraView& view, int width, int height,
                           const glm::dvec3& sunDirectionEcef) {
  params_.widthPx = width;
  params_.heightPx = height;
  terrain::SelectionStats sel;
  const auto tiles = terrain::selectTiles(cache_, view, params_, &sel);
  for (const std::uint64_t key : cache_.takeEvicted()) gpu_.erase(key);

  const gl::Program& p = program_;
  p.set("uViewProjection", glm::mat4(view.viewProjection()));
  p.set("uSunDir", glm::vec3(glm::normalize(sunDirectionEcef)));
  p.set("uCamUp", glm::vec3(view.enu.up));
  p.set("uCamAltitude", static_cast<float>(view.position.heightM));
  if (atmosphere_ != nullptr) atmosphere_->bind(p);
  p.use();
  glBindVertexArray(vao_.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  for (const terrain::Tile* t : tiles) {
    auto [it, fresh] = gpu_.try_emplace(t->key.packed());
    if (fresh) {
      it->second.vertices = gl::createBuffer();
      glNamedBufferStorage(it->second.vertices.id(),
                           static_cast<GLsizeiptr>(t->vertices.size() * sizeof(terrain::TileVertex)),
                           t->vertices.data(), 0);
    }
    // Camera-relative tile origin in double, then float: never float world coordinates.
    p.set("uTileOffset", glm::vec3(t->centreEcef - view.positionEcef));
    glVertexArrayVertexBuffer(vao_.id(), 0, it->second.vertices.id(), 0, sizeof(terrain::TileVertex));
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  }
  stats_.tiles = static_cast<int>(tiles.size());
  stats_.finestLevel = sel.finestLevel;
  stats_.tilesPending = sel.pending;
  stats_.cpuBytes = cache_.bytes();
  stats_.gpuBytes = gpu_.size() * terrain::kTileVertices * sizeof(terrain::TileVertex);
  gl::checkErrors("TerrainRenderer::draw");
}

}  // namespace og::render
