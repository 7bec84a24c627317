// oceanglobe view: the globe in a window, flown by hand from orbit to sea level; screenshots
// and keyframes of the flight for `oceanglobe record`. Controls: docs/controls.md.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/Commands.hpp"
#include "app/PathFiles.hpp"
#include "app/SceneOptions.hpp"
#include "app/viewer/FlightController.hpp"
#include "app/viewer/KeyframeLog.hpp"
#include "app/viewer/TextOverlay.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "data/Elevation.hpp"
#include "data/WindLayers.hpp"
#include "geo/FlightPath.hpp"
#include "geo/Sun.hpp"
#include "gl/GlfwWindow.hpp"
#include "io/CameraPath.hpp"
#include "io/Image.hpp"
#include "ocean/OceanFrame.hpp"
#include "render/GlobeRenderer.hpp"
#include "terrain/Heightfield.hpp"

namespace og::app {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kPi = std::numbers::pi;
constexpr double kTimeStepS = 3600.0;       // time-of-day keys: one hour, 10 min with Ctrl
constexpr double kExposureStep = 1.4142135623730951;  // half a stop
constexpr double kScrollFactor = 0.8;       // distance to the cursor's point per scroll notch
constexpr double kMessageS = 4.0;           // how long a status message stays on screen

struct ViewOptions {
  SceneOptions scene;
  std::string path;
  std::string keyframes = "flight.toml";
  std::string screenshotDir = ".";
  bool noOverlay = false;
};

[[gnu::format(printf, 1, 2)]] std::string format(const char* fmt, ...) {
  char buffer[256];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

std::string heightText(double m) {
  if (std::abs(m) < 1000.0) return format("%.1f m", m);
  if (std::abs(m) < 100000.0) return format("%.2f km", m / 1000.0);
  return format("%.0f km", m / 1000.0);
}

std::string angleText(double deg, char positive, char negative) {
  return format("%.5f\xC2\xB0%c", std::abs(deg), deg >= 0.0 ? positive : negative);
}

enum class Drag { None, Look, Orbit };

class Viewer {
 public:
  Viewer(const ViewOptions& options, io::SceneSettings scene, std::optional<io::CameraPath> path)
      : options_(options),
        scene_(std::move(scene)),
        ground_(data::loadElevationLayer(scene_.elevationLayer)),
        imagery_(loadImageryLayers(scene_)),
        wind_(data::WindLayers::load(
            scene_.windLayers,
            data::windFromSpeedDirection(scene_.windSpeedMs, windTowardsDeg(scene_)), scene_.time)),
        controller_(scene_.camera, [this](double lat, double lon) {
          // The sea is at the ellipsoid; land lifts the floor to the terrain's height, detail
          // included (the same function the tiles are built from).
          return std::max(0.0, ground_.heightM(lat, lon));
        }),
        start_(scene_.camera) {
    if (path) flight_.emplace(path->flight());
    baseTime_ = scene_.time;
    // Sun by angles: fixed in ECEF, given at the last keyframe when playing a path (as record
    // does) or at the starting point.
    io::SceneSettings sunScene = scene_;
    if (flight_) sunScene.camera = flight_->keyframes().back().pose;
    fixedSun_ = sunDirectionOf(sunScene);
    oceanModel_ = oceanModelOf(scene_);
    layersOn_ = wind_.size() > 0;
    showOverlay_ = !options_.noOverlay;
  }

  int run() {
    window_ = std::make_unique<gl::GlfwWindow>(scene_.width, scene_.height, "oceanglobe view");
    log::info("viewer on " + window_->info().renderer);
    GLFWwindow* w = window_->handle();
    glfwSetWindowUserPointer(w, this);
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
      self(win).onKey(key, action, mods);
    });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int mods) {
      self(win).onButton(button, action, mods);
    });
    glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) { self(win).onCursor(x, y); });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double, double y) { self(win).onScroll(y); });
    glfwSwapInterval(1);

    renderer_ = std::make_unique<render::GlobeRenderer>(ground_.layer(), scene_.atmosphere);
    // Progressive terrain: missing tiles are built in the background, never stalling a frame.
    renderer_->terrain().selection().wait = false;
    renderer_->imagery().setLayers(imagery_);
    imagery_ = {};  // on the GPU now: release the CPU copy
    // The renderer reads the layers point by point (wind texture); L switches them off.
    if (wind_.size() > 0) windShared_ = std::make_shared<const data::WindLayers>(wind_);
    renderer_->setWindLayers(layersOn_ ? windShared_ : nullptr);
    overlay_ = std::make_unique<viewer::TextOverlay>();
    oceanFrame_.reset(controller_.pose().position);

    const auto begin = Clock::now();
    auto last = begin;
    fpsSince_ = begin;
    while (!window_->shouldClose()) {
      window_->pollEvents();
      const auto now = Clock::now();
      const double dt = std::chrono::duration<double>(now - last).count();
      last = now;
      wallS_ = std::chrono::duration<double>(now - begin).count();
      step(dt);

      int fbW = 0, fbH = 0;
      window_->framebufferSize(fbW, fbH);
      if (fbW <= 0 || fbH <= 0) {  // minimised: nothing to draw
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        continue;
      }
      drawFrame(fbW, fbH);
      if (screenshotRequested_) screenshot();
      if (keyframeRequested_) keyframe();
      if (showOverlay_) overlay_->draw(overlayLines(), fbW, fbH, fbH >= 700 ? 2 : 1);
      window_->swapBuffers();
      countFrame(now);
    }
    log::info("viewer closed");
    return static_cast<int>(kExitOk);
  }

 private:
  static Viewer& self(GLFWwindow* w) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }

  // --- time and Sun ---------------------------------------------------------------------
  [[nodiscard]] double pathTimeS() const { return flight_ ? playS_ : 0.0; }
  [[nodiscard]] std::optional<UtcTime> currentTime() const {
    if (!baseTime_) return std::nullopt;
    return UtcTime{baseTime_->unixSeconds + timeOffsetS_ + pathTimeS()};
  }
  [[nodiscard]] glm::dvec3 sunDirection() const {
    if (const auto t = currentTime()) return geo::sunEphemeris(*t).directionEcef;
    // A later time of day turns the Earth east under the Sun: the Sun turns west about the
    // polar axis in Earth-fixed axes, 360° per day.
    const double a = -timeOffsetS_ * 2.0 * kPi / 86400.0;
    const double c = std::cos(a), s = std::sin(a);
    return {c * fixedSun_.x - s * fixedSun_.y, s * fixedSun_.x + c * fixedSun_.y, fixedSun_.z};
  }
  [[nodiscard]] data::WindVector windHere() const {
    const auto& g = controller_.pose().position;
    return layersOn_ ? wind_.sample(g.latitudeDeg, g.longitudeDeg) : wind_.fallback();
  }

  // --- input ----------------------------------------------------------------------------
  void say(const std::string& message) {
    message_ = message;
    messageUntilS_ = wallS_ + kMessageS;
  }

  void onKey(int key, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    const bool repeat = action == GLFW_REPEAT;
    const bool fine = (mods & GLFW_MOD_CONTROL) != 0;
    switch (key) {
      case GLFW_KEY_ESCAPE:
      case GLFW_KEY_Q: glfwSetWindowShouldClose(window_->handle(), GLFW_TRUE); break;
      case GLFW_KEY_P:
      case GLFW_KEY_F12: if (!repeat) screenshotRequested_ = true; break;
      case GLFW_KEY_K: if (!repeat) keyframeRequested_ = true; break;
      case GLFW_KEY_H:
      case GLFW_KEY_F1: if (!repeat) showOverlay_ = !showOverlay_; break;
      case GLFW_KEY_O:
        if (repeat) break;
        oceanModel_ = oceanModel_ == render::OceanModel::Bruneton ? render::OceanModel::Classic
                                                                  : render::OceanModel::Bruneton;
        say(std::string("ocean model: ") + oceanModelName());
        break;
      case GLFW_KEY_L:
        if (repeat) break;
        if (wind_.size() == 0) {
          say("no wind layers (--wind-layer FILE)");
        } else {
          layersOn_ = !layersOn_;
          renderer_->setWindLayers(layersOn_ ? windShared_ : nullptr);
          say(layersOn_ ? "wind layers on" : "wind layers off: constant wind");
        }
        break;
      case GLFW_KEY_EQUAL:
      case GLFW_KEY_KP_ADD:
        timeOffsetS_ += fine ? kTimeStepS / 6.0 : kTimeStepS;
        say(format("time of day %+.2f h", timeOffsetS_ / 3600.0));
        break;
      case GLFW_KEY_MINUS:
      case GLFW_KEY_KP_SUBTRACT:
        timeOffsetS_ -= fine ? kTimeStepS / 6.0 : kTimeStepS;
        say(format("time of day %+.2f h", timeOffsetS_ / 3600.0));
        break;
      case GLFW_KEY_RIGHT_BRACKET:
        scene_.exposure = std::min(scene_.exposure * kExposureStep, 1.0e6);
        say(format("exposure %.3g", scene_.exposure));
        break;
      case GLFW_KEY_LEFT_BRACKET:
        scene_.exposure = std::max(scene_.exposure / kExposureStep, 1.0e-6);
        say(format("exposure %.3g", scene_.exposure));
        break;
      case GLFW_KEY_N: controller_.resetNorthUp(); stopPlaying(); break;
      case GLFW_KEY_BACKSPACE:
      case GLFW_KEY_HOME:
        if (repeat) break;
        controller_.setPose(start_);
        stopPlaying();
        say("back to the start view");
        break;
      case GLFW_KEY_SPACE:
        if (repeat) break;
        if (!flight_) {
          say("no path to play (--path FILE)");
        } else {
          if (!playing_ && playS_ >= flight_->durationS()) playS_ = 0.0;
          playing_ = !playing_;
          say(playing_ ? "playing" : "paused");
        }
        break;
      case GLFW_KEY_R:
        if (!repeat && flight_) {
          playS_ = 0.0;
          playing_ = true;
          say("playing from the start");
        }
        break;
      default: break;
    }
  }

  void stopPlaying() {
    if (playing_) say("paused: flying by hand (Space resumes the path)");
    playing_ = false;
  }

  // Cursor in normalised device coordinates of the window (y up).
  [[nodiscard]] glm::dvec2 cursorNdc() const {
    int w = 0, h = 0;
    glfwGetWindowSize(window_->handle(), &w, &h);
    return {2.0 * cursor_.x / std::max(w, 1) - 1.0, 1.0 - 2.0 * cursor_.y / std::max(h, 1)};
  }
  [[nodiscard]] std::optional<glm::dvec3> pickAt(const glm::dvec2& ndc) const {
    int w = 0, h = 0;
    window_->framebufferSize(w, h);
    return controller_.pick(ndc.x, ndc.y, std::max(w, 1), std::max(h, 1));
  }

  void onButton(int button, int action, int mods) {
    if (action == GLFW_RELEASE) {
      drag_ = Drag::None;
      return;
    }
    const bool orbit = button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE ||
                       (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_SHIFT) != 0);
    drag_ = orbit ? Drag::Orbit : Drag::Look;
    if (orbit) {
      // The point under the cursor, else under the centre of the view, else the Earth's centre.
      auto p = pickAt(cursorNdc());
      if (!p) p = pickAt({0.0, 0.0});
      pivot_ = p.value_or(glm::dvec3(0.0));
    }
    stopPlaying();
  }

  void onCursor(double x, double y) {
    const glm::dvec2 previous = cursor_;
    cursor_ = {x, y};
    if (drag_ == Drag::None) return;
    int w = 0, h = 0;
    glfwGetWindowSize(window_->handle(), &w, &h);
    const double dx = x - previous.x, dy = y - previous.y;
    // Drags move the scene with the cursor, as if grabbing it.
    if (drag_ == Drag::Look) {
      const double degPerPx = controller_.pose().verticalFovDeg / std::max(h, 1);
      controller_.look(-dx * degPerPx, dy * degPerPx);
    } else {
      const double radPerPx = kPi / std::max(h, 1);
      controller_.orbit(pivot_, -dx * radPerPx, -dy * radPerPx);
    }
  }

  void onScroll(double notches) {
    stopPlaying();
    const glm::dvec2 ndc = cursorNdc();
    if (const auto target = pickAt(ndc)) {
      controller_.moveToward(*target, std::pow(kScrollFactor, notches));
    } else {
      // On the sky: along the cursor's ray, a quarter of the height per notch.
      int w = 0, h = 0;
      window_->framebufferSize(w, h);
      const geo::CameraView view = geo::makeCameraView(controller_.pose(), std::max(w, 1), std::max(h, 1));
      controller_.moveAlong(view.rayDirection(ndc.x, ndc.y), 0.25 * notches * controller_.speedMs());
    }
  }

  [[nodiscard]] viewer::MoveInput heldKeys() const {
    GLFWwindow* w = window_->handle();
    auto down = [w](int a, int b) { return glfwGetKey(w, a) == GLFW_PRESS || glfwGetKey(w, b) == GLFW_PRESS; };
    auto axis = [&](int plusA, int plusB, int minusA, int minusB) {
      return (down(plusA, plusB) ? 1.0 : 0.0) - (down(minusA, minusB) ? 1.0 : 0.0);
    };
    viewer::MoveInput in;
    in.forward = axis(GLFW_KEY_W, GLFW_KEY_UP, GLFW_KEY_S, GLFW_KEY_DOWN);
    in.right = axis(GLFW_KEY_D, GLFW_KEY_RIGHT, GLFW_KEY_A, GLFW_KEY_LEFT);
    in.up = axis(GLFW_KEY_E, GLFW_KEY_PAGE_UP, GLFW_KEY_C, GLFW_KEY_PAGE_DOWN);
    in.roll = axis(GLFW_KEY_X, GLFW_KEY_X, GLFW_KEY_Z, GLFW_KEY_Z);
    if (down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT)) in.speedFactor *= 5.0;
    if (down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL)) in.speedFactor *= 0.2;
    return in;
  }

  // --- per frame --------------------------------------------------------------------------
  void step(double dt) {
    const viewer::MoveInput in = heldKeys();
    if (in.any()) stopPlaying();
    if (playing_ && flight_) {
      playS_ = std::min(playS_ + dt, flight_->durationS());
      controller_.setPose(flight_->at(flight_->startS() + playS_));
      if (playS_ >= flight_->durationS()) {
        playing_ = false;
        say("end of the path: flying by hand");
      }
    }
    controller_.update(in, dt);
  }

  void drawFrame(int width, int height) {
    const geo::CameraPose& pose = controller_.pose();
    // Waves stay fixed to the Earth while flying low; high up no grid is drawn, so the frame
    // restarts under the camera where no jump can be seen.
    if (pose.position.heightM > render::kOceanGridMaxHeightM)
      oceanFrame_.reset(pose.position);
    else
      oceanFrame_.moveTo(pose.position);
    const data::WindVector wind = windHere();
    render::FrameInput frame;
    frame.camera = pose;
    frame.sunDirectionEcef = sunDirection();
    frame.exposure = scene_.exposure;
    frame.width = width;
    frame.height = height;
    frame.samples = scene_.samples;
    frame.simulationTimeS = wallS_;
    frame.oceanModel = oceanModel_;
    frame.windSpeedMs = std::clamp(std::hypot(wind.uMs, wind.vMs), 0.0, 50.0);
    frame.windDirectionDeg = std::atan2(wind.uMs, wind.vMs) * 180.0 / kPi;
    frame.oceanFrame = &oceanFrame_;
    renderer_->render(frame);
    glBlitNamedFramebuffer(renderer_->displayFramebuffer(), 0, 0, 0, width, height, 0, 0, width,
                           height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }

  void countFrame(Clock::time_point now) {
    ++fpsFrames_;
    const double s = std::chrono::duration<double>(now - fpsSince_).count();
    if (s >= 0.5) {
      fps_ = fpsFrames_ / s;
      fpsFrames_ = 0;
      fpsSince_ = now;
    }
  }

  [[nodiscard]] const char* oceanModelName() const {
    return oceanModel_ == render::OceanModel::Classic ? "classic" : "bruneton";
  }

  [[nodiscard]] std::vector<std::string> overlayLines() const {
    const geo::CameraPose& p = controller_.pose();
    const data::WindVector wind = windHere();
    double windTo = std::atan2(wind.uMs, wind.vMs) * 180.0 / kPi;
    if (windTo < 0.0) windTo += 360.0;
    const geo::HorizontalAngles sun = geo::horizontalAngles(p.position, sunDirection());
    std::vector<std::string> lines;
    lines.push_back("lat " + angleText(p.position.latitudeDeg, 'N', 'S') + "  lon " +
                    angleText(p.position.longitudeDeg, 'E', 'W'));
    lines.push_back("height " + heightText(p.position.heightM) + "  (" +
                    heightText(controller_.heightAboveSurfaceM()) + " above surface)");
    lines.push_back(format("heading %.1f\xC2\xB0  pitch %.1f\xC2\xB0  roll %.1f\xC2\xB0", p.headingDeg,
                           p.pitchDeg, p.rollDeg));
    lines.push_back(format("wind %.1f m/s towards %.0f\xC2\xB0 ", std::hypot(wind.uMs, wind.vMs), windTo) +
                    (wind_.size() == 0 ? "(constant)" : layersOn_ ? "(layers)" : "(layers off)"));
    lines.push_back(format("sun elevation %.1f\xC2\xB0  azimuth %.0f\xC2\xB0", sun.elevationDeg, sun.azimuthDeg));
    if (const auto t = currentTime())
      lines.push_back(t->toIso8601() + " UTC");
    else
      lines.push_back(format("UTC -- (sun by angles, %+.2f h)", timeOffsetS_ / 3600.0));
    lines.push_back(format("exposure %.3g  ocean %s", scene_.exposure, oceanModelName()));
    lines.push_back(format("%.1f fps  speed %s/s  tiles pending %zu", fps_,
                           heightText(controller_.speedMs()).c_str(),
                           renderer_->terrain().stats().tilesPending));
    if (flight_)
      lines.push_back(format("path %.1f / %.1f s %s", playS_, flight_->durationS(),
                             playing_ ? "playing" : "paused"));
    if (wallS_ < messageUntilS_ && !message_.empty()) lines.push_back(message_);
    return lines;
  }

  // --- outputs --------------------------------------------------------------------------
  void screenshot() {
    screenshotRequested_ = false;
    const fs::path dir = options_.screenshotDir;
    fs::path png, exr;
    std::error_code ec;
    for (int n = 1;; ++n) {  // the first number free as both .png and .exr
      const std::string stem = format("oceanglobe_%04d", n);
      png = dir / (stem + ".png");
      exr = dir / (stem + ".exr");
      if (!fs::exists(png, ec) && !fs::exists(exr, ec)) break;
    }
    try {
      io::writeExr(exr, renderer_->radiance());
      io::writePng(png, renderer_->display());  // last: its appearance means both are complete
      std::printf("screenshot: %s %s\n", png.string().c_str(), exr.string().c_str());
      std::fflush(stdout);
      say("screenshot " + png.filename().string() + " + .exr");
    } catch (const InputError& e) {
      log::error(e.what());
      say(std::string("screenshot failed: ") + e.what());
    }
  }

  void keyframe() {
    keyframeRequested_ = false;
    io::SceneSettings s = scene_;
    s.time = currentTime();
    s.oceanModel = oceanModelName();
    if (!layersOn_) s.windLayers.clear();
    try {
      const auto added = viewer::appendKeyframe(options_.keyframes, controller_.pose(), s, sunDirection(),
                                                [this](double lat, double lon) { return ground_.heightM(lat, lon); });
      std::printf("keyframe %zu at %.1f s: %s\n", added.count, added.timeS, options_.keyframes.c_str());
      std::fflush(stdout);
      say(format("keyframe %zu at %.1f s", added.count, added.timeS));
    } catch (const InputError& e) {
      log::error(e.what());
      say(std::string("keyframe not saved: ") + e.what());
    }
  }

  ViewOptions options_;
  io::SceneSettings scene_;
  terrain::Heightfield ground_;  // the elevation layer and its detail: the floor to fly over
  std::vector<data::GeoImage> imagery_;  // --imagery-layer: read before the window opens
  data::WindLayers wind_;
  std::shared_ptr<const data::WindLayers> windShared_;  // the same, for the renderer
  viewer::FlightController controller_;
  geo::CameraPose start_;
  std::optional<geo::FlightPath> flight_;
  std::optional<UtcTime> baseTime_;
  glm::dvec3 fixedSun_{1.0, 0.0, 0.0};
  double timeOffsetS_ = 0.0;
  double playS_ = 0.0;
  bool playing_ = true;  // a path given with --path starts playing at once
  render::OceanModel oceanModel_ = render::OceanModel::Bruneton;
  bool layersOn_ = false;
  bool showOverlay_ = true;
  bool screenshotRequested_ = false;
  bool keyframeRequested_ = false;
  Drag drag_ = Drag::None;
  glm::dvec2 cursor_{0.0};
  glm::dvec3 pivot_{0.0};
  double wallS_ = 0.0;
  std::string message_;
  double messageUntilS_ = 0.0;
  double fps_ = 0.0;
  int fpsFrames_ = 0;
  Clock::time_point fpsSince_{};
  std::unique_ptr<gl::GlfwWindow> window_;
  std::unique_ptr<render::GlobeRenderer> renderer_;
  std::unique_ptr<viewer::TextOverlay> overlay_;
  ocean::OceanFrame oceanFrame_;
};

}  // namespace

