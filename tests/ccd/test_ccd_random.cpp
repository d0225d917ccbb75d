/// Randomised and near-degenerate queries, a million in a release build (sanitizers: 1/50):
/// every tier
/// (public pipeline, certified double tier when it answers, fixed-size exact tier, and its
/// GMP instantiation on a sample) agrees with the rational oracle; queries the filter culls
/// are checked against the exact signs of the coplanarity cubic's Bernstein coefficients;
/// and an independent exact static test at sample times never sees a contact the tiers miss.

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <random>

#include "ccd_test_support.hpp"
#include "support/degenerate_ccd_queries.hpp"
#include "tailor/ccd/ccd.hpp"

namespace tailor {
namespace {

/// Base seed; TAILOR_TEST_SEED overrides it for longer stress runs.
std::uint64_t seed(std::uint64_t offset) {
  const char* s = std::getenv("TAILOR_TEST_SEED");
  return (s ? std::strtoull(s, nullptr, 10) : 0u) * 100000u + offset;
}

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t s) : rng(s) {}
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
  /// One coordinate nudged by one ulp up or down (a nonzero one when there is: one ulp of
  /// zero is a subnormal, the extreme-spread case of CcdDegenerate.ExtremeExponentSpread).
  Vec3 nudge(Vec3 x) {
    int k = pick(3);
    for (int i = 0; i < 3 && x[k] == 0.0; ++i) k = (k + 1) % 3;
    x[k] = std::nextafter(x[k], pick(2) ? 10.0 : -10.0);
    return x;
  }
};

/// 8 points: either independent, or with the first point built to touch the others'
/// primitive exactly at t = 1/2 (`touch`), optionally nudged by one ulp (mode 4).
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

/// Counters shared by the worker threads.
struct Tally {
  std::atomic<long> queries{0}, hits{0}, culled{0}, oracle_calls{0}, double_answers{0},
      oracle_contacts{0}, mismatches{0};
  std::array<std::atomic<long>, kCcdPathCount> paths{};
};

/// Every check on one query; returns false (after recording a failure) on a mismatch.
template <class Q>
bool check(const Q& q, Tally& tally, bool with_gmp, bool static_samples) {
  ++tally.queries;
  const CcdResult pub = test::public_ccd(q);
  ++tally.paths[static_cast<int>(pub.path)];
  const CcdResult exact = test::exact_tier(q);
  const auto dbl = test::double_tier(q);
  if (pub.path == CcdPath::filter) {
    // The filter's claim, proved independently.
    ++tally.culled;
    EXPECT_TRUE(test::never_coplanar_exact(test::filter_points(q)));
    EXPECT_FALSE(exact.hit);
    if (dbl) {
      EXPECT_FALSE(dbl->hit);
    }
    return !exact.hit && !(dbl && dbl->hit);
  }
  ++tally.oracle_calls;
  const CcdResult oracle = test::oracle(q);
  tally.hits += oracle.hit;
  bool ok = test::agrees(pub, oracle) && test::agrees(exact, oracle);
  if (dbl) {
    ++tally.double_answers;
    ok = ok && test::agrees(*dbl, oracle);
  }
  if (with_gmp) ok = ok && test::agrees(test::exact_tier_gmp(q), oracle);
  if (static_samples) {
    // The independent static test at t = k/8: a contact there must be found, no later.
    for (int k = 0; k <= 8; ++k) {
      const mpq_class t(k, 8);
      const bool contact = [&] {
        if constexpr (std::is_same_v<Q, VertexFaceQuery>) {
          return test::vf_contact_at(q, t);
        } else {
          return test::ee_contact_at(q, t);
        }
      }();
      if (contact) {
        ++tally.oracle_contacts;
        ok = ok && pub.hit && pub.toi <= t.get_d();
        break;
      }
    }
  }
  if (!ok) {
    ++tally.mismatches;
    ADD_FAILURE() << "mismatch: oracle hit=" << oracle.hit << " toi=" << oracle.toi
                  << "; public hit=" << pub.hit << " toi=" << pub.toi << " path "
                  << ccd_path_name(pub.path) << "; exact hit=" << exact.hit << " toi=" << exact.toi;
  }
  return ok;
}

int count(int release) {
  return test::sanitized() ? release / 50 : release;
}

/// Queries per test: one million over the ten mode tests in a release build. The rational
/// oracle dominates the cost (~0.2 ms a query; ~0.6 ms for the coplanar mode 3, which
/// therefore gets fewer).
int queries_for_mode(int mode) {
  return count(mode == 3 ? 40000 : 115000);
}

