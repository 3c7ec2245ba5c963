#pragma once
// Runs the real sdfc binary the way a user's shell does, with extra
// environment and shell setup (ulimit) where a test needs them. Shared by
// the CLI, effects, e2e and robustness suites; link sdfc_test_cli.
#include <string>

namespace sdfc::test {

struct RunResult {
  int code = -1;  // exit code, or 128 + signal
  std::string out, err;
};

// Runs `[prefix] sdfc ARGS` through /bin/sh in the repository root, its
// stdout and stderr captured through files in a ScratchDir (so never in a
// directory under test). `prefix` is shell text put before the command
// (e.g. "ulimit -f 4; " or "OCL_ICD_VENDORS=/x ").
RunResult run_sdfc(const std::string& args, const std::string& prefix = "");

// A fresh directory under the test temp dir, removed at the end of scope.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  std::string write(const std::string& name, const std::string& text) const;  // returns the path

 private:
  std::string path_;
};

std::string read_text(const std::string& path);

}  // namespace sdfc::test
