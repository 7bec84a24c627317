// oceanglobe-ffmpeg.so: io/Video.hpp's MP4 through FFmpeg (io/VideoEncoder.hpp), loaded by the
// program when it opens its first video (core/Plugin.hpp).
#include "io/VideoEncoder.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>
#include <string>

#include "core/Error.hpp"
#include "core/Plugin.hpp"

namespace og::io {
namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// FFmpeg's state for one file: used only by the writer's encoder thread after construction.
class FfmpegEncoder final : public VideoEncoder {
 public:
  FfmpegEncoder(const std::filesystem::path& file, const VideoOptions& o) : name_(file.string()) {
    av_log_set_level(AV_LOG_ERROR);  // x264 prints statistics at info level
    if (avformat_alloc_output_context2(&av_.format, nullptr, "mp4", name_.c_str()) < 0 || av_.format == nullptr)
      throw InternalError("FFmpeg has no MP4 muxer");
    const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
    if (codec == nullptr) codec = avcodec_find_encoder(AV_CODEC_ID_H264);
    if (codec == nullptr) throw InternalError("FFmpeg has no H.264 encoder (libx264)");
    stream_ = avformat_new_stream(av_.format, nullptr);
    av_.codec = avcodec_alloc_context3(codec);
    av_.frame = av_frame_alloc();
    av_.packet = av_packet_alloc();
    if (stream_ == nullptr || av_.codec == nullptr || av_.frame == nullptr || av_.packet == nullptr) throw std::bad_alloc();
    openCodec(codec, o);
    writeHeader();
    av_.frame->format = AV_PIX_FMT_YUV420P;
    av_.frame->width = o.width;
    av_.frame->height = o.height;
    if (av_frame_get_buffer(av_.frame, 0) < 0) throw std::bad_alloc();
    av_.sws = sws_getContext(o.width, o.height, AV_PIX_FMT_RGBA, o.width, o.height, AV_PIX_FMT_YUV420P, SWS_BICUBIC,
                          nullptr, nullptr, nullptr);
    if (av_.sws == nullptr) throw InternalError("libswscale cannot convert RGBA to yuv420p");
    // Full-range RGB in, BT.709 limited-range YUV out (matching the codec's tags).
    sws_setColorspaceDetails(av_.sws, sws_getCoefficients(SWS_CS_ITU709), 1, sws_getCoefficients(SWS_CS_ITU709), 0, 0,
                             1 << 16, 1 << 16);
  }


  void encode(const ImageRgba8& image) override {
    // The encoder may still reference the previous frame's buffers.
    const int rc = av_frame_make_writable(av_.frame);
    if (rc < 0) throw InternalError("cannot get a video frame buffer: " + avError(rc));
    const std::uint8_t* src[1] = {image.pixels.data()};
    const int stride[1] = {4 * image.width};
    sws_scale(av_.sws, src, stride, 0, image.height, av_.frame->data, av_.frame->linesize);
    av_.frame->pts = pts_++;
    send(av_.frame);
  }

  void finish() override {
    send(nullptr);
    const int rc = av_write_trailer(av_.format);
    if (rc < 0) throw InputError(name_ + ": cannot finish the MP4: " + avError(rc));
    avio_closep(&av_.format->pb);
    av_.ioOpen = false;
  }

