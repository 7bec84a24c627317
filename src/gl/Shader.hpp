#pragma once
// Shader programs assembled from files under shaders/ with #include "path" (root-relative,
// each file included once). Sources are embedded in the binary at build time; set
// OCEANGLOBE_SHADER_DIR=<checkout>/shaders to read them from the source tree while developing.
// Compile and link errors name the original file and line.
#include <glad/gl.h>
#include <glm/glm.hpp>

#include <string>
#include <unordered_map>
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

/// The directory programs read the shader tree from: OCEANGLOBE_SHADER_DIR, or empty for the
/// tree embedded in the executable.
[[nodiscard]] std::string shaderSourceDir();

/// Reads a file of the shader tree (embedded, or from OCEANGLOBE_SHADER_DIR).
/// Throws og::InternalError when it does not exist.
std::string readShaderFile(const std::string& path);

/// Expands #include directives and inserts the C++/GLSL contract (gl/ShaderContract.hpp) and
/// `defines` ("NAME value" or "NAME") after #version.
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

  /// The uniform's location, looked up once (active uniforms are read at link time); -1 for a
  /// name the program lacks, logged once at debug level (variants may drop unused uniforms).
  [[nodiscard]] GLint location(const char* name) const;
  /// The uniforms among `names` the linked program lacks: misspelt, or unused and optimised out.
  [[nodiscard]] std::vector<std::string> missingUniforms(const std::vector<std::string>& names) const;
  /// Throws og::InternalError naming the program and each uniform of `names` it lacks: called
  /// once after building, it stops the start-up where a typo would silently set nothing.
  void requireUniforms(const std::vector<std::string>& names) const;
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;
  void set(const char* name, const glm::ivec2& v) const;
  void set(const char* name, const glm::ivec4& v) const;
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::mat3& v) const;
  void set(const char* name, const glm::mat4& v) const;

 private:
  void readActiveUniforms();

  ProgramObject program_;
  std::string name_;  ///< its shader files, for messages
  mutable std::unordered_map<std::string, GLint> locations_;  ///< by name, -1 = not in the program
};

}  // namespace og::gl
