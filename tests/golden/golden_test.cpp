// Golden-image tier: small renders of fixed scenes compared with tests/golden/<case>.png under
// per-case tolerances. On failure the actual image and an amplified difference are written to
// the test output directory. Deliberate changes: `og_golden_tests --update-golden` (or the
// `update-golden` build target) rewrites the PNGs and tests/golden/RENDERER.txt, the GL
// renderer and Mesa version they were made with.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Time.hpp"
#include "data/Elevation.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"
#include "support/ImageCompare.hpp"

using namespace og;
namespace fs = std::filesystem;

bool gUpdateGolden = false;

namespace {

struct GoldenCase {
  const char* name;
  geo::CameraPose pose;
  const char* time;         // UTC, or nullptr to use the angles
  double sunElevationDeg;
  double sunAzimuthDeg;
  int width;
  int height;
  test::Tolerance tolerance;
};

geo::CameraPose pose(double lat, double lon, double h, double heading, double pitch, double fov = 45) {
  geo::CameraPose p;
  p.position = {lat, lon, h};
  p.headingDeg = heading;
  p.pitchDeg = pitch;
  p.verticalFovDeg = fov;
  return p;
}

// Tolerances: llvmpipe is deterministic run to run, but LLVM/Mesa updates move transcendental
// functions by an ulp or two, which the tone curve can turn into 1-2 levels at edges.
const GoldenCase kCases[] = {
    {"orbit_atlantic", pose(10, -30, 2.0e7, 0, -90), "2024-06-20T15:00:00Z", 0, 0, 128, 128,
     {6, 0.3, 2, 0.01}},
    {"limb_400km", pose(20, -40, 4.0e5, 90, -15), nullptr, 20, 250, 160, 96, {6, 0.3, 2, 0.01}},
    {"gibraltar_300km", pose(36, -5.5, 3.0e5, 0, -90, 30), nullptr, 45, 160, 128, 128,
     {6, 0.3, 2, 0.01}},
    {"sea_2m_low_sun", pose(0, -140, 2.0, 270, 0, 60), nullptr, 8, 270, 160, 96,
     {8, 0.5, 2, 0.02}},
    {"north_pole_down", pose(90, 0, 3.0e6, 0, -90, 60), nullptr, 15, 100, 96, 96,
     {6, 0.3, 2, 0.01}},
    // Terrain: a coast (land, shallows and sea side by side) and mountains against the sky.
    {"terrain_coast_30km", pose(35.6, -5.6, 3.0e4, 0, -30, 60), nullptr, 45, 160, 160, 96,
     {6, 0.3, 2, 0.01}},
    {"terrain_mountain_15km", pose(27.3, 86.9, 1.5e4, 10, -6), nullptr, 25, 100, 160, 96,
     {6, 0.3, 2, 0.01}},
};

// Keeps CTest's test names readable (gtest would print the struct's bytes).
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

std::string rendererLine(const gl::Context& ctx) {
  return ctx.info().renderer + " | " + ctx.info().version;
}

fs::path goldenDir() { return fs::path(OG_TEST_DATA_DIR) / "golden"; }

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesReferenceImage) {
  const GoldenCase& c = GetParam();
  auto ctx = gl::createHeadlessContext();
  render::GlobeRenderer renderer(data::defaultElevation());
  render::FrameInput f;
  f.camera = c.pose;
  f.width = c.width;
  f.height = c.height;
  f.sunDirectionEcef =
      c.time ? geo::sunEphemeris(*UtcTime::parseIso8601(c.time)).directionEcef
             : geo::sunDirectionFromHorizontal(c.pose.position, c.sunElevationDeg, c.sunAzimuthDeg);
  renderer.render(f);
  const io::ImageRgba8 actual = renderer.display();
  const fs::path golden = goldenDir() / (std::string(c.name) + ".png");

  if (gUpdateGolden) {
    io::writePng(golden, actual);
    std::ofstream(goldenDir() / "RENDERER.txt") << rendererLine(*ctx) << "\n";
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing: run og_golden_tests --update-golden";
  std::ifstream made(goldenDir() / "RENDERER.txt");
  std::string madeWith;
  std::getline(made, madeWith);
  if (madeWith != rendererLine(*ctx))
    std::cerr << "note: goldens were made with '" << madeWith << "', this is '"
              << rendererLine(*ctx) << "'\n";

  const io::ImageRgba8 expected = io::readPng(golden);
  ASSERT_EQ(expected.width, actual.width);
  ASSERT_EQ(expected.height, actual.height);
  const test::Comparison cmp = test::compareRgb(actual, expected, c.tolerance.bound);
  if (!cmp.within(c.tolerance)) {
    const fs::path out(OG_TEST_OUT_DIR);
    io::writePng(out / (std::string(c.name) + ".actual.png"), actual);
    io::writePng(out / (std::string(c.name) + ".diff.png"), cmp.diff);
    ADD_FAILURE() << c.name << ": " << cmp.describe() << " exceeds tolerance (max "
                  << c.tolerance.maxDiff << ", mean " << c.tolerance.meanDiff << ", share "
                  << c.tolerance.maxShareOver << " over " << c.tolerance.bound
                  << "); wrote " << (out / c.name).string() << ".actual.png and .diff.png";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden, ::testing::ValuesIn(kCases),
                         [](const auto& param) { return std::string(param.param.name); });

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--update-golden") gUpdateGolden = true;
  return RUN_ALL_TESTS();
}
