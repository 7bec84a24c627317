// The scene schema (io/SceneSchema.hpp): scene files and camera paths write every setting and
// read it back unchanged, in TOML and JSON; older spellings are still read; ranges are the
// schema's, checked when reading and when validating.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>

#include "core/Error.hpp"
#include "io/CameraPath.hpp"
#include "io/SceneFile.hpp"
#include "io/SceneSchema.hpp"

namespace fs = std::filesystem;
using og::io::CameraPath;
using og::io::FieldValue;
using og::io::SceneField;
using og::io::SceneSettings;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(OG_TEST_OUT_DIR) / "sceneschema";
  fs::create_directories(dir);
  return dir / name;
}

fs::path writeText(const std::string& name, const std::string& text) {
  const fs::path file = scratch(name);
  std::ofstream(file) << text;
  return file;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const og::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// A scene where every setting differs from its default.
SceneSettings unusualScene() {
  SceneSettings s;
  s.camera.position = {12.5, -33.25, 1234.5};
  s.camera.headingDeg = 271.125;
  s.camera.pitchDeg = -12.0625;
  s.camera.rollDeg = 3.5;
  s.camera.verticalFovDeg = 61.0;
  s.time = og::UtcTime::parseIso8601("2024-03-01T07:08:09Z");
  s.width = 321;
  s.height = 123;
  s.exposure = 0.1 + 0.2;  // not a short decimal: written in full
  s.samples = 2;
  s.glBackend = "osmesa";
  s.oceanModel = "classic";
  s.windSpeedMs = 13.7;
  s.windFromDeg = 33.3;
  s.windLayers = {"a.nc:U,V", "b \"quoted\".grib2"};
  s.elevationLayer = "relief.nc:ROSE";
  s.simulationTimeS = 42.125;
  s.timeLapse = 1080.0;
  s.waveSeed = 9007199254740993ull;  // above 2^53: must not pass through a double
  s.atmosphere.mieScattering = {1.5e-6, 2.5e-6, 3.5e-6};
  s.atmosphere.miePhaseG = 0.75;
  s.atmosphere.scatteringOrders = 3;
  return s;
}

// Every setting of `b` equals that of `a` (through the schema, so a new field is covered too).
void expectSameSettings(const SceneSettings& a, const SceneSettings& b, bool withCamera) {
  for (const SceneField& f : og::io::sceneSchema()) {
    if (f.section == "camera" && !withCamera) continue;
    const FieldValue x = f.get(a), y = f.get(b);
    if (f.key == "sun_angular_radius_deg") {  // kept in radians: degrees are rounded once each way
      EXPECT_NEAR(std::get<double>(x), std::get<double>(y), 1e-15) << f.key;
      continue;
    }
    EXPECT_TRUE(x == y) << "[" << f.section << "] " << f.key << " changed on the round trip";
  }
}

}  // namespace

TEST(SceneSchema, EverySettingHasOneKeyAndAUnitInItsName) {
  std::set<std::string> seen;
  for (const SceneField& f : og::io::sceneSchema()) {
    EXPECT_TRUE(seen.insert(std::string(f.section) + "." + std::string(f.key)).second) << f.key;
    const bool unitInName = f.key.ends_with("_deg") || f.key.ends_with("_m") || f.key.ends_with("_ms") || f.key.ends_with("_mib") ||
                            f.key.ends_with("_s");
    if (!f.unit.empty() && f.unit != "px" && f.unit != "1/m") {
      EXPECT_TRUE(unitInName) << f.key;
    }
    EXPECT_TRUE(f.get && f.set) << f.key;
  }
}

TEST(SceneSchema, SceneFilesRoundTripInTomlAndJson) {
  const SceneSettings a = unusualScene();
  for (const char* name : {"scene.toml", "scene.json"}) {
    og::io::writeSceneFile(scratch(name), a);
    const SceneSettings b = og::io::readSceneFile(scratch(name), SceneSettings{});
    expectSameSettings(a, b, true);
  }
  // Sun by angles instead of a time; samples "auto"; default atmosphere (left out, read back).
  SceneSettings c = unusualScene();
  c.time.reset();
  c.sunElevationDeg = -4.25;
  c.sunAzimuthDeg = 300.5;
  c.samples = og::io::kAutoSamples;
  c.atmosphere = SceneSettings{}.atmosphere;
  c.elevationLayer.clear();
  og::io::writeSceneFile(scratch("angles.toml"), c);
  std::ifstream in(scratch("angles.toml"));
  const std::string text(std::istreambuf_iterator<char>(in), {});
  EXPECT_NE(text.find("samples = \"auto\""), std::string::npos) << text;
  EXPECT_EQ(text.find("[atmosphere]"), std::string::npos) << text;
  expectSameSettings(c, og::io::readSceneFile(scratch("angles.toml"), SceneSettings{}), true);
}

