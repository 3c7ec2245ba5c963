// OpenEXR scanline file fed band by band: each band becomes one
// writePixels() call, so a 16384x16384 render never holds the whole image.
// The bytes go through an Imf::OStream over the AtomicFile, so the file only
// appears under its name once it is complete.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <Imath/half.h>

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <sdfrt/errors.hpp>
#include <sdfrt/stream_writers.hpp>

#include "image_io/atomic_file.hpp"
#include "image_io/sample_conversion.hpp"

namespace sdfrt {
namespace {

constexpr float kHalfMax = 65504.0f;  // larger values would become Inf in half

// OpenEXR writes the header, then the lines, then seeks back to fill in the
// line offset table. The first IoError is kept: OpenEXR swallows the ones
// raised while it closes the file.
class AtomicOStream final : public Imf::OStream {
 public:
  AtomicOStream(AtomicFile& file, const std::string& path) : Imf::OStream(path.c_str()), file_(file) {}
  void write(const char c[], int n) override {
    try {
      if (pos_ == file_.bytes_written())
        file_.write(c, static_cast<std::size_t>(n));
      else
        file_.write_at(pos_, c, static_cast<std::size_t>(n));
    } catch (const IoError& e) {
      if (!error_) error_ = e;
      throw;
    }
    pos_ += static_cast<std::size_t>(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = static_cast<std::size_t>(pos); }
  void rethrow_error() const {
    if (error_) throw *error_;
  }

 private:
  AtomicFile& file_;
  std::size_t pos_ = 0;
  std::optional<IoError> error_;
};

class ExrBandWriter final : public BandWriter {
 public:
  ExrBandWriter(const std::string& path, int width, int height, std::vector<ExrChannel> channels)
      : file_(path), stream_(file_, path), path_(path), width_(width), height_(height), channels_(std::move(channels)) {
    if (channels_.empty()) throw std::invalid_argument("an EXR file needs at least one channel");
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& c : channels_) header.channels().insert(c.name, Imf::Channel(c.half ? Imf::HALF : Imf::FLOAT));
    guarded([&] { exr_.emplace(stream_, header); });
  }

  // Converted and handed over in chunks of kChunkRows, so the half/float
  // copies stay a few MiB even for 16384-pixel rows.
  void write_band(const FloatImage& band) override {
    if (band.width != width_ || rows_ + band.height > height_)
      throw std::invalid_argument("EXR band does not fit the image");
    for (int y0 = 0; y0 < band.height; y0 += kChunkRows) write_rows(band, y0, std::min(kChunkRows, band.height - y0));
  }

  WriteReport finish() override {
    if (rows_ != height_)
      throw IoError(fmt::format("cannot write '{}': {} of {} rows were rendered", path_, rows_, height_), path_, 0);
    return commit(nullptr);
  }

  // The rows not rendered become zero (transparent where there is alpha).
  WriteReport finish_partial(const std::string& path) override {
    if (rows_ < height_) {
      std::vector<std::string> names;
      for (std::size_t k = 0; k < channels_.size(); ++k) names.push_back(std::to_string(k));
      const int rows = height_ - rows_;
      FloatImage black(width_, rows, names);
      std::vector<ExrChannel> saved = channels_;
      for (std::size_t k = 0; k < channels_.size(); ++k) channels_[k].plane = static_cast<int>(k);
      write_band(black);
      channels_ = saved;
    }
    return commit(&path);
  }

 private:
  static constexpr int kChunkRows = 16;  // ZIP compresses blocks of 16 lines

  // Rows [y0, y0 + rows) of the band become the file's next rows.
  void write_rows(const FloatImage& band, int y0, int rows) {
    const std::size_t n = std::size_t(rows) * std::size_t(width_), first = std::size_t(y0) * std::size_t(width_);
    halves_.resize(channels_.size());
    floats_.resize(channels_.size());
    Imf::FrameBuffer fb;
    // OpenEXR addresses a slice by absolute row: shift the base so that row
    // `rows_` lands on the chunk's first row.
    const std::size_t shift = std::size_t(rows_) * std::size_t(width_);
    for (std::size_t k = 0; k < channels_.size(); ++k) {
      const auto& c = channels_[k];
      auto plane = band.plane(c.plane).subspan(first, n);
      if (c.half) {
        halves_[k].resize(n);
        for (std::size_t i = 0; i < n; ++i) {
          const float v = finite_or_zero(plane[i], report_.nonfinite_samples);
          halves_[k][i] = half(std::clamp(v, -kHalfMax, kHalfMax));
        }
        fb.insert(c.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves_[k].data() - shift), sizeof(half),
                                     sizeof(half) * std::size_t(width_)));
      } else {
        floats_[k].resize(n);
        for (std::size_t i = 0; i < n; ++i) floats_[k][i] = finite_or_zero(plane[i], report_.nonfinite_samples);
        fb.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(floats_[k].data() - shift), sizeof(float),
                                     sizeof(float) * std::size_t(width_)));
      }
    }
    guarded([&] {
      exr_->setFrameBuffer(fb);
      exr_->writePixels(rows);
    });
    rows_ += rows;
  }

  WriteReport commit(const std::string* other_path) {
    exr_.reset();  // writes the line offset table
    stream_.rethrow_error();
    if (other_path) {
      file_.commit_as(*other_path);
      path_ = *other_path;
    } else {
      file_.commit();
    }
    report_.path = path_;
    report_.bytes = file_.bytes_written();
    return report_;
  }

  // OpenEXR throws its own exceptions; a failed write comes back as the
  // IoError the stream saw, anything else as an IoError naming the file.
  template <class F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const IoError&) {
      throw;
    } catch (const std::exception& e) {
      stream_.rethrow_error();
      throw IoError(fmt::format("cannot write '{}': OpenEXR: {}", path_, e.what()), path_, 0);
    }
  }

  AtomicFile file_;
  AtomicOStream stream_;
  std::string path_;
  int width_, height_;
  std::vector<ExrChannel> channels_;
  std::optional<Imf::OutputFile> exr_;  // destroyed before the stream and the file
  std::vector<std::vector<half>> halves_;
  std::vector<std::vector<float>> floats_;
  int rows_ = 0;
  WriteReport report_;
};

}  // namespace

std::unique_ptr<BandWriter> open_exr_writer(const std::string& path, int width, int height,
                                            std::vector<ExrChannel> channels) {
  return std::make_unique<ExrBandWriter>(path, width, height, std::move(channels));
}

}  // namespace sdfrt
