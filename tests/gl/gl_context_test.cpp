// GL tier: headless contexts, shader assembly and error reporting, reversed-Z depth.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <fstream>
#include <filesystem>

#include "core/Error.hpp"
#include "render/GlobeRenderer.hpp"
#include "data/Elevation.hpp"
#include "gl/Context.hpp"
#include "gl/Objects.hpp"
#include "gl/Readback.hpp"
#include "gl/Shader.hpp"
#include "support/GlFixtures.hpp"

using namespace og;

namespace {
using test::ScopedEnv;
}  // namespace

TEST(GlContext, EglAndOsMesaGiveCoreContexts) {
  for (gl::Backend b : {gl::Backend::Egl, gl::Backend::OsMesa, gl::Backend::Auto}) {
    auto ctx = gl::createHeadlessContext(b);
    ASSERT_TRUE(ctx);
    EXPECT_FALSE(ctx->info().renderer.empty());
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45) << gl::backendName(b);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << gl::backendName(b);
    if (b == gl::Backend::OsMesa) {
      EXPECT_EQ(ctx->info().backend, "osmesa");
    }
    if (b == gl::Backend::Egl) {
      EXPECT_EQ(ctx->info().backend.rfind("egl", 0), 0u);
    }
  }
}

TEST(GlContext, ParseBackend) {
  EXPECT_EQ(gl::parseBackend("egl"), gl::Backend::Egl);
  EXPECT_EQ(gl::parseBackend("osmesa"), gl::Backend::OsMesa);
  EXPECT_EQ(gl::parseBackend("auto"), gl::Backend::Auto);
  EXPECT_FALSE(gl::parseBackend("vulkan"));
}

TEST(GlShader, IncludesExpandWithLineDirectives) {
  const gl::ExpandedSource src = gl::expandShader("render/globe.frag", {"TEST_DEFINE 1"});
  // #version first, then the contract's defines (gl/ShaderContract), then the caller's.
  EXPECT_EQ(src.text.rfind("#version 450 core\n#define OG_PI ", 0), 0u);
  EXPECT_NE(src.text.find("\n#define TEST_DEFINE 1\n#line 2 0\n"), std::string::npos);
  EXPECT_EQ(src.files.at(0), "shaders/render/globe.frag");
  // common/constants.glsl is included by globe.frag and by geo/ellipsoid.glsl: once only.
  std::size_t count = 0;
  for (std::size_t p = 0; (p = src.text.find("const Number WGS84_A", p)) != std::string::npos; ++p)
    ++count;
  EXPECT_EQ(count, 1u);
  EXPECT_EQ(src.text.find("#include"), std::string::npos);
}

TEST(GlShader, CompileErrorNamesIncludedFileAndLine) {
  auto ctx = gl::createHeadlessContext();
  const ScopedEnv env("OCEANGLOBE_SHADER_DIR", OG_TEST_DATA_DIR "/gl/shaders");
  try {
    gl::Program p({{GL_FRAGMENT_SHADER, "bad/main.frag"}});
    FAIL() << "compiling a broken shader must throw";
  } catch (const InternalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shaders/bad/inner.glsl:3"), std::string::npos) << what;
    EXPECT_NE(what.find("undefined_symbol_here"), std::string::npos) << what;
  }
}

