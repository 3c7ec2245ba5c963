// FFmpeg and OpenVDB are loaded by the commands that write a video or a
// mesh, and by no other: the dynamic loader's own log (LD_DEBUG=files) of
// the real binary says which libraries a run opened.
#include <gtest/gtest.h>

#include <string>

#include "run_sdfc.hpp"

namespace {

using sdfc::test::RunResult;
using sdfc::test::ScratchDir;

bool opened(const RunResult& r, const std::string& library) {
  return r.err.find("file=" + library) != std::string::npos;
}

TEST(LibraryLoading, OnlyAVideoLoadsFfmpegAndOnlyAMeshLoadsOpenVdb) {
  ScratchDir dir;
  RunResult png = sdfc::test::run_sdfc("render examples/primitives.yaml --width 32 --height 16 -q -o " +
                                           dir.file("a.png"),
                                       "LD_DEBUG=files ");
  ASSERT_EQ(png.code, 0) << png.err;
  ASSERT_TRUE(opened(png, "libOpenCL")) << "the loader's log is there";
  EXPECT_FALSE(opened(png, "libavcodec")) << "a PNG render loaded FFmpeg";
  EXPECT_FALSE(opened(png, "libopenvdb")) << "a PNG render loaded OpenVDB";

  RunResult video = sdfc::test::run_sdfc("render examples/animated.yaml --width 32 --height 16 --frames 0:1 -q -o " +
                                             dir.file("a.mp4"),
                                         "LD_DEBUG=files ");
  ASSERT_EQ(video.code, 0) << video.err;
  EXPECT_TRUE(opened(video, "libavcodec"));
  EXPECT_TRUE(opened(video, "libavformat"));
  EXPECT_FALSE(opened(video, "libopenvdb"));

  const std::string sphere = dir.write("s.yaml", "scene: {sphere: {radius: 1}}\n");
  RunResult mesh = sdfc::test::run_sdfc("mesh " + sphere + " --resolution 16 -o " + dir.file("s.stl"), "LD_DEBUG=files ");
  ASSERT_EQ(mesh.code, 0) << mesh.err;
  EXPECT_NE(mesh.err.find("libsdfc_openvdb.so"), std::string::npos);
  EXPECT_TRUE(opened(mesh, "libopenvdb"));
  EXPECT_FALSE(opened(mesh, "libavcodec"));
}

}  // namespace
