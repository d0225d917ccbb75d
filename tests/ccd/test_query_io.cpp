/// The query readers: exact parsing, type from the path, errors naming file and line.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "ccd_test_support.hpp"
#include "tailor/ccd/query_io.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "tailor_ccd_io_test" / "vertex-face";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string rows(int n, const std::string& row) {
  std::string s;
  for (int i = 0; i < n; ++i) s += row + "\n";
  return s;
}

TEST(QueryIo, KindFromPath) {
  EXPECT_EQ(ccd_query_kind_from_path("x/erleben-spikes/vertex-face/data_0_0.csv"),
            CcdQueryKind::vertex_face);
  EXPECT_EQ(ccd_query_kind_from_path("x/unit-tests/edge-edge/data_0_1.csv"),
            CcdQueryKind::edge_edge);
  EXPECT_EQ(ccd_query_kind_from_path("cloth-funnel/queries/227vf.csv"), CcdQueryKind::vertex_face);
  EXPECT_EQ(ccd_query_kind_from_path("cloth-funnel/queries/227ee.csv"), CcdQueryKind::edge_edge);
  EXPECT_FALSE(ccd_query_kind_from_path("queries/data.csv").has_value());
}

TEST(QueryIo, ParsesExactly) {
  // 2^-60 * (2^53 - 1) and a denominator of 2^100 stay exact.
  const std::string path = write_temp(
      "ok.csv", rows(8,
                     "9007199254740991,1152921504606846976,3,1267650600228229401496703205376,"
                     "-5,4,1"));
  const CcdQueryFile f = read_ccd_queries(path);
  ASSERT_EQ(f.size(), 1u);
  ASSERT_EQ(f.truth.size(), 1u);
  EXPECT_TRUE(f.truth[0]);
  EXPECT_EQ(f.vertex_face[0].p_t0[0], 9007199254740991.0 * 0x1p-60);
  EXPECT_EQ(f.vertex_face[0].p_t0[1], 3.0 * 0x1p-100);
  EXPECT_EQ(f.vertex_face[0].c_t1[2], -1.25);
}

TEST(QueryIo, ClothFunnelFormatAndTruth) {
  const std::string d = test::data_dir() + "/cloth-funnel";
  const CcdQueryFile vf = read_ccd_queries(d + "/queries/227vf.csv");
  EXPECT_EQ(vf.kind, CcdQueryKind::vertex_face);
  EXPECT_EQ(vf.size(), 92u);
  EXPECT_TRUE(vf.truth.empty());
  EXPECT_EQ(read_ccd_truth_json(d + "/mma_bool/227vf_mma_bool.json").size(), 92u);
}

void expect_error(const std::string& path, const std::string& fragment) {
  try {
    read_ccd_queries(path);
    FAIL() << "no InputError for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
  }
}

TEST(QueryIo, BadFilesNameFileAndLine) {
  expect_error(write_temp("cols.csv", rows(3, "1,1,1,1,1,1,0") + "1,1,1\n"), ":4:");
  expect_error(write_temp("int.csv", rows(2, "1,1,1,1,1,1,0") + "1,x,1,1,1,1,0\n"), ":3:");
  expect_error(write_temp("den.csv", "1,0,1,1,1,1,0\n"), ":1:");
  expect_error(write_temp("inexact.csv", "1,3,1,1,1,1,0\n"), ":1:");
  expect_error(write_temp("count.csv", rows(7, "1,1,1,1,1,1,0")), "multiple of 8");
  expect_error(write_temp("truth.csv", rows(7, "1,1,1,1,1,1,0") + "1,1,1,1,1,1,1\n"), ":8:");
  expect_error(write_temp("missing.csv", "") + ".nope", "cannot open");
  EXPECT_THROW(read_ccd_queries("/tmp/unknown_kind.csv"), InputError);
  EXPECT_THROW(read_ccd_truth_json(write_temp("t.json", "[true, 3]")), InputError);
}

TEST(QueryIo, EmptyFileNamesTheFile) {
  // Used to load as zero queries; ccd-check then failed with a message naming no file.
  expect_error(write_temp("empty.csv", ""), "no queries");
  expect_error(write_temp("blank.csv", "\n  \n"), "no queries");
}

TEST(QueryIo, HostileFilesFailFastWithShortMessages) {
  const auto check_short = [](const std::string& path, const std::string& fragment) {
    try {
      read_ccd_queries(path);
      FAIL() << "no InputError for " << path;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(fragment), std::string::npos) << msg.substr(0, 400);
      EXPECT_LT(msg.size(), path.size() + 200) << msg.substr(0, 400);
    }
  };
  // A 10 KB token: quoted in ~40 bytes.
  check_short(write_temp("token.csv", "1," + std::string(10000, 'x') + ",1,1,1,1\n"),
              "expected integers");
  // An integer far longer than any double needs.
  check_short(write_temp("digits.csv", "1" + std::string(5000, '0') + ",1,1,1,1,1\n"),
              "longer than 1000");
  // 2 GiB of zero bytes (sparse): refused at the first line's 16 KiB, not read whole.
  const std::string zeros = write_temp("zeros.csv", "");
  std::filesystem::resize_file(zeros, std::uintmax_t{2} << 30);
  check_short(zeros, "longer than 16384 bytes");
  std::filesystem::remove(zeros);
  // Too many columns.
  check_short(write_temp("columns.csv", std::string(10'000, ',') + "\n"), "got more");
}

TEST(QueryIo, LongButExactIntegersAreAccepted) {
  // 2^-1074 (the smallest subnormal): its denominator has 324 digits.
  mpz_class denominator = 1;
  denominator <<= 1074;
  const std::string den = denominator.get_str();
  ASSERT_EQ(den.size(), 324u);
  const std::string row = "1," + den + ",0,1,0,1\n";
  std::string text;
  for (int i = 0; i < 8; ++i) text += row;
  const CcdQueryFile f = parse_ccd_queries(text, "queries/vertex-face/tiny.csv");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f.vertex_face[0].p_t0[0], std::ldexp(1.0, -1074));
}

}  // namespace
}  // namespace tailor
