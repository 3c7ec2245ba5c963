// Split renders through the real binary, no scheduler: a still rendered in
// parts and merged, and an animation rendered in shards, have the bytes of
// the one-machine render (every random sequence is on in these scenes);
// merge refuses missing and mismatched parts; a re-run resumes; a stopped
// task leaves no partial file.
#include <gtest/gtest.h>

#include <filesystem>

#include "farm_test_support.hpp"
#include "run_sdfc.hpp"

namespace sdfc::test {
namespace {

const std::string kLens = farm_scene("lens.yaml");    // a 40x30 still: 4 samples, tent, dither, thin lens
const std::string kOrbit = farm_scene("orbit.yaml");  // a 32x24 animation: 2 dithered samples

RunResult ok(const std::string& args) {
  RunResult r = run_sdfc(args + " -q");
  EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
  return r;
}

TEST(SplitRender, StripsMergeToTheWholeStillWithItsAovs) {
  ScratchDir d;
  ok("render " + kLens + " --aov depth,normal,hit -o " + d.file("whole.png"));
  // 30 rows in 4 strips: 7 or 8 rows each, not whole 4x4 packets.
  RunResult r = ok("render " + kLens + " --aov depth,normal,hit --parts 4 -o " + d.file("parts/p_%d.region"));
  EXPECT_EQ(r.out, d.file("parts/p_0.region") + "\n" + d.file("parts/p_1.region") + "\n" + d.file("parts/p_2.region") +
                       "\n" + d.file("parts/p_3.region") + "\n");
  // The same scene from another path (another node's mount) is the same still.
  std::filesystem::copy_file(kLens, d.file("copy.yaml"));
  std::filesystem::remove(d.file("parts/p_2.region"));
  ok("render " + d.file("copy.yaml") + " --aov depth,normal,hit --parts 4 --shard 2/4 -o " + d.file("parts/p_%d.region"));
  ok("merge " + d.file("parts/p_2.region") + " " + d.file("parts/p_0.region") + " " + d.file("parts/p_3.region") + " " +
     d.file("parts/p_1.region") + " -o " + d.file("merged.png"));
  for (const char* f : {".png", ".depth.pfm", ".normal.pfm", ".hit.pfm"})
    EXPECT_EQ(compare_files(d.file(std::string("whole") + f), d.file(std::string("merged") + f)), "");
}

TEST(SplitRender, RectanglesMergeToTheWholeSixteenBitStill) {
  ScratchDir d;
  ok("render " + kLens + " --bit-depth 16 --aov depth -o " + d.file("whole.png"));
  std::string parts;
  for (const char* rect : {"0,0,17,30", "17,0,40,11", "17,11,40,30"}) {
    const std::string out = d.file(std::string("r") + rect[0] + rect[3] + ".region");
    ok("render " + kLens + " --bit-depth 16 --aov depth --region " + rect + " -o " + out);
    parts += " " + out;
  }
  ok("merge" + parts + " -o " + d.file("merged.png"));
  EXPECT_EQ(compare_files(d.file("whole.png"), d.file("merged.png")), "");
  EXPECT_EQ(compare_files(d.file("whole.depth.pfm"), d.file("merged.depth.pfm")), "");
}

TEST(SplitRender, MergeRefusesMissingOverlappingAndMismatchedParts) {
  ScratchDir d;
  ok("render " + kLens + " --parts 4 -o " + d.file("p_%d.region"));
  const std::string p0 = d.file("p_0.region"), p1 = d.file("p_1.region"), p2 = d.file("p_2.region"),
                    p3 = d.file("p_3.region");
  RunResult r = run_sdfc("merge " + p0 + " " + p1 + " " + p3 + " -o " + d.file("m.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("part 2 of 4 is missing"), std::string::npos) << r.err;
  std::filesystem::rename(p2, d.file("moved.region"));
  r = run_sdfc("merge " + p0 + " " + p1 + " " + p2 + " " + p3 + " -o " + d.file("m.png"));
  EXPECT_EQ(r.code, 4);
  EXPECT_NE(r.err.find("cannot read '" + p2 + "'"), std::string::npos) << r.err;
  std::filesystem::rename(d.file("moved.region"), p2);
  r = run_sdfc("merge " + p0 + " " + p1 + " " + p2 + " " + p3 + " " + p1 + " -o " + d.file("m.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("part 1 of 4 is given twice"), std::string::npos) << r.err;
  ok("render " + kLens + " --set render.samples=2 --region 0,0,40,30 -o " + d.file("other.region"));
  ok("render " + kLens + " --region 0,0,40,16 -o " + d.file("top.region"));
  r = run_sdfc("merge " + d.file("top.region") + " " + d.file("other.region") + " -o " + d.file("m.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("another scene or other settings"), std::string::npos) << r.err;
  std::filesystem::resize_file(p3, std::filesystem::file_size(p3) - 1);
  r = run_sdfc("merge " + p0 + " " + p1 + " " + p2 + " " + p3 + " -o " + d.file("m.png"));
  EXPECT_EQ(r.code, 4);
  EXPECT_NE(r.err.find("not a complete region file"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(d.file("m.png")));
  EXPECT_TRUE(leftovers(d.path()).empty());
}

TEST(SplitRender, ShardsOfFramesEqualTheWholeSequence) {
  ScratchDir d;
  ok("render " + kOrbit + " --frames 0:7 -o " + d.file("whole/f_%02d.png"));
  for (const char* mode : {"contiguous", "strided"}) {
    const std::string dir = d.file(mode);
    for (int k = 0; k < 3; ++k)  // 8 frames over 3 tasks: 3, 3 and 2
      ok("render " + kOrbit + " --frames 0:7 --shard " + std::to_string(k) + "/3 --shard-mode " + mode + " -o " + dir +
         "/f_%02d.png");
    for (int f = 0; f < 8; ++f) {
      const std::string name = "/f_0" + std::to_string(f) + ".png";
      EXPECT_EQ(compare_files(d.file("whole") + name, dir + name), "") << mode;
    }
  }
  RunResult r = ok("render " + kOrbit + " --frames 0:7 --shard 1/3 --shard-mode strided -o " + d.file("s/f_%02d.png"));
  EXPECT_EQ(r.out, d.file("s/f_01.png") + "\n" + d.file("s/f_04.png") + "\n" + d.file("s/f_07.png") + "\n");
  // A task with one frame of a sequence still creates the sequence's folder.
  r = ok("render " + kOrbit + " --frames 0:7 --shard 7/8 -o " + d.file("one_each/f_%02d.png"));
  EXPECT_EQ(r.out, d.file("one_each/f_07.png") + "\n");
}

TEST(SplitRender, ARerunSkipsCompleteFramesAndRedoesTheRest) {
  ScratchDir d;
  const std::string args = "render " + kOrbit + " --frames 0:5 --shard 0/1 --aov depth -o " + d.file("f_%d.png");
  ok(args);
  const std::string good = read_text(d.file("f_3.png"));
  std::filesystem::resize_file(d.file("f_3.png"), 100);          // a damaged image
  std::filesystem::remove(d.file("f_5.png"));                    // a frame never written
  std::filesystem::resize_file(d.file("f_1.depth.pfm"), 20);     // a damaged AOV
  RunResult r = run_sdfc(args);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, d.file("f_1.png") + "\n" + d.file("f_1.depth.pfm") + "\n" + d.file("f_3.png") + "\n" +
                       d.file("f_3.depth.pfm") + "\n" + d.file("f_5.png") + "\n" + d.file("f_5.depth.pfm") + "\n");
  EXPECT_NE(r.err.find("frame 0: " + d.file("f_0.png") + " is complete already, skipped"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(d.file("f_3.png")), good);
}

// SIGTERM is how a scheduler stops a task (scancel, requeue, time limit):
// the render stops, its temporary files go, no final name is written.
TEST(SplitRender, ATerminatedRenderLeavesNoPartialFile) {
  ScratchDir d;
  ok("render " + kLens + " --width 32 --height 32 -o " + d.file("warm.png"));  // the kernel in the cache
  RunResult r = run_sdfc("render " + kLens + " --width 640 --height 480 --set render.samples=64 --aov depth --frames 0:3 -o " +
                             d.file("f_%d.png"),
                         "timeout --preserve-status -s TERM 4 ");
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("was not written"), std::string::npos) << r.err;
  // On a quiet machine a frame may finish before the signal: every frame
  // file there is must be a whole PNG (it ends in its IEND chunk), and the
  // frame in progress is not there at all.
  int written = 0;
  for (int i = 0; i < 4; ++i) {
    const std::string f = d.file("f_" + std::to_string(i) + ".png");
    if (!std::filesystem::exists(f)) continue;
    ++written;
    const std::string png = read_text(f);
    EXPECT_TRUE(png.size() > 12 && png.compare(png.size() - 8, 4, "IEND") == 0) << f << " is not a whole PNG";
  }
  EXPECT_LT(written, 4) << "every frame finished: the render was not stopped";
  EXPECT_TRUE(leftovers(d.path()).empty());
}

// A '%' in a still's name: the job's render writes its parts where the merge
// reads them (the parts pattern doubles the '%', the render makes it one).
TEST(SplitRender, APercentInAStillsNameReachesThePartsTheMergeReads) {
  ScratchDir d;
  RunResult r = run_sdfc("farm slurm " + kLens + " --still 40x30 --parts 2 -o '" + d.file("5%%.png") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string array = read_text(d.file("5%%.sbatch")), merge = read_text(d.file("5%%.merge.sbatch"));
  auto normal = [&](const std::string& name) { return std::filesystem::path(d.file(name)).lexically_normal().string(); };
  const std::string pattern = normal("5%%%%.parts/part_%03d.region");
  EXPECT_NE(array.find("-o '" + pattern + "'"), std::string::npos) << array;
  const std::string part0 = normal("5%%.parts/part_000.region"), part1 = normal("5%%.parts/part_001.region");
  EXPECT_NE(merge.find("'" + part0 + "' '" + part1 + "'"), std::string::npos) << merge;
  EXPECT_TRUE(std::filesystem::is_directory(d.file("5%%.parts")));
  r = ok("render " + kLens + " --width 40 --height 30 --parts 2 -o '" + pattern + "'");
  EXPECT_EQ(r.out, part0 + "\n" + part1 + "\n");
  ok("merge '" + part0 + "' '" + part1 + "' -o " + d.file("merged.png"));
}

TEST(SplitRender, HelpAndUsageErrors) {
  for (const char* c : {"merge --help", "farm --help", "farm slurm --help"}) {
    RunResult r = run_sdfc(c);
    EXPECT_EQ(r.code, 0) << c;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << c << ": " << r.out;
  }
  RunResult r = run_sdfc("render " + kOrbit + " --frames 0:7 --shard 8/8 -o /tmp/never_%d.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("TASK must be 0 to 7"), std::string::npos) << r.err;
  r = run_sdfc("render " + kLens + " --parts 2 -o /tmp/never.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("must end in .region"), std::string::npos) << r.err;
  r = run_sdfc("farm slurm " + kLens + " --still 40x30 -o /tmp/never.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--still needs --parts"), std::string::npos) << r.err;
  r = run_sdfc("farm slurm " + kOrbit + " --frames 0:7 --tasks 9 -o /tmp/never_%d.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("only 8 frames"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sdfc::test
