// A still's parts as region files: each part is rendered as a window of the
// whole image (the kernel sees the whole image's size and pixel positions,
// and seeds its samples per pixel), so the merged parts have the bytes of
// one whole render.
#include <fmt/format.h>

#include <sdfrt/errors.hpp>
#include <sdfrt/region_file.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "farm_render.hpp"
#include "sdfc/codegen/emit_opencl.hpp"

namespace sdfc::cli {
namespace {

std::vector<sdfrt::RegionSection> sections_for(const std::vector<std::string>& aovs) {
  std::vector<sdfrt::RegionSection> s{{"beauty", 3}};
  for (const auto& a : aovs) s.push_back({a, a == "normal" ? 3 : 1});
  return s;
}

// The kernel without its comments, which name the scene file and its lines:
// the same scene at another path renders the same pixels.
std::string code_of(const std::string& source) {
  std::string code;
  for (std::size_t at = 0; at < source.size();) {
    const std::size_t nl = std::min(source.find('\n', at), source.size());
    const std::size_t end = std::min(source.find("//", at), nl);
    code.append(source, at, end - at).push_back('\n');
    at = nl + 1;
  }
  return code;
}

// What decides the pixels: parts with different fingerprints do not merge.
std::string identity(const StillJob& job, const std::vector<float>& frame) {
  std::string id = code_of(job.renderer->spec().source);
  id += fmt::format("|{}x{}|{}|{}|{}|", job.width, job.height, job.plan->march.samples, job.plan->march.gamma,
                    job.out.bit_depth);
  for (const auto& a : job.out.aovs) id += a + ",";
  id.append(reinterpret_cast<const char*>(frame.data()), frame.size() * sizeof(float));
  return id;
}

void render_part(const StillJob& job, const Rect& r, int part, int parts, const std::string& path,
                 const std::string& fingerprint, const std::vector<float>& frame) {
  sdfrt::RegionHeader h;
  h.image_width = job.width, h.image_height = job.height;
  h.x0 = r.x0, h.y0 = r.y0, h.x1 = r.x1, h.y1 = r.y1;
  h.bit_depth = job.out.bit_depth;
  h.part = part, h.parts = parts;
  h.fingerprint = fingerprint;
  h.sections = sections_for(job.out.aovs);
  sdfrt::RegionWriter file(path, h);
  OfflineOutput out = job.out;
  out.beauty = path;
  out.keep_partial = false;
  out.window = {job.width, job.height, r.x0, r.y0};
  out.open_band_writer = [&file](const std::string& aov, int, int, std::vector<int> planes) {
    return file.section(aov.empty() ? "beauty" : aov, std::move(planes));
  };
  OfflineFrame f{frame, r.width(), r.height(), job.plan->march.samples, job.plan->march.gamma};

  render_offline(*job.renderer, f, out, job.tile, job.cancel);
  file.commit();
}

void require_region_name(const std::string& path) {
  if (std::filesystem::path(path).extension() != ".region")
    throw std::invalid_argument(fmt::format(
        "-o '{}': a part of a still is a region file, so -o must end in .region (e.g. out/part_%03d.region); "
        "'sdfc merge PARTS... -o image.png' then writes the image",
        path));
}

}  // namespace

int render_still_parts(const StillJob& job, const FarmArgs& farm) {
  require_region_name(job.output);
  const std::vector<float> frame = codegen::frame_params(*job.plan, job.width, job.height, 0.0);
  const std::string fingerprint = sdfrt::region_fingerprint(identity(job, frame));
  if (!farm.region.empty()) {
    if (!farm.shard.empty()) throw std::invalid_argument("--shard splits --parts or --frames, not one --region");
    const Rect r = parse_region(farm.region, job.width, job.height);
    render_part(job, r, -1, 0, job.output, fingerprint, frame);
    std::cout << job.output << "\n";
    return 0;
  }
  if (!has_frame_field(job.output) && farm.parts > 1)
    throw std::invalid_argument(fmt::format(
        "-o '{}': {} parts need a part-number field in the name, e.g. out/part_%03d.region", job.output, farm.parts));
  const IndexSlice mine = farm.task_slice(farm.parts);
  for (int part = int(mine.begin); part < mine.end; part += int(mine.stride)) {
    const Rect r = strip_region(job.width, job.height, part, farm.parts);
    const std::string path = has_frame_field(job.output) ? frame_path(job.output, part) : job.output;
    if ((!farm.shard.empty() || farm.skip_complete) && output_complete(path)) {
      if (!job.out.quiet) std::cerr << fmt::format("part {}: {} is complete already, skipped\n", part, path);
      continue;
    }
    auto parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec) throw sdfrt::IoError(fmt::format("cannot create '{}': {}", parent.string(), ec.message()), parent.string(), ec.value());
    const auto start = std::chrono::steady_clock::now();
    render_part(job, r, part, farm.parts, path, fingerprint, frame);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!job.out.quiet)
      std::cerr << fmt::format("part {} of {} (rows {}..{}): rendered in {:.0f} ms\n", part, farm.parts, r.y0,
                               r.y1 - 1, ms);
    std::cout << path << "\n";
  }
  return 0;
}

}  // namespace sdfc::cli
