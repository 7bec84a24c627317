// oceanglobe record: a camera path file -> H.264 MP4 or a numbered PNG/EXR sequence.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "app/Aovs.hpp"
#include "app/BenchLines.hpp"
#include "app/Commands.hpp"
#include "app/PathFiles.hpp"
#include "app/Recording.hpp"
#include "app/SceneOptions.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Progress.hpp"
#include "data/Elevation.hpp"
#include "data/WindLayers.hpp"
#include "geo/Camera.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "io/Video.hpp"
#include "ocean/OceanFrame.hpp"
#include "render/GlobeRenderer.hpp"

namespace og::app {
namespace fs = std::filesystem;
namespace {

enum class Sink { None, Mp4, Png, Exr };  // None: render only (bench)

std::string lowerExtension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// An image-sequence name with one printf-style frame number: %d, %5d or %05d ("%%" is a
/// literal percent sign). Parsed here rather than handed to printf so a user's pattern can
/// never be a format-string hole.
class FramePattern {
 public:
  explicit FramePattern(const std::string& pattern) {
    bool found = false;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
      if (pattern[i] != '%') {
        (found ? suffix_ : prefix_) += pattern[i];
        continue;
      }
      if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
        (found ? suffix_ : prefix_) += '%';
        ++i;
        continue;
      }
      std::size_t j = i + 1;
      if (j < pattern.size() && pattern[j] == '0') {
        zeroPad_ = true;
        ++j;
      }
      std::size_t digits = 0;
      while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && digits < 2)
        width_ = width_ * 10 + (pattern[j++] - '0'), ++digits;
      if (found || j >= pattern.size() || pattern[j] != 'd')
        throw InputError(pattern + ": a frame pattern takes exactly one %d, %5d or %05d");
      found = true;
      i = j;
    }
    if (!found)
      throw InputError(pattern + ": image sequences need a frame-number pattern, e.g. "
                                 "frames/frame_%05d.png");
  }

  [[nodiscard]] fs::path at(std::int64_t frame) const {
    std::string number = std::to_string(frame);
    if (number.size() < static_cast<std::size_t>(width_))
      number.insert(0, static_cast<std::size_t>(width_) - number.size(), zeroPad_ ? '0' : ' ');
    return prefix_ + number + suffix_;
  }

 private:
  std::string prefix_, suffix_;
  int width_ = 0;
  bool zeroPad_ = false;
};

struct RecordOptions {
  SceneOptions scene;
  std::string pathFile;
  std::string output;
  std::optional<double> fps;
  std::optional<int> crf;
  std::string preset = "veryfast";
  std::string frames;
  bool resume = false;
  bool countFrames = false;
  std::string exrType = "half";
  std::vector<std::string> aovs;
};

/// "A:B" (B exclusive), "A:" or ":B" against `total` frames. B is clamped to total so a fixed
/// chunk size works for the last chunk of a split render.
std::pair<std::int64_t, std::int64_t> parseRange(const std::string& text, std::int64_t total) {
  const std::size_t colon = text.find(':');
  auto part = [&](const std::string& s, std::int64_t fallback) -> std::int64_t {
    if (s.empty()) return fallback;
    std::size_t used = 0;
    long long v = -1;
    try {
      v = std::stoll(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || v < 0)
      throw InputError("--frames: expected A:B with frame numbers >= 0, got '" + text + "'");
    return v;
  };
  if (colon == std::string::npos)
    throw InputError("--frames: expected A:B (frames A to B-1), got '" + text + "'");
  const std::int64_t a = part(text.substr(0, colon), 0);
  const std::int64_t b = std::min(part(text.substr(colon + 1), total), total);
  if (a >= total)
    throw InputError("--frames " + text + ": the path has only " + std::to_string(total) +
                     " frames (0:" + std::to_string(total) + ")");
  if (b <= a) throw InputError("--frames " + text + ": empty range");
  return {a, b};
}

}  // namespace

std::int64_t frameCount(double durationS, double fps) {
  // The tolerance keeps 20 s at 30 fps at 601 frames despite rounding in the product.
  return static_cast<std::int64_t>(std::floor(durationS * fps + 1e-6)) + 1;
}

