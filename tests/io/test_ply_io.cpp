/// @file
/// PLY reading and writing: every encoding and type, odd headers, and bad input.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "io_test_support.hpp"
#include "tailor/io/ply_io.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::read_bytes;
using test::TempDir;
using test::write_bytes;

Positions random_positions(Index n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 20);
  Positions x(n, 3);
  for (Index i = 0; i < n; ++i) {
    for (int j = 0; j < 3; ++j) x(i, j) = std::ldexp(mantissa(rng), exponent(rng));
  }
  x(0, 0) = 0.1;
  x(0, 1) = -0.0;
  x(1, 0) = 1.0 / 3.0;
  return x;
}

FaceArray random_faces(Index nv, Index nf, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<Index> pick(0, nv - 1);
  FaceArray faces(nf, 3);
  for (Index f = 0; f < nf; ++f) {
    do {
      faces.row(f) << pick(rng), pick(rng), pick(rng);
    } while (faces(f, 0) == faces(f, 1) || faces(f, 1) == faces(f, 2) ||
             faces(f, 0) == faces(f, 2));
  }
  return faces;
}

bool bit_equal(const Positions& a, const Positions& b) {
  return a.rows() == b.rows() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(PlyIo, RoundTripsInEveryEncodingAndType) {
  TempDir dir;
  const Positions x = random_positions(240, 3);  // ids up to 239 fit in uint8
  const FaceArray faces = random_faces(240, 400, 5);
  const PlyFormat formats[] = {PlyFormat::ascii, PlyFormat::binary_little_endian,
                               PlyFormat::binary_big_endian};
  const PlyType coords[] = {PlyType::float32, PlyType::float64};
  const std::pair<PlyType, PlyType> lists[] = {
      {PlyType::uint8, PlyType::int32}, {PlyType::uint8, PlyType::uint32},
      {PlyType::int32, PlyType::int32}, {PlyType::uint32, PlyType::uint32},
      {PlyType::int8, PlyType::uint8},  {PlyType::uint16, PlyType::int16}};
  for (PlyFormat format : formats) {
    for (PlyType coord : coords) {
      for (const auto& [count_type, index_type] : lists) {
        const PlyWriteOptions options{format, coord, count_type, index_type};
        SCOPED_TRACE(fmt::format("{} {} {} {}", ply_format_name(format), ply_type_name(coord),
                                 ply_type_name(count_type), ply_type_name(index_type)));
        const auto path = dir / "mesh.ply";
        write_ply(path, x, faces, options);
        const std::string header = read_bytes(path).substr(0, 300);
        EXPECT_NE(header.find(fmt::format("format {} 1.0", ply_format_name(format))),
                  std::string::npos);
        EXPECT_NE(header.find(fmt::format("property list {} {} vertex_indices",
                                          ply_type_name(count_type), ply_type_name(index_type))),
                  std::string::npos);
        const MeshData back = read_ply(path);
        EXPECT_EQ(back.faces, faces);
        if (coord == PlyType::float64) {
          EXPECT_TRUE(bit_equal(back.vertices, x));
        } else {
          const Positions rounded = x.cast<float>().cast<double>();
          EXPECT_TRUE(bit_equal(back.vertices, rounded));
        }
      }
    }
  }
}

TEST(PlyIo, MeshWithoutFacesIsRefused) {
  TempDir dir;
  write_ply(dir / "empty.ply", Positions(0, 3), FaceArray(0, 3));
  expect_contains(input_error_message([&] { read_ply(dir / "empty.ply"); }),
                  {"empty.ply", "no faces"});
  write_bytes(dir / "points.ply",
              "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
              "property float z\nend_header\n0 0 0\n");
  expect_contains(input_error_message([&] { read_ply(dir / "points.ply"); }),
                  {"points.ply", "no faces", "no face element"});
}

/// Builds PLY bodies value by value in any encoding.
class Body {
 public:
  explicit Body(PlyFormat format) : m_format(format) {}
  template <typename T>
  Body& put(T value) {
    if (m_format == PlyFormat::ascii) {
      if (!m_line_start) m_text += ' ';
      if constexpr (sizeof(T) == 1) {
        m_text += std::to_string(static_cast<int>(value));
      } else if constexpr (std::is_floating_point_v<T>) {
        m_text += fmt::format("{}", value);
      } else {
        m_text += std::to_string(value);
      }
      m_line_start = false;
    } else {
      char bytes[sizeof(T)];
      std::memcpy(bytes, &value, sizeof(T));
      const bool big = m_format == PlyFormat::binary_big_endian;
      if (big == (std::endian::native == std::endian::little))
        std::reverse(bytes, bytes + sizeof(T));
      m_text.append(bytes, sizeof(T));
    }
    return *this;
  }
  Body& end() {
    if (m_format == PlyFormat::ascii) m_text += '\n';
    m_line_start = true;
    return *this;
  }
  const std::string& str() const { return m_text; }

 private:
  PlyFormat m_format;
  std::string m_text;
  bool m_line_start = true;
};

/// A file with extra elements and properties of every type, faces before vertices, the
/// `vertex_index` spelling and a quad.
std::string odd_layout_file(PlyFormat format) {
  std::string header = fmt::format(
      "ply\r\nformat {} 1.0\ncomment made by hand\nobj_info nothing\n"
      "element material 2\nproperty uchar red\nproperty list uchar float weights\n"
      "element face 2\nproperty char flags\nproperty list uint8 uint16 vertex_index\n"
      "property list int32 float64 texcoord\nproperty ushort tag\n"
      "element vertex 4\nproperty float32 nx\nproperty double x\nproperty int16 y\n"
      "property int8 z\nproperty uint quality\nproperty short w\n"
      "element extra 1\nproperty int32 id\n"
      "end_header\n",
      ply_format_name(format));
  Body b(format);
  b.put<std::uint8_t>(1).put<std::uint8_t>(2).put<float>(0.5f).put<float>(0.25f).end();
  b.put<std::uint8_t>(2).put<std::uint8_t>(0).end();
  b.put<std::int8_t>(-7)
      .put<std::uint8_t>(3)
      .put<std::uint16_t>(0)
      .put<std::uint16_t>(1)
      .put<std::uint16_t>(2)
      .put<std::int32_t>(2)
      .put<double>(0.5)
      .put<double>(1.5)
      .put<std::uint16_t>(9)
      .end();
  b.put<std::int8_t>(7)
      .put<std::uint8_t>(4)
      .put<std::uint16_t>(0)
      .put<std::uint16_t>(2)
      .put<std::uint16_t>(3)
      .put<std::uint16_t>(1)
      .put<std::int32_t>(0)
      .put<std::uint16_t>(65535)
      .end();
  const double xs[] = {0.125, -1.0, 3.5, 1e-3};
  const std::int16_t ys[] = {0, -300, 32767, 5};
  const std::int8_t zs[] = {-128, 0, 127, -1};
  for (int v = 0; v < 4; ++v) {
    b.put<float>(1.0f)
        .put<double>(xs[v])
        .put<std::int16_t>(ys[v])
        .put<std::int8_t>(zs[v])
        .put<std::uint32_t>(4000000000u)
        .put<std::int16_t>(-2)
        .end();
  }
  b.put<std::int32_t>(-42).end();
  return header + b.str();
}

TEST(PlyIo, SkipsExtraElementsAndPropertiesInEveryEncoding) {
  TempDir dir;
  for (PlyFormat format :
       {PlyFormat::ascii, PlyFormat::binary_little_endian, PlyFormat::binary_big_endian}) {
    SCOPED_TRACE(std::string(ply_format_name(format)));
    write_bytes(dir / "odd.ply", odd_layout_file(format));
    const MeshData m = read_ply(dir / "odd.ply");
    Positions expected_x(4, 3);
    expected_x << 0.125, 0, -128, -1.0, -300, 0, 3.5, 32767, 127, 1e-3, 5, -1;
    EXPECT_TRUE(bit_equal(m.vertices, expected_x)) << m.vertices;
    FaceArray expected_f(3, 3);
    expected_f << 0, 1, 2, 0, 2, 3, 0, 3, 1;  // the quad becomes a fan
    EXPECT_EQ(m.faces, expected_f);
  }
}

// ------------------------------------------------------------------------ bad input

const char* kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

std::string ply_error(const TempDir& dir, const std::string& bytes) {
  const auto path = dir / "bad.ply";
  write_bytes(path, bytes);
  return input_error_message([&] { read_ply(path); });
}

/// A small valid binary file with double coordinates (little endian).
std::string binary_triangle(double x0 = 0.0, std::int32_t last_index = 2, int vertex_count = 3,
                            int face_count = 1) {
  std::string header = fmt::format(
      "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty double x\n"
      "property double y\nproperty double z\nelement face {}\n"
      "property list uchar int vertex_indices\nend_header\n",
      vertex_count, face_count);
  Body b(PlyFormat::binary_little_endian);
  b.put<double>(x0).put<double>(0).put<double>(0);
  b.put<double>(1).put<double>(0).put<double>(0);
  b.put<double>(0).put<double>(1).put<double>(0);
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(last_index);
  return header + b.str();
}

TEST(PlyIoErrors, ValidSmallFilesParse) {
  TempDir dir;
  write_bytes(dir / "ok.ply", binary_triangle());
  EXPECT_EQ(read_ply(dir / "ok.ply").faces.rows(), 1);
  write_bytes(dir / "ok2.ply", std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(read_ply(dir / "ok2.ply").faces.rows(), 1);
}

TEST(PlyIoErrors, TruncatedBinaryFile) {
  TempDir dir;
  const std::string full = binary_triangle();
  // Cut inside the face list.
  expect_contains(ply_error(dir, full.substr(0, full.size() - 3)),
                  {"bad.ply", "byte", "unexpected end of file", "'face' entry 0", "truncated"});
  // Cut inside the vertices: the declared counts cannot fit any more.
  expect_contains(ply_error(dir, full.substr(0, full.size() - 40)),
                  {"bad.ply", "byte", "unexpected end of file", "truncated"});
}

TEST(PlyIoErrors, TruncatedAsciiFile) {
  TempDir dir;
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0.0000 0 0\n1.0000 0 0\n"),
                  {"bad.ply", "line 12", "unexpected end of file", "3 'vertex' entries", "only 2",
                   "truncated"});
  // So short that the declared counts cannot fit: caught before reading the entries.
  expect_contains(
      ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n"),
      {"bad.ply", "line 10", "unexpected end of file", "3 'vertex' entries", "truncated"});
  std::string huge = kAsciiHeader;
  huge.replace(huge.find("vertex 3"), 8, "vertex 2000000000");
  expect_contains(ply_error(dir, huge + "0 0 0\n"), {"bad.ply", "truncated"});
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1"),
                  {"bad.ply", "line 13", "face 0 has too few values", "truncated"});
}

