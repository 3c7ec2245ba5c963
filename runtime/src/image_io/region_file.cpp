#include <sdfrt/errors.hpp>
#include <sdfrt/region_file.hpp>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include "image_io/atomic_file.hpp"
#include "program_cache/fnv1a.hpp"

namespace sdfrt {
namespace {

constexpr const char* kMagic = "sdfc-region 1";

std::string header_text(const RegionHeader& h) {
  std::string s = fmt::format("{}\nimage {} {}\nregion {} {} {} {}\nbit-depth {}\npart {} {}\nfingerprint {}\n", kMagic,
                              h.image_width, h.image_height, h.x0, h.y0, h.x1, h.y1, h.bit_depth, h.part, h.parts,
                              h.fingerprint.empty() ? "-" : h.fingerprint);
  for (const auto& sec : h.sections) s += fmt::format("section {} {}\n", sec.name, sec.channels);
  return s + "data\n";
}

std::uint64_t section_bytes(const RegionHeader& h, const RegionSection& s) {
  return std::uint64_t(h.width()) * std::uint64_t(h.height()) * std::uint64_t(s.channels) * sizeof(float);
}

bool valid(const RegionHeader& h) {
  if (h.image_width < 1 || h.image_height < 1 || h.x0 < 0 || h.y0 < 0 || h.x1 <= h.x0 || h.y1 <= h.y0 ||
      h.x1 > h.image_width || h.y1 > h.image_height || (h.bit_depth != 8 && h.bit_depth != 16) || h.sections.empty())
    return false;
  if (h.parts < 0 || (h.parts > 0 && (h.part < 0 || h.part >= h.parts))) return false;
  for (const auto& s : h.sections)
    if ((s.channels != 1 && s.channels != 3) || s.name.empty()) return false;
  return true;
}

}  // namespace

std::string region_fingerprint(std::string_view identity) {
  Fnv1a64 h;
  h.bytes(identity.data(), identity.size());
  return fmt::format("{:016x}", h.digest());
}

struct RegionWriter::State {
  RegionHeader header;
  AtomicFile file;
  std::string path;
  std::uint64_t data_at = 0;
  std::vector<std::uint64_t> offsets;
  std::vector<int> rows_done;
  State(const std::string& p, RegionHeader h) : header(std::move(h)), file(p), path(p) {}
};

namespace {

// One section's bands, written at their offsets in the shared file.
class SectionWriter final : public BandWriter {
 public:
  SectionWriter(AtomicFile& file, const RegionHeader& h, std::uint64_t at, std::vector<int> planes, int& rows,
                std::string path)
      : file_(file), header_(h), at_(at), planes_(std::move(planes)), rows_(rows), path_(std::move(path)) {}
  void write_band(const FloatImage& band) override {
    const int w = header_.width();
    if (band.width != w || rows_ + band.height > header_.height())
      throw std::invalid_argument("region band does not fit the region");
    const std::size_t n = planes_.size();
    std::vector<float> row(std::size_t(w) * n);
    for (int y = 0; y < band.height; ++y) {
      for (std::size_t c = 0; c < n; ++c) {
        auto plane = band.plane(planes_[c]);
        for (int x = 0; x < w; ++x) row[std::size_t(x) * n + c] = plane[std::size_t(y) * std::size_t(w) + std::size_t(x)];
      }
      const std::uint64_t off = at_ + std::uint64_t(rows_ + y) * row.size() * sizeof(float);
      file_.write_at(off, row.data(), row.size() * sizeof(float));
    }
    rows_ += band.height;
  }
  WriteReport finish() override {
    if (rows_ != header_.height())
      throw IoError(fmt::format("cannot write '{}': {} of {} rows were rendered", path_, rows_, header_.height()), path_,
                    0);
    return WriteReport{path_, 0, 0};
  }

