#pragma once
// Internal: an FFmpeg AVIOContext that writes into an AtomicFile, so a muxer
// (which seeks back to patch sizes, e.g. MP4's mdat) writes the temp file
// and the video only appears under its name when it is committed.
#include <cstdint>
#include <optional>
#include <string>

#include <sdfrt/errors.hpp>

#include "image_io/atomic_file.hpp"

struct AVIOContext;

namespace sdfrt {

class AtomicAvio {
 public:
  explicit AtomicAvio(AtomicFile& file);
  ~AtomicAvio();
  AtomicAvio(const AtomicAvio&) = delete;
  AtomicAvio& operator=(const AtomicAvio&) = delete;

  AVIOContext* context() { return ctx_; }
  // Writes what the context still buffers; rethrows the first write error.
  void flush();
  void rethrow_error() const {
    if (error_) throw *error_;
  }

 private:
  static int on_write(void* opaque, unsigned char* buf, int size);
  static std::int64_t on_seek(void* opaque, std::int64_t offset, int whence);

  AtomicFile& file_;
  AVIOContext* ctx_ = nullptr;
  std::size_t pos_ = 0;
  std::optional<IoError> error_;
};

}  // namespace sdfrt
