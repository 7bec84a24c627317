#include "gl/Probe.hpp"

#include "gl/Objects.hpp"

namespace og::gl {

void runProbe(const Program& program, std::vector<glm::vec4>& values, int groups, const char* where) {
  if (values.empty() || groups <= 0) return;
  const auto bytes = static_cast<GLsizeiptr>(values.size() * sizeof(glm::vec4));
  Buffer buffer = createBuffer();
  glNamedBufferStorage(buffer.id(), bytes, values.data(), GL_DYNAMIC_STORAGE_BIT);
  program.use();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
  glDispatchCompute(static_cast<GLuint>(groups), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), 0, bytes, values.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  checkErrors(where);
}

}  // namespace og::gl
