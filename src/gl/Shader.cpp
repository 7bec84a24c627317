#include "gl/Shader.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/StartupTrace.hpp"
#include "gl/DriverProfile.hpp"
#include "gl/ShaderContract.hpp"

namespace og::embedded::shaders {
std::optional<std::string_view> find(std::string_view path);
}

namespace og::gl {
namespace {

std::string stageName(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_COMPUTE_SHADER: return "compute";
    case GL_GEOMETRY_SHADER: return "geometry";
    default: return "shader";
  }
}

void expandInto(const std::string& path, ExpandedSource& out, std::set<std::string>& seen,
                int depth) {
  if (depth > 32) throw InternalError("shaders/" + path + ": #include nested too deeply");
  const std::string text = readShaderFile(path);
  const int index = static_cast<int>(out.files.size());
  out.files.push_back("shaders/" + path);
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  static const std::regex includeRe(R"(^\s*#\s*include\s+"([^"]+)\"\s*(//.*)?$)");
  std::smatch m;
  while (std::getline(in, line)) {
    ++lineNo;
    if (std::regex_match(line, m, includeRe)) {
      const std::string inc = m[1].str();
      if (seen.insert(inc).second) {
        out.text += "#line 1 " + std::to_string(out.files.size()) + "\n";
        expandInto(inc, out, seen, depth + 1);
      }
      out.text += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(index) + "\n";
      continue;
    }
    out.text += line;
    out.text += '\n';
  }
}

}  // namespace

std::string shaderSourceDir() {
  const char* dir = std::getenv("OCEANGLOBE_SHADER_DIR");
  return dir != nullptr ? dir : "";
}

std::string readShaderFile(const std::string& path) {
  if (const std::string dir = shaderSourceDir(); !dir.empty()) {
    std::ifstream f(dir + "/" + path, std::ios::binary);
    if (!f) throw InternalError(dir + "/" + path + ": cannot read shader file");
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
  }
  const auto embedded = embedded::shaders::find(path);
  if (!embedded) throw InternalError("shaders/" + path + ": no such embedded shader file");
  return std::string(*embedded);
}

ExpandedSource expandShader(const std::string& path, const std::vector<std::string>& defines) {
  ExpandedSource body;
  std::set<std::string> seen{path};
  expandInto(path, body, seen, 0);
  // #version must stay first: move it ahead of the injected defines.
  ExpandedSource out;
  out.files = body.files;
  const std::size_t eol = body.text.find('\n');
  const std::string first = body.text.substr(0, eol);
  if (first.rfind("#version", 0) != 0)
    throw InternalError(body.files[0] + ":1: a shader must start with #version");
  out.text = first + "\n";
  for (const auto& d : contractDefines()) out.text += "#define " + d + "\n";
  for (const auto& d : defines) out.text += "#define " + d + "\n";
  out.text += "#line 2 0\n" + body.text.substr(eol + 1);
  return out;
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files) {
  // Mesa: "0:12(3): error: ..."; NVIDIA: "0(12) : error C1008: ...".
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*)");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*)");
  std::istringstream in(log);
  std::string line, out;
  std::smatch m;
  auto fileName = [&](const std::string& idx) {
    const auto i = static_cast<std::size_t>(std::stoul(idx));
    return i < files.size() ? files[i] : "<source " + idx + ">";
  };
  while (std::getline(in, line)) {
    if (std::regex_search(line, m, mesa))
      line = fileName(m[1]) + ":" + m[2].str() + ":" + m[3].str() + ": " + m.suffix().str();
    else if (std::regex_search(line, m, nvidia))
      line = fileName(m[1]) + ":" + m[2].str() + ": " + m.suffix().str();
    out += line + "\n";
  }
  return out;
}

