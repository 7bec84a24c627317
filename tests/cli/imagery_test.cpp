// `--imagery-layer` end to end: bad imagery (not an image, truncated, not georeferenced,
// absent) exits 2 with one line naming the file, before rendering; a JPEG with a world file
// renders.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/DataFixtures.hpp"
#include "support/RunBinary.hpp"

namespace fs = std::filesystem;

namespace {

fs::path scratch() { return og::test::scratchDir("cli_imagery"); }
og::test::RunResult run(const std::string& args) { return og::test::runOceanglobe(args, "cli_imagery"); }

std::size_t lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n' ? 1 : 0;
  return n + (!s.empty() && s.back() != '\n' ? 1 : 0);
}

const fs::path kJpeg = fs::path(OG_SOURCE_DIR) / "data" / "blue_marble_2048x1024.jpg";
const fs::path kWorld = fs::path(OG_SOURCE_DIR) / "data" / "blue_marble_2048x1024.jgw";

}  // namespace

TEST(CliImagery, BadImageryExits2NamingTheFile) {
  const fs::path dir = scratch();
  const fs::path garbage = dir / "garbage.tif";
  std::ofstream(garbage) << "not an image";
  const fs::path plain = dir / "plain.jpg";  // no world file: nowhere on Earth
  fs::copy_file(kJpeg, plain, fs::copy_options::overwrite_existing);
  const fs::path truncated = dir / "truncated.jpg";  // world file, but half the JPEG
  fs::copy_file(kJpeg, truncated, fs::copy_options::overwrite_existing);
  fs::resize_file(truncated, fs::file_size(kJpeg) / 3);
  fs::copy_file(kWorld, dir / "truncated.jgw", fs::copy_options::overwrite_existing);
  const std::string base = "render --lat 10 --lon 20 --alt 20000000 --width 32 --height 32 -o " +
                           (dir / "out.png").string();
  for (const fs::path& bad : {garbage, plain, truncated, dir / "absent.tif"}) {
    SCOPED_TRACE(bad.string());
    const auto r = run(base + " --imagery-layer " + bad.string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(bad.string() + ": "), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
  }
}

TEST(CliImagery, JpegWithWorldFileRenders) {
  const fs::path dir = scratch();
  fs::copy_file(kJpeg, dir / "world.jpg", fs::copy_options::overwrite_existing);
  fs::copy_file(kWorld, dir / "world.jgw", fs::copy_options::overwrite_existing);
  const auto r = run("render --lat 10 --lon 20 --alt 20000000 --width 32 --height 32 --imagery-layer " +
                     (dir / "world.jpg").string() + " -o " + (dir / "ok.png").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "ok.png"));
}

TEST(CliImagery, BadCacheBudgetsExit2NamingTheSetting) {
  const fs::path dir = scratch();
  const std::string base = "render --lat 10 --lon 20 --alt 20000000 --width 32 --height 32 -o " +
                           (dir / "cache.png").string();
  for (const char* bad : {"--imagery-cache-cpu-mib 0", "--imagery-cache-gpu-mib 70000",
                         "--imagery-cache-gpu-mib -5"}) {
    SCOPED_TRACE(bad);
    const auto r = run(base + " " + std::string(bad));
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("imagery"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cache"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "cache.png"));
  }
  // A scene file's key is checked the same way.
  const fs::path scene = dir / "cache.toml";
  std::ofstream(scene) << "[layers]\nimagery_cache_cpu_mib = 0\n";
  const auto r = run(base + " --config " + scene.string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("imagery_cache_cpu_mib"), std::string::npos) << r.err;
  // In range: renders.
  const auto ok = run(base + " --imagery-cache-cpu-mib 16 --imagery-cache-gpu-mib 16");
  EXPECT_EQ(ok.exitCode, 0) << ok.err;
}
