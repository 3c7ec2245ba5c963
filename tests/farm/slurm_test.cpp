// The farm on a real Slurm (tests/farm/slurm-local starts a one-node
// cluster; SLURM_CONF names it): the scripts `sdfc farm slurm` writes are
// submitted as they are. An animation as a 4-task array and a still as 4
// parts plus a merge equal the one-machine renders byte for byte; a task
// re-queued mid-frame resumes without a partial file; a failed part cancels
// the merge, and `sdfc merge` names the missing part.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <thread>

#include "farm_test_support.hpp"
#include "run_sdfc.hpp"
#include "test_files.hpp"

namespace sdfc::test {
namespace {

const std::string kLens = farm_scene("lens.yaml");
const std::string kOrbit = farm_scene("orbit.yaml");

class Slurm : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* conf = std::getenv("SLURM_CONF");
    const bool ci = std::getenv("CI") && std::string(std::getenv("CI")) == "true";
    const Shell s = shell("sinfo -h -o %T");
    if (!conf || s.code != 0 || s.out.find("idle") == std::string::npos) {
      const std::string why = std::string("no Slurm cluster to submit to (SLURM_CONF=") + (conf ? conf : "unset") +
                              ", sinfo: " + s.out + "); start one with: eval \"$(tests/farm/slurm-local start)\"";
      if (ci) FAIL() << why;
      GTEST_SKIP() << why;
    }
  }
};

// The job ids `sdfc farm slurm --submit` (the submit script) prints.
std::string job_id(const std::string& out, const std::string& label) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex(label + ": (\\d+)"))) return "";
  return m[1];
}

std::string job_states(const std::string& id) {
  return shell("scontrol show job " + id + " | sed -n 's/.*JobState=\\([A-Z_]*\\).*/\\1/p' | sort | uniq -c").out;
}

// Waits until no job of `id` (an array: every task) is pending or running.
bool wait_for(const std::string& id, int seconds = 120) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (shell("squeue -h -j " + id + " -o %T").out.empty()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return false;
}

std::string logs(const std::string& dir) {
  std::string all;
  for (const auto& e : std::filesystem::directory_iterator(dir)) all += read_text(e.path().string());
  return all;
}

RunResult ok(const std::string& args) {
  RunResult r = run_sdfc(args);
  EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
  return r;
}

TEST_F(Slurm, EightFramesAsAFourTaskArrayEqualOneMachine) {
  ScratchDir d;
  ok("render -q " + kOrbit + " --frames 0:7 -o " + d.file("one/f_%02d.png"));
  RunResult r = ok("farm slurm " + kOrbit + " --frames 0:7 --tasks 4 --time 00:05:00 -o " + d.file("farm/f_%02d.png") +
                   " --submit");
  const std::string id = job_id(r.out, "render job array");
  ASSERT_FALSE(id.empty()) << r.out << r.err;
  ASSERT_TRUE(wait_for(id)) << job_states(id);
  EXPECT_EQ(job_states(id), "      4 COMPLETED\n");
  for (int f = 0; f < 8; ++f) {
    const std::string name = "/f_0" + std::to_string(f) + ".png";
    EXPECT_EQ(compare_files(d.file("one") + name, d.file("farm") + name), "");
  }
  // Contiguous shares: task 1 rendered frames 2 and 3.
  const std::string task1 = read_text(d.file("farm/f.logs/sdfc-f-" + id + "_1.log"));
  EXPECT_NE(task1.find("f_02.png"), std::string::npos) << task1;
  EXPECT_NE(task1.find("f_03.png"), std::string::npos) << task1;
  EXPECT_EQ(task1.find("f_04.png"), std::string::npos) << task1;
  EXPECT_TRUE(leftovers(d.path()).empty());
}

TEST_F(Slurm, AFourPartStillMergedEqualsOneMachineWithItsAovs) {
  ScratchDir d;
  ok("render -q " + kLens + " --width 40 --height 30 --aov depth,normal -o " + d.file("one.png"));
  RunResult r = ok("farm slurm " + kLens + " --still 40x30 --parts 4 --aov depth,normal -o " + d.file("farm/still.png") +
                   " --submit");
  const std::string array = job_id(r.out, "render job array"), merge = job_id(r.out, "merge job");
  ASSERT_FALSE(merge.empty()) << r.out << r.err;
  ASSERT_TRUE(wait_for(array) && wait_for(merge)) << job_states(array) << job_states(merge);
  EXPECT_EQ(job_states(array), "      4 COMPLETED\n");
  EXPECT_EQ(job_states(merge), "      1 COMPLETED\n") << logs(d.file("farm/still.logs"));
  for (const char* f : {".png", ".depth.pfm", ".normal.pfm"})
    EXPECT_EQ(compare_files(d.file(std::string("one") + f), d.file(std::string("farm/still") + f)), "");
}

