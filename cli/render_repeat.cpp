#include "render_repeat.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <sdfrt/errors.hpp>
#include <sdfrt/image_io.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "offline_render.hpp"
#include "sdfc/codegen/emit_opencl.hpp"

namespace sdfc::cli {
namespace {

// The whole image lives in host memory (the device only holds one tile), so
// refuse sizes the machine cannot hold before allocating anything.
void check_host_memory(int w, int h, size_t planes) {
  const double bytes = double(w) * double(h) * double(planes) * sizeof(float);
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return;
  const double usable = 0.75 * double(pages) * double(page);
  if (bytes > usable)
    throw sdfrt::DeviceError(fmt::format("a {}x{} image with {} planes needs {:.1f} GiB of memory, more than this "
                                         "machine can give ({:.1f} GiB); render a smaller image",
                                         w, h, planes, bytes / 1073741824.0, usable / 1073741824.0));
}

}  // namespace

int render_repeated(const RepeatJob& job) {
  sdfrt::Renderer& renderer = *job.renderer;
  const int w = job.plan->march.width, h = job.plan->march.height;
  check_host_memory(w, h, renderer.spec().planes.size());
  std::vector<float> frame = codegen::frame_params(*job.plan, w, h, 0.0);
  sdfrt::RenderOptions opt;
  opt.tile_width = opt.tile_height = job.tile;
  opt.cancel = job.cancel;
  // One warm-up frame, then N timed frames; the median is what to quote.
  renderer.render(frame, w, h, opt);
  std::vector<double> times;
  sdfrt::FloatImage img;
  for (int i = 0; i < job.repeat; ++i) {
    sdfrt::RenderStats st;
    img = renderer.render(frame, w, h, opt, &st);
    times.push_back(st.total_ms);
    std::cerr << fmt::format("frame {}: {:.1f} ms\n", i + 1, st.total_ms);
  }
  std::sort(times.begin(), times.end());
  double median = times.size() % 2 ? times[times.size() / 2] : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
  std::cerr << fmt::format("median {:.1f} ms over {} frames ({}x{})\n", median, job.repeat, w, h);
  sdfrt::WriteReport rep = sdfrt::write_png(job.output, img);
  if (rep.nonfinite_samples > 0)
    std::cerr << fmt::format("warning: {} NaN/Inf samples were written as black\n", rep.nonfinite_samples);
  std::cout << rep.path << "\n";
  // The AOVs of the last timed frame, so one run gives both time and error.
  for (const auto& p : write_aovs(renderer.spec(), img, job.output, job.aovs)) std::cout << p << "\n";
  return kOk;
}

}  // namespace sdfc::cli
