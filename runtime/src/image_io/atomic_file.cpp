#include "image_io/atomic_file.hpp"

#include <sdfrt/errors.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

#include "image_io/output_target.hpp"

namespace sdfrt {
namespace {

constexpr std::size_t kBufferSize = 1 << 20;

mode_t current_umask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

std::string directory_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

[[noreturn]] void throw_io(const std::string& path, const char* action, int error) {
  throw IoError(fmt::format("cannot write '{}': {} failed: {}", path, action, std::strerror(error)), path, error);
}

}  // namespace

void AtomicFile::protect_input(const std::string& path) { detail::protect_input_file(path); }

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  detail::OutputTarget t = detail::resolve_output(path_);
  target_ = t.path;
  in_place_ = t.in_place;
  if (in_place_) {
    fd_ = ::open(target_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd_ < 0) throw_io(path_, "opening", errno);
  } else {
    open_temp();
  }
  buffer_.reserve(kBufferSize);
}

void AtomicFile::open_temp() {
  detail::remove_stale_temp_files(target_);
  // The mode is 0666 less the umask, as a plain fopen() would create it.
  fd_ = ::open(directory_of(target_).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd_ >= 0) {
    anonymous_ = true;
    return;
  }
  std::string pattern = detail::temp_pattern(target_);
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
}

// Gives the unnamed file a temp name beside the target (linkat cannot
// replace an existing file, rename can).
void AtomicFile::link_temp() {
  const std::string proc = fmt::format("/proc/self/fd/{}", fd_);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = detail::temp_pattern(target_);
    static const char kChars[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    for (size_t i = name.size() - 6; i < name.size(); ++i) name[i] = kChars[std::rand() % 36];
    int rc = ::linkat(AT_FDCWD, proc.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW);
    if (rc != 0 && errno == ENOENT) rc = ::linkat(fd_, "", AT_FDCWD, name.c_str(), AT_EMPTY_PATH);
    if (rc == 0) {
      temp_path_ = name;
      anonymous_ = false;
      return;
    }
    if (errno != EEXIST) fail("linking the temporary file", errno);
  }
  fail("linking the temporary file", EEXIST);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_path_.empty()) ::unlink(temp_path_.c_str());
}

void AtomicFile::fail(const char* action, int error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temp_path_.empty()) ::unlink(temp_path_.c_str());
  temp_path_.clear();
  throw_io(path_, action, error);
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
  if (!in_place_) target_ = detail::resolve_output(path_).path;
  commit();
}

void AtomicFile::commit() {
  if (fd_ < 0) throw IoError(fmt::format("cannot write '{}': file already closed", path_), path_, 0);
  flush_buffer();
  if (in_place_) {
    // A device or pipe: nothing to rename; fsync means nothing to most.
    if (::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS && errno != ENOTSUP) fail("fsync", errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("close", errno);
    committed_ = true;
    return;
  }
  if (::fsync(fd_) != 0) fail("fsync", errno);
  if (anonymous_) link_temp();
  const int fd = fd_;
  fd_ = -1;  // closed below whatever happens; fail() must not close it again
  if (::close(fd) != 0) fail("close", errno);
  if (::rename(temp_path_.c_str(), target_.c_str()) != 0) fail("rename", errno);
  committed_ = true;
  // Make the rename itself durable; best effort, the data is already safe.
  if (const int dfd = ::open(directory_of(target_).c_str(), O_RDONLY | O_DIRECTORY); dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace sdfrt