TEST(PlyIoErrors, WrongVertexCount) {
  TempDir dir;
  std::string header = kAsciiHeader;
  header.replace(header.find("vertex 3"), 8, "vertex 4");
  expect_contains(ply_error(dir, header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                  {"bad.ply", "line 13", "after the last property of vertex 3", "counts"});
  // Binary: one vertex too many declared -> the data runs out; one too few -> leftovers.
  expect_contains(ply_error(dir, binary_triangle(0.0, 2, 4)), {"bad.ply", "byte"});
  expect_contains(ply_error(dir, binary_triangle(0.0, 2, 3, 0)),
                  {"bad.ply", "byte", "unexpected data after the last element"});
}

TEST(PlyIoErrors, GarbageToken) {
  TempDir dir;
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"),
                  {"bad.ply", "line 11", "garbage token 'zero'"});
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n"),
                  {"bad.ply", "line 13", "garbage token '2.5'"});
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n"),
                  {"bad.ply", "line 13", "does not fit in type 'uchar'"});
}

TEST(PlyIoErrors, NaNCoordinate) {
  TempDir dir;
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"),
                  {"bad.ply", "line 11", "vertex 1", "non-finite coordinate"});
  expect_contains(ply_error(dir, binary_triangle(std::numeric_limits<double>::quiet_NaN())),
                  {"bad.ply", "byte", "vertex 0", "non-finite coordinate"});
}

