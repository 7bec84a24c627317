// CLI tier: Google Earth KML tours end to end: record's frame count and first frame, skipped
// elements, malformed tours, and `path convert` between TOML and KML.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "io/Image.hpp"
#include "support/RunBinary.hpp"

namespace fs = std::filesystem;

namespace {

using og::test::RunResult;

RunResult run(const std::string& args, const std::string& tag = "") {
  return og::test::runOceanglobe(args, "tour", tag);
}

double meanAbsDifference(const fs::path& a, const fs::path& b) {
  const og::io::ImageRgba8 x = og::io::readPng(a), y = og::io::readPng(b);
  EXPECT_EQ(x.pixels.size(), y.pixels.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < std::min(x.pixels.size(), y.pixels.size()); ++i)
    sum += std::abs(int(x.pixels[i]) - int(y.pixels[i]));
  return sum / static_cast<double>(std::max<std::size_t>(x.pixels.size(), 1));
}

// A tour as Google Earth writes one: FlyTo 0.5 s (frame 0 holds the first view), FlyTo 1 s,
// Wait 0.25 s, and a sound cue that is no part of the flight: 1.75 s in all.
fs::path writeTour(const fs::path& dir) {
  const fs::path file = dir / "tour.kml";
  std::ofstream(file) << R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2" xmlns:gx="http://www.google.com/kml/ext/2.2">
<Document><name>test</name>
<gx:Tour><name>descent</name><gx:Playlist>
  <gx:FlyTo><gx:duration>0.5</gx:duration><gx:flyToMode>bounce</gx:flyToMode>
    <Camera><longitude>-14.5</longitude><latitude>37.6</latitude><altitude>300000</altitude>
      <heading>80</heading><tilt>45</tilt><roll>0</roll><altitudeMode>absolute</altitudeMode></Camera>
  </gx:FlyTo>
  <gx:FlyTo><gx:duration>1</gx:duration><gx:flyToMode>smooth</gx:flyToMode>
    <LookAt><longitude>-12</longitude><latitude>38</latitude><altitude>0</altitude>
      <heading>90</heading><tilt>70</tilt><range>40000</range><altitudeMode>relativeToGround</altitudeMode></LookAt>
  </gx:FlyTo>
  <gx:Wait><gx:duration>0.25</gx:duration></gx:Wait>
  <gx:SoundCue><href>music.mp3</href></gx:SoundCue>
</gx:Playlist></gx:Tour>
</Document></kml>
)";
  return file;
}

}  // namespace

