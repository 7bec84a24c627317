// CLI tier: winds that follow the clock in `record` (per-frame wind time, time_lapse) and the
// `--aov` channels of EXR outputs (whitecap coverage, view distance), read back from the files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "io/Image.hpp"
#include "support/DataFixtures.hpp"
#include "support/RunBinary.hpp"

namespace fs = std::filesystem;

namespace {

og::test::RunResult run(const std::string& args, const std::string& tag = "") {
  return og::test::runOceanglobe(args, "seastate_time", tag);
}

double mean(const std::vector<float>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

/// A global wind layer blowing east at speeds[t] m/s at `hours`[t] after 2024-06-20T00:00Z.
fs::path writeWindSteps(const fs::path& file, const std::vector<double>& hours, const std::vector<double>& speeds) {
  og::test::TimedWind wind;
  wind.times = hours;
  wind.units = "hours since 2024-06-20 00:00:00";
  wind.calendar = "gregorian";
  wind.eastMs = speeds;
  wind.gridStepDeg = 10.0;
  return og::test::writeTimedWind(file, wind);
}

/// A still camera 200 m above the Pacific looking straight down for 2 s of path, 1 frame/s.
fs::path writeStillPath(const fs::path& dir, const fs::path& layer, double timeLapse) {
  const fs::path p = dir / "still.toml";
  std::ofstream(p) << "[scene]\ntime = \"2024-06-20T00:00:00Z\"\nwidth = 64\nheight = 48\n"
                   << "time_lapse = " << timeLapse << "\nwind_layers = [\"" << layer.string() << "\"]\n"
                   << "[video]\nfps = 1\n"
                   << "[[keyframe]]\nlatitude_deg = 5\nlongitude_deg = 150\nheight_m = 200\npitch_deg = -90\n"
                   << "[[keyframe]]\ntime_s = 2\n";
  return p;
}

}  // namespace

TEST(SeaStateTime, RecordedWindFollowsTheClockWithTimeLapse) {
  const fs::path dir = og::test::scratchDir("seastate_time");
  // 3 m/s at 00:00 UTC, 20 m/s from 02:00: with time_lapse 3600 frame 2 (2 s) is at 02:00.
  const fs::path layer = writeWindSteps(dir / "front.nc", {0.0, 2.0}, {3.0, 20.0});
  const fs::path path = writeStillPath(dir, layer, 3600.0);
  const auto r = run("record " + path.string() + " --aov whitecap --aov depth -o " +
                     (dir / "f_%02d.exr").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double calm = mean(og::io::readExrChannel(dir / "f_00.exr", "whitecap"));
  const double half = mean(og::io::readExrChannel(dir / "f_01.exr", "whitecap"));
  const double storm = mean(og::io::readExrChannel(dir / "f_02.exr", "whitecap"));
  std::printf("whitecap coverage at 00:00 %.4f, 01:00 %.4f, 02:00 %.4f\n", calm, half, storm);
  EXPECT_LT(calm, 0.002);          // 3 m/s: no whitecaps
  EXPECT_GT(storm, 0.02);          // 20 m/s: Monahan's ~10 %
  EXPECT_GT(half, calm);           // 11.5 m/s at 01:00: some
  EXPECT_LT(half, storm);
  // --aov needs EXR frames: an MP4 exits 2 before rendering anything.
  const auto mp4 = run("record " + path.string() + " --aov depth -o " + (dir / "v.mp4").string(), "mp4");
  EXPECT_EQ(mp4.exitCode, 2);
  EXPECT_NE(mp4.err.find("--aov needs an OpenEXR frame pattern"), std::string::npos) << mp4.err;
  EXPECT_FALSE(fs::exists(dir / "v.mp4"));
  // Real time (time_lapse 1): 2 s later the wind has not changed.
  const fs::path realTime = writeStillPath(dir, layer, 1.0);
  ASSERT_EQ(run("record " + realTime.string() + " --frames 2:3 --aov whitecap -o " +
                    (dir / "r_%02d.exr").string(), "real").exitCode, 0);
  EXPECT_LT(mean(og::io::readExrChannel(dir / "r_02.exr", "whitecap")), 0.002);
  // --time-lapse overrides the path; frame 2 alone equals frame 2 of the whole run.
  ASSERT_EQ(run("record " + realTime.string() + " --time-lapse 3600 --frames 2:3 --aov whitecap -o " +
                    (dir / "l_%02d.exr").string(), "flag").exitCode, 0);
  EXPECT_EQ(og::io::readExrChannel(dir / "l_02.exr", "whitecap"), og::io::readExrChannel(dir / "f_02.exr", "whitecap"));
}

TEST(SeaStateTime, AovChannelsWhitecapAndDepth) {
  const fs::path dir = og::test::scratchDir("seastate_time");
  const std::string view = " --lat 5 --lon 150 --alt 200 --pitch -90 --fov 40 --width 64 --height 48 "
                           "--time 2024-06-20T00:00:00Z";
  ASSERT_EQ(run("render" + view + " --wind 20 --aov whitecap --aov depth -o " + (dir / "storm.exr").string(),
                "storm").exitCode, 0);
  ASSERT_EQ(run("render" + view + " --wind 3 --aov whitecap -o " + (dir / "calm.exr").string(), "calm").exitCode, 0);
  const auto names = og::io::readExrChannelNames(dir / "storm.exr");
  for (const char* n : {"R", "G", "B", "A", "whitecap", "depth"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  const std::vector<float> storm = og::io::readExrChannel(dir / "storm.exr", "whitecap");
  EXPECT_GE(*std::min_element(storm.begin(), storm.end()), 0.0f);
  EXPECT_LE(*std::max_element(storm.begin(), storm.end()), 1.0f);
  EXPECT_GT(mean(storm), 0.02);
  EXPECT_LT(mean(og::io::readExrChannel(dir / "calm.exr", "whitecap")), 0.002);
  // Depth: metres along the ray; straight down the centre pixels see the sea ~200 m below
  // (20 m/s waves move it by a few metres), the corners further by 1/cos of their angle.
  const std::vector<float> depth = og::io::readExrChannel(dir / "storm.exr", "depth");
  const float centre = depth[24 * 64 + 32];
  EXPECT_NEAR(centre, 200.0f, 12.0f);
  EXPECT_GT(depth[0], centre * 1.1f);
  // No extra channels without --aov; --aov with a PNG output exits 2 naming the file.
  ASSERT_EQ(run("render" + view + " -o " + (dir / "plain.exr").string(), "plain").exitCode, 0);
  EXPECT_EQ(og::io::readExrChannelNames(dir / "plain.exr").size(), 4u);
  const auto png = run("render" + view + " --aov depth -o " + (dir / "x.png").string(), "png");
  EXPECT_EQ(png.exitCode, 2);
  EXPECT_NE(png.err.find("x.png: --aov needs an OpenEXR output"), std::string::npos) << png.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  const auto bad = run("render" + view + " --aov normals -o " + (dir / "y.exr").string(), "bad");
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
}

TEST(SeaStateTime, UnsupportedCalendarExitsTwoNamingFileAndAxis) {
  const fs::path dir = og::test::scratchDir("seastate_time");
  const fs::path file = dir / "lunar.nc";
  og::test::TimedWind wind;
  wind.times = {0.0, 1.0};
  wind.units = "days since 2024-01-01";
  wind.calendar = "lunar";
  wind.eastMs = wind.northMs = {5.0, 5.0};
  og::test::writeTimedWind(file, wind);
  const auto r = run("render --width 16 --height 16 --wind-layer " + file.string() + " -o " +
                     (dir / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(file.string() + ": time axis 'time' uses calendar 'lunar', which is not supported"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}