// NVIDIA's drivers lack GL_ARB_shader_stencil_export: a program that enables it fails to compile
// there (the tenth and thirty-third sessions found two). Every shader enables it only under
// OG_STENCIL_EXPORT, which gl::Program defines from the driver profile, so that
// OCEANGLOBE_STENCIL_EXPORT=0 makes llvmpipe's compiler refuse what NVIDIA's would (a test
// shader that writes the stencil value); and the programs such a driver builds compile then.
TEST(GlShader, StencilExportOnlyWhereTheDriverHasIt) {
  namespace fs = std::filesystem;
  int enabled = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(fs::path(OG_SOURCE_DIR) / "shaders")) {
    std::ifstream in(e.path());
    std::string line, previous;
    while (std::getline(in, line)) {
      if (line.find("#extension GL_ARB_shader_stencil_export") != std::string::npos) {
        ++enabled;
        EXPECT_EQ(previous.rfind("#if", 0), 0u) << e.path() << ": " << line;
        EXPECT_NE(previous.find("defined(OG_STENCIL_EXPORT)"), std::string::npos) << e.path() << ": " << previous;
      }
      previous = line;
    }
  }
  EXPECT_EQ(enabled, 4) << "globe.frag, sea_surface.frag, sea_classify.frag, sea_visibility.frag";
  // A shader that writes the stencil value: compiled where the driver exports it, refused
  // where it does not (NVIDIA's compiler: "undefined variable gl_FragStencilRefARB").
  const bool exports = gl::createHeadlessContext()->info().profile.stencilExport;
  {
    const ScopedEnv dir("OCEANGLOBE_SHADER_DIR", OG_TEST_DATA_DIR "/gl/shaders");
    if (exports) {
      auto ctx = gl::createHeadlessContext();
      EXPECT_NO_THROW(gl::Program({{GL_FRAGMENT_SHADER, "stencil/export.frag"}}));
    }
    const ScopedEnv off("OCEANGLOBE_STENCIL_EXPORT", "0");
    auto ctx = gl::createHeadlessContext();
    ASSERT_FALSE(gl::driverProfile().stencilExport);
    try {
      gl::Program p({{GL_FRAGMENT_SHADER, "stencil/export.frag"}});
      ADD_FAILURE() << "a stencil-writing shader compiled without stencil export";
    } catch (const InternalError& e) {
      EXPECT_NE(std::string(e.what()).find("gl_FragStencilRefARB"), std::string::npos) << e.what();
    }
  }
  // The deferred sea by a Himalayan valley from 15 km (bench's mountain-15km), by compute shaders
  // and by fragments: where land may hide the whole sea its classifying draw asks first
  // (OceanRenderer::seaShows), which wrote stencil values (the thirty-third session's crash).
  const ScopedEnv off("OCEANGLOBE_STENCIL_EXPORT", "0");
  for (const char* path : {"compute", "deferred"}) {
    const ScopedEnv sea("OCEANGLOBE_SEA", path);
    auto ctx = gl::createHeadlessContext();
    render::GlobeRenderer r(data::defaultElevation());
    render::FrameInput f = test::frameOf({27.3, 86.9, 15000.0, 10.0, -2.0, 45.0, 160, 90}, 30.0, 120.0);
    f.samples = 1;
    EXPECT_NO_THROW(r.render(f)) << path;
    EXPECT_TRUE(r.ocean().lastDrawDeferred()) << path;  // (after the query: the sea shows there)
  }
}

TEST(GlShader, MissingFileIsReported) {
  auto ctx = gl::createHeadlessContext();
  EXPECT_THROW(gl::Program({{GL_FRAGMENT_SHADER, "no/such.frag"}}), InternalError);
}

// Two surfaces drawn far first must resolve 1 mm apart at 1 m and 10 m apart at 40 000 km:
// reversed-Z with a 32-bit float depth buffer.
TEST(GlDepth, ReversedZResolvesOneMetreAndFortyThousandKm) {
  auto ctx = gl::createHeadlessContext();
  gl::Program solid({{GL_VERTEX_SHADER, "render/solid.vert"}, {GL_FRAGMENT_SHADER, "render/solid.frag"}});
  gl::RenderTarget target = gl::createRenderTarget(8, 8, GL_RGBA8, true);
  gl::VertexArray vao = gl::createVertexArray();
  const float nearM = 0.05f;
  // Reversed-Z infinite projection, 90° field of view (see geo::CameraView::projection).
  const glm::mat4 proj(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 0, -1),
                       glm::vec4(0, 0, nearM, 0));
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
  glViewport(0, 0, 8, 8);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glBindVertexArray(vao.id());
  solid.use();
  for (const auto& [far, near] : {std::pair{1.001f, 1.0f}, std::pair{4.0e7f, 3.999999e7f}}) {
    const float zero = 0.0f, black[] = {0, 0, 0, 1};
    glClearNamedFramebufferfv(target.fbo.id(), GL_DEPTH, 0, &zero);
    glClearNamedFramebufferfv(target.fbo.id(), GL_COLOR, 0, black);
    solid.set("uViewProjection", proj);
    solid.set("uDistance", far);
    solid.set("uColor", glm::vec4(1, 0, 0, 1));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    solid.set("uDistance", near);
    solid.set("uColor", glm::vec4(0, 1, 0, 1));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const auto px = gl::readRgba8(target.fbo.id(), 8, 8);
    EXPECT_EQ(px[4 * 36 + 1], 255) << "nearer surface lost at " << near << " m";
    EXPECT_EQ(px[4 * 36 + 0], 0) << "farther surface won at " << far << " m";
  }
  gl::checkErrors("depth test");
}
