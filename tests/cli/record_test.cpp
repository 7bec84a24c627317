// CLI tier: `oceanglobe record` end to end: MP4 through ffprobe, image sequences, --frames,
// --resume after SIGTERM, determinism, bad path files.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "io/Image.hpp"
#include "support/RunBinary.hpp"

namespace fs = std::filesystem;

namespace {

using og::test::RunResult;
using og::test::slurp;

fs::path scratch() { return og::test::scratchDir("record"); }

RunResult runCommand(const std::string& cmd, const std::string& tag) {
  return og::test::runCommand(cmd, "record", tag);
}

RunResult run(const std::string& args, const std::string& tag = "") {
  return og::test::runOceanglobe(args, "record", tag);
}

// A short path: 1 s at 8 fps = 9 frames, orbit to 1 km.
fs::path writePath(const fs::path& dir) {
  const fs::path p = dir / "short.toml";
  std::ofstream(p) << "[scene]\nsun_elevation_deg = 10\nsun_azimuth_deg = 80\nwidth = 64\nheight = 36\n"
                      "[video]\nfps = 8\n"
                      "[[keyframe]]\nlatitude_deg = 38\nlongitude_deg = -15\nheight_m = 4e5\n"
                      "heading_deg = 70\npitch_deg = -60\n"
                      "[[keyframe]]\nlatitude_deg = 38.3\nlongitude_deg = -12\nheight_m = 1000\n"
                      "pitch_deg = -5\ntime_s = 1\n";
  return p;
}

std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

bool haveFfprobe() { return std::system("ffprobe -version >/dev/null 2>&1") == 0; }

}  // namespace

