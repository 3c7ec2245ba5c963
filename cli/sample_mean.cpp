#include "sample_mean.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

namespace sdfc::cli {

int plane_of(const sdfrt::KernelSpec& spec, const std::string& name) {
  auto it = std::find(spec.planes.begin(), spec.planes.end(), name);
  if (it == spec.planes.end()) throw std::logic_error("the kernel has no plane " + name);
  return static_cast<int>(it - spec.planes.begin());
}

SampleMean::SampleMean(const sdfrt::KernelSpec& spec, int width, int height, float gamma, bool encoded)
    : w_(width), h_(height), gamma_(gamma), encoded_(encoded), names_(spec.planes),
      sum_(std::size_t(width) * std::size_t(height) * 3, 0.0f), row_samples_(std::size_t(height), 0) {
  if (std::find(spec.planes.begin(), spec.planes.end(), "hit") == spec.planes.end()) return;
  const std::size_t n = std::size_t(w_) * std::size_t(h_);
  Aovs a{plane_of(spec, "depth"), plane_of(spec, "normal_x"), plane_of(spec, "normal_y"),
         plane_of(spec, "normal_z"), plane_of(spec, "steps"), plane_of(spec, "material"),
         plane_of(spec, "iterations"), plane_of(spec, "hit"), {}, {}, {}, {}, {}, {}, -1, {}};
  if (std::find(spec.planes.begin(), spec.planes.end(), "albedo_r") != spec.planes.end()) {
    a.albedo = plane_of(spec, "albedo_r");
    a.albedo_sum.assign(3 * n, 0.0f);
  }
  a.hits.assign(n, 0.0f), a.depth_sum.assign(n, 0.0f), a.normal_sum.assign(3 * n, 0.0f), a.steps_sum.assign(n, 0.0f);
  a.iter_sum.assign(n, 0.0f), a.first_material.assign(n, -1.0f);
  aovs_ = std::move(a);
}

void SampleMean::add(const sdfrt::FloatImage& band, int y0) {
  const std::size_t n = std::size_t(w_) * std::size_t(h_), at = std::size_t(y0) * std::size_t(w_);
  // The kernel returns display values, gamma(mean of tone-mapped samples);
  // undoing the gamma gives the tone-mapped mean, which averages across passes.
  for (int c = 0; c < 3; ++c) {
    auto plane = band.plane(c);
    float* s = sum_.data() + c * n + at;
    for (std::size_t i = 0; i < plane.size(); ++i)
      s[i] += encoded_ ? std::pow(std::clamp(plane[i], 0.0f, 1.0f), gamma_) : plane[i];
  }
  for (int y = y0; y < y0 + band.height; ++y) ++row_samples_[std::size_t(y)];
  if (!aovs_) return;
  Aovs& a = *aovs_;
  auto d = band.plane(a.depth), c = band.plane(a.hit), s = band.plane(a.steps), it = band.plane(a.iterations),
       mat = band.plane(a.material);
  std::span<const float> nrm[3] = {band.plane(a.nx), band.plane(a.ny), band.plane(a.nz)};
  for (std::size_t i = 0; i < d.size(); ++i) {
    const std::size_t j = at + i;
    const float k = c[i];  // 1 for a hit (one sample per pass)
    if (k > 0 && a.first_material[j] < 0) a.first_material[j] = mat[i];
    a.hits[j] += k;
    if (k > 0) a.depth_sum[j] += k * d[i], a.iter_sum[j] += k * it[i];
    for (int q = 0; q < 3; ++q) a.normal_sum[q * n + j] += k * nrm[q][i];
    if (a.albedo >= 0)
      for (int q = 0; q < 3; ++q) a.albedo_sum[q * n + j] += k * band.plane(a.albedo + q)[i];
    a.steps_sum[j] += s[i];
  }
}

sdfrt::FloatImage SampleMean::band(int y0, int rows) const {
  const std::size_t n = std::size_t(w_) * std::size_t(h_), at = std::size_t(y0) * std::size_t(w_);
  sdfrt::FloatImage b(w_, rows, names_);
  const float inv_gamma = 1.0f / gamma_;
  for (int c = 0; c < 3; ++c) {
    auto dst = b.plane(c);
    const float* s = sum_.data() + c * n + at;
    for (int y = 0; y < rows; ++y) {
      const int k = row_samples_[std::size_t(y0 + y)];
      const float scale = k > 0 ? 1.0f / float(k) : 0.0f;
      for (int x = 0; x < w_; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(w_) + std::size_t(x);
        dst[i] = encoded_ ? std::pow(s[i] * scale, inv_gamma) : s[i] * scale;
      }
    }
  }
  if (!aovs_) return b;
  const Aovs& a = *aovs_;
  const float inv = passes_ > 0 ? 1.0f / float(passes_) : 0.0f;
  for (std::size_t i = 0; i < b.plane_size(); ++i) {
    const std::size_t j = at + i;
    const float nh = a.hits[j];
    b.plane(a.hit)[i] = nh * inv;
    b.plane(a.depth)[i] = nh > 0 ? a.depth_sum[j] / nh : -1.0f;
    b.plane(a.iterations)[i] = nh > 0 ? a.iter_sum[j] / nh : 0.0f;
    b.plane(a.steps)[i] = a.steps_sum[j] * inv;
    b.plane(a.material)[i] = a.first_material[j];
    const float x = a.normal_sum[j], y = a.normal_sum[n + j], z = a.normal_sum[2 * n + j];
    const float len = std::sqrt(x * x + y * y + z * z);
    const float s = len > 1e-30f ? 1.0f / len : 0.0f;
    b.plane(a.nx)[i] = x * s, b.plane(a.ny)[i] = y * s, b.plane(a.nz)[i] = z * s;
    if (a.albedo >= 0)
      for (int q = 0; q < 3; ++q) b.plane(a.albedo + q)[i] = nh > 0 ? a.albedo_sum[q * n + j] / nh : 0.0f;
  }
  return b;
}

}  // namespace sdfc::cli
