// CLI tier: `oceanglobe info` on real and test-made files, and `render` refusing bad data layers
// before it renders.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/DataFixtures.hpp"
#include "support/RunBinary.hpp"

namespace fs = std::filesystem;

namespace {

using Result = og::test::RunResult;

fs::path scratch() { return og::test::scratchDir("cli_info"); }

Result run(const std::string& args) { return og::test::runOceanglobe(args, "cli_info"); }

std::size_t lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += (c == '\n');
  return n;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

const char* kNavy = "/usr/share/ferret-vis/data/monthly_navy_winds.cdf";
const char* kEtopo5 = "/usr/share/ferret-vis/data/etopo5.cdf";

}  // namespace

TEST(CliInfo, Era5StyleNetcdfTextAndJson) {
  const fs::path dir = scratch();
  const fs::path file = dir / "era5.nc";
  og::test::writeEra5Wind(file);
  Result r = run("info " + file.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "wind: u = u10, v = v10")) << r.out;
  EXPECT_TRUE(contains(r.out, "12 x 7 cells")) << r.out;
  EXPECT_TRUE(contains(r.out, "3 steps on 'valid_time': 2024-06-20T00:00:00Z .. 2024-06-20T12:00:00Z"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "3 of 252 values missing")) << r.out;

  r = run("info --json " + file.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kind"], "wind");
  EXPECT_EQ(j["grid"]["width"], 12);
  EXPECT_EQ(j["grid"]["height"], 7);
  EXPECT_DOUBLE_EQ(j["grid"]["lat_first_deg"].get<double>(), -90.0);
  EXPECT_EQ(j["grid"]["wraps_longitude"], true);
  EXPECT_EQ(j["time"]["steps"], 3);
  EXPECT_EQ(j["time"]["values"][2], "2024-06-20T12:00:00Z");
  EXPECT_EQ(j["variables"][0]["name"], "u10");
  EXPECT_EQ(j["variables"][1]["role"], "v");
  EXPECT_NEAR(j["variables"][0]["max"].get<double>(), og::test::fixtureU(90.0, 330.0, 2), 2e-3);
}

TEST(CliInfo, GfsStyleGrib2AndNamedVariables) {
  const fs::path dir = scratch();
  const fs::path file = dir / "gfs.grib2";
  og::test::writeGfsWind(file);
  Result r = run("info --json " + file.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "GRIB2");
  EXPECT_EQ(j["variables"][0]["name"], "10u");
  EXPECT_EQ(j["time"]["steps"], 2);
  r = run("info " + file.string() + ":10v");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "field       10v")) << r.out;
  r = run("info " + file.string() + ":10v,10x");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_TRUE(contains(r.err, file.string() + ": no variable '10x'")) << r.err;
}

TEST(CliInfo, FerretDatasets) {
  if (!fs::exists(kNavy) || !fs::exists(kEtopo5)) GTEST_SKIP() << "ferret-datasets not installed";
  const fs::path dir = scratch();
  Result r = run(std::string("info ") + kNavy);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "wind: u = UWND, v = VWND")) << r.out;
  EXPECT_TRUE(contains(r.out, "144 x 73 cells, 2.5 x 2.5 deg, global in longitude")) << r.out;
  EXPECT_TRUE(contains(r.out, "132 steps on 'TIME'")) << r.out;
  r = run(std::string("info --json ") + kEtopo5);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["variables"][0]["name"], "ROSE");
  EXPECT_EQ(j["grid"]["width"], 4320);
  EXPECT_LT(j["variables"][0]["min"].get<double>(), -10000.0);
}

TEST(CliInfo, BadFilesExit2WithOneLine) {
  const fs::path dir = scratch();
  const fs::path corpus = fs::path(OG_TEST_DATA_DIR) / "data" / "corpus";
  for (const char* name : {"bad_garbage.grib2", "bad_truncated_classic.nc", "bad_nonmonotonic.nc",
                           "bad_huge_dims.nc", "bad_all_fill.nc"}) {
    SCOPED_TRACE(name);
    const Result r = run("info " + (corpus / name).string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_TRUE(contains(r.err, (corpus / name).string() + ": ")) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
}

TEST(CliInfo, RenderRefusesBadLayersBeforeRendering) {
  const fs::path dir = scratch();
  const fs::path corpus = fs::path(OG_TEST_DATA_DIR) / "data" / "corpus";
  const std::string base = "render --lat 10 --lon -30 --alt 20000000 --width 32 --height 32 -o " +
                           (dir / "out.png").string();
  for (const std::string& layer :
       {"--wind-layer " + (corpus / "bad_garbage.grib2").string(),
        "--wind-layer " + (corpus / "good_small.nc").string() + ":u,nope",
        "--elevation-layer " + (corpus / "bad_nonmonotonic.nc").string(),
        "--elevation-layer " + (dir / "absent.nc").string()}) {
    SCOPED_TRACE(layer);
    const Result r = run(base + " " + layer);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
  }
}

TEST(CliInfo, RenderWithGoodLayers) {
  const fs::path dir = scratch();
  const fs::path era5 = dir / "era5.nc";
  og::test::writeEra5Wind(era5);
  std::string args = "render --lat 10 --lon -30 --alt 20000000 --width 32 --height 32 --time "
                     "2024-06-20T03:00Z --wind-layer " +
                     era5.string() + " -o " + (dir / "out.png").string();
  if (fs::exists(kEtopo5)) args += std::string(" --elevation-layer ") + kEtopo5 + ":ROSE";
  const Result r = run(args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.png"));
}
