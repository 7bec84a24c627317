// Google Earth KML tours: timing as Google Earth plays them, views and altitude modes, fields of
// view, malformed files, and the round trip TOML -> KML -> TOML.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "core/Error.hpp"
#include "io/CameraPath.hpp"
#include "io/KmlTour.hpp"
#include "support/ExpectError.hpp"

namespace fs = std::filesystem;
using namespace og;
using og::geo::Easing;

namespace {
const fs::path kTour = fs::path(OG_TEST_DATA_DIR) / "data" / "kml" / "tour.kml";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(OG_TEST_OUT_DIR) / "kml";
  fs::create_directories(dir);
  return dir / name;
}

// A KML file from the body of its <gx:Playlist> (or the whole text when `whole`).
fs::path kml(const std::string& name, const std::string& playlist, bool whole = false) {
  const fs::path file = scratch(name);
  std::ofstream(file) << (whole ? playlist
                                : "<?xml version=\"1.0\"?>\n<kml xmlns=\"http://www.opengis.net/kml/2.2\" "
                                  "xmlns:gx=\"http://www.google.com/kml/ext/2.2\">\n<gx:Tour><gx:Playlist>\n" +
                                      playlist + "\n</gx:Playlist></gx:Tour></kml>\n");
  return file;
}

const std::string kCamera =
    "<Camera><longitude>10</longitude><latitude>45</latitude><altitude>2000</altitude>"
    "<heading>30</heading><tilt>70</tilt><altitudeMode>absolute</altitudeMode></Camera>";

std::string flyTo(double duration, const std::string& mode, const std::string& view = kCamera) {
  return "<gx:FlyTo><gx:duration>" + std::to_string(duration) + "</gx:duration><gx:flyToMode>" + mode +
         "</gx:flyToMode>" + view + "</gx:FlyTo>";
}

// The sea floor 3000 m down everywhere west of 5.5 W, land 800 m high east of it.
double terrain(double, double lon) { return lon < -5.5 ? -3000.0 : 800.0; }

}  // namespace

TEST(KmlTour, TimingAsGoogleEarthPlaysIt) {
  const io::KmlTour tour = io::readKmlTour(kTour);
  // FlyTo 1.5 s (held: frame 0 is its view), FlyTo 4, FlyTo 3, Wait 0.5: 9 s in all, so
  // floor(9 * fps) + 1 frames.
  ASSERT_EQ(tour.keys.size(), 5u);
  const double times[] = {0.0, 1.5, 5.5, 8.5, 9.0};
  for (std::size_t k = 0; k < 5; ++k) EXPECT_DOUBLE_EQ(tour.keys[k].timeS, times[k]) << k;
  // At rest: the start (the first view's hold), the end of the smooth run (before the Wait) and
  // the end; the run of two smooth FlyTos passes its middle view without stopping.
  EXPECT_EQ(tour.keys[0].easing, Easing::EaseInOut);  // the hold
  EXPECT_EQ(tour.keys[1].easing, Easing::EaseIn);
  EXPECT_EQ(tour.keys[2].easing, Easing::EaseOut);
  EXPECT_EQ(tour.keys[3].easing, Easing::EaseInOut);  // the Wait
  EXPECT_TRUE(tour.keys[0].view.lookAt);
  EXPECT_FALSE(tour.keys[2].view.lookAt);
  EXPECT_EQ(tour.keys[2].view.line, 29);
  EXPECT_FALSE(tour.settings);
}

