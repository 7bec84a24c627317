#pragma once
// The recording loop behind `oceanglobe record` (and `bench --record`): render the frames of a
// camera path at a fixed clock and hand them to an MP4 encoder or an image sequence.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/PassTimer.hpp"
#include "io/CameraPath.hpp"

namespace og::app {

struct RecordJob {
  io::CameraPath path;          ///< keyframes; path.scene is ignored, see `scene`
  io::SceneSettings scene;      ///< the resolved scene (path file, then flags)
  double fps = 30.0;            ///< frame i shows path time startS + i / fps
  int crf = 20;                 ///< H.264 quality for .mp4
  std::string preset = "veryfast";
  std::string output;           ///< OUT.mp4, or a pattern such as frames/f_%05d.png / .exr
  std::int64_t first = 0;       ///< first frame index
  std::int64_t end = -1;        ///< one past the last frame index; -1 = the path's end
  std::int64_t stride = 1;      ///< render every stride-th frame (bench samples the path)
  bool resume = false;          ///< image sequences: skip frames whose files exist
  bool exrFloat = false;        ///< 32-bit float EXR instead of half
  std::vector<std::string> aovs;  ///< extra EXR channels (app/Aovs.hpp); EXR outputs only
  bool progress = true;         ///< show the progress bar / lines
  /// Times each frame's passes (bench --record --breakdown) by a timer of this mode, made with
  /// the recording's context.
  std::optional<gl::PassTimer::Mode> passTimerMode;
};

/// One frame's passes as RecordJob::passTimerMode's timer timed them (ms), and the camera's height (m).
struct FramePasses {
  double heightM = 0.0;
  std::vector<std::pair<std::string, double>> passesMs;
};

struct RecordResult {
  std::int64_t rendered = 0;   ///< frames rendered and written this run
  std::int64_t skipped = 0;    ///< frames already complete (--resume)
  double wallS = 0.0;          ///< from the first frame to the closed output
  double renderS = 0.0;        ///< of which rendering and read-back (the encoder runs alongside)
  bool interrupted = false;    ///< stopped early by SIGINT/SIGTERM; output closed properly
  std::string glRenderer;      ///< GL_RENDERER used
  std::vector<FramePasses> framePasses;  ///< per rendered frame, with RecordJob::passTimerMode
};

/// Frames in a path of `durationS` seconds at `fps`: both ends included (t = 0 ... duration).
std::int64_t frameCount(double durationS, double fps);

/// `oceanglobe bench --record PATH`: frames/s of the path at each size and sample count,
/// rendering only and rendering + MP4 encoding: every frame of the flight where `frames` is 0
/// (what `record` does), else `frames` frames sampled evenly along it (a quicker look, in which
/// the one-time work, the first frame's tiles and programs and the first frame under the grid's
/// ceiling, weighs the stride times its share of the whole recording).
/// With `timerMode`, also the mean time of each pass per frame in bands of camera height (the
/// render-only run's frames, then timed pass by pass).
int benchRecord(const std::string& pathFile, const std::vector<std::pair<int, int>>& sizes,
                int frames, const std::string& glBackend, const std::vector<int>& samples,
                bool json, std::optional<gl::PassTimer::Mode> timerMode = std::nullopt);

/// Runs the job. Throws og::InputError for bad output names or ranges (before rendering).
RecordResult runRecording(const RecordJob& job);

}  // namespace og::app