namespace {

/// Where the frames go, checked before anything is rendered.
struct OutputPlan {
  Sink sink = Sink::None;
  std::optional<FramePattern> pattern;  ///< image sequences
  io::VideoOptions video;               ///< MP4
};

/// Step 1, setup: the output's kind from its name, its options validated and its folder
/// writable (fail before the long render, not after).
OutputPlan planOutput(const RecordJob& job, std::int64_t first) {
  const io::SceneSettings& scene = job.scene;
  const std::string ext = lowerExtension(job.output);
  OutputPlan plan;
  plan.sink = job.output.empty() ? Sink::None : ext == ".mp4" ? Sink::Mp4 : ext == ".png" ? Sink::Png : ext == ".exr" ? Sink::Exr
      : throw InputError(job.output + ": unsupported output '" + ext +
                         "' (use .mp4, or an image pattern like frames/frame_%05d.png or .exr)");
  if (!job.aovs.empty() && plan.sink != Sink::Exr)
    throw InputError(job.output + ": --aov needs an OpenEXR frame pattern (frames/frame_%05d.exr)");
  if (plan.sink == Sink::Mp4) {
    if (job.resume)
      throw InputError("--resume works with image sequences (frames/frame_%05d.png); an MP4 is "
                       "re-recorded whole");
    plan.video.width = scene.width;
    plan.video.height = scene.height;
    plan.video.fps = job.fps;
    plan.video.crf = job.crf;
    plan.video.preset = job.preset;
    io::validateVideoOptions(plan.video);
    checkOutputWritable(job.output);
  } else if (plan.sink != Sink::None) {
    plan.pattern.emplace(job.output);
    checkOutputWritable(plan.pattern->at(first));
  }
  return plan;
}

/// Frames still to do. A frame file exists only once complete (written under a temporary name,
/// then renamed), so existence is the whole resume test; skipped ones are counted in `result`.
std::vector<std::int64_t> framesToDo(const RecordJob& job, const OutputPlan& plan, std::int64_t first,
                                     std::int64_t end, RecordResult& result) {
  std::vector<std::int64_t> todo;
  for (std::int64_t i = first; i < end; i += job.stride) {
    std::error_code ec;
    const bool done = job.resume && plan.pattern && fs::is_regular_file(plan.pattern->at(i), ec) &&
                      fs::file_size(plan.pattern->at(i), ec) > 0;
    if (done)
      ++result.skipped;
    else
      todo.push_back(i);
  }
  return todo;
}

/// The GL side of a recording: the context and the renderer with the scene's data layers.
struct RecordingGl {
  std::unique_ptr<gl::Context> context;
  std::unique_ptr<render::GlobeRenderer> renderer;
};

/// Step 1, setup: data layers before the GL context (as `render` does: a bad file exits 2 at
/// once), then the context and the renderer.
RecordingGl setUpRenderer(const io::SceneSettings& scene, std::size_t frames, RecordResult& result) {
  const std::future<void> defaultImagery = prefetchDefaultImagery();
  const std::shared_ptr<const data::LatLonGrid> elevation = loadElevation(scene);
  const std::shared_ptr<const data::WindLayers> wind = loadWindLayers(scene);
  const std::vector<data::GeoImage> imagery = loadImageryLayers(scene);

  RecordingGl gl;
  gl.context = gl::createHeadlessContext(*gl::parseBackend(scene.glBackend));
  result.glRenderer = gl.context->info().renderer;
  log::info("recording " + std::to_string(frames) + " frames at " + std::to_string(scene.width) +
            "x" + std::to_string(scene.height) + " with " + gl.context->info().backend + " (" +
            gl.context->info().renderer + ")");
  gl.renderer = std::make_unique<render::GlobeRenderer>(elevation, scene.atmosphere);
  gl.renderer->setWindLayers(wind);
  if (wind && wind->timeVarying() && !scene.time)
    log::warn("the wind layers have a time axis but the path has no UTC time ([scene] time or "
              "--time): the winds stay at their first step");
  setImageryLayers(gl.renderer->imagery(), scene, imagery);
  return gl;
}

/// Step 2, per-frame render: frame i of the job is the path at startS + i / fps, the waves'
/// clock in real time and, with a UTC time, the Sun and wind layers at time + (i / fps) *
/// time_lapse.
class FrameRenderer {
 public:
  FrameRenderer(const RecordJob& job, render::GlobeRenderer& renderer)
      : job_(job), flight_(job.path.flight()), renderer_(renderer) {
    // With Sun angles, they hold at the last keyframe (usually the close-up, where a low Sun
    // matters); the direction is then fixed in ECEF for the whole flight.
    io::SceneSettings sunScene = job.scene;
    sunScene.camera = job.path.keyframes.back().pose;
    fixedSun_ = sunDirectionOf(sunScene);
  }

