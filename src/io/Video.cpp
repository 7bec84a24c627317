// io/Video.hpp's writer: the queue and the encoder thread; FFmpeg's side lives in the module
// oceanglobe-ffmpeg.so (io/VideoFfmpeg.cpp), loaded with the first video (core/Plugin.hpp).
#include "io/Video.hpp"

#include <cmath>
#include <set>

#include "core/Error.hpp"
#include "core/Plugin.hpp"
#include "io/VideoEncoder.hpp"

namespace og::io {

void validateVideoOptions(const VideoOptions& o) {
  if (o.width < 2 || o.height < 2 || o.width > 16384 || o.height > 16384)
    throw InputError("video size must be within [2, 16384] pixels");
  if (o.width % 2 != 0 || o.height % 2 != 0)
    throw InputError("MP4 (H.264, yuv420p) needs an even width and height, got " +
                     std::to_string(o.width) + "x" + std::to_string(o.height));
  if (!std::isfinite(o.fps) || o.fps <= 0.0 || o.fps > 240.0)
    throw InputError("fps must be within (0, 240]");
  if (o.crf < 0 || o.crf > 51) throw InputError("crf must be within [0, 51]");
  static const std::set<std::string> presets = {"ultrafast", "superfast", "veryfast", "faster",
                                                "fast", "medium", "slow", "slower", "veryslow"};
  if (presets.count(o.preset) == 0) throw InputError("unknown x264 preset '" + o.preset + "'");
  if (o.queueFrames < 1) throw InputError("the encoder queue needs at least one frame");
}

VideoWriter::VideoWriter(const std::filesystem::path& file, const VideoOptions& o)
    : file_(file), width_(o.width), height_(o.height), capacity_(o.queueFrames) {
  validateVideoOptions(o);
  const auto& ffmpeg = *static_cast<const VideoBackend*>(plugin::load(kFfmpegModule, "writing MP4 video"));
  encoder_ = ffmpeg.open(file, o);
  thread_ = std::thread([this] { encodeLoop(); });
}
VideoWriter::~VideoWriter() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
    queue_.clear();  // abandoning: do not encode what is left
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void VideoWriter::push(ImageRgba8 frame) {
  if (frame.width != width_ || frame.height != height_)
    throw InternalError("video frame size changed mid-stream");
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < capacity_ || failure_; });
  if (failure_) std::rethrow_exception(failure_);
  queue_.push_back(std::move(frame));
  ++queued_;
  lock.unlock();
  changed_.notify_all();
}

void VideoWriter::finish() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (failure_) std::rethrow_exception(failure_);
  encoder_->finish();
  finished_ = true;
}

void VideoWriter::encodeLoop() {
  try {
    for (;;) {
      ImageRgba8 image;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
        if (queue_.empty()) return;  // closing and drained
        image = std::move(queue_.front());
        queue_.pop_front();
      }
      changed_.notify_all();
      encoder_->encode(image);
    }
  } catch (...) {
    std::lock_guard lock(mutex_);
    failure_ = std::current_exception();
    queue_.clear();
    changed_.notify_all();
  }
}

}  // namespace og::io
