#include "frame_writers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sdfrt/stream_writers.hpp>
#include <sdfrt/video_writer.hpp>
#include <stdexcept>

#include "sample_mean.hpp"

namespace sdfc::cli {
namespace {

// The kernel planes an AOV name stands for.
std::vector<int> aov_planes(const sdfrt::KernelSpec& spec, const std::string& aov) {
  if (aov == "normal") return {plane_of(spec, "normal_x"), plane_of(spec, "normal_y"), plane_of(spec, "normal_z")};
  if (aov == "albedo") return {plane_of(spec, "albedo_r"), plane_of(spec, "albedo_g"), plane_of(spec, "albedo_b")};
  return {plane_of(spec, aov)};
}

struct AovWriters {
  std::vector<std::unique_ptr<sdfrt::BandWriter>> writers;
  std::vector<std::string> paths;
  AovWriters(const sdfrt::KernelSpec& spec, int width, int height, const std::string& beauty,
             const std::vector<std::string>& aovs, const decltype(OfflineOutput::open_band_writer)& open = {}) {
    for (const auto& a : aovs) {
      paths.push_back(aov_path(beauty, a));
      writers.push_back(open ? open(a, width, height, aov_planes(spec, a))
                             : sdfrt::open_pfm_writer(paths.back(), width, height, aov_planes(spec, a)));
    }
  }
  void write(const sdfrt::FloatImage& band) {
    for (auto& w : writers) w->write_band(band);
  }
  void finish() {
    for (auto& w : writers) w->finish();
  }
};

// PNG stores straight alpha; the kernel's colour with alpha is display
// encode(premultiplied linear), so straight = value * coverage^(-1/gamma).
sdfrt::FloatImage straight_rgba(const sdfrt::FloatImage& band, int hit, float gamma) {
  sdfrt::FloatImage out(band.width, band.height, {"r", "g", "b", "a"});
  auto a = band.plane(hit);
  for (std::size_t i = 0; i < out.plane_size(); ++i) {
    const float k = std::isfinite(a[i]) ? std::clamp(a[i], 0.0f, 1.0f) : 0.0f;
    const float scale = k > 0 ? std::pow(k, -1.0f / gamma) : 0.0f;
    for (int c = 0; c < 3; ++c) out.plane(c)[i] = band.plane(c)[i] * scale;
    out.plane(3)[i] = k;
  }
  return out;
}

class ImageSink final : public FrameSink {
 public:
  ImageSink(const sdfrt::KernelSpec& spec, int w, int h, float gamma, const OfflineOutput& out)
      : aovs_(spec, w, h, out.beauty, out.format == Format::Exr ? std::vector<std::string>{} : out.aovs,
              out.open_band_writer),
        gamma_(gamma), hit_(out.alpha && out.format == Format::Png ? plane_of(spec, "hit") : -1) {
    if (out.open_band_writer) {  // a region file holds the image and its AOVs
      beauty_ = out.open_band_writer("", w, h, {0, 1, 2});
      return;
    }
    switch (out.format) {
      case Format::Png:
        beauty_ = sdfrt::open_png_writer(out.beauty, w, h, hit_ >= 0 ? std::vector<int>{0, 1, 2, 3} : std::vector<int>{0, 1, 2},
                                         out.bit_depth);
        break;
      case Format::Jpeg: beauty_ = sdfrt::open_jpeg_writer(out.beauty, w, h, {0, 1, 2}, out.quality); break;
      case Format::Pfm: beauty_ = sdfrt::open_pfm_writer(out.beauty, w, h, {0, 1, 2}); break;
      case Format::Exr: beauty_ = sdfrt::open_exr_writer(out.beauty, w, h, exr_channels(spec, out)); break;
      default: throw std::logic_error("ImageSink for a video format");
    }
  }
  void write_band(const sdfrt::FloatImage& band) override {
    // Not `hit_ >= 0 ? straight_rgba(...) : band`: that conditional is a
    // prvalue, so it would copy the whole band when there is no alpha.
    if (hit_ >= 0) beauty_->write_band(straight_rgba(band, hit_, gamma_));
    else beauty_->write_band(band);
    aovs_.write(band);
  }
  std::vector<std::string> finish() override {
    std::vector<std::string> paths{beauty_->finish().path};
    aovs_.finish();
    paths.insert(paths.end(), aovs_.paths.begin(), aovs_.paths.end());
    return paths;
  }
  std::string finish_partial(const std::string& path) override { return beauty_->finish_partial(path).path; }

 private:
  std::unique_ptr<sdfrt::BandWriter> beauty_;
  AovWriters aovs_;
  float gamma_;
  int hit_;
};

// One frame of the video the whole render goes to.
class VideoFrameSink final : public FrameSink {
 public:
  explicit VideoFrameSink(sdfrt::VideoWriter& video) : video_(video) {}
  ~VideoFrameSink() override {
    if (!done_) video_.discard_frame();
  }
  void write_band(const sdfrt::FloatImage& band) override { video_.write_band(band, {0, 1, 2}); }
  std::vector<std::string> finish() override {
    done_ = true;
    return {};
  }
  std::string finish_partial(const std::string&) override {
    throw std::logic_error("a video keeps its finished frames, not a partial one");
  }

 private:
  sdfrt::VideoWriter& video_;
  bool done_ = false;
};

}  // namespace

std::vector<sdfrt::ExrChannel> exr_channels(const sdfrt::KernelSpec& spec, const OfflineOutput& out) {
  const bool half = out.bit_depth != 32;
  std::vector<sdfrt::ExrChannel> c = {{"R", 0, half}, {"G", 1, half}, {"B", 2, half}};
  if (out.alpha) c.push_back({"A", plane_of(spec, "hit"), half});
  for (const auto& a : out.aovs) {
    if (a == "depth") c.push_back({"Z", plane_of(spec, "depth"), false});
    else if (a == "normal")
      for (const char* axis : {"X", "Y", "Z"})
        c.push_back({fmt::format("N.{}", axis), plane_of(spec, fmt::format("normal_{}", char(axis[0] + 32))), false});
    else if (a == "albedo")  // a layer as denoisers (OIDN) read it, with N
      for (const char* ch : {"R", "G", "B"})
        c.push_back({fmt::format("albedo.{}", ch), plane_of(spec, fmt::format("albedo_{}", char(ch[0] + 32))), half});
    else c.push_back({a, plane_of(spec, a), false});
  }
  return c;
}

std::unique_ptr<FrameSink> open_frame_sink(const sdfrt::KernelSpec& spec, int width, int height, float gamma,
                                           const OfflineOutput& out) {
  if (is_video(out.format)) {
    if (!out.video) throw std::logic_error("a video frame without its video");
    return std::make_unique<VideoFrameSink>(*out.video);
  }
  return std::make_unique<ImageSink>(spec, width, height, gamma, out);
}

std::vector<std::string> write_aovs(const sdfrt::KernelSpec& spec, const sdfrt::FloatImage& image,
                                    const std::string& beauty, const std::vector<std::string>& aovs) {
  AovWriters w(spec, image.width, image.height, beauty, aovs);
  w.write(image);
  w.finish();
  return w.paths;
}

}  // namespace sdfc::cli