  /// The camera's height above the ellipsoid in frame i, m.
  [[nodiscard]] double heightM(std::int64_t i) const { return poseAt(i).position.heightM; }

  void render(std::int64_t i) {
    const io::SceneSettings& scene = job_.scene;
    const double t = static_cast<double>(i) / job_.fps;
    advanceOceanFrame(i);
    render::FrameInput frame = frameInputOf(scene);
    frame.camera = poseAt(i);
    frame.oceanFrame = &oceanFrame_;
    // The UTC clock runs time_lapse times faster than the path (Sun, timed wind layers).
    if (scene.time) frame.utcTime = UtcTime{scene.time->unixSeconds + t * scene.timeLapse};
    frame.sunDirectionEcef = frame.utcTime ? geo::sunEphemeris(*frame.utcTime).directionEcef : fixedSun_;
    frame.simulationTimeS = scene.simulationTimeS + t;
    frame.auxiliaryOutputs = needsAuxiliaryOutputs(job_.aovs);
    frame.displayOnly = lowerExtension(job_.output) != ".exr";  // (EXR frames read the radiance)
    renderer_.render(frame);
    // The next frame's imagery tiles, read in the background while this one is written.
    renderer_.imagery().prefetchTiles(geo::makeCameraView(poseAt(i + job_.stride), frame.width, frame.height),
                                      frame.width, frame.height);
  }

 private:
  [[nodiscard]] geo::CameraPose poseAt(std::int64_t j) const {
    return flight_.at(flight_.startS() + static_cast<double>(j) / job_.fps);
  }

  // The ocean frame carries the waves across frames so they stay fixed to the Earth while the
  // camera flies (ocean::OceanFrame). It is a pure function of the frame index: rebuilt from
  // the last frame at or before i where the camera was above the grid's ceiling (no waves
  // drawn, so a fresh frame there is invisible) or from frame 0, by moving it through every
  // frame in between. Consecutive frames continue the same sequence of moves, so a frame is
  // bit-identical alone, in a chunk or in the whole run.
  void advanceOceanFrame(std::int64_t i) {
    if (oceanFrameAt_ < 0 || i < oceanFrameAt_ || i > oceanFrameAt_ + 1) {
      std::int64_t j = i;
      while (j > 0 && poseAt(j).position.heightM < render::kOceanGridMaxHeightM) --j;
      oceanFrame_.reset(poseAt(j).position);
      for (std::int64_t k = j + 1; k < i; ++k) oceanFrame_.moveTo(poseAt(k).position);
      oceanFrameAt_ = i - 1;
    }
    const geo::CameraPose pose = poseAt(i);
    if (pose.position.heightM >= render::kOceanGridMaxHeightM)
      oceanFrame_.reset(pose.position);
    else if (i == 0 && oceanFrameAt_ < 0)
      oceanFrame_.reset(pose.position);
    else
      oceanFrame_.moveTo(pose.position);
    oceanFrameAt_ = i;
  }

