#include "farm_test_support.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <sys/wait.h>

#include "test_files.hpp"

namespace sdfc::test {

Shell shell(const std::string& command) {
  Shell r;
  const std::string full = "cd '" SDFC_SOURCE_DIR "' && { " + command + " ; } 2>&1";
  FILE* p = ::popen(full.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

std::string compare_files(const std::string& a, const std::string& b) {
  if (!std::filesystem::exists(a)) return a + " is missing";
  if (!std::filesystem::exists(b)) return b + " is missing";
  const std::string x = read_text_file(a), y = read_text_file(b);
  if (x.size() != y.size()) return a + " and " + b + " differ in size";
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] != y[i]) return a + " and " + b + " differ at byte " + std::to_string(i);
  return "";
}

std::vector<std::string> leftovers(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".tmp-") != std::string::npos || name.find(".partial.") != std::string::npos)
      out.push_back(e.path().string());
  }
  return out;
}

std::string farm_scene(const std::string& name) { return std::string(SDFC_SOURCE_DIR) + "/tests/farm/scenes/" + name; }

}  // namespace sdfc::test