/// Runs `n` queries of one mode in parallel, in blocks with their own seeds (the checks do
/// not depend on the thread count).
template <class Make>
void run_mode(int n, std::uint64_t base_seed, Tally& tally, Make&& make) {
  constexpr int kBlock = 512;
  const int blocks = (n + kBlock - 1) / kBlock;
  tbb::parallel_for(0, blocks, [&](int b) {
    Gen g(base_seed * 7919u + static_cast<std::uint64_t>(b));
    const int end = std::min(n, (b + 1) * kBlock);
    for (int i = b * kBlock; i < end && tally.mismatches < 10; ++i) make(g, i);
  });
}

void report(const char* what, const Tally& t) {
  std::printf(
      "%s: %ld queries, %ld culled by the filter (checked exactly), %ld against the oracle "
      "(%ld hits, %ld double-tier answers, %ld static contacts); paths:",
      what, t.queries.load(), t.culled.load(), t.oracle_calls.load(), t.hits.load(),
      t.double_answers.load(), t.oracle_contacts.load());
  for (int i = 0; i < kCcdPathCount; ++i) {
    std::printf(" %s %ld", ccd_path_name(static_cast<CcdPath>(i)), t.paths[i].load());
  }
  std::printf("\n");
}

class CcdRandom : public ::testing::TestWithParam<int> {};

// 0 uniform, 1 small integers, 2 quarter grid (+ exact touching at t = 1/2), 3 coplanar
// motion, 4 touching then nudged by one ulp.
TEST_P(CcdRandom, VertexFaceTiersAgreeWithOracle) {
  const int mode = GetParam();
  Tally tally;
  run_mode(queries_for_mode(mode), seed(1000 + mode), tally, [&](Gen& g, int i) {
    const auto x = make_points(g, mode, mode >= 2 && i % 2 == 0, true);
    check(VertexFaceQuery{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}, tally, i % 128 == 0,
          i % 64 == 0);
  });
  report("vf", tally);
  EXPECT_EQ(tally.mismatches, 0);
  EXPECT_GT(tally.oracle_calls, 0);
  if (mode >= 2) {
    EXPECT_GT(tally.oracle_contacts, 0);  // the generator does make contacts
  }
}

TEST_P(CcdRandom, EdgeEdgeTiersAgreeWithOracle) {
  const int mode = GetParam();
  Tally tally;
  run_mode(queries_for_mode(mode), seed(2000 + mode), tally, [&](Gen& g, int i) {
    const auto x = make_points(g, mode, mode >= 2 && i % 2 == 0, false);
    check(EdgeEdgeQuery{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}, tally, i % 128 == 0,
          i % 64 == 0);
  });
  report("ee", tally);
  EXPECT_EQ(tally.mismatches, 0);
  EXPECT_GT(tally.oracle_calls, 0);
  if (mode >= 2) {
    EXPECT_GT(tally.oracle_contacts, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, CcdRandom, ::testing::Values(0, 1, 2, 3, 4));

/// The degenerate generator's stream (every category, nudged or not, at 2^-20..2^20).
TEST(CcdRandomDegenerate, TiersAgreeWithOracle) {
  Tally tally;
  const int n = count(24000);
  constexpr int kBlock = 512;
  tbb::parallel_for(0, (n + kBlock - 1) / kBlock, [&](int b) {
    testing::DegenerateQueryGenerator gen(seed(3000) * 7919u + static_cast<std::uint64_t>(b));
    for (int i = b * kBlock; i < std::min(n, (b + 1) * kBlock) && tally.mismatches < 10; ++i) {
      const testing::DegenerateQuery q = gen.next();
      if (q.vertex_face) {
        check(q.vf, tally, i % 8 == 0, i % 16 == 0);
      } else {
        check(q.ee, tally, i % 8 == 0, i % 16 == 0);
      }
    }
  });
  report("degenerate", tally);
  EXPECT_EQ(tally.mismatches, 0);
  // Degenerate queries exercise every tier beyond the filter.
  EXPECT_GT(tally.paths[static_cast<int>(CcdPath::double_precision)], 0);
  EXPECT_GT(tally.paths[static_cast<int>(CcdPath::exact)], 0);
}

TEST(CcdRandomBatch, ResultsIndependentOfThreadCount) {
  Gen g(77);
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
  for (int i = 0; i < (test::sanitized() ? 100 : 800); ++i) {
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
