// Baseline JPEG through libjpeg, one scanline at a time. libjpeg reports
// errors by calling error_exit, which must not return: it longjmps back
// here, and the error becomes an IoError outside libjpeg's frames.
#include <cstdio>  // jpeglib.h needs FILE and size_t first
#include <jpeglib.h>

#include <fmt/format.h>

#include <csetjmp>
#include <sdfrt/errors.hpp>
#include <sdfrt/stream_writers.hpp>

#include "image_io/atomic_file.hpp"
#include "image_io/sample_conversion.hpp"

namespace sdfrt {
namespace {

constexpr std::size_t kOutBuffer = 1 << 16;

class JpegBandWriter final : public BandWriter {
 public:
  JpegBandWriter(const std::string& path, int width, int height, std::vector<int> planes, int quality)
      : file_(path), path_(path), width_(width), height_(height), planes_(std::move(planes)) {
    if (planes_.size() != 3) throw std::invalid_argument("a JPEG takes three planes (r, g, b)");
    if (quality < 1 || quality > 100) throw std::invalid_argument(fmt::format("JPEG quality must be 1-100, not {}", quality));
    cinfo_.err = jpeg_std_error(&err_.mgr);
    err_.mgr.error_exit = on_error;
    err_.self = this;
    jpeg_create_compress(&cinfo_);
    created_ = true;
    buffer_.resize(kOutBuffer);
    dest_.next_output_byte = buffer_.data();
    dest_.free_in_buffer = buffer_.size();
    dest_.init_destination = [](j_compress_ptr) {};
    dest_.empty_output_buffer = on_buffer_full;
    dest_.term_destination = on_term;
    cinfo_.dest = &dest_;
    cinfo_.client_data = this;
    cinfo_.image_width = static_cast<JDIMENSION>(width_);
    cinfo_.image_height = static_cast<JDIMENSION>(height_);
    cinfo_.input_components = 3;
    cinfo_.in_color_space = JCS_RGB;
    guarded([&] {
      jpeg_set_defaults(&cinfo_);
      jpeg_set_quality(&cinfo_, quality, TRUE);
      jpeg_start_compress(&cinfo_, TRUE);
    });
    row_.resize(static_cast<std::size_t>(width_) * 3);
  }
  ~JpegBandWriter() override {
    if (created_) jpeg_destroy_compress(&cinfo_);
  }

  void write_band(const FloatImage& band) override {
    if (band.width != width_ || rows_ + band.height > height_)
      throw std::invalid_argument("JPEG band does not fit the image");
    for (int y = 0; y < band.height; ++y) {
      for (int c = 0; c < 3; ++c) {
        auto plane = band.plane(planes_[static_cast<std::size_t>(c)]);
        for (int x = 0; x < width_; ++x)
          row_[static_cast<std::size_t>(x) * 3 + c] =
              to_u8(finite_or_zero(plane[static_cast<std::size_t>(y) * width_ + x], report_.nonfinite_samples));
      }
      JSAMPROW row = row_.data();
      guarded([&] { jpeg_write_scanlines(&cinfo_, &row, 1); });
    }
    rows_ += band.height;
  }

  WriteReport finish() override {
    if (rows_ != height_)
      throw IoError(fmt::format("cannot write '{}': {} of {} rows were rendered", path_, rows_, height_), path_, 0);
    guarded([&] { jpeg_finish_compress(&cinfo_); });
    file_.commit();
    report_.path = path_;
    report_.bytes = file_.bytes_written();
    return report_;
  }

 private:
  struct ErrorManager {
    jpeg_error_mgr mgr;
    JpegBandWriter* self;
  };

  template <class F>
  void guarded(F&& f) {
    if (setjmp(jump_)) {
      if (io_failed_) throw IoError(error_, path_, errno_);  // already names the file
      throw IoError(fmt::format("cannot write '{}': {}", path_, error_), path_, 0);
    }
    f();
  }
  static void on_error(j_common_ptr cinfo) {
    auto* self = reinterpret_cast<ErrorManager*>(cinfo->err)->self;
    char msg[JMSG_LENGTH_MAX];
    (*cinfo->err->format_message)(cinfo, msg);
    self->error_ = fmt::format("libjpeg: {}", msg);
    std::longjmp(self->jump_, 1);
  }
  void flush(std::size_t bytes) {
    bool failed = false;
    try {
      file_.write(buffer_.data(), bytes);
    } catch (const IoError& e) {
      error_ = e.what(), errno_ = e.errno_value(), io_failed_ = failed = true;
    }
    if (failed) std::longjmp(jump_, 1);  // outside the handler, so the exception is freed
  }
  static boolean on_buffer_full(j_compress_ptr cinfo) {
    auto* self = static_cast<JpegBandWriter*>(cinfo->client_data);
    self->flush(self->buffer_.size());
    self->dest_.next_output_byte = self->buffer_.data();
    self->dest_.free_in_buffer = self->buffer_.size();
    return TRUE;
  }
  static void on_term(j_compress_ptr cinfo) {
    auto* self = static_cast<JpegBandWriter*>(cinfo->client_data);
    self->flush(self->buffer_.size() - self->dest_.free_in_buffer);
  }

  AtomicFile file_;
  std::string path_;
  int width_, height_;
  std::vector<int> planes_;
  jpeg_compress_struct cinfo_{};
  ErrorManager err_{};
  jpeg_destination_mgr dest_{};
  bool created_ = false;
  std::jmp_buf jump_{};
  std::vector<JOCTET> buffer_;
  std::vector<JSAMPLE> row_;
  int rows_ = 0;
  std::string error_;
  int errno_ = 0;
  bool io_failed_ = false;
  WriteReport report_;
};

}  // namespace

std::unique_ptr<BandWriter> open_jpeg_writer(const std::string& path, int width, int height,
                                             std::vector<int> rgb_planes, int quality) {
  return std::make_unique<JpegBandWriter>(path, width, height, std::move(rgb_planes), quality);
}

}  // namespace sdfrt
