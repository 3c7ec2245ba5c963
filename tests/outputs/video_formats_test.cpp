// Videos decoded with libavformat/libavcodec, as a player reads them: the
// frame count, the size, and the picture against the PNG frames of the
// same render (PSNR).
#include <gtest/gtest.h>
#include <stb_image.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <string>
#include <vector>

#include "run_sdfc.hpp"

namespace {

using sdfc::test::RunResult;
using sdfc::test::ScratchDir;

struct Decoded {
  int width = 0, height = 0;
  std::string codec;
  std::vector<std::vector<unsigned char>> frames;  // RGB24
};

// Every frame of the file's video stream, converted to RGB with BT.709
// (the colour space the stream is tagged with).
Decoded decode(const std::string& path) {
  Decoded d;
  AVFormatContext* fmt = nullptr;
  if (avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) < 0) return d;
  avformat_find_stream_info(fmt, nullptr);
  const int si = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  const AVCodec* codec = avcodec_find_decoder(fmt->streams[si]->codecpar->codec_id);
  AVCodecContext* ctx = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(ctx, fmt->streams[si]->codecpar);
  avcodec_open2(ctx, codec, nullptr);
  d.codec = codec->name;
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* sws = nullptr;
  auto drain = [&] {
    while (avcodec_receive_frame(ctx, frame) == 0) {
      d.width = frame->width, d.height = frame->height;
      if (!sws) {
        sws = sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format), frame->width, frame->height,
                             AV_PIX_FMT_RGB24, SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
      }
      std::vector<unsigned char> rgb(std::size_t(frame->width) * frame->height * 3);
      uint8_t* dst[1] = {rgb.data()};
      const int stride[1] = {frame->width * 3};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
      d.frames.push_back(std::move(rgb));
    }
  };
  while (av_read_frame(fmt, pkt) >= 0) {
    if (pkt->stream_index == si && avcodec_send_packet(ctx, pkt) == 0) drain();
    av_packet_unref(pkt);
  }
  avcodec_send_packet(ctx, nullptr);
  drain();
  sws_freeContext(sws);
  av_frame_free(&frame);
  av_packet_free(&pkt);
  avcodec_free_context(&ctx);
  avformat_close_input(&fmt);
  return d;
}

double psnr(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  double se = 0;
  for (std::size_t i = 0; i < a.size(); ++i) se += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  return 10 * std::log10(255.0 * 255.0 / std::max(se / double(a.size()), 1e-12));
}

std::vector<unsigned char> load_rgb(const std::string& path) {
  int w = 0, h = 0, n = 0;
  unsigned char* p = stbi_load(path.c_str(), &w, &h, &n, 3);
  if (!p) return {};
  std::vector<unsigned char> v(p, p + std::size_t(w) * h * 3);
  stbi_image_free(p);
  return v;
}

const std::string kArgs = "render examples/animated.yaml --width 320 --height 192 --frames 0:7 --fps 24 -q ";

TEST(VideoFormats, EightFrameMp4DecodesToEightFramesCloseToThePngs) {
  ScratchDir dir;
  RunResult r = sdfc::test::run_sdfc(kArgs + "-o " + dir.file("a.mp4"));  // the default quality, CRF 18
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, dir.file("a.mp4") + "\n");
  ASSERT_EQ(sdfc::test::run_sdfc(kArgs + "-o " + dir.file("f_%04d.png")).code, 0);
  Decoded d = decode(dir.file("a.mp4"));
  EXPECT_EQ(d.codec, "h264");
  ASSERT_EQ(d.frames.size(), 8u);
  EXPECT_EQ(d.width, 320);
  EXPECT_EQ(d.height, 192);
  for (int i = 0; i < 8; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "f_%04d.png", i);
    auto png = load_rgb(dir.file(name));
    ASSERT_EQ(png.size(), d.frames[std::size_t(i)].size()) << name;
    const double db = psnr(png, d.frames[std::size_t(i)]);
    std::cerr << "frame " << i << ": PSNR " << db << " dB\n";
    EXPECT_GE(db, 35.0) << "frame " << i;
  }
  EXPECT_LT(psnr(load_rgb(dir.file("f_0000.png")), d.frames[7]), psnr(load_rgb(dir.file("f_0007.png")), d.frames[7]))
      << "the frames are in order";
}

TEST(VideoFormats, WebmIsVp9AndMkvIsH264) {
  ScratchDir dir;
  ASSERT_EQ(sdfc::test::run_sdfc(kArgs + "-o " + dir.file("a.webm")).code, 0);
  ASSERT_EQ(sdfc::test::run_sdfc(kArgs + "--quality 30 -o " + dir.file("a.mkv")).code, 0);
  Decoded webm = decode(dir.file("a.webm")), mkv = decode(dir.file("a.mkv"));
  EXPECT_EQ(webm.codec.substr(0, 3), "vp9") << webm.codec;
  EXPECT_EQ(mkv.codec, "h264");
  EXPECT_EQ(webm.frames.size(), 8u);
  EXPECT_EQ(mkv.frames.size(), 8u);
}

TEST(VideoFormats, NumberFromZeroCountsOutputFramesWithoutGaps) {
  ScratchDir dir;
  const std::string args = "render examples/animated.yaml --width 32 --height 16 --frames 10:30:10 -q ";
  RunResult r = sdfc::test::run_sdfc(args + "--number-from 0 -o " + dir.file("z_%02d.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, dir.file("z_00.png") + "\n" + dir.file("z_01.png") + "\n" + dir.file("z_02.png") + "\n");
  r = sdfc::test::run_sdfc(args + "-o " + dir.file("f_%02d.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, dir.file("f_10.png") + "\n" + dir.file("f_11.png") + "\n" + dir.file("f_12.png") + "\n");
}

}  // namespace
