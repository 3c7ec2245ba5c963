#pragma once
// Offline rendering of one frame to files: the image is rendered band by
// band (one row of tiles at a time) and streamed to the writers, so memory
// stays bounded at any size up to 16384x16384. With render.samples > 1 the
// samples are rendered pass by pass into a running mean. The final name is
// written once, complete; a cancelled render leaves it untouched and, only
// when asked (keep_partial), writes what was done to <stem>.partial.<ext>.
#include <sdfrt/renderer.hpp>
#include <sdfrt/video_writer.hpp>

#include "frame_sequence.hpp"
#include "output_format.hpp"

#include <sdfrt/stream_writers.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sdfc::cli {

struct OfflineOutput {
  std::string beauty;              // the image's path (unused for a video frame)
  Format format = Format::Png;     // EXR gets the kernel's linear colour, the rest display values
  int bit_depth = 8;               // resolved by resolve_choices
  int quality = -1;                // JPEG quality
  bool alpha = false;              // the kernel leaves misses out of the colour; the hit plane is alpha
  std::vector<std::string> aovs;   // of kAovNames
  sdfrt::VideoWriter* video = nullptr;  // video formats: where every frame goes
  bool quiet = false;
  // On cancel, write the tiles done so far to partial_path(beauty) (the
  // rest black); with several samples it is also refreshed after each pass.
  bool keep_partial = false;
  // When set, the bands go here instead of the format's files (a still's
  // region file, cli/region_render.cpp): called with "" for the image, else
  // an AOV's name, and the kernel planes it takes.
  std::function<std::unique_ptr<sdfrt::BandWriter>(const std::string& aov, int width, int height, std::vector<int> planes)>
      open_band_writer;
  // A still's region: the frame's width x height pixels at (x0, y0) of the whole image.
  sdfrt::RenderOptions::Window window;
};

// The AOVs --aov accepts (kernel planes of the same names). With several
// samples per pixel each is a pixel average: "hit" is the coverage (the
// fraction of samples that hit, 0 or 1 with one sample), depth, normal
// (normalised) and iterations the means over the samples that hit, steps
// the mean over all, material that of the first sample that hits.
// albedo: the path integrator's first-hit albedo, for denoisers.
inline const std::vector<std::string> kAovNames = {"depth", "normal", "steps", "iterations", "material", "hit", "albedo"};

// "<dir>/<stem>.<aov>.pfm" beside the beauty image.
std::string aov_path(const std::string& beauty, const std::string& aov);
// "<dir>/<stem>.partial<ext>": out.png -> out.partial.png.
std::string partial_path(const std::string& beauty);

struct OfflineFrame {
  std::vector<float> frame;  // the frame block (frame_params)
  int width = 0, height = 0;
  int samples = 1;
  double gamma = 2.2;
};

// Renders and writes; returns the paths written. Throws sdfrt::Cancelled
// when cancelled, after removing its temporary files (and writing the
// partial image if asked).
std::vector<std::string> render_offline(sdfrt::Renderer& renderer, const OfflineFrame& f, const OfflineOutput& out,
                                        int tile, std::atomic<bool>* cancel);

// Writes the AOVs of a whole rendered image (--repeat); returns the paths.
std::vector<std::string> write_aovs(const sdfrt::KernelSpec& spec, const sdfrt::FloatImage& image,
                                    const std::string& beauty, const std::vector<std::string>& aovs);

}  // namespace sdfc::cli
