// The driver profile (gl/DriverProfile.hpp): one list of software renderers, one set of choices
// per driver, built when the context is made and read everywhere else.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <string>

#include "gl/Context.hpp"
#include "gl/DriverProfile.hpp"
#include "gl/Objects.hpp"

using og::gl::makeDriverProfile;

TEST(DriverProfile, SoftwareRenderersGetTheCheapPaths) {
  for (const char* name : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Mesa X11 swrast",
                           "zink (lavapipe)"}) {
    const og::gl::DriverProfile p = makeDriverProfile(name, 16.0f);
    EXPECT_TRUE(p.software) << name;
    EXPECT_EQ(p.autoSamples, 1) << name;
    EXPECT_EQ(p.maxAnisotropy, 1.0f) << name;
    EXPECT_FALSE(p.timestampsTimeWork) << name;
    EXPECT_TRUE(p.multisampleShadesEveryBlock) << name;
    EXPECT_TRUE(p.seaByVisibility) << name;
  }
  const og::gl::DriverProfile gpu = makeDriverProfile("NVIDIA GeForce RTX 4090/PCIe/SSE2", 16.0f);
  EXPECT_FALSE(gpu.software);
  EXPECT_EQ(gpu.autoSamples, 4);
  EXPECT_EQ(gpu.maxAnisotropy, 16.0f);
  EXPECT_TRUE(gpu.timestampsTimeWork);
  EXPECT_FALSE(gpu.multisampleShadesEveryBlock);
  EXPECT_FALSE(gpu.seaByVisibility);  // (until measured on one)
  EXPECT_EQ(makeDriverProfile("AMD Radeon", 0.0f).maxAnisotropy, 1.0f);  // no anisotropy offered
}

TEST(DriverProfile, TheContextCarriesItsProfile) {
  auto context = og::gl::createHeadlessContext();
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const og::gl::DriverProfile& p = og::gl::driverProfile();
  EXPECT_EQ(&p, &context->info().profile);
  EXPECT_EQ(p.software, og::gl::isSoftwareRendererName(renderer)) << renderer;
  EXPECT_EQ(og::gl::isSoftwareRenderer(), p.software);
  EXPECT_GE(p.maxAnisotropy, 1.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));  // the anisotropy query left no error
}