 private:
  AtomicFile& file_;
  const RegionHeader& header_;
  std::uint64_t at_;
  std::vector<int> planes_;
  int& rows_;
  std::string path_;
};

}  // namespace

RegionWriter::RegionWriter(const std::string& path, RegionHeader header) {
  if (!valid(header)) throw std::invalid_argument(fmt::format("'{}': not a valid region", path));
  state_ = std::make_unique<State>(path, std::move(header));
  const std::string text = header_text(state_->header);
  state_->file.write(text.data(), text.size());
  std::uint64_t at = text.size();
  for (const auto& s : state_->header.sections) {
    state_->offsets.push_back(at);
    at += section_bytes(state_->header, s);
  }
  state_->rows_done.assign(state_->header.sections.size(), 0);
}

RegionWriter::~RegionWriter() = default;

const RegionHeader& RegionWriter::header() const noexcept { return state_->header; }

std::unique_ptr<BandWriter> RegionWriter::section(const std::string& name, std::vector<int> planes) {
  const auto& secs = state_->header.sections;
  for (std::size_t i = 0; i < secs.size(); ++i)
    if (secs[i].name == name) {
      if (int(planes.size()) != secs[i].channels)
        throw std::invalid_argument(fmt::format("region section {} takes {} planes", name, secs[i].channels));
      return std::make_unique<SectionWriter>(state_->file, state_->header, state_->offsets[i], std::move(planes),
                                             state_->rows_done[i], state_->path);
    }
  throw std::invalid_argument(fmt::format("the region has no section {}", name));
}

WriteReport RegionWriter::commit() {
  for (std::size_t i = 0; i < state_->rows_done.size(); ++i)
    if (state_->rows_done[i] != state_->header.height())
      throw IoError(fmt::format("cannot write '{}': section {} has {} of {} rows", state_->path,
                                state_->header.sections[i].name, state_->rows_done[i], state_->header.height()),
                    state_->path, 0);
  state_->file.commit();
  return WriteReport{state_->path, 0, state_->file.bytes_written()};
}

RegionReader::RegionReader(std::string path) : path_(std::move(path)) {
  auto bad = [&](const std::string& why) {
    return IoError(fmt::format("'{}' is not a complete region file: {}", path_, why), path_, 0);
  };
  fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) {
    const int e = errno;
    throw IoError(fmt::format("cannot read '{}': {}", path_, std::strerror(e)), path_, e);
  }
  // The header is short text; 4 KiB holds any real one.
  std::string head(4096, '\0');
  const ssize_t n = ::pread(fd_, head.data(), head.size(), 0);
  head.resize(n > 0 ? std::size_t(n) : 0);
  const std::size_t end = head.find("\ndata\n");
  if (head.rfind(std::string(kMagic) + "\n", 0) != 0 || end == std::string::npos) {
    ::close(fd_);
    fd_ = -1;
    throw bad("no 'sdfc-region 1' header (write region files with 'sdfc render --region' or '--parts')");
  }
  std::istringstream in(head.substr(0, end + 1));
  std::string line, key;
  std::getline(in, line);
  RegionHeader& h = header_;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    ls >> key;
    if (key == "image") ls >> h.image_width >> h.image_height;
    else if (key == "region") ls >> h.x0 >> h.y0 >> h.x1 >> h.y1;
    else if (key == "bit-depth") ls >> h.bit_depth;
    else if (key == "part") ls >> h.part >> h.parts;
    else if (key == "fingerprint") ls >> h.fingerprint;
    else if (key == "section") {
      RegionSection s;
      ls >> s.name >> s.channels;
      h.sections.push_back(s);
    }
    if (!ls) h.image_width = 0;  // a malformed line makes the header invalid
  }
  if (!valid(h)) {
    ::close(fd_);
    fd_ = -1;
    throw bad("its header is malformed");
  }
  std::uint64_t at = end + 6;
  for (const auto& s : h.sections) {
    offsets_.push_back(at);
    at += section_bytes(h, s);
  }
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || std::uint64_t(st.st_size) != at) {
    ::close(fd_);
    fd_ = -1;
    throw bad(fmt::format("{} bytes, expected {}", std::uint64_t(st.st_size), at));
  }
}

RegionReader::~RegionReader() {
  if (fd_ >= 0) ::close(fd_);
}

RegionReader::RegionReader(RegionReader&& o) noexcept
    : path_(std::move(o.path_)), header_(std::move(o.header_)), offsets_(std::move(o.offsets_)), fd_(o.fd_) {
  o.fd_ = -1;
}

void RegionReader::read_rows(int section, int row, int count, float* out) const {
  const auto& s = header_.sections.at(std::size_t(section));
  if (row < 0 || count < 0 || row + count > header_.height())
    throw std::out_of_range("region rows out of range");
  const std::size_t row_floats = std::size_t(header_.width()) * std::size_t(s.channels);
  std::size_t left = row_floats * std::size_t(count) * sizeof(float);
  std::uint64_t at = offsets_[std::size_t(section)] + std::uint64_t(row) * row_floats * sizeof(float);
  auto* p = reinterpret_cast<char*>(out);
  while (left > 0) {
    const ssize_t n = ::pread(fd_, p, left, static_cast<off_t>(at));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int e = n < 0 ? errno : EIO;
      throw IoError(fmt::format("cannot read '{}': {}", path_, std::strerror(e)), path_, e);
    }
    p += n, at += std::uint64_t(n), left -= std::size_t(n);
  }
}

}  // namespace sdfrt
