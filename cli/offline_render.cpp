#include "offline_render.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <regex>
#include <sdfrt/errors.hpp>
#include <sdfrt/progress.hpp>
#include <sdfrt/stream_writers.hpp>
#include <stdexcept>

namespace sdfc::cli {

namespace {

// Progressive rendering keeps a float RGB sum of the whole image; above this
// it renders all samples in one pass, streamed (and says so).
constexpr std::size_t kMaxAccumulatorBytes = std::size_t(1) << 30;

int plane_of(const sdfrt::KernelSpec& spec, const std::string& name) {
  auto it = std::find(spec.planes.begin(), spec.planes.end(), name);
  if (it == spec.planes.end()) throw std::logic_error("the kernel has no plane " + name);
  return static_cast<int>(it - spec.planes.begin());
}

// The hit mask of a band: 1 where depth >= 0 (a hit), 0 on a miss.
sdfrt::FloatImage hit_mask(const sdfrt::FloatImage& band, int depth_plane) {
  sdfrt::FloatImage m(band.width, band.height, {"hit"});
  auto d = band.plane(depth_plane);
  auto h = m.plane(0);
  for (std::size_t i = 0; i < d.size(); ++i) h[i] = d[i] >= 0.0f ? 1.0f : 0.0f;
  return m;
}

struct AovWriters {
  std::vector<std::unique_ptr<sdfrt::BandWriter>> writers;
  std::vector<std::string> paths;
  std::vector<int> derived_from;  // for "hit": the depth plane; -1 otherwise
  AovWriters(const sdfrt::KernelSpec& spec, int width, int height, const std::string& beauty,
             const std::vector<std::string>& aovs) {
    for (const auto& a : aovs) {
      std::vector<int> planes;
      derived_from.push_back(a == "hit" ? plane_of(spec, "depth") : -1);
      if (a == "normal")
        planes = {plane_of(spec, "normal_x"), plane_of(spec, "normal_y"), plane_of(spec, "normal_z")};
      else if (a == "hit")
        planes = {0};
      else
        planes = {plane_of(spec, a)};
      paths.push_back(aov_path(beauty, a));
      writers.push_back(sdfrt::open_pfm_writer(paths.back(), width, height, planes));
    }
  }
  AovWriters(const sdfrt::KernelSpec& spec, const OfflineFrame& f, const OfflineOutput& out)
      : AovWriters(spec, f.width, f.height, out.beauty, out.aovs) {}
  void write(const sdfrt::FloatImage& band) {
    for (std::size_t i = 0; i < writers.size(); ++i) {
      if (derived_from[i] >= 0)
        writers[i]->write_band(hit_mask(band, derived_from[i]));
      else
        writers[i]->write_band(band);
    }
  }
  void finish() {
    for (auto& w : writers) w->finish();
  }
};

// Tile progress over every band (and pass) of a frame.
struct FrameProgress {
  sdfrt::ProgressBar bar{"tiles"};
  int total = 0, done = 0;
  int in_band = 0;  // tiles done in the band being rendered
  bool quiet;
  explicit FrameProgress(bool q) : quiet(q) {}
  std::function<void(int, int)> band_callback() {
    return [this](int d, int) {
      in_band = d;
      if (!quiet) bar.update(done + d, total);
    };
  }
};

int tiles_in(int width, int rows, int tile) { return ((width + tile - 1) / tile) * ((rows + tile - 1) / tile); }

void say_not_written(const OfflineOutput& out) {
  std::cerr << fmt::format("sdfc: stopped; {} was not written{}\n", out.beauty,
                           out.keep_partial ? "" : fmt::format(" (--keep-partial keeps the tiles done in {})",
                                                               partial_path(out.beauty)));
}

// Progressive rendering: the sum of the tone-mapped samples and how many
// samples each row holds (a stopped pass leaves rows with one fewer).
struct RunningMean {
  int w, h;
  float gamma;
  std::vector<float> sum;
  std::vector<int> row_samples;
  RunningMean(int w_, int h_, float g)
      : w(w_), h(h_), gamma(g), sum(std::size_t(w_) * std::size_t(h_) * 3, 0.0f), row_samples(std::size_t(h_), 0) {}

