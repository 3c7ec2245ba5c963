#pragma once
// Progressive rendering (render.samples > 1): pass k renders sample k of
// every pixel; these sums turn the passes into the image the kernel gives
// for one pass of all samples. The colour is averaged as the kernel
// averages it (tone-mapped samples, then gamma; or linear for EXR), the
// AOVs as pixel averages: hit = coverage; depth, normal (normalised) and
// iterations = means over the samples that hit; steps = mean; material =
// that of the first sample that hits.
#include <sdfrt/float_image.hpp>
#include <sdfrt/renderer.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sdfc::cli {

class SampleMean {
 public:
  // `encoded`: the kernel's colour is gamma-encoded (undo it to average).
  SampleMean(const sdfrt::KernelSpec& spec, int width, int height, float gamma, bool encoded);
  // Sums needed per pixel for a kernel with (true) or without AOV planes.
  // (A path-traced kernel's albedo planes add 3.)
  static std::size_t floats_per_pixel(bool aov_planes, bool albedo = false) { return (aov_planes ? 11 : 3) + (albedo ? 3 : 0); }

  // One pass of one sample per pixel, rows [y0, y0 + band.height).
  void add(const sdfrt::FloatImage& band, int y0);
  void end_pass() { ++passes_; }
  // Rows [y0, y0 + rows) of the mean, with the kernel's planes; rows with
  // no sample yet are black.
  sdfrt::FloatImage band(int y0, int rows) const;

 private:
  struct Aovs {
    int depth, nx, ny, nz, steps, material, iterations, hit;  // plane indices
    std::vector<float> hits, depth_sum, normal_sum, steps_sum, iter_sum, first_material;
    int albedo;                     // albedo_r (g, b follow), or -1: a mean over the samples that hit
    std::vector<float> albedo_sum;  // plane-major
  };
  int w_, h_;
  float gamma_;
  bool encoded_;
  std::vector<std::string> names_;
  std::vector<float> sum_;  // RGB, plane-major
  std::vector<int> row_samples_;
  std::optional<Aovs> aovs_;
  int passes_ = 0;
};

// Index of a kernel plane; std::logic_error if the kernel has none of that name.
int plane_of(const sdfrt::KernelSpec& spec, const std::string& name);

}  // namespace sdfc::cli
