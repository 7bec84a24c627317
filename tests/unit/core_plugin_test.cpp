// Modules loaded when first needed (core/Plugin.hpp): a module that is not there, or is another
// build's, is an InternalError naming its file and where it was looked for (a broken
// installation, never a crash); a module that is there is loaded once and answers with the
// same object.
#include <gtest/gtest.h>

#include <string>

#include "core/Error.hpp"
#include "core/Plugin.hpp"
#include "data/GeoRasterBackend.hpp"
#include "io/VideoEncoder.hpp"

TEST(Plugin, AMissingModuleIsAnInternalErrorNamingIt) {
  try {
    (void)og::plugin::load("oceanglobe-nonexistent", "testing");
    FAIL() << "no error";
  } catch (const og::InternalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("oceanglobe-nonexistent.so"), std::string::npos) << what;
    EXPECT_NE(what.find("for testing"), std::string::npos) << what;
    EXPECT_NE(what.find("looked in "), std::string::npos) << what;
  }
}

// A module whose build token is not the program's (another build's classes may differ behind
// the same names) is refused, not called: an InternalError saying so, with both tokens.
TEST(Plugin, AModuleOfAnotherBuildIsRefused) {
  try {
    (void)og::plugin::load("oceanglobe-test-otherbuild", "testing");
    FAIL() << "no error";
  } catch (const og::InternalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("oceanglobe-test-otherbuild.so: built by another build of oceanglobe"), std::string::npos)
        << what;
  }
}

TEST(Plugin, ModulesLoadOnceFromTheBuildTree) {
  void* gdal = og::plugin::load(og::data::kGdalModule, "testing");
  ASSERT_NE(gdal, nullptr);
  EXPECT_EQ(og::plugin::load(og::data::kGdalModule, "testing"), gdal);
  void* ffmpeg = og::plugin::load(og::io::kFfmpegModule, "testing");
  ASSERT_NE(ffmpeg, nullptr);
  EXPECT_NE(ffmpeg, gdal);
}