TEST(KmlTour, ViewsAltitudeModesAndFieldOfView) {
  const io::KmlTour tour = io::readKmlTour(kTour);
  const auto keys = io::kmlKeyframes(tour, 16.0 / 9.0, terrain);
  ASSERT_EQ(keys.size(), 5u);
  // LookAt 0 m above the sea floor (3000 m down): the target is on the floor, 300 km away.
  ASSERT_TRUE(keys[0].lookAt);
  EXPECT_DOUBLE_EQ(keys[0].lookAt->target.heightM, -3000.0);
  EXPECT_DOUBLE_EQ(keys[0].lookAt->rangeM, 3e5);
  EXPECT_DOUBLE_EQ(keys[0].lookAt->tiltDeg, 45.0);
  // Google Earth's 60° horizontal field of view in a 16:9 image: 2 atan(tan 30° / (16/9)).
  const double vertical = 2.0 * std::atan(std::tan(std::numbers::pi / 6) * 9.0 / 16.0) * 180.0 / std::numbers::pi;
  EXPECT_NEAR(keys[0].pose.verticalFovDeg, vertical, 1e-12);
  EXPECT_NEAR(vertical, 35.98, 0.01);
  // Camera, absolute: heights above sea level; pitch = tilt - 90.
  EXPECT_DOUBLE_EQ(keys[2].pose.position.heightM, 30000.0);
  EXPECT_DOUBLE_EQ(keys[2].pose.pitchDeg, -30.0);
  EXPECT_DOUBLE_EQ(keys[2].pose.headingDeg, 95.0);
  // Camera 500 m above the ground, on land 800 m high.
  EXPECT_DOUBLE_EQ(keys[3].pose.position.heightM, 1300.0);
  EXPECT_DOUBLE_EQ(keys[3].pose.rollDeg, -2.0);
  EXPECT_DOUBLE_EQ(keys[4].pose.position.heightM, 1300.0);  // held by the Wait

  // Over the sea, "ground" is the sea surface; clampToSeaFloor puts the target on the floor.
  const auto mode = [&](const std::string& m, double alt) {
    const io::KmlTour t = io::readKmlTour(kml("mode.kml", flyTo(0, "bounce",
        "<LookAt><longitude>-6</longitude><latitude>36</latitude><altitude>" + std::to_string(alt) +
        "</altitude><range>1000</range><altitudeMode>" + m + "</altitudeMode></LookAt>")));
    return io::kmlKeyframes(t, 1.0, terrain).front().lookAt->target.heightM;
  };
  EXPECT_DOUBLE_EQ(mode("relativeToGround", 20), 20.0);
  EXPECT_DOUBLE_EQ(mode("clampToGround", 20), 0.0);
  EXPECT_DOUBLE_EQ(mode("clampToSeaFloor", 20), -3000.0);
  EXPECT_DOUBLE_EQ(mode("absolute", 20), 20.0);
}

TEST(KmlTour, MalformedFilesNameTheFileAndLine) {
  const std::string label = scratch("bad.kml").string();
  auto bad = [&](const std::string& line, const std::string& fragment, const std::string& body, bool whole = false) {
    const fs::path file = kml("bad.kml", body, whole);
    test::expectInputError(file.string() + ":" + line, fragment, [&] { io::readKmlTour(file); });
  };
  bad("5", "'4O' is not a number",
      "<gx:FlyTo><Camera>\n<longitude>4O</longitude></Camera></gx:FlyTo>");
  bad("5", "<tilt> 95 is outside [0, 90]",
      "<gx:FlyTo><LookAt>\n<tilt>95</tilt></LookAt></gx:FlyTo>");
  bad("4", "has no view", "<gx:FlyTo><gx:duration>1</gx:duration></gx:FlyTo>\n<gx:FlyTo><gx:duration>1</gx:duration></gx:FlyTo>");
  bad("3", "the tour has no <gx:FlyTo>", "<gx:Wait><gx:duration>1</gx:duration></gx:Wait>");
  bad("5", "needs a <gx:duration> > 0", flyTo(1, "smooth") + "\n" + flyTo(0, "smooth"));
  bad("4", "not an altitude mode",
      "<gx:FlyTo><Camera><altitudeMode>aboveGround</altitudeMode></Camera></gx:FlyTo>");
  bad("4", "'fast' is not bounce or smooth",
      "<gx:FlyTo><gx:flyToMode>fast</gx:flyToMode>" + kCamera + "</gx:FlyTo>");
  bad("2", "not a KML file", "<?xml version=\"1.0\"?>\n<gpx><trk/></gpx>\n", true);
  bad("3", "not a KML file: ", "<kml>\n<Document>\n<name>x</nam></Document></kml>\n", true);
  bad("1", "no <gx:Tour>", "<kml><Document><Placemark/></Document></kml>", true);
  bad("1", "not a KML file", "[scene]\nwidth = 3\n", true);
  // Views out of range once placed: a camera below -500 m.
  const io::KmlTour deep = io::readKmlTour(kml("deep.kml", flyTo(0, "bounce",
      "<Camera><longitude>-6</longitude><latitude>36</latitude><altitude>-10</altitude>"
      "<altitudeMode>relativeToSeaFloor</altitudeMode></Camera>")));
  test::expectInputError(scratch("deep.kml").string() + ":4", "below sea level",
                         [&] { io::kmlKeyframes(deep, 1.0, terrain); });
  (void)label;
}