TEST(PlyIoErrors, InfiniteCoordinate) {
  TempDir dir;
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 -inf\n0 1 0\n3 0 1 2\n"),
                  {"bad.ply", "line 11", "non-finite coordinate"});
  expect_contains(ply_error(dir, binary_triangle(std::numeric_limits<double>::infinity())),
                  {"bad.ply", "byte", "non-finite coordinate"});
}

TEST(PlyIoErrors, OutOfRangeIndex) {
  TempDir dir;
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
                  {"bad.ply", "line 13", "face 0", "index 3 out of range", "3 vertices"});
  expect_contains(ply_error(dir, binary_triangle(0.0, 3)),
                  {"bad.ply", "byte", "face 0", "index 3 out of range"});
  expect_contains(ply_error(dir, binary_triangle(0.0, -1)),
                  {"bad.ply", "byte", "index -1 out of range"});
}

TEST(PlyIoErrors, RepeatedVertexInFace) {
  TempDir dir;
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 0\n"),
                  {"bad.ply", "line 13", "face 0 repeats vertex 0"});
  expect_contains(ply_error(dir, binary_triangle(0.0, 1)), {"bad.ply", "byte", "repeats vertex 1"});
}

TEST(PlyIoErrors, FaceWithTwoVertices) {
  TempDir dir;
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
                  {"bad.ply", "line 13", "face 0 has 2 vertices"});
}