TEST(SceneSchema, PathWritersKeepTheWholeScene) {
  CameraPath p;
  p.scene = unusualScene();
  p.keyframes.push_back({});
  p.keyframes.back().pose = p.scene.camera;
  p.fps = 25.0;
  for (const char* name : {"path.toml", "path.json"}) {
    const fs::path file = scratch(name);
    if (fs::path(name).extension() == ".json") og::io::writeCameraPathJson(file, p);
    else og::io::writeCameraPathToml(file, p);
    const CameraPath q = og::io::readCameraPath(file);
    expectSameSettings(p.scene, q.scene, false);
    EXPECT_EQ(q.scene.waveSeed, 9007199254740993ull) << name;
    EXPECT_EQ(q.scene.samples, 2) << name;
    EXPECT_EQ(q.scene.simulationTimeS, 42.125) << name;
    EXPECT_EQ(q.scene.glBackend, "osmesa") << name;
    EXPECT_EQ(q.scene.atmosphere.scatteringOrders, 3) << name;
  }
}

TEST(SceneSchema, OlderSpellingsAreStillRead) {
  const fs::path flat = writeText("flat.toml",
                                  "[scene]\ntime = \"2024-06-20T18:00:00Z\"\nwidth = 200\nheight = 100\n"
                                  "exposure = 5\nsamples = 4\nocean_model = \"classic\"\nwind_speed_ms = 11\n"
                                  "wind_direction_deg = 200\nwind_layers = [\"w.nc\"]\n"
                                  "elevation_layer = \"e.nc\"\n"
                                  "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 3\n");
  const fs::path nested = writeText("nested.toml",
                                    "[scene.sun]\ntime = \"2024-06-20T18:00:00Z\"\n"
                                    "[scene.image]\nwidth = 200\nheight = 100\nexposure = 5\nsamples = 4\n"
                                    "[scene.ocean]\nmodel = \"classic\"\nwind_speed_ms = 11\nwind_from_deg = 200\n"
                                    "[scene.layers]\nwind = [\"w.nc\"]\nelevation = \"e.nc\"\n"
                                    "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 3\n");
  const CameraPath a = og::io::readCameraPath(flat), b = og::io::readCameraPath(nested);
  expectSameSettings(a.scene, b.scene, true);
  EXPECT_EQ(a.scene.oceanModel, "classic");
  EXPECT_EQ(a.scene.windFromDeg, 200.0);

  // A scene file's [ocean] wind_direction_deg is the older name of wind_from_deg.
  const fs::path scene = writeText("old_scene.toml", "[ocean]\nwind_direction_deg = 45\n");
  EXPECT_EQ(og::io::readSceneFile(scene, SceneSettings{}).windFromDeg, 45.0);
}

TEST(SceneSchema, RangesComeFromTheSchema) {
  const fs::path speed = writeText("fast.toml", "[ocean]\nmodel = \"classic\"\nwind_speed_ms = 60\n");
  EXPECT_NE(errorOf([&] { (void)og::io::readSceneFile(speed, {}); })
                .find("fast.toml:3: 'wind_speed_ms' must be within [0, 50] m/s"),
            std::string::npos);
  const fs::path path = writeText("fast_path.toml", "[scene.ocean]\n\nwind_speed_ms = 60\n"
                                                    "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 3\n");
  EXPECT_NE(errorOf([&] { (void)og::io::readCameraPath(path); })
                .find("fast_path.toml:3: 'wind_speed_ms' must be within [0, 50] m/s"),
            std::string::npos);
  const fs::path camera = writeText("camera_path.toml", "[scene.camera]\nlatitude_deg = 1\n"
                                                        "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 3\n");
  EXPECT_NE(errorOf([&] { (void)og::io::readCameraPath(camera); }).find("keyframes"), std::string::npos);
  const fs::path samples = writeText("samples_path.toml", "[scene.image]\nsamples = 3\n"
                                                          "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 3\n");
  EXPECT_NE(errorOf([&] { (void)og::io::readCameraPath(samples); })
                .find("samples_path.toml:2: 'samples' must be \"auto\", 1, 2, 4 or 8"),
            std::string::npos);

  SceneSettings s;
  s.windSpeedMs = 51.0;
  EXPECT_NE(errorOf([&] { og::io::validateScene(s, "flags"); }).find("flags: wind speed must be within [0, 50] m/s"),
            std::string::npos);
  s = {};
  s.samples = 3;
  EXPECT_NE(errorOf([&] { og::io::validateScene(s, ""); }).find("samples per pixel must be"), std::string::npos);
  s = {};
  s.oceanModel = "fancy";
  EXPECT_NE(errorOf([&] { og::io::validateScene(s, ""); }).find("ocean model must be one of bruneton, classic"),
            std::string::npos);
}

TEST(SceneSchema, SampleCountsAreListedOnce) {
  for (const int n : {0, 1, 2, 4, 8}) EXPECT_TRUE(og::io::isValidSampleCount(n)) << n;
  for (const int n : {-1, 3, 5, 16}) EXPECT_FALSE(og::io::isValidSampleCount(n)) << n;
  EXPECT_EQ(og::io::parseSampleCount("auto"), og::io::kAutoSamples);
  EXPECT_EQ(og::io::parseSampleCount("8"), 8);
  EXPECT_FALSE(og::io::parseSampleCount("3"));
  EXPECT_FALSE(og::io::parseSampleCount("04"));
}