TEST(KmlTour, RoundTripTomlKmlToml) {
  // A path with camera and look-at keyframes, a rest in the middle, ends at rest (a tour always
  // starts and ends at rest), smooth interpolation and a scene: written as a tour and read
  // back, it flies the same.
  const fs::path toml = scratch("roundtrip.toml");
  std::ofstream(toml) << R"([scene]
time = "2024-06-20T18:30:00Z"
width = 320
height = 180
exposure = 5
wind_speed_ms = 11
[video]
fps = 25
[path]
interpolation = "smooth"
[[keyframe]]
latitude_deg = 46.2
longitude_deg = 6.1
height_m = 25000
heading_deg = 120
pitch_deg = -35
fov_deg = 50
easing = "ease-in"
[[keyframe]]
look_at = { latitude_deg = 45.8326, longitude_deg = 6.8652, height_m = 4808 }
range_m = 9000
tilt_deg = 70
heading_deg = 200
duration_s = 6.25
easing = "ease-out"
[[keyframe]]
heading_deg = 290
duration_s = 4
[[keyframe]]
latitude_deg = 45.9
longitude_deg = 6.95
height_m = 3100.5
pitch_deg = -5
roll_deg = 3
duration_s = 3
easing = "ease-out"
[[keyframe]]
height_m = 2900
duration_s = 2
)";
  const io::CameraPath a = io::readCameraPath(toml);
  ASSERT_TRUE(a.keyframes[2].lookAt);  // keeps the target of the keyframe before
  const fs::path tour = scratch("roundtrip.kml");
  io::writeKmlTour(tour, a);
  const io::KmlTour read = io::readKmlTour(tour);
  ASSERT_TRUE(read.settings);
  io::CameraPath b = *read.settings;
  b.keyframes = io::kmlKeyframes(read, 320.0 / 180.0, [](double, double) -> double { throw 1; });
  const fs::path back = scratch("roundtrip_back.toml");
  io::writeCameraPathToml(back, b);
  const io::CameraPath c = io::readCameraPath(back);

  EXPECT_EQ(c.scene.time->unixSeconds, a.scene.time->unixSeconds);
  EXPECT_EQ(c.scene.width, 320);
  EXPECT_EQ(c.scene.exposure, 5.0);
  EXPECT_EQ(c.scene.windSpeedMs, 11.0);
  EXPECT_EQ(*c.fps, 25.0);
  EXPECT_EQ(c.interpolation, geo::Interpolation::Smooth);
  ASSERT_EQ(c.keyframes.size(), a.keyframes.size());
  for (std::size_t k = 0; k < a.keyframes.size(); ++k) {
    const geo::Keyframe &x = a.keyframes[k], &y = c.keyframes[k];
    EXPECT_EQ(y.timeS, x.timeS) << k;
    EXPECT_EQ(y.lookAt.has_value(), x.lookAt.has_value()) << k;
    EXPECT_NEAR(y.pose.position.latitudeDeg, x.pose.position.latitudeDeg, 1e-12) << k;
    EXPECT_NEAR(y.pose.position.longitudeDeg, x.pose.position.longitudeDeg, 1e-12) << k;
    EXPECT_NEAR(y.pose.position.heightM, x.pose.position.heightM, 1e-6) << k;
    EXPECT_NEAR(y.pose.headingDeg, x.pose.headingDeg, 1e-9) << k;
    EXPECT_NEAR(y.pose.pitchDeg, x.pose.pitchDeg, 1e-9) << k;
    EXPECT_NEAR(y.pose.rollDeg, x.pose.rollDeg, 1e-12) << k;
    EXPECT_NEAR(y.pose.verticalFovDeg, x.pose.verticalFovDeg, 1e-9) << k;
  }
  // The flight itself: rests and all, within a millimetre everywhere.
  const geo::FlightPath fa = a.flight(), fc = c.flight();
  for (int s = 0; s <= 200; ++s) {
    const double t = fa.durationS() * s / 200;
    const geo::CameraPose p = fa.at(t), q = fc.at(t);
    EXPECT_LT(glm::length(geo::geodeticToEcef(p.position) - geo::geodeticToEcef(q.position)), 1e-3) << t;
    EXPECT_NEAR(std::remainder(p.headingDeg - q.headingDeg, 360.0), 0.0, 1e-6) << t;
  }
  // And again: TOML -> KML -> TOML is now a fixed point, byte for byte.
  io::writeKmlTour(scratch("again.kml"), c);
  const io::KmlTour again = io::readKmlTour(scratch("again.kml"));
  io::CameraPath d = *again.settings;
  d.keyframes = io::kmlKeyframes(again, 320.0 / 180.0, {});
  io::writeCameraPathToml(scratch("again.toml"), d);
  std::ifstream f1(back), f2(scratch("again.toml"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(f1), {}), std::string(std::istreambuf_iterator<char>(f2), {}));
}