  const RecordJob& job_;
  const geo::FlightPath flight_;
  render::GlobeRenderer& renderer_;
  glm::dvec3 fixedSun_{0.0};
  ocean::OceanFrame oceanFrame_;
  std::int64_t oceanFrameAt_ = -1;
};

/// Step 4, progress: renders the frames in order, handing each to `write`, until done or
/// stopped (SIGINT/SIGTERM); counts and times them in `result`.
void renderFrames(const std::vector<std::int64_t>& todo, FrameRenderer& frames, gl::PassTimer* timer,
                  Progress& progress, RecordResult& result, const std::function<void(std::int64_t)>& write) {
  using Clock = std::chrono::steady_clock;
  for (const std::int64_t i : todo) {
    if (stopRequested()) {
      result.interrupted = true;
      break;
    }
    const auto s = Clock::now();
    frames.render(i);
    if (timer != nullptr) result.framePasses.push_back({frames.heightM(i), timer->results()});
    write(i);
    result.renderS += std::chrono::duration<double>(Clock::now() - s).count();
    ++result.rendered;
    progress.advance();
  }
}

/// Step 3, encode/write: each frame to the MP4 encoder, to its image file, or read back only.
void renderAndWrite(const RecordJob& job, const OutputPlan& plan, const std::vector<std::int64_t>& todo,
                    render::GlobeRenderer& renderer, gl::PassTimer* timer, Progress& progress, RecordResult& result) {
  FrameRenderer frames(job, renderer);
  auto loop = [&](const std::function<void(std::int64_t)>& write) {
    renderFrames(todo, frames, timer, progress, result, write);
  };
  if (plan.sink == Sink::Mp4) {
    writeFileAtomically(job.output, [&](const fs::path& tmp) {
      io::VideoWriter writer(tmp, plan.video);
      loop([&](std::int64_t) { writer.push(renderer.display()); });
      writer.finish();  // also after an interrupt: the MP4 plays up to the last frame
    });
  } else if (plan.sink == Sink::None) {
    loop([&](std::int64_t) { (void)renderer.display(); });  // read back, as a real sink would
  } else {
    loop([&](std::int64_t i) {
      if (plan.sink == Sink::Png)
        io::writePng(plan.pattern->at(i), renderer.display());
      else
        io::writeExr(plan.pattern->at(i), renderer.radiance(),
                     job.exrFloat ? io::ExrPixelType::Float : io::ExrPixelType::Half,
                     aovChannels(renderer, job.aovs));
    });
  }
}

}  // namespace

RecordResult runRecording(const RecordJob& job) {
  const std::int64_t total = frameCount(job.path.flight().durationS(), job.fps);
  const std::int64_t first = job.first, end = job.end < 0 ? total : job.end;
  const OutputPlan plan = planOutput(job, first);
  RecordResult result;
  const std::vector<std::int64_t> todo = framesToDo(job, plan, first, end, result);
  RecordingGl gl = setUpRenderer(job.scene, todo.size(), result);
  std::optional<gl::PassTimer> timer;  // its queries belong to this context: made after it, gone before it
  if (job.passTimerMode) timer.emplace(*job.passTimerMode);
  gl.renderer->setPassTimer(timer ? &*timer : nullptr);

  installStopHandlers();
  Progress progress("record", static_cast<std::int64_t>(todo.size()),
                    job.progress && log::level() <= log::Level::Warn);
  const auto start = std::chrono::steady_clock::now();
  renderAndWrite(job, plan, todo, *gl.renderer, timer ? &*timer : nullptr, progress, result);
  // Step 5, finish: the wall time up to the closed output, the progress line ended.
  result.wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  return result;
}

