// oceanglobe view: the globe in a window, flown by hand from orbit to sea level; screenshots
// and keyframes of the flight for `oceanglobe record`. Controls: docs/controls.md.
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
#include "geo/Camera.hpp"
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
constexpr double kPrefetchAheadS = 1.0;     // imagery tiles are asked for this far ahead

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
        ground_(loadElevation(scene_)),
        imagery_(loadImageryLayers(scene_)),
        wind_(data::WindLayers::load(scene_.windLayers, scene_.wind().vector(), scene_.time)),
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
    window_->setInput({[this](gl::Key k, gl::KeyAction a, gl::Modifiers m) { onKey(k, a, m); },
                       [this](gl::MouseButton b, bool pressed, gl::Modifiers m) { onButton(b, pressed, m); },
                       [this](double x, double y) { onCursor(x, y); },
                       [this](double notches) { onScroll(notches); }});
    window_->setSwapInterval(1);

    renderer_ = std::make_unique<render::GlobeRenderer>(ground_.sharedLayer(), scene_.atmosphere);
    // Progressive terrain: missing tiles are built in the background, never stalling a frame.
    renderer_->terrain().selection().wait = false;
    setImageryLayers(renderer_->imagery(), scene_, imagery_);
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
  // --- time and Sun ---------------------------------------------------------------------
  [[nodiscard]] double pathTimeS() const { return flight_ ? playS_ : 0.0; }
  [[nodiscard]] std::optional<UtcTime> currentTime() const {
    if (!baseTime_) return std::nullopt;
    return UtcTime{baseTime_->unixSeconds + timeOffsetS_ + pathTimeS() * scene_.timeLapse};
  }
  [[nodiscard]] glm::dvec3 sunDirection() const {
    if (const auto t = currentTime()) return geo::sunEphemeris(*t).directionEcef;
    // A later time of day turns the Earth east under the Sun: the Sun turns west about the
    // polar axis in Earth-fixed axes, 360° per day.
    const double a = -timeOffsetS_ * 2.0 * kPi / 86400.0;
    const double c = std::cos(a), s = std::sin(a);
    return {c * fixedSun_.x - s * fixedSun_.y, s * fixedSun_.x + c * fixedSun_.y, fixedSun_.z};
  }
  // The wind under the camera (the layers', or the constant wind with L off).
  [[nodiscard]] geo::Wind windHere() const {
    const auto& g = controller_.pose().position;
    if (!layersOn_) return geo::Wind::ofVector(wind_.fallback());
    const auto t = currentTime();  // layers with a time axis follow the clock
    return geo::Wind::ofVector(t && wind_.timeVarying() ? wind_.at(*t).sample(g.latitudeDeg, g.longitudeDeg)
                                                        : wind_.sample(g.latitudeDeg, g.longitudeDeg));
  }

  // --- input ----------------------------------------------------------------------------
  void say(const std::string& message) {
    message_ = message;
    messageUntilS_ = wallS_ + kMessageS;
  }

  void onKey(gl::Key key, gl::KeyAction action, gl::Modifiers mods) {
    using gl::Key;
    if (action == gl::KeyAction::Release) return;
    const bool repeat = action == gl::KeyAction::Repeat;
    const bool fine = mods.control;
    switch (key) {
      case Key::Escape:
      case Key::Q: window_->close(); break;
      case Key::P:
      case Key::F12: if (!repeat) screenshotRequested_ = true; break;
      case Key::K: if (!repeat) keyframeRequested_ = true; break;
      case Key::H:
      case Key::F1: if (!repeat) showOverlay_ = !showOverlay_; break;
      case Key::O:
        if (repeat) break;
        oceanModel_ = oceanModel_ == render::OceanModel::Bruneton ? render::OceanModel::Classic
                                                                  : render::OceanModel::Bruneton;
        say(std::string("ocean model: ") + oceanModelName());
        break;
      case Key::L:
        if (repeat) break;
        if (wind_.size() == 0) {
          say("no wind layers (--wind-layer FILE)");
        } else {
          layersOn_ = !layersOn_;
          renderer_->setWindLayers(layersOn_ ? windShared_ : nullptr);
          say(layersOn_ ? "wind layers on" : "wind layers off: constant wind");
        }
        break;
      case Key::Equal:
      case Key::KeypadAdd:
        timeOffsetS_ += fine ? kTimeStepS / 6.0 : kTimeStepS;
        say(format("time of day %+.2f h", timeOffsetS_ / 3600.0));
        break;
      case Key::Minus:
      case Key::KeypadSubtract:
        timeOffsetS_ -= fine ? kTimeStepS / 6.0 : kTimeStepS;
        say(format("time of day %+.2f h", timeOffsetS_ / 3600.0));
        break;
      case Key::RightBracket:
        scene_.exposure = std::min(scene_.exposure * kExposureStep, 1.0e6);
        say(format("exposure %.3g", scene_.exposure));
        break;
      case Key::LeftBracket:
        scene_.exposure = std::max(scene_.exposure / kExposureStep, 1.0e-6);
        say(format("exposure %.3g", scene_.exposure));
        break;
      case Key::N: controller_.resetNorthUp(); stopPlaying(); break;
      case Key::Backspace:
      case Key::Home:
        if (repeat) break;
        controller_.setPose(start_);
        stopPlaying();
        say("back to the start view");
        break;
      case Key::Space:
        if (repeat) break;
        if (!flight_) {
          say("no path to play (--path FILE)");
        } else {
          if (!playing_ && playS_ >= flight_->durationS()) playS_ = 0.0;
          playing_ = !playing_;
          say(playing_ ? "playing" : "paused");
        }
        break;
      case Key::R:
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
    window_->windowSize(w, h);
    return {2.0 * cursor_.x / std::max(w, 1) - 1.0, 1.0 - 2.0 * cursor_.y / std::max(h, 1)};
  }
  [[nodiscard]] std::optional<glm::dvec3> pickAt(const glm::dvec2& ndc) const {
    int w = 0, h = 0;
    window_->framebufferSize(w, h);
    return controller_.pick(ndc.x, ndc.y, std::max(w, 1), std::max(h, 1));
  }

  void onButton(gl::MouseButton button, bool pressed, gl::Modifiers mods) {
    if (!pressed) {
      drag_ = Drag::None;
      return;
    }
    const bool orbit = button == gl::MouseButton::Right || button == gl::MouseButton::Middle ||
                       (button == gl::MouseButton::Left && mods.shift);
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
    window_->windowSize(w, h);
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
    using gl::Key;
    auto down = [this](Key a, Key b) { return window_->isDown(a) || window_->isDown(b); };
    auto axis = [&](Key plusA, Key plusB, Key minusA, Key minusB) {
      return (down(plusA, plusB) ? 1.0 : 0.0) - (down(minusA, minusB) ? 1.0 : 0.0);
    };
    viewer::MoveInput in;
    in.forward = axis(Key::W, Key::Up, Key::S, Key::Down);
    in.right = axis(Key::D, Key::Right, Key::A, Key::Left);
    in.up = axis(Key::E, Key::PageUp, Key::C, Key::PageDown);
    in.roll = axis(Key::X, Key::X, Key::Z, Key::Z);
    if (down(Key::LeftShift, Key::RightShift)) in.speedFactor *= 5.0;
    if (down(Key::LeftControl, Key::RightControl)) in.speedFactor *= 0.2;
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
    frameDtS_ = dt;
  }

  // Imagery tiles the camera will want kPrefetchAheadS from now, read while this frame shows:
  // where the path will be, else where the recent motion leads (viewer::VelocityEstimate, viewer::poseAhead).
  void prefetchAhead(int width, int height) {
    const geo::CameraPose& pose = controller_.pose();
    const glm::dvec3 velocity = velocity_.update(geo::geodeticToEcef(pose.position), frameDtS_);
    const geo::CameraPose ahead =
        playing_ && flight_ ? flight_->at(flight_->startS() + std::min(playS_ + kPrefetchAheadS, flight_->durationS()))
                            : viewer::poseAhead(pose, velocity, kPrefetchAheadS, controller_.surfaceHeightM());
    renderer_->imagery().prefetchTiles(geo::makeCameraView(ahead, width, height), width, height);
  }

  void drawFrame(int width, int height) {
    const geo::CameraPose& pose = controller_.pose();
    // Waves stay fixed to the Earth while flying low; high up no grid is drawn, so the frame
    // restarts under the camera where no jump can be seen.
    if (pose.position.heightM > render::kOceanGridMaxHeightM)
      oceanFrame_.reset(pose.position);
    else
      oceanFrame_.moveTo(pose.position);
    render::FrameInput frame = frameInputOf(scene_);
    frame.camera = pose;
    frame.sunDirectionEcef = sunDirection();
    frame.width = width;
    frame.height = height;
    frame.simulationTimeS = scene_.simulationTimeS + wallS_;
    frame.utcTime = currentTime();
    frame.oceanModel = oceanModel_;
    frame.wind = windHere();
    frame.wind.speedMs = std::min(frame.wind.speedMs, 50.0);
    frame.oceanFrame = &oceanFrame_;
    frame.displayOnly = !screenshotRequested_;  // (a screenshot also writes the radiance's EXR)
    renderer_->render(frame);
    prefetchAhead(width, height);
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
    const geo::Wind wind = windHere();
    const geo::HorizontalAngles sun = geo::horizontalAngles(p.position, sunDirection());
    std::vector<std::string> lines;
    lines.push_back("lat " + angleText(p.position.latitudeDeg, 'N', 'S') + "  lon " +
                    angleText(p.position.longitudeDeg, 'E', 'W'));
    lines.push_back("height " + heightText(p.position.heightM) + "  (" +
                    heightText(controller_.heightAboveSurfaceM()) + " above surface)");
    lines.push_back(format("heading %.1f\xC2\xB0  pitch %.1f\xC2\xB0  roll %.1f\xC2\xB0", p.headingDeg,
                           p.pitchDeg, p.rollDeg));
    lines.push_back(format("wind %.1f m/s towards %.0f\xC2\xB0 ", wind.speedMs, wind.towardsDeg) +
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
  double frameDtS_ = 0.0;          // the last step's time step, s
  viewer::VelocityEstimate velocity_;  // the eye's smoothed motion (prefetchAhead)
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
