#pragma once
// Shader programs assembled from files under shaders/ with #include "path" (root-relative,
// each file included once). Sources are embedded in the binary at build time; set
// OCEANGLOBE_SHADER_DIR=<checkout>/shaders to read them from the source tree while developing.
// Compile and link errors name the original file and line.
#include <glad/gl.h>
#include <glm/glm.hpp>

#include <string>
#include <utility>
#include <vector>

#include "gl/Objects.hpp"

namespace og::gl {

/// A shader's text after #include expansion, with `#line L F` directives; files[F] names the
/// file behind source-string number F in driver messages.
struct ExpandedSource {
  std::string text;
  std::vector<std::string> files;
};

/// Reads a file of the shader tree (embedded, or from OCEANGLOBE_SHADER_DIR).
/// Throws og::InternalError when it does not exist.
std::string readShaderFile(const std::string& path);

/// Expands #include directives and inserts `defines` ("NAME value" or "NAME") after #version.
ExpandedSource expandShader(const std::string& path, const std::vector<std::string>& defines = {});

/// Rewrites driver log lines "0:12(3): error" / "0(12) : error" as "file.glsl:12: error".
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files);

class Program {
 public:
  Program() = default;
  /// Compiles and links stages given as {GL_VERTEX_SHADER, "render/globe.vert"}, ...
  /// Throws og::InternalError with the file, line and driver log on failure.
  Program(const std::vector<std::pair<GLenum, std::string>>& stages,
          const std::vector<std::string>& defines = {});

  [[nodiscard]] GLuint id() const { return program_.id(); }
  void use() const { glUseProgram(program_.id()); }

  [[nodiscard]] GLint location(const char* name) const;
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;
  void set(const char* name, const glm::ivec2& v) const;
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::mat3& v) const;
  void set(const char* name, const glm::mat4& v) const;

 private:
  ProgramObject program_;
};

}  // namespace og::gl
