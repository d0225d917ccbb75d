/// @file
/// Frame listing (folders and printf patterns) and checked frame loading.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "io_test_support.hpp"
#include "tailor/io/frame_sequence.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

using namespace test;  // io_test_support.hpp

MeshData frame(double shift, Index extra_vertices = 0, bool flip = false) {
  MeshData m;
  m.vertices.resize(4 + extra_vertices, 3);
  for (Index v = 0; v < m.vertices.rows(); ++v) m.vertices.row(v) << v + shift, v * v, -shift;
  m.faces.resize(2, 3);
  m.faces << 0, 1, 2, 0, 2, 3;
  if (flip) m.faces.row(1) << 0, 3, 2;
  return m;
}

void write_frame(const std::filesystem::path& path, const MeshData& m) {
  write_mesh(path, m.vertices, m.faces);
}

TEST(FrameSequence, FolderIsSortedByNumberThenName) {
  TempDir dir;
  for (const char* name : {"frame10.obj", "frame2.ply", "frame1.obj", "frame02.obj", "b.obj",
                           "a.PLY", "frame_0003.obj"}) {
    write_frame(dir / name, frame(0));
  }
  test::write_bytes(dir / "notes.txt", "not a mesh");
  std::filesystem::create_directories(dir / "sub.obj");
  EXPECT_EQ(file_names(list_frame_files(dir.path())),
            (std::vector<std::string>{"frame1.obj", "frame02.obj", "frame2.ply", "frame_0003.obj",
                                      "frame10.obj", "a.PLY", "b.obj"}));
}

TEST(FrameSequence, PatternsStartAtZeroOrOne) {
  TempDir dir;
  for (int i = 0; i < 3; ++i) write_frame(dir / fmt::format("{}.ply", i), frame(i));
  write_frame(dir / "4.ply", frame(4));  // after a gap: not part of the sequence
  EXPECT_EQ(file_names(list_frame_files((dir / "%d.ply").string())),
            (std::vector<std::string>{"0.ply", "1.ply", "2.ply"}));
  for (int i = 1; i <= 12; ++i) write_frame(dir / fmt::format("cloth_{:04d}.obj", i), frame(i));
  const auto padded = list_frame_files((dir / "cloth_%04d.obj").string());
  ASSERT_EQ(padded.size(), 12u);
  EXPECT_EQ(padded.front().filename(), "cloth_0001.obj");
  EXPECT_EQ(padded.back().filename(), "cloth_0012.obj");
  expect_contains(input_error_message([&] { list_frame_files((dir / "none_%d.obj").string()); }),
                  {"no frame files match", "none_%d.obj"});
  expect_contains(input_error_message([&] { list_frame_files((dir / "%s.obj").string()); }),
                  {"unsupported conversion"});
  expect_contains(input_error_message([&] { list_frame_files((dir / "%d_%d.obj").string()); }),
                  {"more than one"});
  expect_contains(input_error_message([&] { list_frame_files(dir / "missing-folder"); }),
                  {"missing-folder", "not a folder"});
  std::filesystem::create_directories(dir / "empty");
  expect_contains(input_error_message([&] { list_frame_files(dir / "empty"); }),
                  {"no .obj or .ply files", "empty"});
}

TEST(FrameSequence, LoadsFramesLazilyAndChecksThem) {
  TempDir dir;
  for (int i = 0; i < 3; ++i) write_frame(dir / fmt::format("f{}.obj", i), frame(0.5 * i));
  const FrameSequence frames(dir.path());
  ASSERT_EQ(frames.num_frames(), 3);
  EXPECT_EQ(frames.num_vertices(), 4);
  EXPECT_EQ(frames.faces(), frame(0).faces);
  for (Index i = 0; i < 3; ++i) EXPECT_EQ(frames.load(i), frame(0.5 * i).vertices);
  EXPECT_THROW(frames.load(3), InputError);
}

TEST(FrameSequence, DifferentVertexCountIsAnError) {
  TempDir dir;
  write_frame(dir / "1.ply", frame(0));
  write_frame(dir / "2.ply", frame(1, 2));
  const FrameSequence frames((dir / "%d.ply").string());
  ASSERT_EQ(frames.num_frames(), 2);
  expect_contains(input_error_message([&] { frames.load(1); }),
                  {"2.ply", "6 vertices", "first frame", "1.ply", "has 4"});
}

TEST(FrameSequence, DifferentFacesIsAnError) {
  TempDir dir;
  write_frame(dir / "1.obj", frame(0));
  write_frame(dir / "2.obj", frame(1, 0, true));
  const FrameSequence frames(dir.path());
  expect_contains(input_error_message([&] { frames.load(1); }),
                  {"2.obj", "faces differ", "1.obj", "face 1"});
}

TEST(FrameSequence, ObjFramesWithTheFirstFramesFacesWrittenOtherwiseOrAsPly) {
  // Frames whose text after the vertices is not the first frame's are parsed in full.
  TempDir dir;
  write_frame(dir / "0.obj", frame(0));
  write_bytes(dir / "1.obj", "v 1 0 -1\nv 2 1 -1\nv 3 4 -1\nv 4 9 -1\nf 1/1 2/1 3/1\nf 1 3 4\n");
  write_frame(dir / "2.ply", frame(2));
  write_frame(dir / "3.obj", frame(3));
  const FrameSequence frames(dir.path());
  ASSERT_EQ(frames.num_frames(), 4);
  for (Index i = 0; i < 4; ++i) EXPECT_EQ(frames.load(i), frame(i).vertices) << "frame " << i;
}

TEST(FrameSequence, ReferenceClothFunnelFrames) {
  const std::filesystem::path folder =
      std::filesystem::path(TAILOR_DATA_DIR) / "cloth-funnel/frames";
  const FrameSequence frames(folder);
  ASSERT_EQ(frames.num_frames(), 2);
  EXPECT_EQ(frames.path(0).filename(), "227.ply");
  EXPECT_EQ(frames.path(1).filename(), "228.ply");
  EXPECT_EQ(frames.num_vertices(), 9450);
  EXPECT_EQ(frames.faces().rows(), 18484);
  const Positions x1 = frames.load(1);
  EXPECT_EQ(x1.rows(), 9450);
  EXPECT_NE(x1, frames.load(0));
}

}  // namespace
}  // namespace tailor
