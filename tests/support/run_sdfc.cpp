#include "run_sdfc.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sdfc::test {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
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
