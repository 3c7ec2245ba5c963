// Outputs through AtomicFile: a device or FIFO is written in place (never
// replaced by a regular file), a symlink's target is written, an input is
// never overwritten, stale temp files of dead runs are cleaned up. These
// tests run as root on the CI machine, where replacing a device node would
// succeed: they use device nodes of their own (mknod), never /dev's.
#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdio>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>

#include "run_sdfc.hpp"

namespace sdfc::test {
namespace {

namespace fs = std::filesystem;

const char* kScene = "camera: {position: [0, -4, 1], target: [0, 0, 0]}\nrender: {width: 16, height: 16}\n"
                     "scene: {sphere: {radius: 1}}\n";

bool is_char_device(const std::string& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

TEST(OutputPaths, DeviceTargetsAreWrittenInPlace) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kScene);
  std::string null_dev = dir.file("null"), full_dev = dir.file("full");
  ASSERT_EQ(::mknod(null_dev.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
  ASSERT_EQ(::mknod(full_dev.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0);
  // A device's name has no extension: render is told the format.
  for (const char* cmd : {"render --format png", "compile"}) {
    SCOPED_TRACE(cmd);
    RunResult r = run_sdfc(std::string(cmd) + " " + scene + " -o " + null_dev);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(is_char_device(null_dev)) << "the null device was replaced";
    r = run_sdfc(std::string(cmd) + " " + scene + " -o " + full_dev);
    EXPECT_EQ(r.code, 4) << "a full device is a full disk: " << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
    EXPECT_TRUE(is_char_device(full_dev)) << "the full device was replaced";
  }
}

TEST(OutputPaths, AFifoIsWrittenInPlace) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kScene);
  std::string fifo = dir.file("pipe"), got = dir.file("got");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  RunResult r = run_sdfc("compile " + scene + " -o " + fifo, "(cat " + fifo + " > " + got + " &) ; ");
  EXPECT_EQ(r.code, 0) << r.err;
  std::string text;
  for (int i = 0; i < 500 && text.find("sdfc_render") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    text = read_text(got);
  }
  EXPECT_NE(text.find("__kernel"), std::string::npos) << "the reader got the kernel";
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo))) << "the FIFO was replaced";
}

TEST(OutputPaths, ASymlinksTargetIsWritten) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kScene);
  fs::create_directory(dir.file("real"));
  fs::create_symlink("real/kernel.cl", dir.file("link.cl"));
  RunResult r = run_sdfc("compile " + scene + " -o " + dir.file("link.cl"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir.file("link.cl")))) << "the link was replaced";
  EXPECT_NE(read_text(dir.file("real/kernel.cl")).find("__kernel"), std::string::npos);
  r = run_sdfc("render " + scene + " -q -o " + dir.file("link.png"),
               "ln -s real/image.png " + dir.file("link.png") + " && ");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir.file("link.png"))));
  EXPECT_GT(fs::file_size(dir.file("real/image.png")), 0u);
}

TEST(OutputPaths, AnOutputOntoAnInputIsRefused) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kScene);
  fs::create_symlink("s.yaml", dir.file("alias.yaml"));
  // --format png: without it the .yaml name is already refused as no image format.
  for (const std::string& args : {"render " + scene + " -q --format png -o " + scene, "compile " + scene + " -o " + scene,
                                  "compile " + scene + " -o " + dir.file("alias.yaml"),
                                  "render " + dir.file("alias.yaml") + " -q --format png -o " + scene}) {
    SCOPED_TRACE(args);
    RunResult r = run_sdfc(args);
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_NE(r.err.find("input"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(scene), kScene) << "the scene was overwritten";
  }
}

// Only files, devices and pipes are written: a directory or a socket is an
// output problem (exit 4), and stays what it was.
TEST(OutputPaths, ADirectoryOrASocketIsRefused) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kScene);
  fs::create_directory(dir.file("d"));
  int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(sock, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string sock_path = dir.file("sock");
  ASSERT_LT(sock_path.size(), sizeof addr.sun_path);
  std::snprintf(addr.sun_path, sizeof addr.sun_path, "%s", sock_path.c_str());
  ASSERT_EQ(::bind(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  for (const std::string& target : {dir.file("d"), sock_path})
    for (const char* cmd : {"render --format png -q", "compile"}) {
      SCOPED_TRACE(std::string(cmd) + " -o " + target);
      RunResult r = run_sdfc(std::string(cmd) + " " + scene + " -o " + target);
      EXPECT_EQ(r.code, 4) << r.err;
      EXPECT_NE(r.err.find(target == sock_path ? "it is a socket" : "it is a directory"), std::string::npos) << r.err;
    }
  ::close(sock);
  EXPECT_TRUE(fs::is_directory(dir.file("d")));
  EXPECT_TRUE(fs::is_socket(fs::symlink_status(sock_path)));
}

TEST(OutputPaths, StaleTempFilesOfDeadRunsAreRemoved) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kScene);
  // A pid that no process has (kill answers ESRCH), and our own, alive.
  pid_t dead = 4194000;
  while (::kill(dead, 0) == 0 || errno != ESRCH) --dead;
  std::string stale = dir.write("out.cl.tmp-" + std::to_string(dead) + "-abc123", "x");
  std::string live = dir.write("out.cl.tmp-" + std::to_string(::getpid()) + "-abc123", "x");
  std::string other = dir.write("out.cl.tmp-notours", "x");
  RunResult r = run_sdfc("compile " + scene + " -o " + dir.file("out.cl"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale)) << "a dead run's temp file is removed";
  EXPECT_TRUE(fs::exists(live)) << "a running process's temp file is kept";
  EXPECT_TRUE(fs::exists(other)) << "a name not of our pattern is kept";
}

}  // namespace
}  // namespace sdfc::test
