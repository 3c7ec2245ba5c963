#pragma once
// File utilities shared by every test suite (the runtime's too, so no
// dependency on the compiler or the runtime): temp dirs and whole-file reads.
#include <filesystem>
#include <string>
#include <vector>

namespace sdfc::test {

// A fresh directory under the temp dir, removed with its contents.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::vector<std::string> file_names() const;  // sorted

 private:
  std::filesystem::path path_;
};

// Reads a whole file into a string; throws std::runtime_error when it cannot.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace sdfc::test
