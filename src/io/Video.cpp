#include "io/Video.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <new>
#include <set>

#include "core/Error.hpp"

namespace og::io {
namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

}  // namespace

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

// FFmpeg state, owned by the writer and used only by the encoder thread after construction.
struct VideoWriter::Impl {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  bool headerWritten = false;
  bool ioOpen = false;
  std::int64_t pts = 0;

  ~Impl() {
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    if (format != nullptr && ioOpen) avio_closep(&format->pb);
    avformat_free_context(format);
  }

  // Sends `f` (nullptr = flush) and writes every packet the encoder returns.
  void encode(const AVFrame* f) {
    int rc = avcodec_send_frame(codec, f);
    if (rc < 0) throw InternalError("H.264 encoder rejected a frame: " + avError(rc));
    while ((rc = avcodec_receive_packet(codec, packet)) >= 0) {
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format, packet);  // takes the packet's reference
      if (rc < 0) throw InputError("cannot write video: " + avError(rc));
    }
    if (rc != AVERROR(EAGAIN) && rc != AVERROR_EOF)
      throw InternalError("H.264 encoder failed: " + avError(rc));
  }
};

VideoWriter::VideoWriter(const std::filesystem::path& file, const VideoOptions& o)
    : impl_(std::make_unique<Impl>()), file_(file), capacity_(o.queueFrames) {
  validateVideoOptions(o);
  av_log_set_level(AV_LOG_ERROR);  // x264 prints statistics at info level
  Impl& v = *impl_;
  const std::string name = file.string();
  if (avformat_alloc_output_context2(&v.format, nullptr, "mp4", name.c_str()) < 0 || v.format == nullptr)
    throw InternalError("FFmpeg has no MP4 muxer");
  const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
  if (codec == nullptr) codec = avcodec_find_encoder(AV_CODEC_ID_H264);
  if (codec == nullptr) throw InternalError("FFmpeg has no H.264 encoder (libx264)");
  v.stream = avformat_new_stream(v.format, nullptr);
  v.codec = avcodec_alloc_context3(codec);
  v.frame = av_frame_alloc();
  v.packet = av_packet_alloc();
  if (v.stream == nullptr || v.codec == nullptr || v.frame == nullptr || v.packet == nullptr)
    throw std::bad_alloc();

  const AVRational rate = av_d2q(o.fps, 1 << 20);  // 30 -> 30/1, 29.97 -> 2997/100
  v.codec->width = o.width;
  v.codec->height = o.height;
  v.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  v.codec->time_base = av_inv_q(rate);
  v.codec->framerate = rate;
  // A key frame (and so an MP4 fragment) every second: a killed recording loses < 1 s.
  v.codec->gop_size = std::max(1, static_cast<int>(std::lround(o.fps)));
  // Frames are sRGB-encoded; tag BT.709 primaries and matrix in limited range (what players
  // assume for HD) with the sRGB transfer curve.
  v.codec->color_range = AVCOL_RANGE_MPEG;
  v.codec->colorspace = AVCOL_SPC_BT709;
  v.codec->color_primaries = AVCOL_PRI_BT709;
  v.codec->color_trc = AVCOL_TRC_IEC61966_2_1;
  if ((v.format->oformat->flags & AVFMT_GLOBALHEADER) != 0) v.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_opt_set(v.codec->priv_data, "preset", o.preset.c_str(), 0);
  av_opt_set(v.codec->priv_data, "crf", std::to_string(o.crf).c_str(), 0);
  int rc = avcodec_open2(v.codec, codec, nullptr);
  if (rc < 0) throw InternalError("cannot open the H.264 encoder: " + avError(rc));
  rc = avcodec_parameters_from_context(v.stream->codecpar, v.codec);
  if (rc < 0) throw InternalError("cannot set the video stream parameters: " + avError(rc));
  v.stream->time_base = v.codec->time_base;
  v.stream->avg_frame_rate = rate;

  rc = avio_open(&v.format->pb, name.c_str(), AVIO_FLAG_WRITE);
  if (rc < 0) throw InputError(name + ": cannot open for writing: " + avError(rc));
  v.ioOpen = true;
  AVDictionary* muxerOptions = nullptr;
  av_dict_set(&muxerOptions, "movflags", "frag_keyframe+empty_moov+default_base_moof", 0);
  rc = avformat_write_header(v.format, &muxerOptions);
  av_dict_free(&muxerOptions);
  if (rc < 0) throw InputError(name + ": cannot write the MP4 header: " + avError(rc));
  v.headerWritten = true;

  v.frame->format = AV_PIX_FMT_YUV420P;
  v.frame->width = o.width;
  v.frame->height = o.height;
  rc = av_frame_get_buffer(v.frame, 0);
  if (rc < 0) throw std::bad_alloc();
  v.sws = sws_getContext(o.width, o.height, AV_PIX_FMT_RGBA, o.width, o.height, AV_PIX_FMT_YUV420P,
                         SWS_BICUBIC, nullptr, nullptr, nullptr);
  if (v.sws == nullptr) throw InternalError("libswscale cannot convert RGBA to yuv420p");
  // Full-range RGB in, BT.709 limited-range YUV out (matching the tags above).
  sws_setColorspaceDetails(v.sws, sws_getCoefficients(SWS_CS_ITU709), 1,
                           sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);

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
  if (frame.width != impl_->codec->width || frame.height != impl_->codec->height)
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
  Impl& v = *impl_;
  v.encode(nullptr);
  const int rc = av_write_trailer(v.format);
  if (rc < 0) throw InputError(file_.string() + ": cannot finish the MP4: " + avError(rc));
  avio_closep(&v.format->pb);
  v.ioOpen = false;
  finished_ = true;
}

void VideoWriter::encodeLoop() {
  Impl& v = *impl_;
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
      // The encoder may still reference the previous frame's buffers.
      int rc = av_frame_make_writable(v.frame);
      if (rc < 0) throw InternalError("cannot get a video frame buffer: " + avError(rc));
      const std::uint8_t* src[1] = {image.pixels.data()};
      const int stride[1] = {4 * image.width};
      sws_scale(v.sws, src, stride, 0, image.height, v.frame->data, v.frame->linesize);
      v.frame->pts = v.pts++;
      v.encode(v.frame);
    }
  } catch (...) {
    std::lock_guard lock(mutex_);
    failure_ = std::current_exception();
    queue_.clear();
    changed_.notify_all();
  }
}

}  // namespace og::io
