/// Randomised and near-degenerate queries: whenever the double path answers, it equals the
/// exact path; the public answer equals the exact path; toi bounds hold; and an independent
/// exact static test at sample times (orientation predicates in rationals) never sees a
/// contact the exact path misses.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <random>

#include "ccd_test_support.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/ccd/ccd_exact.hpp"

namespace tailor {
namespace {

int count(int release) {
  return test::sanitized() ? release / 8 : release;
}

/// Base seed; TAILOR_TEST_SEED overrides it for longer stress runs.
std::uint64_t seed(std::uint64_t offset) {
  const char* s = std::getenv("TAILOR_TEST_SEED");
  return (s ? std::strtoull(s, nullptr, 10) : 0u) * 100000u + offset;
}

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  double uniform() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng); }
  double small_int() { return static_cast<double>(std::uniform_int_distribution<int>(-2, 2)(rng)); }
  double quarter() { return std::uniform_int_distribution<int>(-4, 4)(rng) / 4.0; }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
  Vec3 vec(int mode) {
    switch (mode) {
      case 0:
        return {uniform(), uniform(), uniform()};
      case 1:
        return {small_int(), small_int(), small_int()};
      case 2:
        return {quarter(), quarter(), quarter()};
      default:
        return {quarter(), quarter(), 0.0};  // coplanar motion in z = 0
    }
  }
  /// One coordinate nudged by one ulp up or down.
  Vec3 nudge(Vec3 x) {
    const int k = pick(3);
    x[k] = std::nextafter(x[k], pick(2) ? 10.0 : -10.0);
    return x;
  }
};

/// 8 points: either independent, or with the first point built to touch the others'
/// primitive exactly at t = 1/2 (`touch`), optionally nudged by one ulp.
std::array<Vec3, 8> make_points(Gen& g, int mode, bool touch, bool vf) {
  std::array<Vec3, 8> x;
  for (auto& v : x) v = g.vec(mode == 4 ? 2 : mode);
  if (touch) {
    // Position at t = 1/2 of each point is (x0 + x1) / 2; choose a target on the primitive
    // with dyadic weights, then set the mover's end so that it passes there at t = 1/2.
    auto mid = [&](int i) -> Vec3 { return 0.5 * (x[i] + x[i + 4]); };
    const double w[5] = {0.0, 0.25, 0.5, 0.75, 1.0};
    Vec3 target;
    if (vf) {
      double u = w[g.pick(5)], v = w[g.pick(5)];
      if (u + v > 1.0) v = 1.0 - u;
      target = mid(1) + u * (mid(2) - mid(1)) + v * (mid(3) - mid(1));
    } else {
      const double s = w[g.pick(5)];
      // Mover is point 0 of edge a; its partner keeps its offset.
      target = mid(2) + s * (mid(3) - mid(2));
      const Vec3 off0 = x[1] - x[0], off1 = x[5] - x[4];
      x[4] = 2.0 * target - x[0];
      x[1] = x[0] + off0;
      x[5] = x[4] + off1;
    }
    x[4] = 2.0 * target - x[0];
    if (mode == 4) {
      const int k = g.pick(8);
      x[k] = g.nudge(x[k]);
    }
  }
  return x;
}

struct Stats {
  int queries = 0, hits = 0, double_answers = 0, oracle_contacts = 0;
};

void check_vf(const VertexFaceQuery& q, Stats& st) {
  const CcdResult exact = detail::vertex_face_ccd_exact(q);
  const CcdResult pub = vertex_face_ccd(q);
  const auto dbl = detail::vertex_face_ccd_double(q);
  ++st.queries;
  st.hits += exact.hit;
  ASSERT_EQ(pub.hit, exact.hit);
  if (dbl) {
    ++st.double_answers;
    ASSERT_EQ(dbl->hit, exact.hit);
    if (exact.hit) {
      EXPECT_LE(dbl->toi, exact.toi + 0x1p-21);
      EXPECT_GE(dbl->toi, exact.toi - 1e-6);
    }
  }
  if (exact.hit) {
    EXPECT_LE(pub.toi, exact.toi + 0x1p-21);
    EXPECT_GE(pub.toi, exact.toi - 1e-6);
  }
  for (int k = 0; k <= 8; ++k) {
    const mpq_class t(k, 8);
    if (test::vf_contact_at(q, t)) {
      ++st.oracle_contacts;
      ASSERT_TRUE(exact.hit) << "contact at t=" << k << "/8 missed";
      EXPECT_LE(exact.toi, t.get_d());
      EXPECT_LE(pub.toi, t.get_d());
      break;
    }
  }
}