TEST(Tour, KmlFrameCountAndFirstFrame) {
  const fs::path dir = og::test::scratchDir("tour");
  const fs::path tour = writeTour(dir);
  // Durations 0.5 + 1 + 0.25 at 8 fps: floor(1.75 * 8) + 1 = 15 frames.
  RunResult r = run("record " + tour.string() + " --fps 8 --count-frames", "count");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "15\n");
  // One warning for the element that is no part of a camera flight, naming where it is.
  EXPECT_NE(r.err.find("tour.kml:14: skipped <gx:SoundCue>"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;

  // Frame 0 is the first view: the same image `render` makes of that camera (Google Earth's
  // 60° horizontal field of view is 35.98° vertical in a 16:9 image; pitch = tilt - 90).
  const std::string scene = " --width 96 --height 54 --time 2024-06-20T09:00Z";
  r = run("record " + tour.string() + scene + " --fps 8 --frames 0:2 -o " + (dir / "f_%02d.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double fov = 2.0 * std::atan(std::tan(std::numbers::pi / 6.0) * 54.0 / 96.0) * 180.0 / std::numbers::pi;
  char fovText[32];
  std::snprintf(fovText, sizeof fovText, "%.17g", fov);
  r = run("render --lat 37.6 --lon -14.5 --alt 300000 --heading 80 --pitch -45 --fov " +
          std::string(fovText) + scene + " -o " + (dir / "still.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_LT(meanAbsDifference(dir / "f_00.png", dir / "still.png"), 0.01);
  // Held for the first FlyTo's 0.5 s: frame 1 (0.125 s) shows the same view.
  EXPECT_LT(meanAbsDifference(dir / "f_01.png", dir / "still.png"), 0.5);
}

TEST(Tour, MalformedKmlExitsTwoNamingFileAndLine) {
  const fs::path dir = og::test::scratchDir("tour");
  const fs::path bad = dir / "bad.kml";
  std::ofstream(bad) << "<kml xmlns:gx=\"http://www.google.com/kml/ext/2.2\">\n<gx:Tour><gx:Playlist>\n"
                        "<gx:FlyTo><Camera>\n<latitude>north</latitude>\n</Camera></gx:FlyTo>\n"
                        "</gx:Playlist></gx:Tour></kml>\n";
  const fs::path empty = dir / "empty.kml";
  std::ofstream(empty) << "<kml xmlns:gx=\"http://www.google.com/kml/ext/2.2\">\n<gx:Tour><gx:Playlist>\n"
                          "<gx:FlyTo><gx:duration>2</gx:duration></gx:FlyTo>\n</gx:Playlist></gx:Tour></kml>\n";
  const fs::path text = dir / "notes.kml";
  std::ofstream(text) << "just some notes\n";
  const std::pair<std::string, std::string> cases[] = {
      {"record " + bad.string() + " -o " + (dir / "a.mp4").string(), "bad.kml:4: <latitude> 'north' is not a number"},
      {"record " + empty.string() + " -o " + (dir / "a.mp4").string(), "empty.kml:3: <gx:FlyTo> has no view"},
      {"record " + text.string() + " -o " + (dir / "a.mp4").string(), "notes.kml:1: not a KML file"},
      {"path convert " + bad.string() + " " + (dir / "out.toml").string(), "bad.kml:4:"},
      {"view --keyframes " + text.string(), "notes.kml:1: not a KML file"},
  };
  for (const auto& [args, needle] : cases) {
    const RunResult r = run(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "a.mp4"));
  EXPECT_FALSE(fs::exists(dir / "out.toml"));
}

TEST(Tour, PathConvertTomlToKmlAndBackFliesTheSame) {
  const fs::path dir = og::test::scratchDir("tour");
  const fs::path toml = dir / "flight.toml";
  std::ofstream(toml) << "[scene]\ntime = \"2024-06-20T07:00:00Z\"\nwidth = 64\nheight = 36\n[video]\nfps = 4\n"
                         "[path]\ninterpolation = \"smooth\"\n"
                         "[[keyframe]]\nlatitude_deg = 38\nlongitude_deg = -15\nheight_m = 4e5\n"
                         "heading_deg = 70\npitch_deg = -60\neasing = \"ease-in-out\"\n"
                         "[[keyframe]]\nlook_at = { latitude_deg = 38.3, longitude_deg = -12 }\n"
                         "range_m = 5000\ntilt_deg = 75\nheading_deg = 100\ntime_s = 2\n";
  RunResult r = run("path convert " + toml.string() + " " + (dir / "flight.kml").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = run("path convert " + (dir / "flight.kml").string() + " " + (dir / "back.toml").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string back = og::test::slurp(dir / "back.toml");
  EXPECT_NE(back.find("time = \"2024-06-20T07:00:00Z\""), std::string::npos) << back;
  EXPECT_NE(back.find("interpolation = \"smooth\""), std::string::npos) << back;
  EXPECT_NE(back.find("range_m = 5000"), std::string::npos) << back;
  // The three files fly the same (starting and ending at rest, as tours do): frame 4, mid-flight.
  for (const char* name : {"flight.toml", "flight.kml", "back.toml"}) {
    r = run("record " + (dir / name).string() + " --frames 4:5 -o " + (dir / (std::string(name) + "_%d.png")).string());
    ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
  }
  EXPECT_LT(meanAbsDifference(dir / "flight.toml_4.png", dir / "flight.kml_4.png"), 0.01);
  EXPECT_LT(meanAbsDifference(dir / "flight.toml_4.png", dir / "back.toml_4.png"), 0.01);
}
