#pragma once
// A video file encoded frame by frame as a render produces it (FFmpeg's
// libavcodec/libavformat): H.264 (yuv420p) in MP4 or Matroska, VP9 in WebM.
// Frames arrive as bands of rows like the image writers; the last row of a
// frame sends it to the encoder, so only one frame is held. The file is an
// AtomicFile: it appears under its name on finish(), and a writer destroyed
// before that leaves nothing behind.
#include <sdfrt/float_image.hpp>
#include <sdfrt/image_io.hpp>

#include <array>
#include <memory>
#include <string>

namespace sdfrt {

enum class VideoContainer { Mp4, Matroska, WebM };

struct VideoSettings {
  int width = 0, height = 0;  // both even (yuv420p)
  double fps = 30;
  VideoContainer container = VideoContainer::Mp4;
  // Constant rate factor: lower is better. H.264 0-51, VP9 0-63.
  int crf = 20;
};

class VideoWriter {
 public:
  // Throws IoError (the file cannot be created, FFmpeg cannot be loaded) or std::invalid_argument
  // (odd size, CRF out of range, no encoder for the codec).
  VideoWriter(const std::string& path, const VideoSettings& settings);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // The next rows of the current frame, display-encoded RGB planes.
  void write_band(const FloatImage& band, std::array<int, 3> rgb_planes);
  // Drops the rows of an unfinished frame (a stopped render).
  void discard_frame();
  int frames() const;
  // Time spent converting, encoding and muxing, in seconds.
  double encode_seconds() const;
  // Flushes the encoder and commits the file; throws IoError.
  WriteReport finish();
  // The same under another name in the same directory (a stopped render's
  // playable file of the frames done).
  WriteReport finish_as(const std::string& path);

  // Default CRF of each codec.
  static int default_crf(VideoContainer c) { return c == VideoContainer::WebM ? 32 : 18; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sdfrt