void check_ee(const EdgeEdgeQuery& q, Stats& st) {
  const CcdResult exact = detail::edge_edge_ccd_exact(q);
  const CcdResult pub = edge_edge_ccd(q);
  const auto dbl = detail::edge_edge_ccd_double(q);
  ++st.queries;
  st.hits += exact.hit;
  ASSERT_EQ(pub.hit, exact.hit);
  if (dbl) {
    ++st.double_answers;
    ASSERT_EQ(dbl->hit, exact.hit);
    if (exact.hit) {
      EXPECT_LE(dbl->toi, exact.toi + 0x1p-21);
      EXPECT_GE(dbl->toi, exact.toi - 1e-6);
    }
  }
  if (exact.hit) {
    EXPECT_LE(pub.toi, exact.toi + 0x1p-21);
    EXPECT_GE(pub.toi, exact.toi - 1e-6);
  }
  for (int k = 0; k <= 8; ++k) {
    const mpq_class t(k, 8);
    if (test::ee_contact_at(q, t)) {
      ++st.oracle_contacts;
      ASSERT_TRUE(exact.hit) << "contact at t=" << k << "/8 missed";
      EXPECT_LE(exact.toi, t.get_d());
      EXPECT_LE(pub.toi, t.get_d());
      break;
    }
  }
}

class CcdRandom : public ::testing::TestWithParam<int> {};

TEST_P(CcdRandom, VertexFaceDoubleAgreesWithExact) {
  const int mode = GetParam();
  Gen g(seed(1000 + mode));
  Stats st;
  for (int i = 0; i < count(600); ++i) {
    const auto x = make_points(g, mode, mode >= 2 && i % 2 == 0, true);
    check_vf({x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}, st);
    if (HasFatalFailure()) return;
  }
  RecordProperty("hits", st.hits);
  std::printf(
      "vf mode %d: %d queries, %d hits, %d decided by the double path, %d oracle contacts\n", mode,
      st.queries, st.hits, st.double_answers, st.oracle_contacts);
  if (mode >= 2) {
    EXPECT_GT(st.oracle_contacts, 0);  // the generator does produce exact contacts
  }
}

TEST_P(CcdRandom, EdgeEdgeDoubleAgreesWithExact) {
  const int mode = GetParam();
  Gen g(seed(2000 + mode));
  Stats st;
  for (int i = 0; i < count(600); ++i) {
    const auto x = make_points(g, mode, mode >= 2 && i % 2 == 0, false);
    check_ee({x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}, st);
    if (HasFatalFailure()) return;
  }
  std::printf(
      "ee mode %d: %d queries, %d hits, %d decided by the double path, %d oracle contacts\n", mode,
      st.queries, st.hits, st.double_answers, st.oracle_contacts);
  if (mode >= 2) {
    EXPECT_GT(st.oracle_contacts, 0);
  }
}

// 0 uniform, 1 small integers, 2 quarter grid (+ exact touching at t = 1/2), 3 coplanar
// motion, 4 touching then nudged by one ulp.
INSTANTIATE_TEST_SUITE_P(Modes, CcdRandom, ::testing::Values(0, 1, 2, 3, 4));

TEST(CcdRandomBatch, ResultsIndependentOfThreadCount) {
  Gen g(77);
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
  for (int i = 0; i < count(800); ++i) {
    const auto x = make_points(g, i % 4, i % 3 == 0, true);
    vf.push_back({x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]});
    const auto y = make_points(g, i % 4, i % 3 == 0, false);
    ee.push_back({y[0], y[1], y[2], y[3], y[4], y[5], y[6], y[7]});
  }
  std::vector<CcdResult> vf1(vf.size()), vfn(vf.size()), ee1(ee.size()), een(ee.size());
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    vertex_face_ccd(vf, vf1);
    edge_edge_ccd(ee, ee1);
  }
  vertex_face_ccd(vf, vfn);
  edge_edge_ccd(ee, een);
  for (std::size_t i = 0; i < vf.size(); ++i) {
    EXPECT_EQ(vf1[i].hit, vfn[i].hit);
    EXPECT_EQ(vf1[i].toi, vfn[i].toi);
    EXPECT_EQ(vf1[i].path, vfn[i].path);
    EXPECT_EQ(ee1[i].hit, een[i].hit);
    EXPECT_EQ(ee1[i].toi, een[i].toi);
    EXPECT_EQ(ee1[i].path, een[i].path);
  }
}

}  // namespace
}  // namespace tailor
