// sdfc merge PARTS... -o OUT.png: joins the region files of a still (from
// `sdfc render --parts` or `--region`) into the PNG and every AOV the parts
// carry, band by band, so only a few rows of the image are ever in memory.
#include <fmt/format.h>

#include <sdfrt/errors.hpp>
#include <sdfrt/progress.hpp>
#include <sdfrt/region_file.hpp>
#include <sdfrt/stream_writers.hpp>

#include <algorithm>
#include <iostream>

#include "commands.hpp"
#include "merge_plan.hpp"
#include "offline_render.hpp"

namespace sdfc::cli {
namespace {

constexpr int kBandRows = 64;

struct MergeArgs {
  std::vector<std::string> parts;
  std::string output;
  bool quiet = false;
};

std::vector<std::string> plane_names(const sdfrt::RegionSection& s) {
  if (s.channels == 1) return {s.name};
  return {s.name + "_0", s.name + "_1", s.name + "_2"};
}

// Rows [y0, y0 + rows) of one section of the whole image, from the parts
// that cover them.
sdfrt::FloatImage gather(const std::vector<sdfrt::RegionReader>& readers, int section, int y0, int rows) {
  const auto& first = readers.front().header();
  const auto& sec = first.sections[std::size_t(section)];
  const std::size_t ch = std::size_t(sec.channels), w = std::size_t(first.image_width);
  sdfrt::FloatImage band(first.image_width, rows, plane_names(sec));
  std::vector<float> buf;
  for (const auto& r : readers) {
    const auto& h = r.header();
    const int from = std::max(y0, h.y0), to = std::min(y0 + rows, h.y1);
    if (from >= to) continue;
    const std::size_t pw = std::size_t(h.width());
    buf.resize(pw * ch * std::size_t(to - from));
    r.read_rows(section, from - h.y0, to - from, buf.data());
    for (int y = from; y < to; ++y)
      for (std::size_t c = 0; c < ch; ++c) {
        float* dst = band.plane(int(c)).data() + std::size_t(y - y0) * w + std::size_t(h.x0);
        const float* src = buf.data() + std::size_t(y - from) * pw * ch + c;
        for (std::size_t x = 0; x < pw; ++x) dst[x] = src[x * ch];
      }
  }
  return band;
}

int run_merge(const MergeArgs& a) {
  std::vector<sdfrt::RegionReader> readers;
  std::vector<PartInfo> infos;
  for (const auto& p : a.parts) {
    try {
      readers.emplace_back(p);
    } catch (const sdfrt::IoError& e) {
      throw sdfrt::IoError(fmt::format("{} (file {} of the {} given; did its task fail?)", e.what(),
                                       readers.size() + 1, a.parts.size()),
                           e.path(), e.errno_value());
    }
    infos.push_back({p, readers.back().header()});
  }
  check_parts(infos);
  const auto& h = readers.front().header();
  std::vector<std::unique_ptr<sdfrt::BandWriter>> writers;
  for (const auto& s : h.sections) {
    if (s.name == "beauty")
      writers.push_back(sdfrt::open_png_writer(a.output, h.image_width, h.image_height, {0, 1, 2}, h.bit_depth));
    else
      writers.push_back(sdfrt::open_pfm_writer(aov_path(a.output, s.name), h.image_width, h.image_height,
                                               s.channels == 1 ? std::vector<int>{0} : std::vector<int>{0, 1, 2}));
  }
  sdfrt::ProgressBar bar("rows");
  for (int y0 = 0; y0 < h.image_height; y0 += kBandRows) {
    const int rows = std::min(kBandRows, h.image_height - y0);
    for (std::size_t s = 0; s < h.sections.size(); ++s) writers[s]->write_band(gather(readers, int(s), y0, rows));
    if (!a.quiet) bar.update(y0 + rows, h.image_height);
  }
  if (!a.quiet) bar.finish();
  long long nonfinite = 0;
  for (auto& w : writers) {
    const sdfrt::WriteReport rep = w->finish();
    nonfinite += rep.nonfinite_samples;
    std::cout << rep.path << "\n";
  }
  if (nonfinite > 0) std::cerr << fmt::format("warning: {} NaN/Inf samples were written as 0\n", nonfinite);
  return kOk;
}

}  // namespace

Action add_merge(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "merge", "Join the region files of a still (sdfc render --parts/--region) into its PNG and AOVs");
  auto a = std::make_shared<MergeArgs>();
  cmd->add_option("parts", a->parts, "Region files, every part of the image exactly once")->required();
  cmd->add_option("-o,--output", a->output,
                  "Output PNG (8 or 16 bit, as the parts were rendered); AOVs go beside it as OUT.<aov>.pfm")
      ->required();
  cmd->add_flag("-q,--quiet", a->quiet, "No progress on stderr");
  return [a] { return run_merge(*a); };
}

}  // namespace sdfc::cli
