#pragma once
// Runs the real sdfc binary the way a user's shell does, with extra
// environment and shell setup (ulimit) where a test needs them, or as a
// process the test watches and signals (Ctrl-C, SIGKILL). Shared by the
// CLI, effects, e2e, outputs, hardening and robustness suites; link sdfc_test_cli.
#include <sys/types.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

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

// The names in `dir`, sorted (to check that no temp file is left behind).
std::vector<std::string> dir_entries(const std::string& dir);

// `sdfc ARGS` started in the repository root (fork and exec, no shell), its
// stderr going to `stderr_path` so the test can watch its progress while it
// runs. `address_space_kib` > 0 limits its address space as `ulimit -v`
// does. The destructor kills and reaps a process still running.
class SdfcProcess {
 public:
  SdfcProcess(const std::vector<std::string>& args, std::string stderr_path, long address_space_kib = 0);
  ~SdfcProcess();
  SdfcProcess(const SdfcProcess&) = delete;
  SdfcProcess& operator=(const SdfcProcess&) = delete;

  // Polls until `ready()` (typically a look at stderr()) holds: true, or
  // false when the process ended first or `timeout` passed. A readiness
  // wait, not a timing assertion.
  bool wait_until(const std::function<bool()>& ready, std::chrono::seconds timeout = std::chrono::minutes(3));
  void signal(int sig);
  // Waits for the end: the exit code, or 128 + the signal.
  int wait();
  std::string stderr_text() const { return read_text(stderr_path_); }

 private:
  pid_t pid_ = -1;
  int code_ = -1;
  std::string stderr_path_;
};

}  // namespace sdfc::test
