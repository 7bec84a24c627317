// CLI tier: the start-up report (`bench --startup`) and the derived-data cache beside the
// atmosphere's: a stale or corrupt cache file is rebuilt, never trusted or fatal.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/RunBinary.hpp"

namespace fs = std::filesystem;

namespace {

using og::test::RunResult;

RunResult run(const std::string& args, const std::string& tag = "") {
  return og::test::runOceanglobe(args, "startup", tag);
}

}  // namespace

TEST(Startup, BenchReportsEveryStageOfACachedStart) {
  const RunResult r = run("bench --startup --startup-runs 1 --size 32x18 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* key : {"\"first_frame_written_ms\"", "\"first_run_ms\"", "exec + shared libraries",
                          "GL context", "data: elevation layer", "atmosphere: cached tables",
                          "first frame (render + glFinish)", "read-back + write image",
                          "shaders: compile + link", "shaders/render/globe.frag"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " missing from\n" << r.out;
  // The second start found the atmosphere's tables cached (the first filled the cache).
  EXPECT_EQ(r.out.find("tables precomputed (cache miss)"), std::string::npos) << r.out;
}
