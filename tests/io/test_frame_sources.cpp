/// @file
/// Frame arguments to one sequence: folders, globs, file lists, the simulator's layout, and
/// the errors for mixed or ambiguous sequences.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "io_test_support.hpp"
#include "tailor/io/frame_sources.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

using namespace test;  // io_test_support.hpp

TEST(FrameSources, OneSequenceFromAFolderAGlobOrFiles) {
  TempDir dir;
  for (int i : {1, 2, 10}) write_triangle(dir / fmt::format("frame_{}.obj", i));
  const std::vector<std::string> expected = {"frame_1.obj", "frame_2.obj", "frame_10.obj"};
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{dir.path().string()},
        std::vector<std::string>{(dir / "frame_*.obj").string()},
        // As a shell expands the glob: in byte order, which is not the frame order.
        std::vector<std::string>{(dir / "frame_1.obj").string(), (dir / "frame_10.obj").string(),
                                 (dir / "frame_2.obj").string()}}) {
    const FrameSources sources = resolve_frame_sources(arguments);
    EXPECT_EQ(file_names(sources.frames), expected) << arguments.front();
    EXPECT_EQ(sources.frames_pattern, "frame_*.obj");
    EXPECT_TRUE(sources.obstacle.empty());
    EXPECT_FALSE(sources.obstacle_from_layout);
  }
  const FrameSources single = resolve_frame_sources({(dir / "frame_2.obj").string()});
  EXPECT_EQ(file_names(single.frames), (std::vector<std::string>{"frame_2.obj"}));
}

TEST(FrameSources, SimulatorLayoutTakesTheArmAsObstacle) {
  TempDir dir;
  for (int i = 0; i < 3; ++i) {
    write_triangle(dir / fmt::format("cloth_{:04d}.obj", i));
    write_triangle(dir / fmt::format("arm_{:04d}.obj", i));
  }
  test::write_bytes(dir / "steps.jsonl", "{}\n");
  const FrameSources sources = resolve_frame_sources({dir.path().string()});
  EXPECT_EQ(file_names(sources.frames),
            (std::vector<std::string>{"cloth_0000.obj", "cloth_0001.obj", "cloth_0002.obj"}));
  EXPECT_EQ(file_names(sources.obstacle),
            (std::vector<std::string>{"arm_0000.obj", "arm_0001.obj", "arm_0002.obj"}));
  EXPECT_EQ(sources.obstacle_pattern, "arm_*.obj");
  EXPECT_TRUE(sources.obstacle_from_layout);

  // A named obstacle replaces the arm; a pattern picks one sequence with no obstacle.
  std::filesystem::create_directories(dir / "elsewhere");
  write_triangle(dir / "elsewhere" / "floor.obj");
  const FrameSources named =
      resolve_frame_sources({dir.path().string()}, (dir / "elsewhere" / "floor.obj").string());
  EXPECT_EQ(file_names(named.obstacle), (std::vector<std::string>{"floor.obj"}));
  EXPECT_FALSE(named.obstacle_from_layout);
  const FrameSources arm_only = resolve_frame_sources({(dir / "arm_*.obj").string()});
  EXPECT_EQ(arm_only.frames.size(), 3u);
  EXPECT_TRUE(arm_only.obstacle.empty());
}

TEST(FrameSources, MixedSequencesAskForAPattern) {
  TempDir dir;
  for (int i = 0; i < 2; ++i) {
    write_triangle(dir / fmt::format("a_{}.obj", i));
    write_triangle(dir / fmt::format("b_{}.obj", i));
  }
  write_triangle(dir / "b_7.ply");
  const std::string message =
      input_error_message([&] { resolve_frame_sources({dir.path().string()}); });
  expect_contains(message, {dir.path().string(), "mixes 3 frame sequences", "a_*.obj (2 files)",
                            "b_*.obj (2 files)", "b_*.ply (1 file)", "name one with a pattern",
                            (dir / "a_*.obj").string()});
  expect_contains(input_error_message([&] {
                    resolve_frame_sources({(dir / "a_0.obj").string()}, dir.path().string());
                  }),
                  {"mixes 3 frame sequences"});
}

TEST(FrameSources, AmbiguousOrMissingFilesAreErrors) {
  TempDir dir;
  write_triangle(dir / "f_2.obj");
  write_triangle(dir / "f_02.obj");
  expect_contains(input_error_message([&] { resolve_frame_sources({dir.path().string()}); }),
                  {"f_02.obj", "f_2.obj", "both carry frame number 2"});
  expect_contains(
      input_error_message([&] {
        resolve_frame_sources({(dir / "f_2.obj").string(), (dir / "missing_3.obj").string()});
      }),
      {"missing_3.obj", "cannot open"});
  expect_contains(input_error_message([&] { resolve_frame_sources({}); }), {"no frames"});
  expect_contains(input_error_message([&] { resolve_frame_sources({(dir / "nothing").string()}); }),
                  {"nothing", "not a folder"});
}

}  // namespace
}  // namespace tailor
