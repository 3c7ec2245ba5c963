#pragma once
// `sdfc render --frames A:B -o anim.mp4`: the video file the frames are
// encoded into as they render, the frames-done progress with its ETA, and
// what a stop leaves (nothing, or with --keep-partial a playable
// anim.partial.mp4 of the frames done).
#include <sdfrt/progress.hpp>
#include <sdfrt/video_writer.hpp>

#include <chrono>
#include <memory>
#include <string>

#include "output_format.hpp"

namespace sdfc::cli {

class VideoOutput {
 public:
  VideoOutput(const std::string& path, Format format, int width, int height, double fps, int crf, int frames,
              bool quiet);
  sdfrt::VideoWriter* writer() { return writer_.get(); }
  void frame_done();
  // Commits the video; returns its path and prints the encoder's share of the time.
  std::string finish();
  // After a stop: commits the frames done as the partial file when asked.
  void stopped(bool keep_partial);

 private:
  std::string path_;
  std::unique_ptr<sdfrt::VideoWriter> writer_;
  sdfrt::ProgressBar progress_;
  int total_, done_ = 0;
  bool quiet_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace sdfc::cli