 private:
  void openCodec(const AVCodec* codec, const VideoOptions& o) {
    const AVRational rate = av_d2q(o.fps, 1 << 20);  // 30 -> 30/1, 29.97 -> 2997/100
    av_.codec->width = o.width;
    av_.codec->height = o.height;
    av_.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    av_.codec->time_base = av_inv_q(rate);
    av_.codec->framerate = rate;
    // A key frame (and so an MP4 fragment) every second: a killed recording loses < 1 s.
    av_.codec->gop_size = std::max(1, static_cast<int>(std::lround(o.fps)));
    // Frames are sRGB-encoded; tag BT.709 primaries and matrix in limited range (what players
    // assume for HD) with the sRGB transfer curve.
    av_.codec->color_range = AVCOL_RANGE_MPEG;
    av_.codec->colorspace = AVCOL_SPC_BT709;
    av_.codec->color_primaries = AVCOL_PRI_BT709;
    av_.codec->color_trc = AVCOL_TRC_IEC61966_2_1;
    if ((av_.format->oformat->flags & AVFMT_GLOBALHEADER) != 0) av_.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    av_opt_set(av_.codec->priv_data, "preset", o.preset.c_str(), 0);
    av_opt_set(av_.codec->priv_data, "crf", std::to_string(o.crf).c_str(), 0);
    int rc = avcodec_open2(av_.codec, codec, nullptr);
    if (rc < 0) throw InternalError("cannot open the H.264 encoder: " + avError(rc));
    rc = avcodec_parameters_from_context(stream_->codecpar, av_.codec);
    if (rc < 0) throw InternalError("cannot set the video stream parameters: " + avError(rc));
    stream_->time_base = av_.codec->time_base;
    stream_->avg_frame_rate = rate;
  }

  void writeHeader() {
    int rc = avio_open(&av_.format->pb, name_.c_str(), AVIO_FLAG_WRITE);
    if (rc < 0) throw InputError(name_ + ": cannot open for writing: " + avError(rc));
    av_.ioOpen = true;
    AVDictionary* muxerOptions = nullptr;
    av_dict_set(&muxerOptions, "movflags", "frag_keyframe+empty_moov+default_base_moof", 0);
    rc = avformat_write_header(av_.format, &muxerOptions);
    av_dict_free(&muxerOptions);
    if (rc < 0) throw InputError(name_ + ": cannot write the MP4 header: " + avError(rc));
  }

  // Sends `f` (nullptr = flush) and writes every packet the encoder returns.
  void send(const AVFrame* f) {
    int rc = avcodec_send_frame(av_.codec, f);
    if (rc < 0) throw InternalError("H.264 encoder rejected a frame: " + avError(rc));
    while ((rc = avcodec_receive_packet(av_.codec, av_.packet)) >= 0) {
      av_packet_rescale_ts(av_.packet, av_.codec->time_base, stream_->time_base);
      av_.packet->stream_index = stream_->index;
      rc = av_interleaved_write_frame(av_.format, av_.packet);  // takes the packet's reference
      if (rc < 0) throw InputError("cannot write video: " + avError(rc));
    }
    if (rc != AVERROR(EAGAIN) && rc != AVERROR_EOF) throw InternalError("H.264 encoder failed: " + avError(rc));
  }

  // FFmpeg's objects, freed with this member also when the constructor throws half-way.
  struct Objects {
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    SwsContext* sws = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    bool ioOpen = false;
    Objects() = default;
    Objects(const Objects&) = delete;
    Objects& operator=(const Objects&) = delete;
    ~Objects() {
      sws_freeContext(sws);
      av_frame_free(&frame);
      av_packet_free(&packet);
      avcodec_free_context(&codec);
      if (format != nullptr && ioOpen) avio_closep(&format->pb);
      avformat_free_context(format);
    }
  };

  std::string name_;
  Objects av_;
  AVStream* stream_ = nullptr;  // (the format's)
  std::int64_t pts_ = 0;
};

class FfmpegVideo final : public VideoBackend {
 public:
  [[nodiscard]] std::unique_ptr<VideoEncoder> open(const std::filesystem::path& file,
                                                   const VideoOptions& options) const override {
    return std::make_unique<FfmpegEncoder>(file, options);
  }
};

}  // namespace
}  // namespace og::io

extern "C" __attribute__((visibility("default"))) void* oceanglobe_plugin_entry(const og::plugin::Host* host) {
  if (!og::plugin::acceptHost(host)) return nullptr;
  static og::io::FfmpegVideo video;
  return static_cast<og::io::VideoBackend*>(&video);
}