  // The kernel returns display values, gamma(mean of tone-mapped samples);
  // undoing the gamma gives the tone-mapped mean, which averages across passes.
  void add(const sdfrt::FloatImage& band, int y0) {
    const std::size_t pixels = std::size_t(w) * std::size_t(h), at = std::size_t(y0) * std::size_t(w);
    for (int c = 0; c < 3; ++c) {
      auto plane = band.plane(c);
      float* s = sum.data() + c * pixels + at;
      for (std::size_t i = 0; i < plane.size(); ++i) s[i] += std::pow(std::clamp(plane[i], 0.0f, 1.0f), gamma);
    }
    for (int y = y0; y < y0 + band.height; ++y) ++row_samples[std::size_t(y)];
  }

  // Streams the mean to a PNG writer, `tile` rows at a time (black where a
  // row has no sample yet).
  void write(sdfrt::BandWriter& out, int tile) const {
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    const float inv_gamma = 1.0f / gamma;
    for (int y0 = 0; y0 < h; y0 += tile) {
      const int rows = std::min(tile, h - y0);
      sdfrt::FloatImage band(w, rows, {"r", "g", "b"});
      for (int c = 0; c < 3; ++c) {
        auto dst = band.plane(c);
        const float* s = sum.data() + c * pixels + std::size_t(y0) * std::size_t(w);
        for (int y = 0; y < rows; ++y) {
          const int n = row_samples[std::size_t(y0 + y)];
          const float scale = n > 0 ? 1.0f / float(n) : 0.0f;
          for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            dst[i] = std::pow(s[i] * scale, inv_gamma);
          }
        }
      }
      out.write_band(band);
    }
  }
};

}  // namespace

std::vector<std::string> write_aovs(const sdfrt::KernelSpec& spec, const sdfrt::FloatImage& image,
                                    const std::string& beauty, const std::vector<std::string>& aovs) {
  AovWriters w(spec, image.width, image.height, beauty, aovs);
  w.write(image);
  w.finish();
  return w.paths;
}

std::string aov_path(const std::string& beauty, const std::string& aov) {
  std::filesystem::path p(beauty);
  return (p.parent_path() / (p.stem().string() + "." + aov + ".pfm")).string();
}

