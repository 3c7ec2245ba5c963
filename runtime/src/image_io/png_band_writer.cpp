// PNG through libpng, one row at a time, so 16-bit output and images larger
// than memory both work (stb writes 8-bit PNGs from a whole image only).
#include <png.h>

#include <fmt/format.h>

#include <algorithm>
#include <csetjmp>
#include <sdfrt/errors.hpp>
#include <sdfrt/stream_writers.hpp>

#include "image_io/atomic_file.hpp"
#include "image_io/sample_conversion.hpp"

namespace sdfrt {
namespace {

class PngBandWriter final : public BandWriter {
 public:
  PngBandWriter(const std::string& path, int width, int height, std::vector<int> planes, int bit_depth)
      : file_(path), path_(path), width_(width), height_(height), planes_(std::move(planes)), depth_(bit_depth) {
    if (bit_depth != 8 && bit_depth != 16)
      throw std::invalid_argument(fmt::format("PNG bit depth must be 8 or 16, not {}", bit_depth));
    if (planes_.size() != 3 && planes_.size() != 4)
      throw std::invalid_argument("a PNG takes three planes (r, g, b) or four (r, g, b, a)");
    const int channels = static_cast<int>(planes_.size());
    png_ = png_create_write_struct(PNG_LIBPNG_VER_STRING, this, on_error, on_warning);
    info_ = png_ ? png_create_info_struct(png_) : nullptr;
    if (!png_ || !info_) throw IoError(fmt::format("cannot write '{}': libpng could not start", path_), path_, 0);
    png_set_write_fn(png_, this, on_write, nullptr);
    guarded([&] {
      png_set_IHDR(png_, info_, static_cast<png_uint_32>(width_), static_cast<png_uint_32>(height_), depth_,
                   channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
      // Large images favour speed over the last few percent of size. One
      // filter (Sub) for every row instead of libpng's trial of all five per
      // row: half the encoding time, and on rendered images the file comes
      // out within 1 % of the adaptive choice's size (often smaller).
      png_set_compression_level(png_, 3);
      png_set_filter(png_, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
      png_write_info(png_, info_);
    });
    row_.resize(static_cast<std::size_t>(width_) * planes_.size() * (depth_ / 8));
  }
  ~PngBandWriter() override { png_destroy_write_struct(&png_, &info_); }

  void write_band(const FloatImage& band) override {
    if (band.width != width_ || rows_ + band.height > height_)
      throw std::invalid_argument("PNG band does not fit the image");
    const int channels = static_cast<int>(planes_.size());
    for (int y = 0; y < band.height; ++y) {
      for (int c = 0; c < channels; ++c) {
        auto plane = band.plane(planes_[static_cast<std::size_t>(c)]);
        for (int x = 0; x < width_; ++x) {
          float v = finite_or_zero(plane[static_cast<std::size_t>(y) * width_ + x], report_.nonfinite_samples);
          v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
          std::size_t i = static_cast<std::size_t>(x) * channels + c;
          if (depth_ == 8) {
            row_[i] = static_cast<png_byte>(v * 255.0f + 0.5f);
          } else {
            auto code = static_cast<unsigned>(v * 65535.0f + 0.5f);
            row_[2 * i] = static_cast<png_byte>(code >> 8);  // PNG samples are big-endian
            row_[2 * i + 1] = static_cast<png_byte>(code & 0xff);
          }
        }
      }
      guarded([&] { png_write_row(png_, row_.data()); });
    }
    rows_ += band.height;
  }

  WriteReport finish() override {
    if (rows_ != height_)
      throw IoError(fmt::format("cannot write '{}': {} of {} rows were rendered", path_, rows_, height_), path_, 0);
    guarded([&] { png_write_end(png_, info_); });
    file_.commit();
    report_.path = path_;
    report_.bytes = file_.bytes_written();
    return report_;
  }

  WriteReport finish_partial(const std::string& path) override {
    std::fill(row_.begin(), row_.end(), png_byte{0});
    for (; rows_ < height_; ++rows_) guarded([&] { png_write_row(png_, row_.data()); });
    guarded([&] { png_write_end(png_, info_); });
    file_.commit_as(path);
    path_ = path;
    report_.path = path_;
    report_.bytes = file_.bytes_written();
    return report_;
  }

 private:
  // libpng reports errors by longjmp; turn them into IoError here, outside
  // the frames libpng owns.
  template <class F>
  void guarded(F&& f) {
    if (setjmp(png_jmpbuf(png_))) {
      throw IoError(fmt::format("cannot write '{}': libpng: {}", path_, error_), path_, 0);
    }
    f();
  }
  static void on_error(png_structp png, png_const_charp msg) {
    static_cast<PngBandWriter*>(png_get_error_ptr(png))->error_ = msg;
    png_longjmp(png, 1);
  }
  static void on_warning(png_structp, png_const_charp) {}
  static void on_write(png_structp png, png_bytep data, png_size_t size) {
    auto* self = static_cast<PngBandWriter*>(png_get_io_ptr(png));
    bool failed = false;
    try {
      self->file_.write(data, size);
    } catch (const IoError& e) {
      self->error_ = e.what();
      failed = true;
    }
    if (failed) png_longjmp(png, 1);  // outside the handler, so the exception is freed
  }

  AtomicFile file_;
  std::string path_;
  int width_, height_;
  std::vector<int> planes_;
  int depth_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
  std::vector<png_byte> row_;
  int rows_ = 0;
  std::string error_;
  WriteReport report_;
};

}  // namespace

WriteReport BandWriter::finish_partial(const std::string&) {
  throw std::logic_error("only PNG images can be kept as partial files");
}

std::unique_ptr<BandWriter> open_png_writer(const std::string& path, int width, int height,
                                            std::vector<int> rgb_planes, int bit_depth) {
  return std::make_unique<PngBandWriter>(path, width, height, std::move(rgb_planes), bit_depth);
}

}  // namespace sdfrt
