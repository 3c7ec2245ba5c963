// Frames -> swscale (RGB24 to yuv420p, BT.709) -> libx264 or libvpx-vp9 ->
// the muxer -> AtomicAvio -> AtomicFile.
#include <sdfrt/video_writer.hpp>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <fmt/format.h>

#include <chrono>
#include <sdfrt/errors.hpp>
#include <vector>

#include "image_io/atomic_file.hpp"
#include "image_io/sample_conversion.hpp"
#include "video/atomic_avio.hpp"
#include "video/ffmpeg_api.hpp"

namespace sdfrt {
namespace {

std::string av_message(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  ffmpeg().av_strerror(code, buf, sizeof buf);
  return buf;
}

const char* muxer_name(VideoContainer c) {
  return c == VideoContainer::Mp4 ? "mp4" : c == VideoContainer::Matroska ? "matroska" : "webm";
}

}  // namespace

struct VideoWriter::Impl {
  std::string path;
  VideoSettings settings;
  AtomicFile file;
  AtomicAvio avio{file};
  AVFormatContext* mux = nullptr;
  AVCodecContext* enc = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  std::vector<std::uint8_t> rgb;  // the frame being filled, RGB24
  int rows = 0, frames = 0;
  long long nonfinite = 0;
  double encode_s = 0;

  Impl(const std::string& p, const VideoSettings& s) : path(p), settings(s), file(p) {}
  ~Impl() {
    ffmpeg().sws_freeContext(sws);
    ffmpeg().av_packet_free(&packet);
    ffmpeg().av_frame_free(&frame);
    ffmpeg().avcodec_free_context(&enc);
    ffmpeg().avformat_free_context(mux);  // the AVIOContext is ours (AtomicAvio)
  }

  [[noreturn]] void fail(const std::string& what, int code) {
    avio.rethrow_error();  // a failed write says what the disk said
    throw IoError(fmt::format("cannot write '{}': {}: {}", path, what, av_message(code)), path, 0);
  }

  void open() {
    const bool vp9 = settings.container == VideoContainer::WebM;
    const char* encoder = vp9 ? "libvpx-vp9" : "libx264";
    const AVCodec* codec = ffmpeg().avcodec_find_encoder_by_name(encoder);
    if (!codec) codec = ffmpeg().avcodec_find_encoder(vp9 ? AV_CODEC_ID_VP9 : AV_CODEC_ID_H264);
    if (!codec) throw std::invalid_argument(fmt::format("this FFmpeg has no {} encoder", vp9 ? "VP9" : "H.264"));
    if (ffmpeg().avformat_alloc_output_context2(&mux, nullptr, muxer_name(settings.container), path.c_str()) < 0 || !mux)
      throw std::invalid_argument(fmt::format("this FFmpeg has no {} muxer", muxer_name(settings.container)));
    mux->pb = avio.context();
    mux->flags |= AVFMT_FLAG_CUSTOM_IO;
    stream = ffmpeg().avformat_new_stream(mux, nullptr);
    enc = ffmpeg().avcodec_alloc_context3(codec);
    frame = ffmpeg().av_frame_alloc();
    packet = ffmpeg().av_packet_alloc();
    if (!stream || !enc || !frame || !packet) throw std::bad_alloc();
    const AVRational rate = ffmpeg().av_d2q(settings.fps, 100000);
    enc->width = settings.width;
    enc->height = settings.height;
    enc->framerate = rate;
    enc->time_base = av_inv_q(rate);
    enc->pix_fmt = AV_PIX_FMT_YUV420P;
    enc->color_primaries = AVCOL_PRI_BT709;
    enc->color_trc = AVCOL_TRC_BT709;
    enc->colorspace = AVCOL_SPC_BT709;
    enc->color_range = AVCOL_RANGE_MPEG;
    if (mux->oformat->flags & AVFMT_GLOBALHEADER) enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    ffmpeg().av_opt_set_int(enc->priv_data, "crf", settings.crf, 0);
    if (vp9) {
      enc->bit_rate = 0;  // constant quality
      ffmpeg().av_opt_set(enc->priv_data, "deadline", "good", 0);
      ffmpeg().av_opt_set_int(enc->priv_data, "cpu-used", 4, 0);
      ffmpeg().av_opt_set_int(enc->priv_data, "row-mt", 1, 0);
    }
    if (int e = ffmpeg().avcodec_open2(enc, codec, nullptr); e < 0) fail("opening the encoder", e);
    if (int e = ffmpeg().avcodec_parameters_from_context(stream->codecpar, enc); e < 0) fail("the stream parameters", e);
    stream->time_base = enc->time_base;
    stream->avg_frame_rate = rate;
    if (int e = ffmpeg().avformat_write_header(mux, nullptr); e < 0) fail("the header", e);
    frame->format = AV_PIX_FMT_YUV420P;
    frame->width = settings.width;
    frame->height = settings.height;
    if (int e = ffmpeg().av_frame_get_buffer(frame, 0); e < 0) fail("a frame buffer", e);
    sws = ffmpeg().sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGB24, settings.width, settings.height,
                         AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr,
                         nullptr);
    if (!sws) throw std::bad_alloc();
    const int* bt709 = ffmpeg().sws_getCoefficients(SWS_CS_ITU709);
    ffmpeg().sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    rgb.resize(std::size_t(settings.width) * std::size_t(settings.height) * 3);
  }

