#pragma once
// Internal: a file that appears under its final name only once it is
// completely written. Writes go to an unnamed file in the target's
// directory (O_TMPFILE, so a crash or SIGKILL leaves nothing behind);
// commit() fsyncs, links it under a temp name and renames it over the
// target. Where O_TMPFILE is missing the temp file is
// "<path>.tmp-<pid>-XXXXXX", and stale ones of dead processes are removed
// on the next write. A symlink's target is what gets written; a device or
// FIFO is written in place; a directory, a socket or a file registered with
// protect_input() is refused. Destroying an uncommitted AtomicFile removes
// the temp file. Every failure throws IoError.
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
  // No AtomicFile may replace this file (an input of the command).
  static void protect_input(const std::string& path);

 private:
  [[noreturn]] void fail(const char* action, int error);
  void flush_buffer();
  void open_temp();
  void link_temp();

  std::string path_;    // the name the user gave (for messages)
  std::string target_;  // the file written: path_ with symlinks followed
  std::string temp_path_;  // named temp file (fallback, or once linked)
  bool in_place_ = false;  // a device or FIFO written directly
  bool anonymous_ = false;  // an O_TMPFILE not yet linked
  int fd_ = -1;
  std::string buffer_;  // batches small writes (PFM rows) into few syscalls
  std::size_t written_ = 0;
  bool committed_ = false;
};

}  // namespace sdfrt
