#include "video_output.hpp"

#include <fmt/format.h>

#include <iostream>

#include "offline_render.hpp"

namespace sdfc::cli {

namespace {
sdfrt::VideoContainer container_of(Format f) {
  return f == Format::Webm ? sdfrt::VideoContainer::WebM
                           : f == Format::Mkv ? sdfrt::VideoContainer::Matroska : sdfrt::VideoContainer::Mp4;
}
}  // namespace

VideoOutput::VideoOutput(const std::string& path, Format format, int width, int height, double fps, int crf,
                         int frames, bool quiet)
    : path_(path), progress_("frames"), total_(frames), quiet_(quiet) {
  sdfrt::VideoSettings s;
  s.width = width, s.height = height, s.fps = fps, s.container = container_of(format), s.crf = crf;
  writer_ = std::make_unique<sdfrt::VideoWriter>(path, s);
}

void VideoOutput::frame_done() {
  ++done_;
  if (!quiet_) progress_.update(done_, total_);
}

std::string VideoOutput::finish() {
  sdfrt::WriteReport r = writer_->finish();
  progress_.finish();
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (!quiet_)
    std::cerr << fmt::format("video: {} frames, {:.2f} MB in {:.1f} s; encoding took {:.2f} s ({:.0f}% of the time)\n",
                             writer_->frames(), double(r.bytes) / 1e6, total_s, writer_->encode_seconds(),
                             total_s > 0 ? 100.0 * writer_->encode_seconds() / total_s : 0.0);
  if (r.nonfinite_samples > 0)
    std::cerr << fmt::format("warning: {} NaN/Inf samples were written as black\n", r.nonfinite_samples);
  return r.path;
}

void VideoOutput::stopped(bool keep_partial) {
  progress_.finish();
  const int frames = writer_->frames();
  if (!keep_partial || frames == 0) {
    std::cerr << fmt::format("sdfc: stopped; {} was not written{}\n", path_,
                             keep_partial ? " (no frame was finished)"
                                          : fmt::format(" (--keep-partial keeps the {} frame(s) done in {})", frames,
                                                        partial_path(path_)));
    writer_.reset();  // removes the temporary file
    return;
  }
  writer_->discard_frame();
  std::cerr << fmt::format("sdfc: stopped; partial video: {} ({} of {} frames)\n",
                           writer_->finish_as(partial_path(path_)).path, frames, total_);
}

}  // namespace sdfc::cli
