#pragma once
// The FFmpeg side of io/Video.hpp: implemented in the module oceanglobe-ffmpeg.so
// (io/VideoFfmpeg.cpp), which the program loads when it opens its first video (core/Plugin.hpp),
// so that a start writing none does not load FFmpeg's ~95 libraries.
#include <filesystem>
#include <memory>

#include "io/Image.hpp"
#include "io/Video.hpp"

namespace og::io {

/// The module's name (core/Plugin.hpp: oceanglobe-ffmpeg.so beside the executable).
inline constexpr const char* kFfmpegModule = "oceanglobe-ffmpeg";

/// One open MP4 (VideoWriter's body, used by its encoder thread after construction).
class VideoEncoder {
 public:
  virtual ~VideoEncoder() = default;
  /// Converts `frame` (the options' size, top row first) to yuv420p and encodes it as the next
  /// frame. Throws og::InputError when the file cannot be written, og::InternalError when the
  /// encoder fails.
  virtual void encode(const ImageRgba8& frame) = 0;
  /// Flushes the encoder, writes the trailer and closes the file. Throws as encode does.
  virtual void finish() = 0;
};

/// The module's one object (alive as long as the process).
class VideoBackend {
 public:
  virtual ~VideoBackend() = default;
  /// Opens `file` (options already validated) and writes the MP4's header. Throws
  /// og::InputError for an unwritable file, og::InternalError when FFmpeg has no H.264 encoder.
  [[nodiscard]] virtual std::unique_ptr<VideoEncoder> open(const std::filesystem::path& file,
                                                           const VideoOptions& options) const = 0;
};

}  // namespace og::io
