/// @file
/// The OBJ parser's two paths: plain `v`/`f` lines read in one pass and every other line
/// read token by token must accept the same numbers, give the same values and report the
/// same errors (same line, same message).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "io_test_support.hpp"
#include "tailor/io/obj_io.hpp"
#include "tailor/io/obj_parser.hpp"

namespace tailor {
namespace {

using test::expect_contains;

using test::bit_equal;
using test::expect_same;
using Outcome = test::MeshOutcome;

/// The mesh parse_obj() returns, or the message of the InputError it throws.
Outcome parse(const std::string& text) {
  return test::outcome_of([&] { return parse_obj(text, "mem.obj"); });
}

const char* kTail = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";

/// A first vertex `v <token> 0 0` on a plain line, and the same with a comment or a w (the
/// general path) and with tabs and CR-LF.
std::vector<std::string> vertex_line_variants(const std::string& token) {
  return {"v " + token + " 0 0\n", "v " + token + " 0 0 # c\n", "v " + token + " 0 0 1\n",
          "v\t" + token + "\t0 0\r\n"};
}

/// The outcome of a file whose first vertex has x = `token`, after checking that every
/// line variant agrees with the plain one.
Outcome first_x(const std::string& token) {
  const std::vector<std::string> lines = vertex_line_variants(token);
  const Outcome plain = parse(lines[0] + kTail);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    expect_same(plain, parse(lines[i] + kTail),
                "token '" + token + "', variant " + std::to_string(i));
  }
  return plain;
}

double accepted_x(const std::string& token) {
  const Outcome outcome = first_x(token);
  if (const auto* message = std::get_if<std::string>(&outcome)) {
    ADD_FAILURE() << "'" << token << "' refused: " << *message;
    return std::nan("");
  }
  return std::get<MeshData>(outcome).vertices(0, 0);
}

std::string refused_x(const std::string& token) {
  const Outcome outcome = first_x(token);
  if (const auto* message = std::get_if<std::string>(&outcome)) return *message;
  ADD_FAILURE() << "'" << token << "' accepted";
  return "";
}

TEST(ObjParser, DecimalNumbersWithAnOptionalPlus) {
  EXPECT_EQ(accepted_x("1.5"), 1.5);
  EXPECT_EQ(accepted_x("+1.5"), 1.5);
  EXPECT_EQ(accepted_x("-2.25e-3"), -2.25e-3);
  EXPECT_EQ(accepted_x("1E3"), 1000.0);
  EXPECT_EQ(accepted_x(".5"), 0.5);
  EXPECT_EQ(accepted_x("5."), 5.0);
  EXPECT_EQ(accepted_x("0.1000000000000000055511151231257827"), 0.1);
  EXPECT_TRUE(bit_equal(accepted_x("-0"), -0.0));
  EXPECT_TRUE(bit_equal(accepted_x("+0"), 0.0));
  EXPECT_EQ(accepted_x("4.9406564584124654e-324"), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(accepted_x("1.7976931348623157e308"), std::numeric_limits<double>::max());
}

TEST(ObjParser, UnderflowReadsAsZero) {
  // from_chars reports these out of range; like strtod, they read as (signed) zero.
  EXPECT_TRUE(bit_equal(accepted_x("1e-400"), 0.0));
  EXPECT_TRUE(bit_equal(accepted_x("-1e-400"), -0.0));
  EXPECT_TRUE(bit_equal(accepted_x("+1e-400"), 0.0));
}

TEST(ObjParser, NonFiniteCoordinatesAreRefused) {
  for (const char* token : {"inf", "-inf", "+inf", "infinity", "INF", "nan", "-nan", "+nan",
                            "nan(123)", "1e400", "-1e999", "+1e309"}) {
    expect_contains(refused_x(token), {"mem.obj", "line 1", "non-finite coordinate", token});
  }
}

TEST(ObjParser, OtherNumberSyntaxIsGarbage) {
  // Hex floats, a sign after '+', separators and suffixes are not numbers here.
  for (const char* token : {"0x1p3", "0x10", "0X1.8p1", "+-1", "++1", "-+1", "--1", "+", "-", "1,5",
                            "1.5.2", "1e", "e5", "1.5f", "1_000", "0b1", "1d0"}) {
    expect_contains(refused_x(token), {"mem.obj", "line 1", "garbage token", token});
  }
}

TEST(ObjParser, TokensEndAtBlanksNotAtOtherBytes) {
  std::string nul_inside = "1";
  nul_inside.push_back('\0');
  nul_inside += "5";
  expect_contains(refused_x(nul_inside), {"line 1", "garbage token", "1\\x005"});
  expect_contains(refused_x("1/2"), {"line 1", "garbage token", "1/2"});
  EXPECT_EQ(parse("v 1\v2\f3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").index(), 0U);  // \v and \f blanks
  // A comment right after a number ends the token too.
  const Outcome commented = parse("v 1 2 3#c\n" + std::string(kTail));
  ASSERT_EQ(commented.index(), 0U);
  EXPECT_EQ(std::get<MeshData>(commented).vertices(0, 2), 3.0);
}

TEST(ObjParser, FaceIndicesOnPlainAndGeneralLines) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
  // Each pair: a plain face line and the same face written for the general path.
  const std::vector<std::pair<std::string, std::string>> faces = {
      {"f 1 2 3\n", "f 1 2 3 # c\n"},
      {"f 1 2 3\n", "f +1 +2 +3\n"},
      {"f 1 2 3\n", "f 1/1 2/2 3/3\n"},
      {"f -4 -3 -2\n", "f -4//1 -3//1 -2//1\n"},
      {"f 1 2 4 3\n", "f 1 2 4 3 # quad\n"},
      {"f 1 2 5\n", "f 1 2 5 #\n"},      // forward reference out of range
      {"f 1 2 0\n", "f 1 2 +0\n"},       // index 0
      {"f 1 2 1\n", "f 1 2 1 #\n"},      // repeated vertex
      {"f 1 2\n", "f 1 2 #\n"},          // two vertices
      {"f\n", "f #\n"},                  // none
      {"f 1 2 -9\n", "f 1 2 -9 #\n"},    // before the first vertex
      {"f 1 2 3x\n", "f 1 2 3x #\n"},    // garbage
      {"f 1 2 +-3\n", "f 1 2 +-3 #\n"},  // a sign after '+'
      {"f 1 2 3.0\n", "f 1 2 3.0 #\n"},  // not an integer
      {"f 1 2 99999999999999999999\n", "f 1 2 99999999999999999999 #\n"},  // beyond int64
      {"f 0 2 x\n", "f 0 2 x #\n"},  // the first problem, left to right, wins
  };
  for (const auto& [plain, general] : faces) {
    expect_same(parse(vertices + plain), parse(vertices + general), plain + " / " + general);
    expect_same(parse(vertices + plain + "f 1 2 3\n"), parse(vertices + general + "f 1 2 3\n"),
                "followed by a face: " + plain);
  }
}

TEST(ObjParser, LargePolygonsTakeTheGeneralPathWithTheSameFan) {
  // Past 64 vertices a face line is left to the general path; both give the same fan.
  std::string text;
  for (int i = 0; i < 80; ++i) text += fmt::format("v {} {} 0\n", i, i * i);
  std::string face = "f";
  for (int i = 1; i <= 80; ++i) face += fmt::format(" {}", i);
  const Outcome plain = parse(text + face + "\n");
  expect_same(plain, parse(text + face + " # c\n"), "80-gon");
  ASSERT_EQ(plain.index(), 0U);
  const MeshData& mesh = std::get<MeshData>(plain);
  ASSERT_EQ(mesh.faces.rows(), 78);
  EXPECT_EQ(mesh.faces.row(77), (Eigen::RowVector3i(0, 78, 79)));
}

TEST(ObjParser, LineNumbersCountBothPaths) {
  const Outcome outcome = parse("v 0 0 0\nv 1 0 0 # c\n\n# comment\nv 0 1 0\nf 1 2 3\nf 1 2 x\n");
  ASSERT_EQ(outcome.index(), 1U);
  expect_contains(std::get<std::string>(outcome), {"mem.obj", "line 7", "'x'"});
}

TEST(ObjParser, FaceTextStartsAfterTheLastVertexLine) {
  const std::string text = "# cloth\nv 0 0 0\nv 1 0 0\nv 0 1 0\ng part\nf 1 2 3\nf 3 2 1\n";
  const ObjParseResult parsed = parse_obj_text(text, "mem.obj");
  EXPECT_EQ(text.substr(parsed.face_text_start), "g part\nf 1 2 3\nf 3 2 1\n");
  EXPECT_EQ(parsed.num_polygons, 0U);
  // A face before the last vertex: no face text.
  EXPECT_EQ(parse_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 1 1 0\nf 2 4 3\n", "mem.obj")
                .face_text_start,
            std::string_view::npos);
  // The last line without a newline; a quad counted as a polygon.
  const std::string no_newline = "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 0\r\nf 1 2 4 3";
  const ObjParseResult quad = parse_obj_text(no_newline, "mem.obj");
  EXPECT_EQ(no_newline.substr(quad.face_text_start), "f 1 2 4 3");
  EXPECT_EQ(quad.num_polygons, 1U);
}

}  // namespace
}  // namespace tailor