TEST(CameraPathForms, LookAtKeyframesAndOrbits) {
  const fs::path orbit = scratch("orbit.toml");
  std::ofstream(orbit) << "[orbit]\nlatitude_deg = 27.988\nlongitude_deg = 86.925\nheight_m = 8848\n"
                          "range_m = 20000\ntilt_deg = 60\ndegrees = 90\nduration_s = 12\n";
  const io::CameraPath p = io::readCameraPath(orbit);
  ASSERT_EQ(p.keyframes.size(), 4u);  // 0, 30, 60, 90 degrees
  EXPECT_DOUBLE_EQ(p.keyframes.back().lookAt->headingDeg, 90.0);
  EXPECT_DOUBLE_EQ(p.keyframes.back().timeS, 12.0);

  auto bad = [&](const std::string& line, const std::string& fragment, const std::string& text) {
    const fs::path file = scratch("badform.toml");
    std::ofstream(file) << text;
    test::expectInputError(file.string() + ":" + line, fragment, [&] { io::readCameraPath(file); });
  };
  bad("1", "not both", "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 3\nrange_m = 4\n");
  bad("1", "needs range_m", "[[keyframe]]\nlook_at = { latitude_deg = 1, longitude_deg = 2 }\n");
  bad("2", "needs latitude_deg and longitude_deg", "[[keyframe]]\nlook_at = { height_m = 2 }\nrange_m = 5\n");
  bad("1", "tilt must be within [0, 90]",
      "[[keyframe]]\nlook_at = { latitude_deg = 1, longitude_deg = 2 }\nrange_m = 5\ntilt_deg = 120\n");
  bad("2", "unknown key 'lat'", "[[keyframe]]\nlook_at = { lat = 1, longitude_deg = 2 }\n");
  bad("2", "unknown interpolation 'spline'", "[path]\ninterpolation = \"spline\"\n");
  bad("1", "[orbit] needs", "[orbit]\nlatitude_deg = 1\n");
  bad("1", "not both", "[orbit]\nlatitude_deg = 1\nlongitude_deg = 1\nrange_m = 1\nduration_s = 1\n"
                       "[[keyframe]]\nlatitude_deg = 1\nlongitude_deg = 2\nheight_m = 3\n");
}

TEST(KmlTour, HostileFilesAreRefusedCleanly) {
  // Entities are not expanded (no "billion laughs"), deep nesting does not recurse, and huge or
  // odd numbers are refused: every case is an og::InputError, never a crash or a hang.
  std::string laughs = "<?xml version=\"1.0\"?>\n<!DOCTYPE kml [<!ENTITY a \"aaaaaaaaaa\">";
  for (int i = 1; i < 10; ++i)
    laughs += "<!ENTITY " + std::string(1, char('a' + i)) + " \"" + std::string(10, '&') + "\">";
  laughs += "]>\n<kml><gx:Tour><gx:Playlist><gx:FlyTo><Camera>\n<latitude>&j;</latitude></Camera>"
            "</gx:FlyTo></gx:Playlist></gx:Tour></kml>\n";
  std::string deep = "<kml>";
  for (int i = 0; i < 200000; ++i) deep += "<Folder>";
  deep += "\n";
  const std::string huge = "<kml><gx:Tour><gx:Playlist><gx:FlyTo><Camera><altitude>1e999</altitude>"
                           "</Camera></gx:FlyTo></gx:Playlist></gx:Tour></kml>";
  const std::string hex = "<kml><gx:Tour><gx:Playlist><gx:FlyTo><Camera><latitude>0x10</latitude>"
                          "</Camera></gx:FlyTo></gx:Playlist></gx:Tour></kml>";
  for (const std::string* text : std::initializer_list<const std::string*>{&laughs, &deep, &huge, &hex}) {
    const fs::path file = kml("hostile.kml", *text, true);
    EXPECT_THROW(io::readKmlTour(file), InputError) << text->substr(0, 60);
  }
}
