/// @file
/// Frame file names: natural order, globs, name patterns and groups.

#include <gtest/gtest.h>

#include "io_test_support.hpp"
#include "tailor/io/frame_files.hpp"
#include "tailor/io/frame_sequence.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

using namespace test;  // io_test_support.hpp

TEST(FrameFiles, NaturalOrder) {
  std::vector<std::filesystem::path> paths = {"d/frame_10.obj",
                                              "d/frame_2.obj",
                                              "d/frame_1.obj",
                                              "d/plain.obj",
                                              "d/frame_02.obj",
                                              "d/frame_100.obj",
                                              "d/frame_99999999999999999999999.obj"};
  sort_frame_files(paths);
  EXPECT_EQ(file_names(paths),
            (std::vector<std::string>{"frame_1.obj", "frame_02.obj", "frame_2.obj", "frame_10.obj",
                                      "frame_100.obj", "frame_99999999999999999999999.obj",
                                      "plain.obj"}));
}

TEST(FrameFiles, NumbersAndNamePatterns) {
  EXPECT_EQ(frame_number("out/cloth_0012.obj"), "12");
  EXPECT_EQ(frame_number("out/cloth_0000.obj"), "0");
  EXPECT_EQ(frame_number("run3/f7_final.PLY"), "7");
  EXPECT_EQ(frame_number("mesh.obj"), "");
  EXPECT_EQ(frame_name_pattern("out/cloth_0012.OBJ"), "cloth_*.obj");
  EXPECT_EQ(frame_name_pattern("227.ply"), "*.ply");
  EXPECT_EQ(frame_name_pattern("run2_frame7_final.obj"), "run2_frame*_final.obj");
  EXPECT_EQ(frame_name_pattern("mesh.obj"), "mesh.obj");
}

TEST(FrameFiles, GroupsKeepTheGivenOrder) {
  const std::vector<std::filesystem::path> paths = {"arm_0000.obj", "cloth_0000.obj",
                                                    "arm_0001.obj", "cloth_0001.obj", "a.ply"};
  const std::vector<FrameFileGroup> groups = group_frame_files(paths);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].name_pattern, "arm_*.obj");
  EXPECT_EQ(file_names(groups[0].paths),
            (std::vector<std::string>{"arm_0000.obj", "arm_0001.obj"}));
  EXPECT_EQ(groups[1].name_pattern, "cloth_*.obj");
  EXPECT_EQ(file_names(groups[1].paths),
            (std::vector<std::string>{"cloth_0000.obj", "cloth_0001.obj"}));
  EXPECT_EQ(groups[2].name_pattern, "a.ply");
}

TEST(FrameFiles, GlobExpandsInNaturalOrderAndKeepsMeshesOnly) {
  TempDir dir;
  for (const char* name : {"frame_10.obj", "frame_2.obj", "frame_1.obj", "other_1.obj"}) {
    write_triangle(dir / name);
  }
  test::write_bytes(dir / "frame_3.txt", "not a mesh");
  std::filesystem::create_directories(dir / "frame_4.obj");  // a folder, not a frame
  EXPECT_TRUE(has_glob_wildcard("out/cloth_*.obj"));
  EXPECT_TRUE(has_glob_wildcard("out/cloth_?.obj"));
  EXPECT_FALSE(has_glob_wildcard("out/cloth_%04d.obj"));
  const std::string pattern = (dir / "frame_*").string();
  EXPECT_EQ(file_names(expand_frame_glob(pattern)),
            (std::vector<std::string>{"frame_1.obj", "frame_2.obj", "frame_10.obj"}));
  EXPECT_EQ(file_names(list_frame_files(pattern)), file_names(expand_frame_glob(pattern)));
  EXPECT_EQ(file_names(expand_frame_glob((dir / "frame_?.obj").string())),
            (std::vector<std::string>{"frame_1.obj", "frame_2.obj"}));
  expect_contains(input_error_message([&] { expand_frame_glob((dir / "none_*.obj").string()); }),
                  {"no .obj or .ply files match", "none_*.obj"});
  expect_contains(input_error_message([&] { list_frame_files((dir / "*.txt").string()); }),
                  {"no .obj or .ply files match", "*.txt"});
}

}  // namespace
}  // namespace tailor
