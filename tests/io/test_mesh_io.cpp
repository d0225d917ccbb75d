/// @file
/// Extension dispatch of read_mesh / write_mesh.

#include <gtest/gtest.h>

#include "io_test_support.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;

MeshData small_mesh() {
  MeshData m;
  m.vertices.resize(4, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.1, 0.2, 0.3;
  m.faces.resize(2, 3);
  m.faces << 0, 1, 2, 0, 2, 3;
  return m;
}

TEST(MeshIo, DispatchesOnExtensionCaseInsensitively) {
  TempDir dir;
  const MeshData m = small_mesh();
  for (const char* name : {"a.obj", "b.OBJ", "c.ply", "d.PlY"}) {
    SCOPED_TRACE(name);
    write_mesh(dir / name, m.vertices, m.faces);
    const MeshData back = read_mesh(dir / name);
    EXPECT_EQ(back.vertices, m.vertices);
    EXPECT_EQ(back.faces, m.faces);
  }
  // The content really is in the format the extension says.
  EXPECT_EQ(test::read_bytes(dir / "c.ply").substr(0, 4), "ply\n");
  EXPECT_EQ(test::read_bytes(dir / "a.obj").substr(0, 2), "v ");
  EXPECT_TRUE(is_mesh_file_name("x/y/Frame_01.OBJ"));
  EXPECT_FALSE(is_mesh_file_name("x/y/frame.stl"));
}

TEST(MeshIo, UnknownExtension) {
  TempDir dir;
  test::write_bytes(dir / "mesh.stl", "solid x\nendsolid x\n");
  expect_contains(input_error_message([&] { read_mesh(dir / "mesh.stl"); }),
                  {"mesh.stl", "unknown mesh file extension '.stl'"});
  expect_contains(input_error_message([&] { read_mesh(dir / "noext"); }),
                  {"noext", "unknown mesh file extension"});
  const MeshData m = small_mesh();
  expect_contains(input_error_message([&] { write_mesh(dir / "out.off", m.vertices, m.faces); }),
                  {"out.off", "unknown mesh file extension"});
}

TEST(MeshIo, MissingFile) {
  TempDir dir;
  expect_contains(input_error_message([&] { read_mesh(dir / "nothing-here.ply"); }),
                  {"cannot open", "nothing-here.ply"});
  expect_contains(input_error_message([&] { read_mesh(dir / "nothing-here.obj"); }),
                  {"cannot open", "nothing-here.obj"});
  std::filesystem::create_directories(dir / "folder.obj");
  expect_contains(input_error_message([&] { read_mesh(dir / "folder.obj"); }),
                  {"cannot open", "folder.obj", "directory"});
}

}  // namespace
}  // namespace tailor