namespace {

/// bench --record --breakdown: the mean of each pass over the frames whose camera is in each
/// band of height (the globe's sea above the grid's ceiling; the grid's sea to 1 km; below),
/// printed as "band (N frames, M ms): pass ms ..." lines and into `out` by band.
void printRecordBreakdown(const std::vector<FramePasses>& frames, nlohmann::json& out, bool json) {
  struct Band {
    const char* name;
    double lowM, highM;
  };
  const Band bands[] = {{"from 20 km up", render::kOceanGridMaxHeightM, 1e300},
                        {"1 to 20 km", 1000.0, render::kOceanGridMaxHeightM},
                        {"under 1 km", -1e300, 1000.0}};
  for (const Band& b : bands) {
    std::vector<std::pair<std::string, double>> sums;  // in the order the passes first ran
    int n = 0;
    for (const FramePasses& f : frames) {
      if (f.heightM < b.lowM || f.heightM >= b.highM) continue;
      ++n;
      for (const auto& pass : f.passesMs) {
        auto it = std::find_if(sums.begin(), sums.end(), [&pass](const auto& e) { return e.first == pass.first; });
        if (it == sums.end()) it = sums.insert(sums.end(), {pass.first, 0.0});
        it->second += pass.second;
      }
    }
    if (n == 0) continue;
    double total = 0.0;
    for (auto& [name, sum] : sums) {
      sum /= n;  // the mean
      total += sum;
    }
    nlohmann::json band = nlohmann::json::object();
    const std::string line = namedValuesLine(sums, band);
    out[b.name] = {{"frames", n}, {"passes_ms", band}};
    if (!json) std::printf("    %s (%d frames, %.0f ms):%s ms\n", b.name, n, total, line.c_str());
  }
}

/// bench --record --breakdown --json: each timed frame's camera height (m) and passes (ms), in
/// the order rendered (every --frames-th frame of the path).
nlohmann::json framePassesJson(const std::vector<FramePasses>& frames) {
  nlohmann::json out = nlohmann::json::array();
  for (const FramePasses& f : frames) {
    nlohmann::json passes = nlohmann::json::object();
    for (const auto& [name, ms] : f.passesMs) passes[name] = ms;
    out.push_back({{"height_m", f.heightM}, {"passes_ms", passes}});
  }
  return out;
}

}  // namespace

int benchRecord(const std::string& pathFile, const std::vector<std::pair<int, int>>& sizes,
                int frames, const std::string& glBackend, const std::vector<int>& samples,
                bool json, std::optional<gl::PassTimer::Mode> timerMode) {
  RecordJob job;
  job.path = loadPathFile(pathFile, [](const io::SceneSettings& s) { return s; });
  job.scene = job.path.scene;
  job.scene.glBackend = glBackend;
  job.fps = job.path.fps.value_or(30.0);
  job.crf = job.path.crf.value_or(20);
  job.progress = false;
  // Every frame, or a sample of the whole flight taken evenly: orbit frames and sea-level
  // frames cost differently.
  const geo::FlightPath flight = job.path.flight();
  const std::int64_t total = frameCount(flight.durationS(), job.fps);
  job.stride = frames <= 0 ? 1 : std::max<std::int64_t>(1, total / frames);
  const fs::path dir = fs::temp_directory_path();
  const fs::path mp4 = dir / ("oceanglobe-bench-" + std::to_string(::getpid()) + ".mp4");

  nlohmann::json report;
  if (!json) {
    if (job.stride == 1)
      std::printf("oceanglobe bench --record %s (all %lld frames, preset %s, crf %d)\n", pathFile.c_str(),
                  static_cast<long long>(total), job.preset.c_str(), job.crf);
    else  // the one-time work (first frame, first frame under the grid's ceiling) weighs more
      std::printf("oceanglobe bench --record %s (every %lld. of %lld frames, preset %s, crf %d; a "
                  "sample: its one-time work weighs %lld times its share of the recording)\n",
                  pathFile.c_str(), static_cast<long long>(job.stride), static_cast<long long>(total),
                  job.preset.c_str(), job.crf, static_cast<long long>(job.stride));
    std::printf("%10s %7s %7s %14s %16s %10s\n", "size", "samples", "frames", "render fps", "render+mp4 fps",
                "ratio");
  }
  for (const auto& [w, h] : sizes) {
    for (const int count : samples) {
      job.scene.samples = count;
      job.scene.width = w;
      job.scene.height = h;
      job.output.clear();
      job.passTimerMode = timerMode;
      const RecordResult renderOnly = runRecording(job);
      job.passTimerMode.reset();
      job.output = mp4.string();
      RecordResult withVideo;
      try {
        withVideo = runRecording(job);
      } catch (...) {
        std::error_code ignored;
        fs::remove(mp4, ignored);
        throw;
      }
      std::error_code ignored;
      fs::remove(mp4, ignored);
      const double n = static_cast<double>(withVideo.rendered);
      const double renderFps = n / renderOnly.wallS, videoFps = n / withVideo.wallS;
      // ratio 100 %: encoding entirely hidden behind rendering (it runs on its own thread).
      const std::string size = std::to_string(w) + "x" + std::to_string(h);
      report["record"].push_back({{"path", pathFile}, {"size", size}, {"samples", count},
                                  {"frames", withVideo.rendered}, {"render_fps", renderFps},
                                  {"render_encode_fps", videoFps}, {"renderer", withVideo.glRenderer}});
      if (!json)
        std::printf("%10s %7d %7lld %14.2f %16.2f %9.0f%%\n", size.c_str(), count,
                    static_cast<long long>(withVideo.rendered), renderFps, videoFps,
                    100.0 * videoFps / renderFps);
      if (timerMode) {
        printRecordBreakdown(renderOnly.framePasses, report["record"].back()["passes_by_height"], json);
        report["record"].back()["passes_by_frame"] = framePassesJson(renderOnly.framePasses);
      }
    }
  }
  if (json) std::printf("%s\n", report.dump(2).c_str());
  return static_cast<int>(kExitOk);
}

