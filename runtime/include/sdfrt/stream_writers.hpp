#pragma once
// Image writers fed band by band (top to bottom), so an image never has to
// be held whole: a 16384x16384 render streams through bands of tile rows.
// Like the whole-image writers they write "<path>.tmp-XXXXXX" and rename on
// finish(); destroying an unfinished writer removes the temp file.
#include <sdfrt/float_image.hpp>
#include <sdfrt/image_io.hpp>

#include <memory>
#include <string>
#include <vector>

namespace sdfrt {

class BandWriter {
 public:
  virtual ~BandWriter() = default;
  // The next rows of the image, from the top; band.width must match.
  virtual void write_band(const FloatImage& band) = 0;
  // Throws IoError unless every row was written.
  virtual WriteReport finish() = 0;
  // An interrupted render: the rows not written yet become black and the
  // file is committed under `path` (same directory) instead of its own
  // name. PNG and EXR; other writers throw std::logic_error.
  virtual WriteReport finish_partial(const std::string& path);
};

// RGB PNG, 8 or 16 bits per channel (libpng), from three planes of
// display-encoded values clamped to [0, 1]; a fourth plane makes it RGBA
// (straight alpha, as PNG defines it).
std::unique_ptr<BandWriter> open_png_writer(const std::string& path, int width, int height,
                                            std::vector<int> rgb_planes, int bit_depth);

// Baseline JPEG (libjpeg), 8 bits, from three display-encoded planes;
// quality 1-100.
std::unique_ptr<BandWriter> open_jpeg_writer(const std::string& path, int width, int height,
                                             std::vector<int> rgb_planes, int quality);

// One channel of an OpenEXR file: its name ("R", "Z", "N.X"), the band
// plane it comes from, and whether it is stored as half or float.
struct ExrChannel {
  std::string name;
  int plane = 0;
  bool half = false;
};

// Scanline OpenEXR, ZIP-compressed, values as they are (NaN/Inf -> 0,
// half channels clamped to the half range).
std::unique_ptr<BandWriter> open_exr_writer(const std::string& path, int width, int height,
                                            std::vector<ExrChannel> channels);

// Portable Float Map of one plane ("Pf") or three ("PF"), values as they are.
std::unique_ptr<BandWriter> open_pfm_writer(const std::string& path, int width, int height,
                                            std::vector<int> planes);

}  // namespace sdfrt
