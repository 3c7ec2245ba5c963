#pragma once
// A region file: one rectangle of a still rendered on its own (a render-farm
// task), with its place in the whole image, so `sdfc merge` can stream the
// parts into the final PNG and AOVs. The samples are the floats the image
// writers would have been given, so a merged image has the same bytes as one
// rendered whole. Layout: a text header ending in "data\n", then each
// section's samples, one section after another (float32 little-endian, rows
// top-down, a pixel's channels together).
#include <sdfrt/image_io.hpp>
#include <sdfrt/stream_writers.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sdfrt {

struct RegionSection {
  std::string name;  // "beauty" (the display RGB) or an AOV ("depth", "normal", ...)
  int channels = 1;  // 1 or 3
};

struct RegionHeader {
  int image_width = 0, image_height = 0;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the pixels [x0, x1) x [y0, y1)
  int bit_depth = 8;                   // of the final PNG
  int part = -1, parts = 0;            // part `part` of `parts` of a split (-1: not part of a split)
  std::string fingerprint;             // of the scene and settings; every part of an image carries the same
  std::vector<RegionSection> sections;
  int width() const noexcept { return x1 - x0; }
  int height() const noexcept { return y1 - y0; }
};

// A stable text fingerprint (hex FNV-1a) of what decides the pixels.
std::string region_fingerprint(std::string_view identity);

// Writes a region file through a temporary file; commit() renames it into
// place once every section is complete, and destroying the writer before
// that removes the temporary file.
class RegionWriter {
 public:
  RegionWriter(const std::string& path, RegionHeader header);
  ~RegionWriter();
  RegionWriter(const RegionWriter&) = delete;
  RegionWriter& operator=(const RegionWriter&) = delete;
  // Bands of the region (its width, top-down) for one section: the given
  // planes of each band, as many as the section's channels. Each band
  // writer's finish() checks that every row came; the writer must outlive it.
  std::unique_ptr<BandWriter> section(const std::string& name, std::vector<int> planes);
  // Throws IoError unless every section was written whole.
  WriteReport commit();
  const RegionHeader& header() const noexcept;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Reads a region file's header and its rows on demand (never the whole
// file). Throws IoError when the file is missing, is not a region file or
// is shorter than its header says.
class RegionReader {
 public:
  explicit RegionReader(std::string path);
  ~RegionReader();
  RegionReader(RegionReader&&) noexcept;
  RegionReader(const RegionReader&) = delete;
  RegionReader& operator=(const RegionReader&) = delete;
  const RegionHeader& header() const noexcept { return header_; }
  const std::string& path() const noexcept { return path_; }
  // Rows [row, row + count) of the region (0 = its top row) of a section,
  // count * width * channels floats in the file's order.
  void read_rows(int section, int row, int count, float* out) const;

 private:
  std::string path_;
  RegionHeader header_;
  std::vector<std::uint64_t> offsets_;  // of each section's first sample
  int fd_ = -1;
};

}  // namespace sdfrt
