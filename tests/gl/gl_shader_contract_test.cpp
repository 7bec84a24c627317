// The C++/GLSL contract (gl/ShaderContract.hpp) reaches every shader, and uniforms a program
// lacks are reported when it is built, not silently ignored when set.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "geo/Wgs84.hpp"
#include "gl/Context.hpp"
#include "gl/Shader.hpp"
#include "gl/ShaderContract.hpp"

TEST(ShaderContract, ConstantsAndUnitsAreInjectedFromCpp) {
  const og::gl::ExpandedSource src = og::gl::expandShader("render/solid.frag");
  EXPECT_EQ(src.text.rfind("#version", 0), 0u);
  EXPECT_NE(src.text.find("#define OG_PI 3.1415926535897931\n"), std::string::npos);
  EXPECT_NE(src.text.find("#define OG_UNIT_WIND " + std::to_string(og::gl::kUnitWind) + "\n"),
            std::string::npos);
  // The values are C++'s, to the last digit a double holds.
  for (const std::string& d : og::gl::contractDefines()) {
    if (d.rfind("OG_WGS84_A ", 0) == 0) {
      EXPECT_EQ(std::stod(d.substr(11)), og::geo::kWgs84SemiMajorM);
    }
    if (d.rfind("OG_WGS84_B ", 0) == 0) {
      EXPECT_EQ(std::stod(d.substr(11)), og::geo::kWgs84SemiMinorM);
    }
  }
  // Shaders no longer carry their own copies.
  const std::string constants = og::gl::readShaderFile("common/constants.glsl");
  EXPECT_EQ(constants.find("3.14159"), std::string::npos);
  EXPECT_EQ(og::gl::readShaderFile("ocean/wind.glsl").find("binding = 1"), std::string::npos);
}

TEST(ShaderContract, MissingUniformsAreReportedAtStartUp) {
  auto context = og::gl::createHeadlessContext();
  const og::gl::Program p({{GL_VERTEX_SHADER, "render/solid.vert"}, {GL_FRAGMENT_SHADER, "render/solid.frag"}});
  EXPECT_TRUE(p.missingUniforms({"uViewProjection", "uDistance", "uColor"}).empty());
  EXPECT_EQ(p.missingUniforms({"uColor", "uColour"}), std::vector<std::string>{"uColour"});
  try {
    p.requireUniforms({"uViewProjection", "uColour", "uDistanse"});
    ADD_FAILURE() << "a misspelt uniform was not reported";
  } catch (const og::InternalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shaders/render/solid.vert shaders/render/solid.frag"), std::string::npos) << what;
    EXPECT_NE(what.find("uColour, uDistanse"), std::string::npos) << what;
  }
  // Locations come from the table read at link time; a missing name is -1 and sets nothing.
  EXPECT_EQ(p.location("uColor"), glGetUniformLocation(p.id(), "uColor"));
  EXPECT_EQ(p.location("uColour"), -1);
  p.set("uColour", glm::vec4(1.0f));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}
