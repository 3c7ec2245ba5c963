#pragma once
// What the farm suites share: a shell command's output, byte comparison of
// files, leftovers of interrupted writes, and the farm test scenes.
#include <string>
#include <vector>

namespace sdfc::test {

struct Shell {
  int code = -1;
  std::string out;  // stdout and stderr together
};
// Runs `command` through /bin/sh from the repository root.
Shell shell(const std::string& command);

// "" when both files exist with the same bytes, else what differs.
std::string compare_files(const std::string& a, const std::string& b);

// Files under `dir` (recursively) whose names show an unfinished write:
// "*.tmp-*" temporaries and "*.partial.*" images.
std::vector<std::string> leftovers(const std::string& dir);

// tests/farm/scenes/NAME (absolute).
std::string farm_scene(const std::string& name);

}  // namespace sdfc::test
