#include "run_sdfc.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace sdfc::test {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> dir_entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

namespace {
int exit_code(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }
}  // namespace

SdfcProcess::SdfcProcess(const std::vector<std::string>& args, std::string stderr_path, long address_space_kib)
    : stderr_path_(std::move(stderr_path)) {
  std::filesystem::remove(stderr_path_);  // a readiness wait reads it
  std::vector<std::string> argv_text = {SDFC_BINARY};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  pid_ = fork();
  if (pid_ == 0) {
    if (chdir(SDFC_SOURCE_DIR) != 0) _exit(120);
    int fd = open(stderr_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || dup2(fd, 2) < 0) _exit(122);
    if (address_space_kib > 0) {
      rlimit lim{rlim_t(address_space_kib) * 1024, rlim_t(address_space_kib) * 1024};
      if (setrlimit(RLIMIT_AS, &lim) != 0) _exit(123);
    }
    std::vector<char*> argv;
    for (auto& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(121);
  }
}

SdfcProcess::~SdfcProcess() {
  if (pid_ > 0 && code_ < 0) {
    kill(pid_, SIGKILL);
    wait();
  }
}

bool SdfcProcess::wait_until(const std::function<bool()>& ready, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!ready()) {
    int st = 0;
    if (code_ >= 0 || std::chrono::steady_clock::now() > deadline) return false;
    if (waitpid(pid_, &st, WNOHANG) == pid_) {
      code_ = exit_code(st);
      return ready();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

void SdfcProcess::signal(int sig) {
  if (code_ < 0) kill(pid_, sig);
}

int SdfcProcess::wait() {
  if (code_ < 0) {
    int st = 0;
    if (waitpid(pid_, &st, 0) == pid_) code_ = exit_code(st);
  }
  return code_;
}

RunResult run_sdfc(const std::string& args, const std::string& prefix) {
  ScratchDir io;
  std::string cmd = std::string("cd ") + SDFC_SOURCE_DIR + " && " + prefix + SDFC_BINARY + " " + args + " >" +
                    io.file("out") + " 2>" + io.file("err");
  int status = std::system(cmd.c_str());
  RunResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(io.file("out"));
  r.err = read_text(io.file("err"));
  return r;
}

ScratchDir::ScratchDir() {
  static int n = 0;
  path_ = ::testing::TempDir() + "/sdfc_robust_" + std::to_string(getpid()) + "_" + std::to_string(n++);
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string ScratchDir::write(const std::string& name, const std::string& text) const {
  std::string p = file(name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

}  // namespace sdfc::test
