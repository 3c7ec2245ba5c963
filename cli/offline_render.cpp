// One band loop for every output: each band of tile rows the renderer
// returns goes to a FrameSink (frame_writers.hpp), which turns it into the
// format's file(s). Progressive samples go through a SampleMean first and
// then stream to the same sink.
#include "offline_render.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <sdfrt/errors.hpp>
#include <sdfrt/progress.hpp>

#include "frame_writers.hpp"
#include "sdfc/codegen/kernel_abi.hpp"
#include "sample_mean.hpp"

namespace sdfc::cli {

namespace {

// Progressive rendering keeps float sums of the whole image; above this
// it renders all samples in one pass, streamed (and says so).
constexpr std::size_t kMaxAccumulatorBytes = std::size_t(1) << 30;

// The formats a stopped render can leave a partial image in (JPEG and PFM
// keep nothing; a video keeps its finished frames, see video_output.cpp).
bool keeps_partial(Format f) { return f == Format::Png || f == Format::Exr; }

int tiles_in(int width, int rows, int tile) { return ((width + tile - 1) / tile) * ((rows + tile - 1) / tile); }

// Renders one frame band by band; the renderer hands over the band with the
// finished tiles when it is cancelled.
class BandLoop {
 public:
  BandLoop(sdfrt::Renderer& renderer, const OfflineFrame& f, const OfflineOutput& out, int tile, int passes,
           std::atomic<bool>* cancel)
      : renderer_(renderer), f_(f), out_(out), tile_(tile), progress_("tiles") {
    total_ = tiles_in(f.width, f.height, tile) * passes;
    opt_.tile_width = opt_.tile_height = tile;
    opt_.cancel = cancel;
    opt_.progress = [this](int d, int) {
      in_band_ = d;
      if (!out_.quiet) progress_.update(done_ + d, total_);
    };
    if (out.keep_partial) opt_.partial = &stopped_band_;
    opt_.window = out.window;
  }

  // Renders every band of `frame`, passing each with its first row to
  // `take`. On cancel: `stopped(first_row)` (with stopped_band() holding the
  // finished tiles), then rethrows sdfrt::Cancelled.
  void run(const std::vector<float>& frame, const std::function<void(const sdfrt::FloatImage&, int)>& take,
           const std::function<void(int)>& stopped) {
    for (int y0 = 0; y0 < f_.height; y0 += tile_) {
      opt_.row_begin = y0;
      opt_.row_count = std::min(tile_, f_.height - y0);
      sdfrt::FloatImage band;
      try {
        band = renderer_.render(frame, f_.width, f_.height, opt_);
      } catch (const sdfrt::Cancelled&) {
        progress_.finish();
        if (!is_video(out_.format))  // a video says what it keeps (video_output.cpp)
          std::cerr << fmt::format("sdfc: stopped; {} was not written{}\n", out_.beauty,
                                 out_.keep_partial || !keeps_partial(out_.format)
                                     ? ""
                                     : fmt::format(" (--keep-partial keeps the tiles done in {})", partial_path(out_.beauty)));
        if (out_.keep_partial) stopped(y0);
        throw;
      }
      take(band, y0);
      done_ += tiles_in(f_.width, opt_.row_count, tile_);
    }
  }
  const sdfrt::FloatImage& stopped_band() const { return stopped_band_; }
  std::string tiles_done() const { return fmt::format("{} of {} tiles", done_ + in_band_, total_); }
  void finish() { progress_.finish(); }