std::string partial_path(const std::string& beauty) {
  std::filesystem::path p(beauty);
  return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

std::vector<std::string> render_offline(sdfrt::Renderer& renderer, const OfflineFrame& f, const OfflineOutput& out,
                                        int tile, std::atomic<bool>* cancel) {
  const sdfrt::KernelSpec& spec = renderer.spec();
  const int w = f.width, h = f.height;
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const bool progressive = f.samples > 1 && pixels * 3 * sizeof(float) <= kMaxAccumulatorBytes;
  if (f.samples > 1 && !progressive && !out.quiet)
    std::cerr << fmt::format("note: {}x{} is too large to refine progressively; rendering all {} samples in one pass\n",
                             w, h, f.samples);
  const int passes = progressive ? f.samples : 1;
  const int bands = (h + tile - 1) / tile;
  const std::string partial = partial_path(out.beauty);
  FrameProgress progress(out.quiet);
  progress.total = tiles_in(w, h, tile) * passes;

  sdfrt::RenderOptions opt;
  opt.tile_width = opt.tile_height = tile;
  opt.cancel = cancel;
  opt.progress = progress.band_callback();
  // On cancel the renderer hands over the band with the tiles it finished.
  sdfrt::FloatImage stopped_band;
  if (out.keep_partial) opt.partial = &stopped_band;

  AovWriters aovs(spec, f, out);
  std::vector<std::string> written;
  std::vector<float> frame = f.frame;
  auto done = [&] {
    progress.bar.finish();
    // A partial file from an earlier, interrupted run of the same output is stale now.
    if (out.keep_partial) {
      std::error_code ec;
      std::filesystem::remove(partial, ec);
    }
    written.insert(written.end(), aovs.paths.begin(), aovs.paths.end());
    return written;
  };
  if (!progressive) {
    auto beauty = sdfrt::open_png_writer(out.beauty, w, h, {0, 1, 2}, out.bit_depth);
    for (int b = 0; b < bands; ++b) {
      opt.row_begin = b * tile;
      opt.row_count = std::min(tile, h - opt.row_begin);
      sdfrt::FloatImage band;
      try {
        band = renderer.render(frame, w, h, opt);
      } catch (const sdfrt::Cancelled&) {
        progress.bar.finish();
        say_not_written(out);
        if (out.keep_partial) {
          // The bands streamed so far, this band's finished tiles, black below.
          beauty->write_band(stopped_band);
          std::cerr << fmt::format("sdfc: partial image: {} ({} of {} tiles; the rest is black)\n",
                                   beauty->finish_partial(partial).path, progress.done + progress.in_band,
                                   progress.total);
        }
        throw;
      }
      beauty->write_band(band);
      aovs.write(band);
      progress.done += tiles_in(w, opt.row_count, tile);
    }
    written.push_back(beauty->finish().path);
    aovs.finish();
    return done();
  }

  // Progressive: pass k renders sample k of every pixel into a running mean.
  RunningMean mean(w, h, static_cast<float>(f.gamma));
  for (int pass = 0; pass < passes; ++pass) {
    frame[26] = static_cast<float>(pass);
    frame[27] = 1.0f;
    for (int b = 0; b < bands; ++b) {
      opt.row_begin = b * tile;
      opt.row_count = std::min(tile, h - opt.row_begin);
      sdfrt::FloatImage band;
      try {
        band = renderer.render(frame, w, h, opt);
      } catch (const sdfrt::Cancelled&) {
        progress.bar.finish();
        say_not_written(out);
        if (out.keep_partial) {
          // In the first pass the unfinished tiles stay black; later, the
          // band keeps the mean of the passes before.
          if (pass == 0) mean.add(stopped_band, opt.row_begin);
          auto writer = sdfrt::open_png_writer(out.beauty, w, h, {0, 1, 2}, out.bit_depth);
          mean.write(*writer, tile);
          std::cerr << fmt::format("sdfc: partial image: {} (stopped in pass {} of {}: {} sample(s) per pixel{})\n",
                                   writer->finish_partial(partial).path, pass + 1, passes, std::max(pass, 1),
                                   pass == 0 ? ", the tiles not done are black" : ", one more above the stop");
        }
        throw;
      }
      mean.add(band, opt.row_begin);
      if (pass == 0) aovs.write(band);
      progress.done += tiles_in(w, opt.row_count, tile);
    }
    if (pass == 0) aovs.finish();
    if (out.keep_partial && pass + 1 < passes) {
      // Refreshed after every pass, to watch the image refine.
      auto writer = sdfrt::open_png_writer(out.beauty, w, h, {0, 1, 2}, out.bit_depth);
      mean.write(*writer, tile);
      writer->finish_partial(partial);
    }
  }
  auto beauty = sdfrt::open_png_writer(out.beauty, w, h, {0, 1, 2}, out.bit_depth);
  mean.write(*beauty, tile);
  written.push_back(beauty->finish().path);
  return done();
}

std::vector<int> parse_frames(const std::string& spec) {
  static const std::regex re(R"(^(\d+)(?::(\d+)(?::(\d+))?)?$)");
  std::smatch m;
  if (!std::regex_match(spec, m, re))
    throw std::invalid_argument(fmt::format("--frames '{}': expected N, FIRST:LAST or FIRST:LAST:STEP (e.g. 0:120)", spec));
  int first = std::stoi(m[1]);
  int last = m[2].matched ? std::stoi(m[2]) : first;
  int step = m[3].matched ? std::stoi(m[3]) : 1;
  if (last < first || step < 1)
    throw std::invalid_argument(fmt::format("--frames '{}': LAST must not be before FIRST and STEP must be at least 1", spec));
  if ((last - first) / step >= 100000) throw std::invalid_argument(fmt::format("--frames '{}': more than 100000 frames", spec));
  std::vector<int> out;
  for (int i = first; i <= last; i += step) out.push_back(i);
  return out;
}

namespace {
const std::regex kFrameField(R"(%(0?\d*)d)");
}

bool has_frame_field(const std::string& pattern) {
  return std::distance(std::sregex_iterator(pattern.begin(), pattern.end(), kFrameField), std::sregex_iterator()) == 1;
}

std::string frame_path(const std::string& pattern, int frame) {
  std::smatch m;
  if (!has_frame_field(pattern) || !std::regex_search(pattern, m, kFrameField))
    throw std::invalid_argument(fmt::format(
        "-o '{}': a sequence needs one frame-number field such as %04d in the file name", pattern));
  std::string flags = m[1];
  int width = flags.empty() ? 0 : std::stoi(flags);
  std::string num = fmt::format("{}", frame);
  if (static_cast<int>(num.size()) < width) num = std::string(width - num.size(), flags[0] == '0' ? '0' : ' ') + num;
  return m.prefix().str() + num + m.suffix().str();
}

}  // namespace sdfc::cli
