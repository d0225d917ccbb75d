/// The query writer: files read back bit for bit (normal, subnormal, huge and negative
/// coordinates, with and without the truth column), and its errors.

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "ccd_test_support.hpp"
#include "tailor/ccd/query_io.hpp"
#include "tailor/ccd/query_writer.hpp"

namespace tailor {
namespace {

std::filesystem::path temp_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "tailor_ccd_writer_test";
  std::filesystem::create_directories(dir);
  return dir;
}

Vec3 random_vec(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    switch (rng() % 5) {
      case 0:
        v[k] = 0.0;
        break;
      case 1:
        v[k] = std::ldexp(unit(rng), -1070);  // subnormal
        break;
      case 2:
        v[k] = std::ldexp(unit(rng), 1000);
        break;
      default:
        v[k] = unit(rng);
    }
  }
  return v;
}

TEST(QueryWriter, RoundTripsExactly) {
  std::mt19937_64 rng(4);
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
  std::vector<bool> truth;
  for (int i = 0; i < 50; ++i) {
    vf.push_back({random_vec(rng), random_vec(rng), random_vec(rng), random_vec(rng),
                  random_vec(rng), random_vec(rng), random_vec(rng), random_vec(rng)});
    ee.push_back({random_vec(rng), random_vec(rng), random_vec(rng), random_vec(rng),
                  random_vec(rng), random_vec(rng), random_vec(rng), random_vec(rng)});
    truth.push_back(rng() & 1);
  }
  const std::string vf_path = (temp_dir() / "roundtripvf.csv").string();
  const std::string ee_path = (temp_dir() / "roundtripee.csv").string();
  write_ccd_queries(vf_path, vf, truth);
  write_ccd_queries(ee_path, ee);
  const CcdQueryFile rvf = read_ccd_queries(vf_path), ree = read_ccd_queries(ee_path);
  ASSERT_EQ(rvf.kind, CcdQueryKind::vertex_face);
  ASSERT_EQ(ree.kind, CcdQueryKind::edge_edge);
  ASSERT_EQ(rvf.vertex_face.size(), vf.size());
  ASSERT_EQ(ree.edge_edge.size(), ee.size());
  EXPECT_EQ(rvf.truth, truth);
  EXPECT_TRUE(ree.truth.empty());
  for (std::size_t i = 0; i < vf.size(); ++i) {
    EXPECT_TRUE(test::same(rvf.vertex_face[i], vf[i])) << i;
    EXPECT_TRUE(test::same(ree.edge_edge[i], ee[i])) << i;
  }
}

TEST(QueryWriter, RejectsNonFiniteAndMismatchedTruth) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Vec3 o(0, 0, 0);
  const std::vector<VertexFaceQuery> bad{{Vec3(nan, 0, 0), o, o, o, o, o, o, o}};
  EXPECT_THROW(ccd_queries_csv(bad), std::invalid_argument);
  const std::vector<VertexFaceQuery> good{{o, o, o, o, o, o, o, o}};
  EXPECT_THROW(ccd_queries_csv(good, {true, false}), std::invalid_argument);
  std::string zeros;
  for (int i = 0; i < 8; ++i) zeros += "0,1,0,1,0,1\n";
  EXPECT_EQ(ccd_queries_csv(good), zeros);
  const std::vector<VertexFaceQuery> half{{Vec3(0.5, -3, 0x1p-1074), o, o, o, o, o, o, o}};
  const std::string first = ccd_queries_csv(half).substr(0, ccd_queries_csv(half).find('\n'));
  EXPECT_EQ(first, "1,2,-3,1,1," + mpz_class(mpz_class(1) << 1074).get_str());
}

}  // namespace
}  // namespace tailor
