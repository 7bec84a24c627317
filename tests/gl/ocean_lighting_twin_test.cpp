// The GPU's ocean/lighting.glsl against its C++ twin (ocean/Lighting.cpp, the same file compiled
// as C++ through core/GlslShim.hpp): shaders/ocean/lighting_probe.comp evaluates the shader at
// the inputs the CPU evaluates. Fails if the shim's built-ins differ from GLSL's (argument order,
// atan, mod, step...), if a function compiles to something else on either side, or if a uniform
// the twin sets is not the shader's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "gl/Context.hpp"
#include "gl/Probe.hpp"
#include "gl/Shader.hpp"
#include "ocean/Lighting.hpp"

using namespace og;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
// Unit direction of zenith angle z and azimuth a (degrees) about the vertical `up`.
glm::dvec3 dirAbout(const glm::dvec3& up, double zDeg, double aDeg) {
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), up));
  const glm::dvec3 north = glm::cross(up, east);
  return std::sin(zDeg * kDeg) * (std::cos(aDeg * kDeg) * east + std::sin(aDeg * kDeg) * north) +
         std::cos(zDeg * kDeg) * up;
}

// Samples over the globe (not at the poles: the shader's frame there is the same code), steep
// to grazing views, the glint's peak and flank, smooth to rough, tilted normals, foam.
std::vector<ocean::lighting::SeaSample> samples() {
  std::vector<ocean::lighting::SeaSample> out;
  const glm::dvec3 ups[] = {glm::normalize(glm::dvec3(-0.66, -0.55, 0.5)), glm::normalize(glm::dvec3(1, 0, 0.05))};
  for (const glm::dvec3& up : ups)
    for (double viewZenith : {5.0, 45.0, 80.0, 88.0})
      for (double sunZenith : {20.0, 60.0, 87.0})
        for (double sigma2 : {0.002, 0.02}) {
          ocean::lighting::SeaSample p;
          p.up = up;
          p.toSun = dirAbout(up, sunZenith, 30.0);
          p.toEye = dirAbout(up, viewZenith, 30.0 + 180.0 + (sigma2 > 0.01 ? 15.0 : 0.0));
          p.normal = glm::normalize(up + 0.04 * dirAbout(up, 90.0, 70.0));
          p.wind = dirAbout(up, 90.0, 110.0);
          p.slopeCovariance = {sigma2, 0.6 * sigma2, 0.2 * sigma2};
          p.foamCoverage = viewZenith > 60.0 ? 0.1 : 0.0;
          out.push_back(p);
        }
  return out;
}
}  // namespace

TEST(OceanLightingTwinGpu, ShaderAndCppTwinAgree) {
  auto context = gl::createHeadlessContext();
  ocean::lighting::Settings s;
  s.skyZenithRadiance = {0.04, 0.07, 0.14};
  s.skyHorizonRadiance = {0.09, 0.11, 0.14};
  s.seaColorPerSr = {0.004, 0.012, 0.025};
  s.sunVisibility = 0.8;
  const std::vector<ocean::lighting::SeaSample> in = samples();
  std::vector<glm::vec4> buffer;
  for (const auto& p : in) {
    for (const glm::dvec3& v : {p.toEye, p.normal, p.wind, p.up, p.toSun}) buffer.emplace_back(glm::vec3(v), 0.0f);
    buffer.emplace_back(glm::vec3(p.slopeCovariance), static_cast<float>(p.foamCoverage));
    buffer.emplace_back(0.0f);
    buffer.emplace_back(0.0f);
  }
  const gl::Program probe({{GL_COMPUTE_SHADER, "ocean/lighting_probe.comp"}});
  probe.requireUniforms({"uSkyZenith", "uSkyHorizon", "uSeaColor", "uLightingTerms", "uSunVisibility"});
  probe.set("uSkyZenith", glm::vec3(s.skyZenithRadiance));
  probe.set("uSkyHorizon", glm::vec3(s.skyHorizonRadiance));
  probe.set("uSeaColor", glm::vec3(s.seaColorPerSr));
  probe.set("uLightingTerms", glm::vec4(s.terms));
  probe.set("uSunVisibility", static_cast<float>(s.sunVisibility));
  ASSERT_NO_THROW(gl::runProbe(probe, buffer, static_cast<int>(in.size()), "lighting probe"));

  int lit = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const glm::dvec3 cpu = ocean::lighting::seaRadiance(s, in[i]);
    const glm::dvec3 cpuMirror = ocean::lighting::seaRadianceMirror(s, in[i], in[i].slopeCovariance);
    const glm::dvec3 gpu(buffer[8 * i + 6]), gpuMirror(buffer[8 * i + 7]);
    // Single against double precision: 1 % of the sample's brightest channel (the glint's
    // exponent amplifies float rounding near its peak), plus a floor far below the sky's 0.1.
    for (int c = 0; c < 3; ++c) {
      const double tol = 0.01 * std::max({cpu.x, cpu.y, cpu.z}) + 2e-5;
      EXPECT_NEAR(gpu[c], cpu[c], tol) << "sample " << i << " channel " << c;
      const double tolMirror = 0.01 * std::max({cpuMirror.x, cpuMirror.y, cpuMirror.z}) + 2e-5;
      EXPECT_NEAR(gpuMirror[c], cpuMirror[c], tolMirror) << "mirror sample " << i << " channel " << c;
    }
    if (cpu.x > 1e-3) ++lit;
  }
  EXPECT_GT(lit, static_cast<int>(in.size()) / 2);  // the comparison is of light, not of zeros
}
