#include "offline_render.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
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

struct AovWriters {
  std::vector<std::unique_ptr<sdfrt::BandWriter>> writers;
  std::vector<std::string> paths;
  AovWriters(const sdfrt::KernelSpec& spec, int width, int height, const std::string& beauty,
             const std::vector<std::string>& aovs) {
    for (const auto& a : aovs) {
      std::vector<int> planes;
      if (a == "normal")
        planes = {plane_of(spec, "normal_x"), plane_of(spec, "normal_y"), plane_of(spec, "normal_z")};
      else
        planes = {plane_of(spec, a)};
      paths.push_back(aov_path(beauty, a));
      writers.push_back(sdfrt::open_pfm_writer(paths.back(), width, height, planes));
    }
  }
  AovWriters(const sdfrt::KernelSpec& spec, const OfflineFrame& f, const OfflineOutput& out)
      : AovWriters(spec, f.width, f.height, out.beauty, out.aovs) {}
  void write(const sdfrt::FloatImage& band) {
    for (auto& w : writers) w->write_band(band);
  }
  void finish() {
    for (auto& w : writers) w->finish();
  }
};

// Progressive rendering with AOVs: each pass gives the AOVs of one sample;
// these sums make them the pixel averages the kernel gives for a pass of
// several samples (hit = coverage; depth, normal, iterations = means over
// the samples that hit; steps = mean; material = the first sample that hits).
struct AovMean {
  int w, h;
  int depth, nx, ny, nz, steps, material, iterations, hit;  // planes of the band
  std::vector<std::string> names;
  std::vector<float> hits, depth_sum, normal_sum, steps_sum, iter_sum, first_material;
  int passes = 0;
  AovMean(const sdfrt::KernelSpec& spec, int w_, int h_)
      : w(w_), h(h_), depth(plane_of(spec, "depth")), nx(plane_of(spec, "normal_x")), ny(plane_of(spec, "normal_y")),
        nz(plane_of(spec, "normal_z")), steps(plane_of(spec, "steps")), material(plane_of(spec, "material")),
        iterations(plane_of(spec, "iterations")), hit(plane_of(spec, "hit")), names(spec.planes) {
    const std::size_t n = std::size_t(w) * std::size_t(h);
    hits.assign(n, 0.0f), depth_sum.assign(n, 0.0f), normal_sum.assign(3 * n, 0.0f), steps_sum.assign(n, 0.0f);
    iter_sum.assign(n, 0.0f), first_material.assign(n, -1.0f);
  }
  // One pass of one sample per pixel, rows [y0, y0 + band.height).
  void add(const sdfrt::FloatImage& band, int y0) {
    const std::size_t n = std::size_t(w) * std::size_t(h), at = std::size_t(y0) * std::size_t(w);
    auto d = band.plane(depth), c = band.plane(hit), s = band.plane(steps), it = band.plane(iterations),
         mat = band.plane(material);
    std::span<const float> nrm[3] = {band.plane(nx), band.plane(ny), band.plane(nz)};
    for (std::size_t i = 0; i < d.size(); ++i) {
      const std::size_t j = at + i;
      const float k = c[i];  // 1 for a hit (one sample per pass)
      if (k > 0 && first_material[j] < 0) first_material[j] = mat[i];
      hits[j] += k;
      if (k > 0) depth_sum[j] += k * d[i], iter_sum[j] += k * it[i];
      for (int a = 0; a < 3; ++a) normal_sum[a * n + j] += k * nrm[a][i];
      steps_sum[j] += s[i];
    }
  }
  // The averages of rows [y0, y0 + rows), as a band with the kernel's planes.
  sdfrt::FloatImage band(int y0, int rows) const {
    const std::size_t n = std::size_t(w) * std::size_t(h), at = std::size_t(y0) * std::size_t(w);
    sdfrt::FloatImage b(w, rows, names);
    const float inv = passes > 0 ? 1.0f / float(passes) : 0.0f;
    for (std::size_t i = 0; i < b.plane_size(); ++i) {
      const std::size_t j = at + i;
      const float nh = hits[j];
      b.plane(hit)[i] = nh * inv;
      b.plane(depth)[i] = nh > 0 ? depth_sum[j] / nh : -1.0f;
      b.plane(iterations)[i] = nh > 0 ? iter_sum[j] / nh : 0.0f;
      b.plane(steps)[i] = steps_sum[j] * inv;
      b.plane(material)[i] = first_material[j];
      const float x = normal_sum[j], y = normal_sum[n + j], z = normal_sum[2 * n + j];
      const float len = std::sqrt(x * x + y * y + z * z);
      const float s = len > 1e-30f ? 1.0f / len : 0.0f;
      b.plane(nx)[i] = x * s, b.plane(ny)[i] = y * s, b.plane(nz)[i] = z * s;
    }
    return b;
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
  // RGB sums, and with AOVs 8 more planes of sums (AovMean)
  const std::size_t sums = out.aovs.empty() ? 3 : 11;
  const bool progressive = f.samples > 1 && pixels * sums * sizeof(float) <= kMaxAccumulatorBytes;
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
  std::optional<AovMean> aov_mean;
  if (!out.aovs.empty()) aov_mean.emplace(spec, w, h);
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
      if (aov_mean) aov_mean->add(band, opt.row_begin);
      progress.done += tiles_in(w, opt.row_count, tile);
    }
    if (aov_mean) ++aov_mean->passes;
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
  if (aov_mean) {
    for (int y0 = 0; y0 < h; y0 += tile) aovs.write(aov_mean->band(y0, std::min(tile, h - y0)));
    aovs.finish();
  }
  return done();
}

std::vector<int> parse_frames(const std::string& spec) {
  static const std::regex re(R"(^(\d+)(?::(\d+)(?::(\d+))?)?$)");
  std::smatch m;
  if (!std::regex_match(spec, m, re))
    throw std::invalid_argument(fmt::format("--frames '{}': expected N, FIRST:LAST or FIRST:LAST:STEP (e.g. 0:120)", spec));
  auto number = [&](const std::string& digits) {
    if (digits.size() > 9) throw std::invalid_argument(fmt::format("--frames '{}': frame numbers go up to 999999999", spec));
    return std::stoi(digits);
  };
  int first = number(m[1]);
  int last = m[2].matched ? number(m[2]) : first;
  int step = m[3].matched ? number(m[3]) : 1;
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
  if (flags.size() > 2)  // %0Nd up to 99 digits wide; a wider field is a typo, not a name
    throw std::invalid_argument(fmt::format("-o '{}': the frame field is wider than 99 digits", pattern.substr(0, 200)));
  int width = flags.empty() ? 0 : std::stoi(flags);
  std::string num = fmt::format("{}", frame);
  if (static_cast<int>(num.size()) < width) num = std::string(width - num.size(), flags[0] == '0' ? '0' : ' ') + num;
  return m.prefix().str() + num + m.suffix().str();
}

}  // namespace sdfc::cli
