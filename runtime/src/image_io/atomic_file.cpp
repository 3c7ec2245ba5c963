#include "image_io/atomic_file.hpp"

#include <sdfrt/errors.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace sdfrt {
namespace {

constexpr std::size_t kBufferSize = 1 << 20;

mode_t current_umask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  std::string pattern = path_ + ".tmp-XXXXXX";
  fd_ = ::mkstemp(pattern.data());
  if (fd_ < 0) {
    const int error = errno;
    throw IoError(fmt::format("cannot write '{}': creating a temporary file failed: {}", path_,
                              std::strerror(error)),
                  path_, error);
  }
  temp_path_ = pattern;
  // mkstemp makes 0600 files; give the result the permissions a plain
  // fopen() would have.
  if (::fchmod(fd_, 0666 & ~current_umask()) != 0) fail("setting permissions", errno);
  buffer_.reserve(kBufferSize);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_path_.empty()) ::unlink(temp_path_.c_str());
}

void AtomicFile::fail(const char* action, int error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temp_path_.c_str());
  temp_path_.clear();
  throw IoError(fmt::format("cannot write '{}': {} failed: {}", path_, action,
                            std::strerror(error)),
                path_, error);
}

void AtomicFile::flush_buffer() {
  const char* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    if (n == 0) fail("write", ENOSPC);
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  buffer_.clear();
}

void AtomicFile::write(const void* data, std::size_t size) {
  if (fd_ < 0) throw IoError(fmt::format("cannot write '{}': file already closed", path_), path_, 0);
  const char* p = static_cast<const char*>(data);
  written_ += size;
  while (size > 0) {
    const std::size_t chunk = std::min(size, kBufferSize - buffer_.size());
    buffer_.append(p, chunk);
    p += chunk;
    size -= chunk;
    if (buffer_.size() == kBufferSize) flush_buffer();
  }
}

void AtomicFile::write_at(std::size_t offset, const void* data, std::size_t size) {
  if (fd_ < 0) throw IoError(fmt::format("cannot write '{}': file already closed", path_), path_, 0);
  flush_buffer();
  const char* p = static_cast<const char*>(data);
  std::size_t at = offset, left = size;
  while (left > 0) {
    const ssize_t n = ::pwrite(fd_, p, left, static_cast<off_t>(at));
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    if (n == 0) fail("write", ENOSPC);
    p += n;
    at += static_cast<std::size_t>(n);
    left -= static_cast<std::size_t>(n);
  }
  written_ = std::max(written_, offset + size);
  if (::lseek(fd_, static_cast<off_t>(written_), SEEK_SET) < 0) fail("seek", errno);
}

void AtomicFile::commit_as(std::string path) {
  path_ = std::move(path);
  commit();
}

void AtomicFile::commit() {
  if (fd_ < 0) throw IoError(fmt::format("cannot write '{}': file already closed", path_), path_, 0);
  flush_buffer();
  if (::fsync(fd_) != 0) fail("fsync", errno);
  const int fd = fd_;
  fd_ = -1;  // closed below whatever happens; fail() must not close it again
  if (::close(fd) != 0) fail("close", errno);
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) fail("rename", errno);
  committed_ = true;
  // Make the rename itself durable; best effort, the data is already safe.
  const std::filesystem::path parent = std::filesystem::path(path_).parent_path();
  const std::string dir = parent.empty() ? std::string(".") : parent.string();
  if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY); dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace sdfrt
