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
  // name. PNG only; other writers throw std::logic_error.
  virtual WriteReport finish_partial(const std::string& path);
};

// RGB PNG, 8 or 16 bits per channel (libpng), from three planes of
// display-encoded values clamped to [0, 1].
std::unique_ptr<BandWriter> open_png_writer(const std::string& path, int width, int height,
                                            std::vector<int> rgb_planes, int bit_depth);

// Portable Float Map of one plane ("Pf") or three ("PF"), values as they are.
std::unique_ptr<BandWriter> open_pfm_writer(const std::string& path, int width, int height,
                                            std::vector<int> planes);

}  // namespace sdfrt
