#pragma once
// H.264 video in MP4 through FFmpeg (libavcodec, libavformat, libswscale), loaded with the first
// video (io/VideoEncoder.hpp, core/Plugin.hpp).
//
// The MP4 is fragmented (movflags frag_keyframe+empty_moov, one key frame per second), so a
// file cut short by a crash or kill still plays up to its last complete fragment. Encoding runs
// on its own thread behind a small bounded queue: the caller renders frame i+1 while frame i is
// converted to yuv420p and encoded.
//
// VideoWriter writes exactly the file it is given; wrap it in og::writeFileAtomically to get a
// temporary name that is renamed into place once finish() returned.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "io/Image.hpp"

namespace og::io {

class VideoEncoder;  // io/VideoEncoder.hpp

struct VideoOptions {
  int width = 1280;                 ///< pixels, even (yuv420p halves chroma), [2, 16384]
  int height = 720;                 ///< pixels, even
  double fps = 30.0;                ///< frames per second, (0, 240]
  int crf = 20;                     ///< x264 constant rate factor [0, 51]: lower = better, larger
  std::string preset = "veryfast";  ///< x264 preset: ultrafast ... veryslow
  std::size_t queueFrames = 3;      ///< frames buffered between renderer and encoder, >= 1
};

/// Throws og::InputError naming the problem when options cannot make a valid H.264 stream
/// (odd size, fps or crf out of range, unknown preset).
void validateVideoOptions(const VideoOptions& options);

class VideoWriter {
 public:
  /// Opens `file` for writing and starts the encoder thread. Throws og::InputError for bad
  /// options or an unwritable file, og::InternalError when no H.264 encoder is available or
  /// FFmpeg's module cannot be loaded (io/VideoEncoder.hpp).
  VideoWriter(const std::filesystem::path& file, const VideoOptions& options);
  /// Without finish(): stops the encoder and closes the file as it stands.
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Queues one frame (top row first, options' size) with presentation time
  /// framesQueued()/fps. Blocks while the queue is full. Rethrows an encoder failure.
  void push(ImageRgba8 frame);
  /// Encodes what is queued, flushes the encoder and writes the trailer. Rethrows failures.
  void finish();

  [[nodiscard]] std::int64_t framesQueued() const { return queued_; }

 private:
  void encodeLoop();

  std::filesystem::path file_;
  int width_ = 0, height_ = 0;
  std::unique_ptr<VideoEncoder> encoder_;  ///< FFmpeg's side (io/VideoEncoder.hpp), the thread's after construction
  std::size_t capacity_ = 3;
  std::int64_t queued_ = 0;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<ImageRgba8> queue_;
  bool closing_ = false;
  bool finished_ = false;
  std::exception_ptr failure_;
  std::thread thread_;
};

}  // namespace og::io
