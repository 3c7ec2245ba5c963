// PFM stores rows bottom-up; bands arrive top-down, so each row is written
// at its offset in the file instead of holding the image.
#include <fmt/format.h>

#include <sdfrt/errors.hpp>
#include <sdfrt/stream_writers.hpp>

#include "image_io/atomic_file.hpp"
#include "image_io/sample_conversion.hpp"

namespace sdfrt {
namespace {

class PfmBandWriter final : public BandWriter {
 public:
  PfmBandWriter(const std::string& path, int width, int height, std::vector<int> planes)
      : file_(path), path_(path), width_(width), height_(height), planes_(std::move(planes)) {
    if (planes_.size() != 1 && planes_.size() != 3) throw std::invalid_argument("a PFM takes one plane or three");
    header_ = fmt::format("{}\n{} {}\n-1.0\n", planes_.size() == 1 ? "Pf" : "PF", width_, height_);
    file_.write(header_.data(), header_.size());
    row_.resize(static_cast<std::size_t>(width_) * planes_.size());
  }

  void write_band(const FloatImage& band) override {
    if (band.width != width_ || rows_ + band.height > height_)
      throw std::invalid_argument("PFM band does not fit the image");
    const std::size_t n = planes_.size();
    const std::size_t row_bytes = row_.size() * sizeof(float);
    for (int y = 0; y < band.height; ++y) {
      for (std::size_t c = 0; c < n; ++c) {
        auto plane = band.plane(planes_[c]);
        for (int x = 0; x < width_; ++x)
          row_[static_cast<std::size_t>(x) * n + c] =
              finite_or_zero(plane[static_cast<std::size_t>(y) * width_ + x], report_.nonfinite_samples);
      }
      const int image_row = rows_ + y;
      const std::size_t at = header_.size() + static_cast<std::size_t>(height_ - 1 - image_row) * row_bytes;
      file_.write_at(at, row_.data(), row_bytes);
    }
    rows_ += band.height;
  }

  WriteReport finish() override {
    if (rows_ != height_)
      throw IoError(fmt::format("cannot write '{}': {} of {} rows were rendered", path_, rows_, height_), path_, 0);
    file_.commit();
    report_.path = path_;
    report_.bytes = file_.bytes_written();
    return report_;
  }

 private:
  AtomicFile file_;
  std::string path_;
  int width_, height_;
  std::vector<int> planes_;
  std::string header_;
  std::vector<float> row_;
  int rows_ = 0;
  WriteReport report_;
};

}  // namespace

std::unique_ptr<BandWriter> open_pfm_writer(const std::string& path, int width, int height, std::vector<int> planes) {
  return std::make_unique<PfmBandWriter>(path, width, height, std::move(planes));
}

}  // namespace sdfrt