Run addRecordCommand(CLI::App& parent) {
  auto o = std::make_shared<RecordOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "record", "render a camera path (TOML/JSON, or a Google Earth KML tour) to an H.264 MP4 or a PNG/EXR frame sequence");
  cmd->add_option("path", o->pathFile, "camera path file (.toml, .json or .kml), see docs/recording.md")
      ->required();
  cmd->add_option("-o,--output", o->output,
                  "OUT.mp4, or a frame pattern such as frames/frame_%05d.png or .exr (required)");
  cmd->add_flag("--count-frames", o->countFrames,
                "print the number of frames at the chosen fps and exit (for splitting a render)");
  o->scene.add(*cmd);
  // The camera comes from the path: hide the still-image camera flags (SceneOptions still
  // looks them up) and refuse them below.
  hideCameraFlags(*cmd);
  cmd->add_option("--fps", o->fps, "frames per second (default: the path's [video] fps, or 30)")
      ->check(CLI::Range(0.001, 240.0));
  cmd->add_option("--crf", o->crf, "H.264 quality, 0 (lossless) to 51 (default: the path's, or 20)")
      ->check(CLI::Range(0, 51));
  cmd->add_option("--preset", o->preset, "x264 speed preset (ultrafast ... veryslow)");
  cmd->add_option("--frames", o->frames,
                  "render frames A to B-1 only ('A:B', 'A:' or ':B'), e.g. one chunk of a split render");
  cmd->add_flag("--resume", o->resume,
                "image sequences: skip frames whose files already exist (they are complete)");
  cmd->add_option("--exr-type", o->exrType, "EXR pixel type: half or float")
      ->check(CLI::IsMember({"half", "float"}));
  addAovOption(*cmd, o->aovs);
  return [o, cmd]() {
    refuseCameraFlags(*cmd, "record");
    RecordJob job;
    job.path = loadPathFile(o->pathFile, [&](const io::SceneSettings& s) { return o->scene.resolve(s); });
    job.scene = job.path.scene;
    job.fps = o->fps.value_or(job.path.fps.value_or(30.0));
    job.crf = o->crf.value_or(job.path.crf.value_or(20));
    job.preset = o->preset;
    job.output = o->output;
    job.resume = o->resume;
    job.exrFloat = o->exrType == "float";
    job.aovs = o->aovs;
    if (o->countFrames) {
      std::printf("%lld\n", static_cast<long long>(
                                 frameCount(job.path.flight().durationS(), job.fps)));
      return static_cast<int>(kExitOk);
    }
    if (job.output.empty()) throw InputError("record: -o/--output is required");
    if (!o->frames.empty()) {
      const geo::FlightPath flight = job.path.flight();
      std::tie(job.first, job.end) = parseRange(o->frames, frameCount(flight.durationS(), job.fps));
    }
    const RecordResult r = runRecording(job);
    if (r.interrupted) {
      log::error("interrupted after " + std::to_string(r.rendered) + " frames; " + job.output +
                 (lowerExtension(job.output) == ".mp4" ? " was closed and plays up to there"
                                                       : ": re-run with --resume to continue"));
      return static_cast<int>(kExitInterrupted);
    }
    log::info("wrote " + std::to_string(r.rendered) + " frames (" + std::to_string(r.skipped) +
              " already complete) to " + job.output);
    return static_cast<int>(kExitOk);
  };
}

}  // namespace og::app
