// CLI tier: runs the built oceanglobe binary end to end and checks exit codes, messages and
// the files it leaves behind.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/Image.hpp"
#include "support/ImageCompare.hpp"
#include "support/RunBinary.hpp"

namespace fs = std::filesystem;

namespace {

using og::test::RunResult;
using og::test::slurp;

fs::path scratch() { return og::test::scratchDir("cli"); }

RunResult run(const std::string& args) { return og::test::runOceanglobe(args, "cli"); }

std::size_t lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += (c == '\n');
  return n;
}

std::size_t filesIn(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

const std::string kGlobe = "render --lat 10 --lon -30 --alt 20000000 --width 256 --height 256";

}  // namespace

TEST(Cli, VersionAndHelp) {
  RunResult r = run("--version");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("oceanglobe 0."), std::string::npos) << r.out;
  for (const char* cmd : {"--help", "render --help", "bench --help"}) {
    r = run(cmd);
    EXPECT_EQ(r.exitCode, 0) << cmd;
    EXPECT_NE(r.out.find("--"), std::string::npos) << cmd;
  }
}

TEST(Cli, RendersGlobePngWithSpaceInTheCorners) {
  const fs::path dir = scratch();
  const RunResult r = run(kGlobe + " -o " + (dir / "a.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const og::io::ImageRgba8 img = og::io::readPng(dir / "a.png");
  ASSERT_EQ(img.width, 256);
  ASSERT_EQ(img.height, 256);
  auto at = [&](int x, int y) { return &img.pixels[4 * static_cast<std::size_t>(y * 256 + x)]; };
  int centre = 0;
  for (int c = 0; c < 3; ++c) centre += at(128, 128)[c];
  EXPECT_GT(centre, 30);
  for (auto [x, y] : {std::pair{0, 0}, {255, 0}, {0, 255}, {255, 255}, {5, 128}})
    EXPECT_EQ(at(x, y)[0] + at(x, y)[1] + at(x, y)[2], 0) << x << "," << y;
  EXPECT_EQ(filesIn(dir), 1u) << "temporary files left behind";
}

TEST(Cli, RendersFiniteLinearExr) {
  const fs::path dir = scratch();
  for (const char* type : {"half", "float"}) {
    const RunResult r = run(kGlobe + " --exr-type " + type + " -o " + (dir / "a.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const og::io::ImageRgbaF img = og::io::readExr(dir / "a.exr");
    ASSERT_EQ(img.width, 256);
    for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v));
    const float* centre = &img.pixels[4 * (128 * 256 + 128)];
    EXPECT_GT(centre[0] + centre[1] + centre[2], 0.0f);
    EXPECT_EQ(img.pixels[0] + img.pixels[1] + img.pixels[2], 0.0f);  // corner: black space
  }
}

TEST(Cli, EglAndOsMesaMatch) {
  const fs::path dir = scratch();
  ASSERT_EQ(run(kGlobe + " --gl egl -o " + (dir / "egl.png").string()).exitCode, 0);
  ASSERT_EQ(run(kGlobe + " --gl osmesa -o " + (dir / "osmesa.png").string()).exitCode, 0);
  const auto c = og::test::compareRgb(og::io::readPng(dir / "egl.png"),
                                      og::io::readPng(dir / "osmesa.png"), 1);
  EXPECT_LE(c.maxDiff, 1) << c.describe();
}

TEST(Cli, BadInputExitsTwoWithOneLineAndNoFile) {
  const fs::path dir = scratch();
  const std::string out = (dir / "x.png").string();
  const std::pair<std::string, std::string> cases[] = {
      {"render --lat 95 -o " + out, "latitude"},
      {"render --width 0 -o " + out, "size"},
      {"render --height -3 -o " + out, "size"},
      {"render --pitch -120 -o " + out, "pitch"},
      {"render --fov 0 -o " + out, "field of view"},
      {"render --alt nan -o " + out, "height"},
      {"render --exposure -1 -o " + out, "exposure"},
      {"render --time 2024-13-01T00:00Z -o " + out, "--time"},
      {"render --sun-elevation 100 -o " + out, "Sun elevation"},
      {"render --gl vulkan -o " + out, "backend"},
      {"render --wind 5,abc -o " + out, "--wind"},
      {"render --wind 80 -o " + out, "wind speed"},
      {"render --ocean fancy -o " + out, "ocean model"},
      {"render --samples 3 -o " + out, "--samples: expected auto, 1, 2, 4 or 8, got '3'"},
      {"render --samples 0 -o " + out, "--samples"},
      {"render --lat abc -o " + out, "--lat"},
      {"render --no-such-flag -o " + out, "no-such-flag"},
      {"render", "--output"},
      {"render -o " + (dir / "missing" / "x.png").string(), "does not exist"},
      {"render -o " + (dir / "x.jpg").string(), "unsupported output format"},
      {"render -o " + dir.string(), ""},
      {"render --config " + (dir / "none.toml").string() + " -o " + out, "none.toml"},
      {"frobnicate", ""},
      {"bench --size 0x7", "--size"},
      {"bench --samples 3", "--samples"},
  };
  for (const auto& [args, needle] : cases) {
    const RunResult r = run(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1u) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(filesIn(dir), 0u) << "a failed run left a file behind";
}

TEST(Cli, ConfigFileIsReadAndFlagsOverrideIt) {
  const fs::path dir = scratch();
  std::ofstream(dir / "scene.toml") << "[camera]\nlatitude_deg = 10\nlongitude_deg = -30\n"
                                       "height_m = 2.0e7\n[image]\nwidth = 96\nheight = 64\n"
                                       "samples = 2\n"
                                       "[sun]\nelevation_deg = 40\nazimuth_deg = 120\n";
  RunResult r = run("render --config " + (dir / "scene.toml").string() + " --width 80 -o " +
                    (dir / "a.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto img = og::io::readPng(dir / "a.png");
  EXPECT_EQ(img.width, 80);   // flag wins
  EXPECT_EQ(img.height, 64);  // from the file

  std::ofstream(dir / "bad.toml") << "[camera]\nlatitude_deg = 10\nlatitude = 3\n";
  r = run("render --config " + (dir / "bad.toml").string() + " -o " + (dir / "b.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("bad.toml:3: unknown key 'latitude'"), std::string::npos) << r.err;

  std::ofstream(dir / "type.toml") << "[image]\nwidth = \"wide\"\n";
  r = run("render --config " + (dir / "type.toml").string() + " -o " + (dir / "b.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("type.toml:2: 'width' must be an integer"), std::string::npos) << r.err;

  std::ofstream(dir / "samples.toml") << "[image]\nwidth = 64\nsamples = 3\n";
  r = run("render --config " + (dir / "samples.toml").string() + " -o " + (dir / "b.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("samples.toml:3: 'samples' must be \"auto\", 1, 2, 4 or 8"), std::string::npos) << r.err;

  std::ofstream(dir / "syntax.toml") << "[camera\nlatitude_deg = 1\n";
  r = run("render --config " + (dir / "syntax.toml").string() + " -o " + (dir / "b.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("syntax.toml:1"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "b.png"));
}

TEST(Cli, FailedRunLeavesExistingOutputUntouched) {
  const fs::path dir = scratch();
  const fs::path out = dir / "keep.png";
  ASSERT_EQ(run("render --width 32 --height 32 -o " + out.string()).exitCode, 0);
  const std::string before = slurp(out);
  EXPECT_EQ(run("render --lat 95 -o " + out.string()).exitCode, 2);
  EXPECT_EQ(slurp(out), before);
  EXPECT_EQ(filesIn(dir), 1u);
}

TEST(Cli, BenchPrintsFrameTimes) {
  const RunResult r = run("bench --frames 1 --size 64x48 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"median_ms\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("orbit-20000km"), std::string::npos) << r.out;
}
