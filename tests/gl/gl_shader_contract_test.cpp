// The C++/GLSL contract (gl/ShaderContract.hpp) reaches every shader, and uniforms a program
// lacks are reported when it is built, not silently ignored when set.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>
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

// Every sampler of the frame's passes takes its unit from the contract: no literal number in the
// GLSL, and no two of the frame's samplers on one unit (the passes of their own aside).
TEST(ShaderContract, EverySamplerOfTheFrameIsNamedInTheContract) {
  static const std::regex literalSampler(R"(layout\s*\(\s*binding\s*=\s*[0-9]+\s*\)\s*uniform\s+\w*sampler)");
  static const std::regex namedSampler(R"(layout\s*\(\s*binding\s*=\s*(OG_UNIT_\w+)\s*\)\s*uniform\s+\w*sampler)");
  std::set<std::string> named;
  for (const char* file : {"render/elevation.glsl", "ocean/wind.glsl", "atmosphere/model.glsl",
                           "atmosphere/skymap.glsl", "ocean/classic.frag", "ocean/patterns.glsl",
                           "terrain/shadow.glsl", "terrain/imagery.glsl", "terrain/landmask.glsl",
                           "render/tonemap.frag", "viewer/text.frag", "render/globe.frag", "ocean/water_volume.glsl",
                           "render/aerial.glsl", "render/open_sea_map.glsl"}) {
    const std::string text = og::gl::readShaderFile(file);
    EXPECT_FALSE(std::regex_search(text, literalSampler)) << file << " binds a sampler to a literal unit";
    for (auto it = std::sregex_iterator(text.begin(), text.end(), namedSampler); it != std::sregex_iterator(); ++it)
      named.insert((*it)[1].str());
  }
  std::set<std::string> defined;
  for (const std::string& d : og::gl::contractDefines()) defined.insert(d.substr(0, d.find(' ')));
  for (const std::string& n : named) EXPECT_TRUE(defined.count(n) == 1) << n << " is not in the contract";
  EXPECT_EQ(named.size(), 29u);  // the land mask, imagery, sky, patterns, open sea, caustics... all of them
  // The frame's units are distinct (tone mapping and the overlay are passes of their own).
  std::set<unsigned> units;
  for (unsigned u : {og::gl::kUnitElevation, og::gl::kUnitWind, og::gl::kUnitAtmTransmittance,
                     og::gl::kUnitAtmScattering, og::gl::kUnitAtmSingleMie, og::gl::kUnitAtmIrradiance,
                     og::gl::kUnitSkyMap, og::gl::kUnitSkyIrradiance, og::gl::kUnitBumpMap,
                     og::gl::kUnitFresnelRamp, og::gl::kUnitShadowMap,
                     og::gl::kUnitPatternDisplacement, og::gl::kUnitPatternSlopes, og::gl::kUnitImageryDay,
                     og::gl::kUnitImageryNight, og::gl::kUnitImageryLayers, og::gl::kUnitLandMask,
                     og::gl::kUnitImageryTiles, og::gl::kUnitOpenSea, og::gl::kUnitSkyRadialSums,
                     og::gl::kUnitCausticCurvature, og::gl::kUnitLandMaskFine, og::gl::kUnitSkyLow,
                     og::gl::kUnitAerialTable, og::gl::kUnitTerrainAerialTable,
                     og::gl::kUnitSkyRadialSumsLayers, og::gl::kUnitLandFraction})
    EXPECT_TRUE(units.insert(u).second) << "unit " << u << " named twice";
  // The uniform blocks too (the per-wind pattern tables).
  static const std::regex namedBlock(R"(layout\s*\(\s*std140\s*,\s*binding\s*=\s*(OG_BLOCK_\w+)\s*\)\s*uniform)");
  const std::string patterns = og::gl::readShaderFile("ocean/patterns.glsl");
  std::smatch block;
  ASSERT_TRUE(std::regex_search(patterns, block, namedBlock)) << "ocean/patterns.glsl's table block";
  EXPECT_TRUE(defined.count(block[1].str()) == 1) << block[1].str() << " is not in the contract";
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