  // Sends `f` (nullptr flushes) and writes every packet the encoder returns.
  void encode(AVFrame* f) {
    if (int e = ffmpeg().avcodec_send_frame(enc, f); e < 0) fail("encoding", e);
    for (;;) {
      int e = ffmpeg().avcodec_receive_packet(enc, packet);
      if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return;
      if (e < 0) fail("encoding", e);
      ffmpeg().av_packet_rescale_ts(packet, enc->time_base, stream->time_base);
      packet->stream_index = stream->index;
      e = ffmpeg().av_interleaved_write_frame(mux, packet);
      if (e < 0) fail("writing a frame", e);
    }
  }

  void encode_frame() {
    const auto start = std::chrono::steady_clock::now();
    if (int e = ffmpeg().av_frame_make_writable(frame); e < 0) fail("a frame buffer", e);
    const std::uint8_t* src[1] = {rgb.data()};
    const int stride[1] = {settings.width * 3};
    ffmpeg().sws_scale(sws, src, stride, 0, settings.height, frame->data, frame->linesize);
    frame->pts = frames;
    encode(frame);
    ++frames;
    rows = 0;
    encode_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  WriteReport close(const std::string* other) {
    const auto start = std::chrono::steady_clock::now();
    if (rows != 0) throw IoError(fmt::format("cannot write '{}': the last frame is incomplete", path), path, 0);
    encode(nullptr);
    if (int e = ffmpeg().av_write_trailer(mux); e < 0) fail("the trailer", e);
    avio.flush();
    if (other) {
      file.commit_as(*other);
      path = *other;
    } else {
      file.commit();
    }
    encode_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    WriteReport r;
    r.path = path;
    r.bytes = file.bytes_written();
    r.nonfinite_samples = nonfinite;
    return r;
  }
};

VideoWriter::VideoWriter(const std::string& path, const VideoSettings& s) {
  if (s.width <= 0 || s.height <= 0 || s.width % 2 || s.height % 2)
    throw std::invalid_argument(fmt::format("a video needs an even width and height (yuv420p), not {}x{}", s.width, s.height));
  const int max_crf = s.container == VideoContainer::WebM ? 63 : 51;
  if (s.crf < 0 || s.crf > max_crf)
    throw std::invalid_argument(fmt::format("--quality for this video is a CRF from 0 (best) to {}, not {}", max_crf, s.crf));
  ffmpeg().av_log_set_level(AV_LOG_ERROR);  // the encoders' statistics are not for users
  impl_ = std::make_unique<Impl>(path, s);
  impl_->open();
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write_band(const FloatImage& band, std::array<int, 3> planes) {
  Impl& m = *impl_;
  if (band.width != m.settings.width || m.rows + band.height > m.settings.height)
    throw std::invalid_argument("video band does not fit the frame");
  const std::size_t w = std::size_t(band.width);
  std::uint8_t* dst = m.rgb.data() + std::size_t(m.rows) * w * 3;
  for (int c = 0; c < 3; ++c) {
    auto plane = band.plane(planes[std::size_t(c)]);
    for (std::size_t i = 0; i < plane.size(); ++i) dst[i * 3 + std::size_t(c)] = to_u8(finite_or_zero(plane[i], m.nonfinite));
  }
  m.rows += band.height;
  if (m.rows == m.settings.height) m.encode_frame();
}

void VideoWriter::discard_frame() { impl_->rows = 0; }
int VideoWriter::frames() const { return impl_->frames; }
double VideoWriter::encode_seconds() const { return impl_->encode_s; }
WriteReport VideoWriter::finish() { return impl_->close(nullptr); }
WriteReport VideoWriter::finish_as(const std::string& path) { return impl_->close(&path); }

}  // namespace sdfrt
