/// @file
/// OBJ reading and writing: round trips, accepted syntax, and every kind of bad input.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "io_test_support.hpp"
#include "tailor/io/obj_io.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;
using test::write_bytes;

/// Random positions over many magnitudes (and signs), to test full precision.
Positions random_positions(Index n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  Positions x(n, 3);
  for (Index i = 0; i < n; ++i) {
    for (int j = 0; j < 3; ++j) x(i, j) = std::ldexp(mantissa(rng), exponent(rng));
  }
  if (n > 2) {
    x(0, 0) = 0.1;
    x(0, 1) = -0.0;
    x(1, 0) = std::numeric_limits<double>::min();
    x(1, 1) = std::numeric_limits<double>::denorm_min();
    x(1, 2) = std::numeric_limits<double>::max();
    x(2, 0) = 1.0 / 3.0;
  }
  return x;
}

FaceArray strip_faces(Index n) {
  FaceArray faces(n - 2, 3);
  for (Index i = 0; i + 2 < n; ++i) faces.row(i) << i, i + 1, i + 2;
  return faces;
}

bool bit_equal(const Positions& a, const Positions& b) {
  return a.rows() == b.rows() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(ObjIo, RoundTripIsBitExact) {
  TempDir dir;
  const Positions x = random_positions(500, 7);
  const FaceArray faces = strip_faces(500);
  write_obj(dir / "mesh.obj", x, faces);
  const MeshData back = read_obj(dir / "mesh.obj");
  EXPECT_TRUE(bit_equal(back.vertices, x));
  EXPECT_EQ(back.faces, faces);
}

TEST(ObjIo, WriterUsesOneBasedFaces) {
  TempDir dir;
  Positions x(3, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  FaceArray f(1, 3);
  f << 0, 1, 2;
  write_obj(dir / "t.obj", x, f);
  EXPECT_NE(test::read_bytes(dir / "t.obj").find("f 1 2 3\n"), std::string::npos);
}

TEST(ObjIo, ReadsAllFaceFormsAndIgnoresOtherStatements) {
  TempDir dir;
  write_bytes(dir / "forms.obj",
              "# a comment\n"
              "mtllib cloth.mtl\n"
              "o cloth\n"
              "g part\n"
              "v 0 0 0 1.0\n"
              "v 1 0 0 0.5 0.5 0.5\n"
              "v +1 1 0\n"
              "v 0 1e0 -0 # trailing comment\n"
              "vn 0 0 1\n"
              "vt 0 0\n"
              "usemtl red\n"
              "s off\n"
              "f 1 2 3\n"
              "f 1/1 3/1 4/1\n"
              "f 1//1 2//1 4//1\n"
              "f 1/1/1 2/1/1 4/1/1\n"
              "f -4 -3 -1\n"
              "\n"
              "   \t\n");
  const MeshData m = read_obj(dir / "forms.obj");
  ASSERT_EQ(m.vertices.rows(), 4);
  EXPECT_EQ(m.vertices(2, 0), 1.0);
  EXPECT_EQ(m.vertices(3, 1), 1.0);
  FaceArray expected(5, 3);
  expected << 0, 1, 2, 0, 2, 3, 0, 1, 3, 0, 1, 3, 0, 1, 3;
  EXPECT_EQ(m.faces, expected);
}

TEST(ObjIo, CrLfLineEndingsAndForwardReferences) {
  TempDir dir;
  write_bytes(dir / "crlf.obj", "f 1 2 3\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n");
  const MeshData m = read_obj(dir / "crlf.obj");
  EXPECT_EQ(m.vertices.rows(), 3);
  EXPECT_EQ(m.faces.rows(), 1);
}

TEST(ObjIo, PolygonsAreSplitIntoFans) {
  TempDir dir;
  write_bytes(dir / "quad.obj",
              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3 4 1\n");
  const MeshData m = read_obj(dir / "quad.obj");
  FaceArray expected(5, 3);
  expected << 0, 1, 2, 0, 2, 3, 1, 4, 2, 1, 2, 3, 1, 3, 0;
  EXPECT_EQ(m.faces, expected);
}

TEST(ObjIo, FileWithoutFacesIsRefused) {
  TempDir dir;
  write_bytes(dir / "empty.obj", "");
  expect_contains(input_error_message([&] { read_obj(dir / "empty.obj"); }),
                  {"empty.obj", "no faces"});
  write_bytes(dir / "points.obj", "v 0 0 0\nv 1 0 0\n# no face\n");
  expect_contains(input_error_message([&] { read_obj(dir / "points.obj"); }),
                  {"points.obj", "no faces", "2 vertices"});
}

/// Writes `text` to a file and returns the message of the InputError reading it throws.
std::string obj_error(const TempDir& dir, const std::string& text) {
  const auto path = dir / "bad.obj";
  write_bytes(path, text);
  return input_error_message([&] { read_obj(path); });
}

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ObjIoErrors, FaceWithTwoVertices) {
  TempDir dir;
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2\n"),
                  {"bad.obj", "line 4", "face with 2 vertices"});
}

TEST(ObjIoErrors, GarbageToken) {
  TempDir dir;
  expect_contains(obj_error(dir, "v 0 0 0\nv 1 zero 0\n"),
                  {"bad.obj", "line 2", "garbage", "zero"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 x\n"),
                  {"bad.obj", "line 4", "'x'"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 3/\n"), {"line 4", "garbage"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 3//a\n"), {"line 4", "garbage"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 3.5\n"), {"line 4", "garbage"});
  expect_contains(obj_error(dir, "v 0 0 0 extra\n"), {"line 1", "garbage", "extra"});
}

TEST(ObjIoErrors, UnknownStatement) {
  TempDir dir;
  expect_contains(obj_error(dir, std::string(kTriangle) + "bogus 1 2 3\n"),
                  {"bad.obj", "line 4", "unknown statement 'bogus'"});
}

TEST(ObjIoErrors, TooFewCoordinates) {
  TempDir dir;
  expect_contains(obj_error(dir, "v 0 0\n"), {"bad.obj", "line 1", "fewer than 3 coordinates"});
}

TEST(ObjIoErrors, NaNCoordinate) {
  TempDir dir;
  expect_contains(obj_error(dir, "v 0 0 0\nv nan 0 0\n"),
                  {"bad.obj", "line 2", "non-finite coordinate"});
}

TEST(ObjIoErrors, InfiniteCoordinate) {
  TempDir dir;
  expect_contains(obj_error(dir, "v 0 -inf 0\n"), {"bad.obj", "line 1", "non-finite coordinate"});
  expect_contains(obj_error(dir, "v 0 1e999 0\n"), {"bad.obj", "line 1", "non-finite coordinate"});
}

TEST(ObjIoErrors, OutOfRangeIndex) {
  TempDir dir;
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 3\nf 1 2 4\n"),
                  {"bad.obj", "line 5", "out of range", "3 vertices"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f -1 -2 -4\n"),
                  {"bad.obj", "line 4", "before the first vertex"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 0 1 2\n"),
                  {"bad.obj", "line 4", "index 0"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 99999999999\n"),
                  {"bad.obj", "line 4", "out of range"});
}

TEST(ObjIoErrors, RepeatedVertexInFace) {
  TempDir dir;
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 1\n"),
                  {"bad.obj", "line 4", "repeats vertex 1"});
  expect_contains(obj_error(dir, std::string(kTriangle) + "f 1 2 -3\n"), {"line 4", "repeats"});
}

TEST(ObjIoErrors, MissingFile) {
  TempDir dir;
  expect_contains(input_error_message([&] { read_obj(dir / "missing.obj"); }),
                  {"cannot open", "missing.obj"});
}

TEST(ObjIoErrors, WriterRejectsNonFiniteAndBadFaces) {
  TempDir dir;
  Positions x(3, 3);
  x << 0, 0, 0, 1, 0, 0, 0, std::nan(""), 0;
  FaceArray f(1, 3);
  f << 0, 1, 2;
  expect_contains(input_error_message([&] { write_obj(dir / "w.obj", x, f); }),
                  {"w.obj", "vertex 2", "non-finite"});
  x(2, 1) = 1.0;
  f(0, 2) = 3;
  expect_contains(input_error_message([&] { write_obj(dir / "w.obj", x, f); }),
                  {"w.obj", "face 0", "out of range"});
  f(0, 2) = 2;
  expect_contains(input_error_message([&] { write_obj(dir / "no-such-dir" / "w.obj", x, f); }),
                  {"cannot open", "w.obj"});
}

}  // namespace
}  // namespace tailor