Run addViewCommand(CLI::App& parent) {
  auto opts = std::make_shared<ViewOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "view", "fly the globe by hand in a window (controls: docs/controls.md)");
  opts->scene.add(*cmd);
  cmd->add_option("--path", opts->path, "camera path file (TOML/JSON, or a Google Earth KML tour) to play");
  cmd->add_option("--keyframes", opts->keyframes,
                  "path file (.toml, .json or .kml) that K appends the current view to (created if absent)");
  cmd->add_option("--screenshot-dir", opts->screenshotDir,
                  "directory for screenshots (P): oceanglobe_NNNN.png + .exr");
  cmd->add_flag("--no-overlay", opts->noOverlay, "start with the text overlay hidden (H shows it)");
  return [opts]() {
    std::optional<io::CameraPath> path;
    io::SceneSettings scene;
    scene.width = 960;  // a window, not an image: a size that fits any screen
    scene.height = 540;
    if (!opts->path.empty()) {
      path = loadPathFile(opts->path, [&](const io::SceneSettings& s) { return opts->scene.resolve(s); });
      scene = path->scene;
    } else {
      scene = opts->scene.resolve(scene);
    }
    // Fail before opening the window: a bad output place or keyframe file exits 2.
    std::error_code ec;
    if (!fs::is_directory(opts->screenshotDir, ec))
      throw InputError("--screenshot-dir: '" + opts->screenshotDir + "' is not a directory");
    checkOutputWritable(fs::path(opts->screenshotDir) / "oceanglobe_0001.png");
    checkOutputWritable(opts->keyframes);
    if (fs::exists(opts->keyframes, ec)) {
      if (io::isKmlFile(opts->keyframes))
        (void)io::readKmlTour(opts->keyframes);
      else
        (void)io::readCameraPath(opts->keyframes);
    }
    if (scene.glBackend != "auto") log::info("--gl is ignored by view: the window has its own context");
    Viewer viewer(*opts, scene, std::move(path));
    return viewer.run();
  };
}

}  // namespace og::app