TEST(Record, Mp4HasTheExpectedFramesRateAndSize) {
  if (!haveFfprobe()) GTEST_SKIP() << "ffprobe not installed (scripts/install-deps.sh installs ffmpeg)";
  const fs::path dir = scratch();
  const fs::path path = writePath(dir);
  RunResult r = run("record " + path.string() + " -o " + (dir / "a.mp4").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(filesIn(dir), (std::set<std::string>{"short.toml", "a.mp4"})) << "temporary files left";
  r = runCommand("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                 "stream=codec_name,width,height,pix_fmt,r_frame_rate,nb_read_frames -of "
                 "default=noprint_wrappers=1 " + (dir / "a.mp4").string(), "probe");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("codec_name=h264"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("width=64"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("height=36"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pix_fmt=yuv420p"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("r_frame_rate=8/1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nb_read_frames=9"), std::string::npos) << r.out;

  // --fps overrides the path file; --frames takes a sub-range.
  r = run("record " + path.string() + " --fps 12 --frames 2:7 --width 80 --height 48 -o " +
          (dir / "b.mp4").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runCommand("ffprobe -v error -count_frames -show_entries stream=width,r_frame_rate,nb_read_frames "
                 "-of default=noprint_wrappers=1 " + (dir / "b.mp4").string(), "probe2");
  EXPECT_NE(r.out.find("r_frame_rate=12/1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("width=80"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nb_read_frames=5"), std::string::npos) << r.out;
}

TEST(Record, FramesAreTheSameAloneOrInSequence) {
  const fs::path dir = scratch();
  const fs::path path = writePath(dir);
  fs::create_directories(dir / "all");
  fs::create_directories(dir / "part");
  RunResult r = run("record " + path.string() + " -o " + (dir / "all" / "f_%03d.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::set<std::string> expected;
  for (int i = 0; i <= 8; ++i) expected.insert("f_00" + std::to_string(i) + ".png");
  EXPECT_EQ(filesIn(dir / "all"), expected);
  // A sub-range, as one chunk of a split render: frames 5 and 6 only, bit-identical.
  r = run("record " + path.string() + " --frames 5:7 -o " + (dir / "part" / "f_%03d.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(filesIn(dir / "part"), (std::set<std::string>{"f_005.png", "f_006.png"}));
  for (const char* name : {"f_005.png", "f_006.png"})
    EXPECT_EQ(slurp(dir / "part" / name), slurp(dir / "all" / name)) << name;
  // The flight moves: first frame (orbit) differs from the last (1 km).
  EXPECT_NE(slurp(dir / "all" / "f_000.png"), slurp(dir / "all" / "f_008.png"));
  // EXR sequences too.
  r = run("record " + path.string() + " --frames 8: -o " + (dir / "part" / "e_%d.exr").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const og::io::ImageRgbaF exr = og::io::readExr(dir / "part" / "e_8.exr");
  EXPECT_EQ(exr.width, 64);
}

TEST(Record, KilledRunResumesToTheSameFrames) {
  const fs::path dir = scratch();
  const fs::path path = dir / "long.toml";
  // 4 s at 10 fps = 41 frames of 96x54: long enough to be stopped part-way.
  std::ofstream(path) << "[scene]\nwidth = 96\nheight = 54\n[video]\nfps = 10\n"
                         "[[keyframe]]\nlatitude_deg = 20\nlongitude_deg = -30\nheight_m = 2e6\n"
                         "[[keyframe]]\nlongitude_deg = -20\nheight_m = 1e4\npitch_deg = -30\ntime_s = 4\n";
  fs::create_directories(dir / "ref");
  fs::create_directories(dir / "cut");
  ASSERT_EQ(run("record " + path.string() + " -o " + (dir / "ref" / "f_%04d.png").string()).exitCode, 0);

  // Start a render, SIGTERM it once a few frames exist, check no partial frame is visible.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string out = (dir / "cut" / "f_%04d.png").string();
    const std::string log = (dir / "cut.log").string();
    std::freopen(log.c_str(), "w", stderr);
    ::execl(OG_BINARY, OG_BINARY, "record", path.c_str(), "-o", out.c_str(), static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (filesIn(dir / "cut").size() < 5 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of stopping cleanly";
  const std::size_t partial = filesIn(dir / "cut").size();
  if (WEXITSTATUS(status) == 0) {
    GTEST_SKIP() << "the render finished before SIGTERM arrived";
  }
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir / "cut.log");
  EXPECT_LT(partial, 41u);
  // Only complete frames: every file is a readable PNG with a final name.
  for (const auto& name : filesIn(dir / "cut")) {
    EXPECT_EQ(name.rfind("f_", 0), 0u) << "temporary file left: " << name;
    EXPECT_EQ(og::io::readPng(dir / "cut" / name).width, 96) << name;
  }

  const RunResult r = run("record " + path.string() + " --resume -o " + (dir / "cut" / "f_%04d.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(filesIn(dir / "cut"), filesIn(dir / "ref"));
  for (const auto& name : filesIn(dir / "ref"))
    EXPECT_EQ(slurp(dir / "cut" / name), slurp(dir / "ref" / name)) << name;
}

TEST(Record, InterruptedMp4IsClosedAndPlayable) {
  if (!haveFfprobe()) GTEST_SKIP() << "ffprobe not installed";
  const fs::path dir = scratch();
  const fs::path path = dir / "long.toml";
  std::ofstream(path) << "[scene]\nwidth = 96\nheight = 54\n[video]\nfps = 10\n"
                         "[[keyframe]]\nlatitude_deg = 20\nlongitude_deg = -30\nheight_m = 2e6\n"
                         "[[keyframe]]\nheight_m = 1e4\ntime_s = 600\n";  // 6001 frames, ~20 s
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  const std::string out = (dir / "a.mp4").string();
  if (pid == 0) {
    std::freopen((dir / "log").c_str(), "w", stderr);
    ::execl(OG_BINARY, OG_BINARY, "record", path.c_str(), "-o", out.c_str(), static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  // Interrupt once the first fragment is out: the temporary MP4 has grown past its header
  // (a fixed delay is too short on a busy machine, where start-up alone can take seconds).
  auto fragmentWritten = [&] {
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      std::error_code ec;
      if (name.rfind(".a", 0) == 0 && name.find(".tmp") != std::string::npos && fs::file_size(e.path(), ec) > 4096)
        return true;
    }
    return false;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fragmentWritten() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir / "log");
  ASSERT_TRUE(fs::exists(out)) << slurp(dir / "log");
  const RunResult r = runCommand("ffprobe -v error -count_frames -show_entries stream=nb_read_frames "
                                 "-of default=noprint_wrappers=1 " + out, "probe");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto at = r.out.find("nb_read_frames=");
  ASSERT_NE(at, std::string::npos) << r.out;
  const int frames = std::atoi(r.out.c_str() + at + 15);
  EXPECT_GT(frames, 0);
  EXPECT_LT(frames, 6001);
}

TEST(Record, BadInputExitsTwoWithFileAndLine) {
  const fs::path dir = scratch();
  const fs::path paths = fs::path(OG_TEST_DATA_DIR) / "data" / "paths";
  const fs::path good = paths / "good.toml";
  const std::pair<std::string, std::string> cases[] = {
      {"record " + (paths / "out_of_order.toml").string() + " -o " + (dir / "a.mp4").string(),
       "out_of_order.toml:11: keyframe 3: keyframes out of order"},
      {"record " + (paths / "unknown_key.toml").string() + " -o " + (dir / "a.mp4").string(),
       "unknown_key.toml:5: unknown key 'altitude_m'"},
      {"record " + (paths / "too_low.toml").string() + " -o " + (dir / "a.mp4").string(),
       "too_low.toml:8:"},
      {"record " + (paths / "non_finite.toml").string() + " -o " + (dir / "a.mp4").string(),
       "non_finite.toml:4:"},
      {"record " + (dir / "none.toml").string() + " -o " + (dir / "a.mp4").string(), "none.toml"},
      {"record " + good.string() + " -o " + (dir / "a.png").string(), "frame-number pattern"},
      {"record " + good.string() + " -o " + (dir / "a_%d_%d.png").string(), "exactly one"},
      {"record " + good.string() + " -o " + (dir / "a.avi").string(), "unsupported output"},
      {"record " + good.string() + " --resume -o " + (dir / "a.mp4").string(), "--resume"},
      {"record " + good.string() + " --width 63 -o " + (dir / "a.mp4").string(), "even"},
      {"record " + good.string() + " --frames 9999:10000 -o " + (dir / "f%d.png").string(), "--frames"},
      {"record " + good.string() + " --frames 5:2 -o " + (dir / "f%d.png").string(), "empty range"},
      {"record " + good.string() + " --frames x -o " + (dir / "f%d.png").string(), "--frames"},
      {"record " + good.string() + " --lat 3 -o " + (dir / "a.mp4").string(), "--lat"},
      {"record " + good.string() + " -o " + (dir / "missing" / "a.mp4").string(), "does not exist"},
      {"record " + good.string() + " --crf 60 -o " + (dir / "a.mp4").string(), "--crf"},
      {"record " + good.string() + " --samples 3 -o " + (dir / "a.mp4").string(), "--samples"},
  };
  for (const auto& [args, needle] : cases) {
    const RunResult r = run(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "a failed run left a file behind";
}

// The shipped camera paths stay valid: they parse, and --count-frames gives their length.
TEST(Record, ShippedPathsParse) {
  const fs::path source = OG_SOURCE_DIR;
  for (const auto& [file, frames] : {std::pair{"config/flythrough.toml", 601},
                                     std::pair{"config/himalaya.toml", 601},
                                     std::pair{"config/gibraltar_tour.kml", 691}}) {
    const RunResult r = run("record " + (source / file).string() + " --count-frames", "count");
    ASSERT_EQ(r.exitCode, 0) << file << ": " << r.err;
    EXPECT_NE(r.out.find(std::to_string(frames)), std::string::npos) << file << ": " << r.out;
  }
}

// `bench --record --breakdown`: where a recording's time goes, pass by pass, in bands of the
// camera's height (the globe's sea from 20 km up, the projected grid's below): the short path
// flies from 400 km to 1 km, so both bands have frames and their own passes.
TEST(Record, BenchBreakdownByHeight) {
  const fs::path dir = scratch();
  const fs::path path = writePath(dir);
  const RunResult r = run("bench --record " + path.string() + " --size 64x36 --frames 9 --breakdown --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::size_t high = r.out.find("\"from 20 km up\""), low = r.out.find("\"1 to 20 km\"");
  ASSERT_NE(high, std::string::npos) << r.out;
  ASSERT_NE(low, std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\"under 1 km\""), std::string::npos) << r.out;  // the path ends at 1 km
  // Bands print in key order ("1 to 20 km" first): the grid's pass ("ocean", on every
  // driver's path) in its band only.
  const std::string lowBand = r.out.substr(low, high - low), highBand = r.out.substr(high);
  EXPECT_NE(lowBand.find("\"ocean\":"), std::string::npos) << lowBand;
  EXPECT_EQ(highBand.find("\"ocean\":"), std::string::npos) << highBand;
  EXPECT_NE(highBand.find("\"globe\":"), std::string::npos) << highBand;
  // And frame by frame, in the order rendered: heights falling from 400 km.
  const nlohmann::json report = nlohmann::json::parse(r.out);
  const nlohmann::json& frames = report.at("record").at(0).at("passes_by_frame");
  ASSERT_GE(frames.size(), 9u) << r.out;
  EXPECT_DOUBLE_EQ(frames.front().at("height_m").get<double>(), 400000.0);
  for (std::size_t i = 1; i < frames.size(); ++i)
    EXPECT_LT(frames[i].at("height_m").get<double>(), frames[i - 1].at("height_m").get<double>()) << i;
  EXPECT_TRUE(frames.back().at("passes_ms").contains("ocean")) << frames.back();
}

// `bench --record` times the recording `record` makes: every frame of the path unless --frames
// asks for a sample (the short path at 40 frames/s: 41 frames, twice the sample it took before
// by default; a sample of 3 takes every 13th).
TEST(Record, BenchRecordsEveryFrameUnlessAskedForASample) {
  const fs::path dir = scratch();
  const fs::path path = writePath(dir);
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t at = text.find("fps = 8");
  ASSERT_NE(at, std::string::npos);
  std::ofstream(path) << text.replace(at, 7, "fps = 40");
  const RunResult all = run("bench --record " + path.string() + " --size 64x36 --samples 1 --json");
  ASSERT_EQ(all.exitCode, 0) << all.err;
  EXPECT_EQ(nlohmann::json::parse(all.out).at("record").at(0).at("frames").get<int>(), 41) << all.out;
  const RunResult sample = run("bench --record " + path.string() + " --size 64x36 --samples 1 --frames 3");
  ASSERT_EQ(sample.exitCode, 0) << sample.err;
  EXPECT_NE(sample.out.find("every 13. of 41 frames"), std::string::npos) << sample.out;
  EXPECT_NE(sample.out.find("      4 "), std::string::npos) << sample.out;  // frames 0, 13, 26, 39
}