TEST_F(Slurm, ATaskRequeuedMidFrameResumesWithoutAPartialFile) {
  ScratchDir d;
  // Eight frames of about half a second each, in one task.
  const std::string size = " --set render.width=256 --set render.height=192 --set render.samples=8";
  ok("render -q " + kOrbit + size + " --frames 0:7 -o " + d.file("one/f_%d.png"));
  RunResult r = ok("farm slurm " + kOrbit + size + " --frames 0:7 --tasks 1 -o " + d.file("farm/f_%d.png") + " --submit");
  const std::string id = job_id(r.out, "render job array");
  ASSERT_FALSE(id.empty()) << r.out << r.err;
  // Once the first frame is written, the task is in the middle of the next.
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!std::filesystem::exists(d.file("farm/f_0.png")) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(std::filesystem::exists(d.file("farm/f_0.png"))) << job_states(id);
  ASSERT_FALSE(std::filesystem::exists(d.file("farm/f_7.png"))) << "the task finished before it could be re-queued";
  const Shell rq = shell("scontrol requeue " + id);
  ASSERT_EQ(rq.code, 0) << rq.out;
  // slurm-local's cred_expire=5 lets the re-queued task start again after about 5 s.
  ASSERT_TRUE(wait_for(id, 180)) << job_states(id);
  EXPECT_EQ(job_states(id), "      1 COMPLETED\n");
  const std::string log = logs(d.file("farm/f.logs"));
  EXPECT_NE(log.find("was not written"), std::string::npos) << log;  // stopped mid-frame by SIGTERM
  EXPECT_TRUE(std::regex_search(log, std::regex("frame 0: \\S*f_0.png is complete already, skipped"))) << log;
  for (int f = 0; f < 8; ++f) {
    const std::string name = "/f_" + std::to_string(f) + ".png";
    EXPECT_EQ(compare_files(d.file("one") + name, d.file("farm") + name), "");
  }
  EXPECT_TRUE(leftovers(d.path()).empty());
}

TEST_F(Slurm, AFailedPartCancelsTheMergeAndMergeNamesIt) {
  ScratchDir d;
  RunResult r = ok("farm slurm " + kLens + " --still 40x30 --parts 4 -o " + d.file("farm/still.png"));
  // Part 2 cannot be written: a directory stands where its file goes.
  const std::string part2 = d.file("farm/still.parts/part_002.region");
  std::filesystem::create_directories(part2);
  const Shell sub = shell("sh " + d.file("farm/still.submit.sh"));
  ASSERT_EQ(sub.code, 0) << sub.out;
  const std::string array = job_id(sub.out, "render job array"), merge = job_id(sub.out, "merge job");
  ASSERT_FALSE(merge.empty()) << sub.out;
  ASSERT_TRUE(wait_for(array) && wait_for(merge)) << job_states(array) << job_states(merge);
  EXPECT_EQ(job_states(array), "      3 COMPLETED\n      1 FAILED\n");
  EXPECT_EQ(job_states(merge), "      1 CANCELLED\n");
  EXPECT_FALSE(std::filesystem::exists(d.file("farm/still.png")));
  std::filesystem::remove(part2);
  std::string parts;
  for (int k = 0; k < 4; ++k) parts += " " + d.file("farm/still.parts/part_00" + std::to_string(k) + ".region");
  RunResult m = run_sdfc("merge" + parts + " -o " + d.file("farm/still.png"));
  EXPECT_EQ(m.code, 4);
  EXPECT_NE(m.err.find("cannot read '" + part2 + "'"), std::string::npos) << m.err;
  const std::string three = std::regex_replace(parts, std::regex(" \\S*part_002.region"), "");
  m = run_sdfc("merge" + three + " -o " + d.file("farm/still.png"));
  EXPECT_EQ(m.code, 2);
  EXPECT_NE(m.err.find("part 2 of 4 is missing"), std::string::npos) << m.err;
}

}  // namespace
}  // namespace sdfc::test
