/// @file
/// OBJ frames read against the first frame's face text: whatever a later frame holds, the
/// result (mesh or error message) is read_obj()'s.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "io_test_support.hpp"
#include "tailor/io/obj_frames.hpp"
#include "tailor/io/obj_io.hpp"
#include "tailor/io/obj_parser.hpp"

namespace tailor {
namespace {

using test::TempDir;
using test::write_bytes;

using test::expect_same;
using test::outcome_of;

/// Four vertices shifted by `shift`, as `v` lines.
std::string vertex_lines(double shift, int count = 4) {
  std::string text;
  for (int v = 0; v < count; ++v) text += fmt::format("v {} {} {}\n", v + shift, v * v, -shift);
  return text;
}

const std::string kFaces = "g cloth\nf 1 2 3\nf 1 3 4\n";

TEST(ObjFrames, FirstFrameKeepsItsFaceText) {
  TempDir dir;
  write_bytes(dir / "0.obj", "# frame 0\n" + vertex_lines(0) + kFaces);
  std::optional<ObjFaceText> face_text;
  const MeshData first = read_first_obj_frame(dir / "0.obj", face_text);
  ASSERT_TRUE(face_text.has_value());
  EXPECT_EQ(face_text->bytes, kFaces);
  EXPECT_EQ(face_text->num_vertices, 4);
  EXPECT_EQ(face_text->faces, first.faces);
  EXPECT_EQ(face_text->num_polygons, 0U);
  expect_same(first, read_obj(dir / "0.obj"), "first frame");
}

TEST(ObjFrames, NoFaceTextWhenAFaceComesBeforeTheLastVertexOrItIsHuge) {
  TempDir dir;
  std::optional<ObjFaceText> face_text;
  write_bytes(dir / "mixed.obj", vertex_lines(0, 3) + "f 1 2 3\nv 3 9 0\nf 1 3 4\n");
  read_first_obj_frame(dir / "mixed.obj", face_text);
  EXPECT_FALSE(face_text.has_value());
  // Megabytes of comments among two faces are not worth keeping in memory.
  write_bytes(dir / "comments.obj", vertex_lines(0) + kFaces + std::string(1 << 20, '#') + "\n");
  read_first_obj_frame(dir / "comments.obj", face_text);
  EXPECT_FALSE(face_text.has_value());
}

TEST(ObjFrames, LaterFramesReadAsReadObjReadsThem) {
  TempDir dir;
  write_bytes(dir / "first.obj", vertex_lines(0) + kFaces);
  std::optional<ObjFaceText> face_text;
  read_first_obj_frame(dir / "first.obj", face_text);
  ASSERT_TRUE(face_text.has_value());
  const std::vector<std::pair<std::string, std::string>> frames = {
      {"same face text", vertex_lines(1.5) + kFaces},
      {"comment before it", "# moved\n" + vertex_lines(2) + kFaces},
      {"faces written otherwise", vertex_lines(1) + "g cloth\nf 1/1 2/2 3/3\nf 1 3 4\n"},
      {"other faces", vertex_lines(1) + "g cloth\nf 1 2 3\nf 1 4 3\n"},
      {"a comment among the faces", vertex_lines(1) + "g cloth\nf 1 2 3\n# c\nf 1 3 4\n"},
      {"a vertex after the faces", vertex_lines(1) + kFaces + "v 7 7 7\n"},
      {"one vertex more", vertex_lines(1, 5) + kFaces},
      {"one vertex fewer", vertex_lines(1, 3) + kFaces},
      {"no vertices", kFaces},
      {"face text cut short", vertex_lines(1) + kFaces.substr(0, kFaces.size() - 3)},
      {"garbage in the face text", vertex_lines(1) + "g cloth\nf 1 2 3\nf 1 3 x\n"},
      {"garbage in a vertex", vertex_lines(1, 3) + "v 1 nan 0\n" + kFaces},
      {"crlf", vertex_lines(1) + "g cloth\r\nf 1 2 3\r\nf 1 3 4\r\n"},
      {"a face before the vertices", "f 1 2 3\n" + vertex_lines(1) + "g cloth\nf 1 3 4\n"},
      {"empty", ""},
  };
  for (const auto& [what, text] : frames) {
    write_bytes(dir / "frame.obj", text);
    expect_same(outcome_of([&] { return read_obj_frame(dir / "frame.obj", *face_text); }),
                outcome_of([&] { return read_obj(dir / "frame.obj"); }), what);
  }
  expect_same(outcome_of([&] { return read_obj_frame(dir / "missing.obj", *face_text); }),
              outcome_of([&] { return read_obj(dir / "missing.obj"); }), "missing file");
}

TEST(ObjFrames, EqualFaceTextIsTakenNotParsed) {
  // A face text whose faces are not what its bytes say shows which path was taken.
  ObjFaceText marked;
  marked.bytes = "f 1 2 3\n";
  marked.num_vertices = 3;
  marked.faces.resize(1, 3);
  marked.faces << 2, 1, 0;
  const auto faces_of = [&](const std::string& text) {
    return parse_obj_text(text, "mem.obj", &marked).mesh.faces;
  };
  EXPECT_EQ(faces_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), marked.faces);
  EXPECT_EQ(faces_of("# c\nv 0 0 0\nv 1 0 0 # c\nv 0 1 0 1\nf 1 2 3\n"), marked.faces);
  const FaceArray parsed = (FaceArray(1, 3) << 0, 1, 2).finished();
  EXPECT_EQ(faces_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 \n"), parsed);
  EXPECT_EQ(faces_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n"), parsed);
  EXPECT_EQ(faces_of("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 3\n"), parsed);
}

TEST(ObjFrames, PolygonsOfTheFaceTextAreCounted) {
  TempDir dir;
  write_bytes(dir / "0.obj", vertex_lines(0) + "f 1 2 3 4\n");
  std::optional<ObjFaceText> face_text;
  read_first_obj_frame(dir / "0.obj", face_text);
  ASSERT_TRUE(face_text.has_value());
  EXPECT_EQ(face_text->num_polygons, 1U);
  EXPECT_EQ(face_text->faces.rows(), 2);
  write_bytes(dir / "1.obj", vertex_lines(3) + "f 1 2 3 4\n");
  expect_same(read_obj_frame(dir / "1.obj", *face_text), read_obj(dir / "1.obj"), "quad");
}

}  // namespace
}  // namespace tailor
