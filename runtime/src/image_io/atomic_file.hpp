#pragma once
// Internal: a file that appears under its final name only once it is
// completely written. Writes go to "<path>.tmp-XXXXXX" in the same
// directory; commit() fsyncs and renames. Destroying an uncommitted
// AtomicFile removes the temp file. Every failure throws IoError.
#include <cstddef>
#include <string>

namespace sdfrt {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(const void* data, std::size_t size);
  // Writes at a byte offset (for formats stored in another order than they
  // are produced, like PFM's bottom-up rows); later write() calls append
  // after the furthest byte written.
  void write_at(std::size_t offset, const void* data, std::size_t size);
  void commit();
  // Commits under `path` instead (the same directory as the original
  // name, so the rename stays atomic): an interrupted render's partial file.
  void commit_as(std::string path);
  std::size_t bytes_written() const noexcept { return written_; }

 private:
  [[noreturn]] void fail(const char* action, int error);
  void flush_buffer();

  std::string path_;
  std::string temp_path_;
  int fd_ = -1;
  std::string buffer_;  // batches small writes (PFM rows) into few syscalls
  std::size_t written_ = 0;
  bool committed_ = false;
};

}  // namespace sdfrt
