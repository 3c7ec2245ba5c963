#include "image_io/output_target.hpp"

#include <sdfrt/errors.hpp>

#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <filesystem>
#include <mutex>
#include <set>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace sdfrt::detail {
namespace {

std::mutex g_mutex;
std::set<std::pair<dev_t, ino_t>> g_inputs;

[[noreturn]] void refuse(const std::string& path, const std::string& why, int error) {
  throw IoError(fmt::format("cannot write '{}': {}", path, why), path, error);
}

// Follows symlinks (up to 40, as the kernel does) to the name they end at,
// which need not exist yet.
std::string follow_links(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    std::error_code ec;
    fs::path to = fs::read_symlink(p, ec);
    if (ec) refuse(path, "reading the symbolic link failed: " + ec.message(), ec.value());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  refuse(path, "too many levels of symbolic links", ELOOP);
}

}  // namespace

void protect_input_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  std::lock_guard<std::mutex> lock(g_mutex);
  g_inputs.insert({st.st_dev, st.st_ino});
}

OutputTarget resolve_output(const std::string& path) {
  OutputTarget t{follow_links(path), false};
  struct stat st {};
  if (::stat(t.path.c_str(), &st) != 0) return t;  // absent: created through a temp file
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    if (g_inputs.count({st.st_dev, st.st_ino}))
      refuse(path, "it is one of this command's input files (choose another output name)", EEXIST);
  }
  if (S_ISREG(st.st_mode)) return t;
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) || S_ISFIFO(st.st_mode)) {
    t.in_place = true;
    return t;
  }
  if (S_ISDIR(st.st_mode)) refuse(path, "it is a directory", EISDIR);
  refuse(path, "it is a socket or another special file (only files, devices and pipes can be written)", EINVAL);
}

std::string temp_pattern(const std::string& path) { return fmt::format("{}.tmp-{}-XXXXXX", path, ::getpid()); }

void remove_stale_temp_files(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path p = path;
  const std::string dir = p.parent_path().empty() ? "." : p.parent_path().string();
  const std::string prefix = p.filename().string() + ".tmp-";
  DIR* d = ::opendir(dir.c_str());
  if (!d) return;
  while (dirent* e = ::readdir(d)) {
    std::string name = e->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    // Ours: "<pid>-XXXXXX" after the prefix, from a process that is gone.
    const std::string rest = name.substr(prefix.size());
    const size_t dash = rest.find('-');
    if (dash == std::string::npos || dash == 0 || rest.size() != dash + 7) continue;
    if (rest.find_first_not_of("0123456789") != dash) continue;
    const long pid = std::strtol(rest.c_str(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    ::unlink((dir + "/" + name).c_str());
  }
  ::closedir(d);
}

}  // namespace sdfrt::detail
