#pragma once
// GPU probes: a compute shader run once per work group over a buffer of vec4s (std430, binding
// 0) that it reads and overwrites, so tests can compare shader code with its CPU twin at chosen
// inputs (atmosphere/probe.comp, terrain/landmask_probe.comp, ocean/lighting_probe.comp).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Shader.hpp"

namespace og::gl {

/// Uploads `values`, dispatches `program` (already given its uniforms and textures) as
/// `groups` work groups with the buffer on shader-storage binding 0, and reads the buffer back
/// into `values`. Throws og::InternalError (via checkErrors, naming `where`) on a GL error.
void runProbe(const Program& program, std::vector<glm::vec4>& values, int groups, const char* where);

}  // namespace og::gl