TEST(PlyIoErrors, NegativeCount) {
  TempDir dir;
  std::string header = kAsciiHeader;
  header.replace(header.find("vertex 3"), 8, "vertex -3");
  expect_contains(ply_error(dir, header), {"bad.ply", "line 3", "negative count -3"});
}

TEST(PlyIoErrors, TrailingData) {
  TempDir dir;
  expect_contains(ply_error(dir, binary_triangle() + "xyz"),
                  {"bad.ply", "byte", "3 bytes of unexpected data"});
  expect_contains(ply_error(dir, std::string(kAsciiHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n"),
                  {"bad.ply", "line 14", "unexpected data after the last element"});
}

TEST(PlyIoErrors, BadHeaders) {
  TempDir dir;
  const std::string h = kAsciiHeader;
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = h;
    s.replace(s.find(from), from.size(), to);
    return s + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  };
  expect_contains(ply_error(dir, "obj\n" + h.substr(4)), {"bad.ply", "line 1", "not a PLY file"});
  expect_contains(ply_error(dir, replaced("format ascii 1.0\n", "")),
                  {"bad.ply", "missing format"});
  expect_contains(ply_error(dir, replaced("ascii 1.0", "ascii 2.0")),
                  {"bad.ply", "line 2", "version"});
  expect_contains(ply_error(dir, replaced("ascii", "utf8")),
                  {"bad.ply", "line 2", "unknown format"});
  expect_contains(ply_error(dir, replaced("property float z\n", "")),
                  {"bad.ply", "no property 'z'"});
  expect_contains(ply_error(dir, replaced("vertex_indices", "corners")),
                  {"bad.ply", "no list property 'vertex_indices'"});
  expect_contains(ply_error(dir, replaced("float y", "real y")),
                  {"bad.ply", "line 5", "unknown property type 'real'"});
  expect_contains(ply_error(dir, replaced("uchar int", "float int")),
                  {"bad.ply", "line 8", "not an integer type"});
  expect_contains(ply_error(dir, replaced("uchar int vertex", "uchar float vertex")),
                  {"bad.ply", "non-integer type"});
  expect_contains(ply_error(dir, replaced("element vertex 3", "element vertex three")),
                  {"bad.ply", "line 3", "garbage element count 'three'"});
  expect_contains(ply_error(dir, replaced("element vertex 3", "element vertices 3")),
                  {"bad.ply", "no 'vertex' element"});
  expect_contains(ply_error(dir, h.substr(0, h.find("end_header"))), {"bad.ply", "no end_header"});
  expect_contains(ply_error(dir, "ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
                  {"bad.ply", "line 3", "before any element"});
  expect_contains(ply_error(dir, replaced("end_header", "weird line\nend_header")),
                  {"bad.ply", "line 9", "unknown header keyword 'weird'"});
}

TEST(PlyIoErrors, MissingFile) {
  TempDir dir;
  expect_contains(input_error_message([&] { read_ply(dir / "missing.ply"); }),
                  {"cannot open", "missing.ply"});
}

TEST(PlyIoErrors, WriterRejectsBadOptionsAndValues) {
  TempDir dir;
  const Positions x = random_positions(300, 1);
  const FaceArray f = random_faces(300, 10, 2);
  expect_contains(input_error_message([&] {
                    write_ply(dir / "w.ply", x, f,
                              {PlyFormat::ascii, PlyType::float64, PlyType::uint8, PlyType::uint8});
                  }),
                  {"w.ply", "uchar", "299"});
  expect_contains(input_error_message([&] {
                    write_ply(dir / "w.ply", x, f,
                              {PlyFormat::ascii, PlyType::int32, PlyType::uint8, PlyType::int32});
                  }),
                  {"w.ply", "coordinate type"});
  Positions big = x;
  big(5, 1) = 1e300;
  expect_contains(input_error_message([&] {
                    write_ply(dir / "w.ply", big, f,
                              {PlyFormat::binary_little_endian, PlyType::float32, PlyType::uint8,
                               PlyType::int32});
                  }),
                  {"w.ply", "vertex 5", "float"});
  big(5, 1) = std::numeric_limits<double>::infinity();
  expect_contains(input_error_message([&] { write_ply(dir / "w.ply", big, f); }),
                  {"w.ply", "vertex 5", "not finite"});
}

}  // namespace
}  // namespace tailor
