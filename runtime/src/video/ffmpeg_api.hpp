#pragma once
// FFmpeg's functions as the video writer calls them: looked up in
// libavutil, libswscale, libavcodec and libavformat when the first video is
// written (see loading/dynamic_library.hpp), so that the other commands do
// not pay for loading FFmpeg and the hundred codec libraries behind it.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/mathematics.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace sdfrt {

// X(library, function): 0 libavutil, 1 libswscale, 2 libavcodec, 3 libavformat.
#define SDFRT_FFMPEG_FUNCTIONS(X)                                                                           \
  X(0, av_d2q) X(0, av_frame_alloc) X(0, av_frame_free) X(0, av_frame_get_buffer)                         \
  X(0, av_frame_make_writable) X(0, av_free) X(0, av_freep) X(0, av_log_set_level) X(0, av_malloc)        \
  X(0, av_opt_set) X(0, av_opt_set_int) X(0, av_strerror)                                                 \
  X(1, sws_freeContext) X(1, sws_getCoefficients) X(1, sws_getContext) X(1, sws_scale)                    \
  X(1, sws_setColorspaceDetails)                                                                          \
  X(2, av_packet_alloc) X(2, av_packet_free) X(2, av_packet_rescale_ts) X(2, avcodec_alloc_context3)      \
  X(2, avcodec_find_encoder) X(2, avcodec_find_encoder_by_name) X(2, avcodec_free_context)                \
  X(2, avcodec_open2) X(2, avcodec_parameters_from_context) X(2, avcodec_receive_packet)                  \
  X(2, avcodec_send_frame)                                                                                \
  X(3, av_interleaved_write_frame) X(3, av_write_trailer) X(3, avformat_alloc_output_context2)            \
  X(3, avformat_free_context) X(3, avformat_new_stream) X(3, avformat_write_header)                       \
  X(3, avio_alloc_context) X(3, avio_context_free) X(3, avio_flush)

struct FfmpegApi {
#define SDFRT_FFMPEG_MEMBER(lib, name) decltype(&::name) name;
  SDFRT_FFMPEG_FUNCTIONS(SDFRT_FFMPEG_MEMBER)
#undef SDFRT_FFMPEG_MEMBER
};

// Loads the libraries once; throws IoError (naming the library that is
// missing) when they cannot be loaded.
const FfmpegApi& ffmpeg();

}  // namespace sdfrt