Program::Program(const std::vector<std::pair<GLenum, std::string>>& stages,
                 const std::vector<std::string>& defines) {
  const core::startup::Scope timed("shaders: compile + link");
  const auto t0 = core::startup::Clock::now();
  program_ = ProgramObject(glCreateProgram());
  std::vector<ShaderObject> shaders;
  // GL_ARB_shader_stencil_export is enabled (#extension) only under OG_STENCIL_EXPORT, which the
  // driver profile sets: with OCEANGLOBE_STENCIL_EXPORT=0 a program that writes
  // gl_FragStencilRefARB then fails on llvmpipe as it does on drivers without the extension.
  std::vector<std::string> all = defines;
  if (driverProfile().stencilExport) all.emplace_back("OG_STENCIL_EXPORT");
  for (const auto& [stage, path] : stages) {
    const ExpandedSource src = expandShader(path, all);
    ShaderObject s(glCreateShader(stage));
    const char* text = src.text.c_str();
    glShaderSource(s.id(), 1, &text, nullptr);
    glCompileShader(s.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(s.id(), GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
      GLint len = 0;
      glGetShaderiv(s.id(), GL_INFO_LOG_LENGTH, &len);
      std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
      glGetShaderInfoLog(s.id(), len, nullptr, log.data());
      throw InternalError("cannot compile " + stageName(stage) + " shader shaders/" + path +
                          ":\n" + mapShaderLog(log.c_str(), src.files));
    }
    glAttachShader(program_.id(), s.id());
    shaders.push_back(std::move(s));
  }
  glLinkProgram(program_.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetProgramiv(program_.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program_.id(), len, nullptr, log.data());
    std::string names;
    for (const auto& st : stages) names += " shaders/" + st.second;
    throw InternalError("cannot link program" + names + ":\n" + log.c_str());
  }
  for (const auto& s : shaders) glDetachShader(program_.id(), s.id());
  for (const auto& st : stages) name_ += (name_.empty() ? "shaders/" : " shaders/") + st.second;
  readActiveUniforms();
  std::string variant;
  for (const auto& s : defines) variant += (variant.empty() ? " [" : ", ") + s;
  // One row per program, "program: " first: bench --startup lists them apart from the stages.
  core::startup::add("program: " + name_ + (variant.empty() ? "" : variant + "]"), t0,
                     std::chrono::duration<double, std::milli>(core::startup::Clock::now() - t0).count());
}

void Program::readActiveUniforms() {
  GLint count = 0;
  glGetProgramInterfaceiv(id(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[256];
    GLsizei length = 0;
    glGetProgramResourceName(id(), GL_UNIFORM, static_cast<GLuint>(i), sizeof name, &length, name);
    const GLint loc = glGetUniformLocation(id(), name);
    if (loc >= 0) locations_.emplace(std::string(name, static_cast<std::size_t>(length)), loc);
  }
}

GLint Program::location(const char* name) const {
  if (const auto it = locations_.find(name); it != locations_.end()) return it->second;
  // Not an active uniform by its own name: an array element or struct member, or missing.
  const GLint loc = glGetUniformLocation(id(), name);
  locations_.emplace(name, loc);
  if (loc < 0) log::debug(name_ + ": no active uniform '" + name + "' (misspelt, or unused and optimised out)");
  return loc;
}

std::vector<std::string> Program::missingUniforms(const std::vector<std::string>& names) const {
  std::vector<std::string> missing;
  for (const std::string& n : names)
    if (glGetUniformLocation(id(), n.c_str()) < 0) missing.push_back(n);
  return missing;
}

void Program::requireUniforms(const std::vector<std::string>& names) const {
  const std::vector<std::string> missing = missingUniforms(names);
  if (missing.empty()) return;
  std::string list;
  for (const std::string& n : missing) list += (list.empty() ? "" : ", ") + n;
  throw InternalError(name_ + ": no active uniform " + list + " (misspelt, or unused and optimised out)");
}
void Program::set(const char* n, float v) const { glProgramUniform1f(id(), location(n), v); }
void Program::set(const char* n, int v) const { glProgramUniform1i(id(), location(n), v); }
void Program::set(const char* n, const glm::ivec2& v) const {
  glProgramUniform2iv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec4& v) const {
  glProgramUniform4iv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec2& v) const {
  glProgramUniform2fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
  glProgramUniform3fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
  glProgramUniform4fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat3& v) const {
  glProgramUniformMatrix3fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace og::gl
