// [layers] imagery in scene files, [scene.layers] imagery in path files (the older flat
// imagery_layers still read): read in order, written back by the scene and path writers (so
// `path convert` and recorded settings keep them), and a wrong type is refused with the file
// and line. The key is declared once in io/SceneSchema.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "io/CameraPath.hpp"
#include "io/SceneFile.hpp"
#include "support/DataFixtures.hpp"

namespace fs = std::filesystem;

TEST(ImagerySettings, PathFileImageryLayersRoundTrip) {
  const std::string text =
      "[scene]\nimagery_layers = [\"base.tif\", \"top.jpg\"]\n\n"
      "[[keyframe]]\ntime_s = 0\nlatitude_deg = 30\nlongitude_deg = 31\nheight_m = 30000\n";
  const og::io::CameraPath path = og::io::readCameraPathText(text, "flight.toml", 1);
  EXPECT_EQ(path.scene.imageryLayers, (std::vector<std::string>{"base.tif", "top.jpg"}));
  const std::string written = og::io::pathSettingsToml(path);
  EXPECT_NE(written.find("[scene.layers]"), std::string::npos) << written;
  EXPECT_NE(written.find("imagery = [\"base.tif\", \"top.jpg\"]"), std::string::npos) << written;
  const std::string rewritten = written +
      "\n[[keyframe]]\ntime_s = 0\nlatitude_deg = 30\nlongitude_deg = 31\nheight_m = 30000\n";
  EXPECT_EQ(og::io::readCameraPathText(rewritten, "flight.toml", 1).scene.imageryLayers,
            path.scene.imageryLayers)
      << rewritten;
  const fs::path json = og::test::fixtureDir("io_imagery") / "flight.json";
  og::io::writeCameraPathJson(json, path);
  EXPECT_EQ(og::io::readCameraPath(json).scene.imageryLayers, path.scene.imageryLayers);
}

TEST(ImagerySettings, SceneFileLayersImagery) {
  const fs::path file = og::test::fixtureDir("io_imagery") / "scene.toml";
  std::ofstream(file) << "[layers]\nimagery = [\"a.tif\", \"b.tif\"]\n";
  EXPECT_EQ(og::io::readSceneFile(file, {}).imageryLayers, (std::vector<std::string>{"a.tif", "b.tif"}));
  og::io::SceneSettings written;
  written.imageryLayers = {"c.tif", "d.jpg"};
  og::io::writeSceneFile(file, written);
  EXPECT_EQ(og::io::readSceneFile(file, {}).imageryLayers, written.imageryLayers);
  std::ofstream(file) << "[layers]\nimagery = \"a.tif\"\n";
  try {
    (void)og::io::readSceneFile(file, {});
    ADD_FAILURE() << "a string instead of an array must be refused";
  } catch (const og::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":2"), std::string::npos) << e.what();
  }
}
