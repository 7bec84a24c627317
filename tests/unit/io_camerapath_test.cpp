#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/Error.hpp"
#include "io/CameraPath.hpp"

namespace fs = std::filesystem;
using og::io::CameraPath;
using og::io::readCameraPath;

namespace {
const fs::path kPaths = fs::path(OG_TEST_DATA_DIR) / "data" / "paths";

std::string errorOf(const fs::path& file) {
  try {
    readCameraPath(file);
  } catch (const og::InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(CameraPath, ReadsKeyframesSceneAndVideo) {
  const CameraPath p = readCameraPath(kPaths / "good.toml");
  ASSERT_EQ(p.keyframes.size(), 3u);
  EXPECT_EQ(p.keyframes[0].timeS, 0.0);
  EXPECT_EQ(p.keyframes[1].timeS, 4.0);   // duration_s after the first
  EXPECT_EQ(p.keyframes[2].timeS, 10.0);  // time_s
  // Omitted keys are inherited from the keyframe before.
  EXPECT_EQ(p.keyframes[1].pose.position.latitudeDeg, 36.0);
  EXPECT_EQ(p.keyframes[1].pose.headingDeg, 90.0);
  EXPECT_EQ(p.keyframes[1].pose.position.heightM, 1000.0);
  EXPECT_EQ(p.keyframes[1].easing, og::geo::Easing::EaseOut);
  EXPECT_EQ(p.keyframes[2].easing, og::geo::Easing::Smooth);
  EXPECT_EQ(p.keyframes[2].pose.verticalFovDeg, 60.0);
  EXPECT_EQ(p.scene.width, 160);
  EXPECT_EQ(p.scene.height, 90);
  EXPECT_EQ(p.scene.exposure, 8.0);
  EXPECT_EQ(p.scene.windSpeedMs, 9.0);
  EXPECT_EQ(*p.scene.sunElevationDeg, 10.0);
  EXPECT_EQ(*p.fps, 24.0);
  EXPECT_EQ(*p.crf, 23);
  EXPECT_EQ(p.scene.camera.position.heightM, 400000.0);  // the first keyframe
}

TEST(CameraPath, BadFilesNameFileLineAndProblem) {
  const std::pair<const char*, const char*> cases[] = {
      {"unknown_key.toml", "unknown_key.toml:5: unknown key 'altitude_m'"},
      {"unknown_section.toml", "unknown_section.toml:6: unknown section [camera]"},
      {"wrong_type.toml", "wrong_type.toml:3: 'longitude_deg' must be a number"},
      {"out_of_order.toml", "out_of_order.toml:11: keyframe 3: keyframes out of order"},
      {"zero_duration.toml", "zero_duration.toml:7: keyframe 2: duration_s must be > 0"},
      {"non_finite.toml", "non_finite.toml:4: 'height_m' must be finite"},
      {"infinite_fov.toml", "infinite_fov.toml:8: 'fov_deg' must be finite"},
      {"too_low.toml", "too_low.toml:8: keyframe 2: height_m -800 is below"},
      {"bad_pose.toml", "bad_pose.toml:6: keyframe 2: "},
      {"missing_position.toml", "missing_position.toml:1: keyframe 1: the first keyframe needs"},
      {"missing_time.toml", "missing_time.toml:6: keyframe 2: needs time_s or duration_s"},
      {"both_times.toml", "both_times.toml:8: keyframe 2: give time_s or duration_s, not both"},
      {"bad_easing.toml", "bad_easing.toml:5: keyframe 1: unknown easing 'bouncy'"},
      {"no_keyframes.toml", "no_keyframes.toml:1: no keyframes"},
      {"syntax.toml", "syntax.toml:1: "},
      {"bad_scene.toml", "bad_scene.toml:1: [scene]: give either a time or Sun"},
      {"bad_time.toml", "bad_time.toml:2: 'time' is not an ISO-8601 UTC time"},
      {"bad_fps.toml", "bad_fps.toml:2: 'fps' must be within (0, 240]"},
      {"keyframe_not_array.toml", "keyframe_not_array.toml:1: 'keyframe' must be an array"},
  };
  for (const auto& [file, expected] : cases) {
    const std::string message = errorOf(kPaths / file);
    EXPECT_NE(message.find(expected), std::string::npos) << file << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_NE(errorOf(kPaths / "does_not_exist.toml").find("does_not_exist.toml"), std::string::npos);
}

TEST(CameraPath, JsonRoundTrip) {
  const CameraPath p = readCameraPath(kPaths / "good.toml");
  const fs::path json = fs::path(OG_TEST_OUT_DIR) / "camerapath_roundtrip.json";
  og::io::writeCameraPathJson(json, p);
  const CameraPath q = readCameraPath(json);
  ASSERT_EQ(q.keyframes.size(), p.keyframes.size());
  for (std::size_t i = 0; i < p.keyframes.size(); ++i) {
    EXPECT_EQ(q.keyframes[i].timeS, p.keyframes[i].timeS);
    EXPECT_EQ(q.keyframes[i].pose.position.latitudeDeg, p.keyframes[i].pose.position.latitudeDeg);
    EXPECT_EQ(q.keyframes[i].pose.position.heightM, p.keyframes[i].pose.position.heightM);
    EXPECT_EQ(q.keyframes[i].pose.pitchDeg, p.keyframes[i].pose.pitchDeg);
    EXPECT_EQ(q.keyframes[i].easing, p.keyframes[i].easing);
  }
  EXPECT_EQ(q.scene.width, 160);
  EXPECT_EQ(*q.scene.sunAzimuthDeg, 250.0);
  EXPECT_EQ(*q.fps, 24.0);

  // JSON errors name the file and the key (JSON has no line numbers to give).
  const fs::path bad = fs::path(OG_TEST_OUT_DIR) / "camerapath_bad.json";
  std::ofstream(bad) << R"({"keyframe": [{"latitude_deg": 1, "longitude_deg": 2, "height_m": 3, "zoom": 1}]})";
  EXPECT_NE(errorOf(bad).find("camerapath_bad.json: unknown key 'zoom'"), std::string::npos) << errorOf(bad);
  std::ofstream(bad) << "{\"keyframe\": [";
  EXPECT_NE(errorOf(bad).find("camerapath_bad.json: JSON syntax error"), std::string::npos) << errorOf(bad);
}

TEST(CameraPath, TheDemoFlightIsValid) {
  const CameraPath p = readCameraPath(fs::path(OG_SOURCE_DIR) / "config" / "flythrough.toml");
  ASSERT_GE(p.keyframes.size(), 2u);
  EXPECT_GE(p.keyframes.front().pose.position.heightM, 3.0e5);
  EXPECT_LE(p.keyframes.back().pose.position.heightM, 10.0);
  const double duration = p.keyframes.back().timeS - p.keyframes.front().timeS;
  EXPECT_GE(duration, 15.0);
  EXPECT_LE(duration, 30.0);
}

TEST(CameraPath, TimeLapseReadWrittenAndChecked) {
  const fs::path file = fs::path(OG_TEST_OUT_DIR) / "camerapath_timelapse.toml";
  std::ofstream(file) << "[scene]\ntime = \"2024-06-20T06:00:00Z\"\ntime_lapse = 1080\n"
                         "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 300\n"
                         "[[keyframe]]\ntime_s = 20\n";
  const CameraPath p = readCameraPath(file);
  EXPECT_EQ(p.scene.timeLapse, 1080.0);  // 20 s of path = 6 h of UTC
  const fs::path json = fs::path(OG_TEST_OUT_DIR) / "camerapath_timelapse.json";
  og::io::writeCameraPathJson(json, p);
  EXPECT_EQ(readCameraPath(json).scene.timeLapse, 1080.0);
  EXPECT_NE(og::io::pathSettingsToml(p).find("time_lapse = 1080"), std::string::npos);
  EXPECT_EQ(og::io::pathSettingsToml(readCameraPath(kPaths / "good.toml")).find("time_lapse"), std::string::npos);
  std::ofstream(file) << "[scene]\ntime_lapse = -2\n[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\n";
  EXPECT_NE(errorOf(file).find("'time_lapse' must be within [0, "), std::string::npos) << errorOf(file);
}