 private:
  sdfrt::Renderer& renderer_;
  const OfflineFrame& f_;
  const OfflineOutput& out_;
  int tile_;
  sdfrt::RenderOptions opt_;
  sdfrt::ProgressBar progress_;
  sdfrt::FloatImage stopped_band_;
  int total_ = 0, done_ = 0, in_band_ = 0;
};

// A partial file from an earlier, interrupted run of the same output is stale now.
void remove_stale_partial(const OfflineOutput& out) {
  if (!out.keep_partial || !keeps_partial(out.format)) return;
  std::error_code ec;
  std::filesystem::remove(partial_path(out.beauty), ec);
}

}  // namespace

std::vector<std::string> render_offline(sdfrt::Renderer& renderer, const OfflineFrame& f, const OfflineOutput& out,
                                        int tile, std::atomic<bool>* cancel) {
  const sdfrt::KernelSpec& spec = renderer.spec();
  const int w = f.width, h = f.height;
  const float gamma = static_cast<float>(f.gamma);
  // A region decides progressive or not as its whole image does: the same bytes.
  const std::size_t pixels = out.window.full_width > 0 ? std::size_t(out.window.full_width) * std::size_t(out.window.full_height)
                                                     : static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const bool aov_planes = spec.planes.size() > 4;
  const std::size_t sums = SampleMean::floats_per_pixel(aov_planes, spec.planes.size() > abi::kImagePlanes.size() + abi::kAovPlanes.size());
  const bool progressive = f.samples > 1 && pixels * sums * sizeof(float) <= kMaxAccumulatorBytes;
  if (f.samples > 1 && !progressive && !out.quiet)
    std::cerr << fmt::format("note: {}x{} is too large to refine progressively; rendering all {} samples in one pass\n",
                             w, h, f.samples);
  const int passes = progressive ? f.samples : 1;
  const std::string partial = partial_path(out.beauty);
  BandLoop loop(renderer, f, out, tile, passes, cancel);
  auto open_sink = [&] { return open_frame_sink(spec, w, h, gamma, out); };

  if (!progressive) {
    auto sink = open_sink();
    loop.run(
        f.frame, [&](const sdfrt::FloatImage& band, int) { sink->write_band(band); },
        [&](int) {
          if (!keeps_partial(out.format)) return;
          // The bands streamed so far, this band's finished tiles, black below.
          sink->write_band(loop.stopped_band());
          std::cerr << fmt::format("sdfc: partial image: {} ({}; the rest is black)\n", sink->finish_partial(partial),
                                   loop.tiles_done());
        });
    std::vector<std::string> written = sink->finish();
    loop.finish();
    remove_stale_partial(out);
    return written;
  }

  // Progressive: pass k renders sample k of every pixel into a running mean.
  SampleMean mean(spec, w, h, gamma, out.format != Format::Exr);
  auto stream_mean = [&](FrameSink& sink) {
    for (int y0 = 0; y0 < h; y0 += tile) sink.write_band(mean.band(y0, std::min(tile, h - y0)));
  };
  std::vector<float> frame = f.frame;
  for (int pass = 0; pass < passes; ++pass) {
    frame[abi::kFirstSample] = static_cast<float>(pass);
    frame[abi::kSampleCount] = 1.0f;
    loop.run(
        frame, [&](const sdfrt::FloatImage& band, int y0) { mean.add(band, y0); },
        [&](int y0) {
          if (!keeps_partial(out.format)) return;
          // In the first pass the unfinished tiles stay black; later, the
          // band keeps the mean of the passes before.
          if (pass == 0) mean.add(loop.stopped_band(), y0);
          auto sink = open_sink();
          stream_mean(*sink);
          std::cerr << fmt::format("sdfc: partial image: {} (stopped in pass {} of {}: {} sample(s) per pixel{})\n",
                                   sink->finish_partial(partial), pass + 1, passes, std::max(pass, 1),
                                   pass == 0 ? ", the tiles not done are black" : ", one more above the stop");
        });
    mean.end_pass();
    if (out.keep_partial && pass + 1 < passes && keeps_partial(out.format)) {
      // Refreshed after every pass, to watch the image refine.
      auto sink = open_sink();
      stream_mean(*sink);
      sink->finish_partial(partial);
    }
  }
  auto sink = open_sink();
  stream_mean(*sink);
  std::vector<std::string> written = sink->finish();
  loop.finish();
  remove_stale_partial(out);
  return written;
}

}  // namespace sdfc::cli
