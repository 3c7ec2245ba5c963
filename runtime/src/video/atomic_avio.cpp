#include "video/atomic_avio.hpp"
#include "video/ffmpeg_api.hpp"

extern "C" {
#include <libavformat/avio.h>
#include <libavutil/error.h>
#include <libavutil/mem.h>
}

#include <cerrno>
#include <new>

namespace sdfrt {
namespace {
constexpr int kBufferSize = 1 << 16;
}

AtomicAvio::AtomicAvio(AtomicFile& file) : file_(file) {
  auto* buffer = static_cast<unsigned char*>(ffmpeg().av_malloc(kBufferSize));
  if (!buffer) throw std::bad_alloc();
  ctx_ = ffmpeg().avio_alloc_context(buffer, kBufferSize, 1, this, nullptr, on_write, on_seek);
  if (!ctx_) {
    ffmpeg().av_free(buffer);
    throw std::bad_alloc();
  }
}

AtomicAvio::~AtomicAvio() {
  if (ctx_) ffmpeg().av_freep(&ctx_->buffer);
  ffmpeg().avio_context_free(&ctx_);
}

void AtomicAvio::flush() {
  ffmpeg().avio_flush(ctx_);
  rethrow_error();
}

int AtomicAvio::on_write(void* opaque, unsigned char* buf, int size) {
  auto* self = static_cast<AtomicAvio*>(opaque);
  if (self->error_) return AVERROR(EIO);
  try {
    if (self->pos_ == self->file_.bytes_written())
      self->file_.write(buf, static_cast<std::size_t>(size));
    else
      self->file_.write_at(self->pos_, buf, static_cast<std::size_t>(size));
  } catch (const IoError& e) {
    self->error_ = e;
    return AVERROR(e.errno_value() ? e.errno_value() : EIO);
  }
  self->pos_ += static_cast<std::size_t>(size);
  return size;
}

std::int64_t AtomicAvio::on_seek(void* opaque, std::int64_t offset, int whence) {
  auto* self = static_cast<AtomicAvio*>(opaque);
  const long long size = static_cast<long long>(self->file_.bytes_written());
  long long to = 0;
  switch (whence & ~AVSEEK_FORCE) {
    case AVSEEK_SIZE: return size;
    case SEEK_SET: to = offset; break;
    case SEEK_CUR: to = static_cast<long long>(self->pos_) + offset; break;
    case SEEK_END: to = size + offset; break;
    default: return AVERROR(EINVAL);
  }
  if (to < 0) return AVERROR(EINVAL);
  self->pos_ = static_cast<std::size_t>(to);
  return to;
}

}  // namespace sdfrt
