// CLI tier: the start-up report (`bench --startup`) and the derived-data caches beside the
// atmosphere's tables (embedded data, sky maps): a stale or corrupt cache file is rebuilt,
// never trusted or fatal, and the picture stays the same byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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

namespace {

/// The embedded-*.bin files of a cache folder, by name.
std::vector<fs::path> embeddedFiles(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind("embedded-", 0) == 0) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST(Startup, CorruptOrTruncatedDataCacheIsRebuiltAndRendersTheSame) {
  const fs::path dir = og::test::scratchDir("startup");
  const fs::path cache = dir / "cache";
  fs::create_directories(cache);
  // The atmosphere's tables from the tests' shared cache, when there: only the data and the sky
  // maps (one file then: this view's) are rebuilt.
  const fs::path shared = fs::path(OG_TEST_OUT_DIR) / "atmosphere-cache";
  if (fs::exists(shared))
    for (const auto& e : fs::directory_iterator(shared))
      if (e.path().filename().string().rfind("atmosphere-tables-", 0) == 0)
        fs::copy_file(e.path(), cache / e.path().filename());
  const std::string env = "OCEANGLOBE_CACHE_DIR=" + cache.string() + " ";
  const std::string view = " render --lat 24.2 --lon -78.2 --alt 3000 --pitch -30 --width 64 --height 36 --output ";
  auto render = [&](const std::string& prefix, const fs::path& out, const std::string& tag) {
    const RunResult r = og::test::runCommand(prefix + OG_BINARY + view + out.string(), "startup", tag);
    EXPECT_EQ(r.exitCode, 0) << tag << ": " << r.err;
    // A rejected atmosphere/sky-map cache is a warning; nothing else may be said.
    EXPECT_EQ(r.err.find("error"), std::string::npos) << tag << ": " << r.err;
    return r.err;
  };
  EXPECT_EQ(render(env, dir / "filled.png", "-filled"), "");
  const std::vector<fs::path> files = embeddedFiles(cache);
  ASSERT_EQ(files.size(), 4u) << "elevation, land mask, day and night imagery";
  std::vector<std::uintmax_t> sizes;
  for (const fs::path& f : files) sizes.push_back(fs::file_size(f));
  EXPECT_EQ(render(env, dir / "cached.png", "-cached"), "");
  fs::path skyMaps;  // the atmosphere's sky maps, cached beside its tables
  for (const auto& e : fs::directory_iterator(cache))
    if (e.path().filename().string().find("-skymaps-") != std::string::npos) skyMaps = e.path();
  ASSERT_FALSE(skyMaps.empty());
  const auto skySize = fs::file_size(skyMaps);

  // Corrupt them four ways: truncated, a flipped payload byte, garbage, emptied.
  fs::resize_file(files[0], sizes[0] / 2);
  {
    std::fstream f(files[1], std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(sizes[1] / 2));
    f.put('\x5a');
  }
  {
    std::ofstream f(files[2], std::ios::binary | std::ios::trunc);
    f << "not a cache file";
  }
  fs::resize_file(files[3], 0);
  fs::resize_file(skyMaps, skySize - 100);
  const std::string said = render(env, dir / "rebuilt.png", "-rebuilt");
  EXPECT_NE(said.find("sky-map cache"), std::string::npos) << said;
  EXPECT_EQ(fs::file_size(skyMaps), skySize);
  const std::vector<fs::path> again = embeddedFiles(cache);
  ASSERT_EQ(again.size(), 4u);
  for (std::size_t i = 0; i < again.size(); ++i) EXPECT_EQ(fs::file_size(again[i]), sizes[i]) << again[i];
  EXPECT_EQ(render("OCEANGLOBE_NO_DATA_CACHE=1 " + env, dir / "uncached.png", "-uncached"), "");

  const std::string filled = og::test::slurp(dir / "filled.png");
  ASSERT_FALSE(filled.empty());
  for (const char* name : {"cached.png", "rebuilt.png", "uncached.png"})
    EXPECT_EQ(og::test::slurp(dir / name), filled) << name << " differs from the first render";
}

namespace {

/// The files the dynamic loader opened for `command` (LD_DEBUG=files, written beside `dir`'s
/// other files, one log a process), all logs joined.
std::string loadedFiles(const fs::path& dir, const std::string& tag, const std::string& command) {
  const fs::path logs = dir / ("ld-" + tag);
  fs::create_directories(logs);
  const RunResult r = og::test::runCommand(
      "LD_DEBUG=files LD_DEBUG_OUTPUT=" + (logs / "ld").string() + " " + command, "startup", "-" + tag);
  EXPECT_EQ(r.exitCode, 0) << tag << ": " << r.err;
  std::string all;
  for (const auto& e : fs::directory_iterator(logs)) all += og::test::slurp(e.path());
  EXPECT_NE(all.find("file=libc.so.6"), std::string::npos) << tag << ": the loader's log is empty";
  return all;
}

}  // namespace

// GDAL's and FFmpeg's ~150 shared libraries cost every start ~100-200 ms of relocations before
// main when linked into the executable (docs/performance.md, "Forty-first session"): they are modules
// (core/Plugin.hpp), loaded only by what reads a GDAL raster or writes an MP4. A cached render
// loads neither; the same render without the data cache decodes the embedded imagery through
// GDAL's module, a recording to MP4 loads FFmpeg's.
TEST(Startup, GdalAndFfmpegLoadOnlyWhenARunNeedsThem) {
  const fs::path dir = og::test::scratchDir("startup");
  const std::string render = std::string(OG_BINARY) + " render --lat 24.2 --lon -78.2 --alt 3000 --pitch -30 --width 32 --height 18 --output ";
  const std::string uncached = loadedFiles(dir, "uncached", "OCEANGLOBE_NO_DATA_CACHE=1 " + render + (dir / "a.png").string());
  EXPECT_NE(uncached.find("oceanglobe-gdal.so"), std::string::npos);
  EXPECT_NE(uncached.find("libgdal.so"), std::string::npos);
  EXPECT_EQ(uncached.find("libavcodec.so"), std::string::npos);
  // (The tests' cache folder: the atmosphere's tables, and the data's once this has filled it.)
  ASSERT_EQ(og::test::runCommand(render + (dir / "b.png").string(), "startup", "-filling").exitCode, 0);
  const std::string cached = loadedFiles(dir, "cached", render + (dir / "c.png").string());
  for (const char* library : {"oceanglobe-gdal.so", "libgdal.so", "oceanglobe-ffmpeg.so", "libavcodec.so", "libavformat.so"})
    EXPECT_EQ(cached.find(library), std::string::npos) << library << " loaded by a cached render";
  const fs::path path = dir / "short.toml";
  std::ofstream(path) << "[scene]\nwidth = 32\nheight = 18\n[video]\nfps = 2\n"
                         "[[keyframe]]\nlatitude_deg = 38\nlongitude_deg = -15\nheight_m = 4e5\npitch_deg = -60\n"
                         "[[keyframe]]\nlatitude_deg = 38.1\nlongitude_deg = -14\nheight_m = 3e5\npitch_deg = -60\ntime_s = 1\n";
  const std::string record = loadedFiles(dir, "record", std::string(OG_BINARY) + " record " + path.string() + " -o " + (dir / "v.mp4").string());
  EXPECT_NE(record.find("oceanglobe-ffmpeg.so"), std::string::npos);
  EXPECT_NE(record.find("libavcodec.so"), std::string::npos);
  EXPECT_GT(fs::file_size(dir / "v.mp4"), 0u);
}
