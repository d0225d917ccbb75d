/// @file
/// The advancement in vector lanes against the scalar calls it mirrors: on random and
/// degenerate vertex-face and edge-edge pairs (approaching, grazing, parallel, crossing,
/// points, triangles that are segments, pairs that move together, corners on a small
/// integer grid where the closest points fall exactly on region boundaries, tiny and huge
/// scales)
/// every pair stops where the scalar loop stops, with bit-identical times and the same
/// witness after a short advance, in the widest build and in the two-lane one; and the
/// batched queries answer every query exactly as the single query does.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "support/sanitized.hpp"
#include "tailor/ccd/advance_lanes.hpp"
#include "tailor/ccd/thickness_ccd.hpp"

namespace tailor {
namespace {

/// A moving pair: its corners at both ends (p, a, b, c or a, b, c, d).
struct MovingPair {
  FourPoints x0, x1;
};

/// Random pairs of many kinds at the scale `scale`.
std::vector<MovingPair> random_pairs(int count, unsigned seed, double scale) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> kind(0, 6), grid(-2, 2);
  const auto point = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  std::vector<MovingPair> pairs;
  for (int i = 0; i < count; ++i) {
    MovingPair p;
    for (Vec3& x : p.x0) x = point();
    const Vec3 shift = 0.5 * point();
    for (int j = 0; j < 4; ++j) p.x1[j] = p.x0[j] + 0.3 * point() + (j >= 2 ? shift : Vec3::Zero());
    switch (kind(rng)) {
      case 0:  // parallel edges, moving parallel
        p.x0[3] = p.x0[2] + (p.x0[1] - p.x0[0]);
        p.x1[3] = p.x1[2] + (p.x1[1] - p.x1[0]);
        break;
      case 1:  // the first edge a point
        p.x0[1] = p.x0[0];
        p.x1[1] = p.x1[0];
        break;
      case 2:  // both edges points, one of them still
        p.x0[1] = p.x0[0], p.x1[1] = p.x1[0], p.x0[3] = p.x0[2], p.x1[3] = p.x1[2];
        p.x1[0] = p.x0[0], p.x1[1] = p.x0[1];
        break;
      case 3:  // moving together (a rigid translation)
        for (int j = 0; j < 4; ++j) p.x1[j] = p.x0[j] + shift;
        break;
      case 4:  // crossing: the second edge passes through the first's middle
        p.x1[2] = 0.5 * (p.x0[0] + p.x0[1]) + (p.x0[2] - p.x0[3]) * 0.5;
        p.x1[3] = 0.5 * (p.x0[0] + p.x0[1]) - (p.x0[2] - p.x0[3]) * 0.5;
        p.x1[0] = p.x0[0], p.x1[1] = p.x0[1];
        break;
      case 5:  // small integers: exact zeros on the closest points' region boundaries
        for (int j = 0; j < 4; ++j) {
          p.x0[j] = Vec3(grid(rng), grid(rng), grid(rng));
          p.x1[j] = Vec3(grid(rng), grid(rng), grid(rng));
        }
        break;
      default:
        break;
    }
    for (int j = 0; j < 4; ++j) p.x0[j] *= scale, p.x1[j] *= scale;
    pairs.push_back(p);
  }
  return pairs;
}

/// The scalar loop the lanes mirror (EarliestWithin::advance up to its first decision).
PairAdvance scalar_advance(const MovingPair& p, const CornerDifferences& d, PairShape shape,
                           double h, double witness_reach, double narrowest, int max_steps) {
  const ClosestDirectionAdvance advance(p.x0, p.x1, d, shape, h);
  PairAdvance out;
  double t = 0;
  for (int step = 0; step < max_steps; ++step) {
    const double next =
        step == 0 ? advance.clear_from_start(closest_weights(p.x0, shape)) : advance.clear_from(t);
    if (next >= 1 || (next == t && step == 0) || !(next - t >= narrowest)) {
      out.t = t, out.step = step, out.next = next, out.has_next = true;
      // A short advance: EarliestWithin's witness at the narrowest interval's midpoint.
      if (!(next >= 1) && !(next == t && step == 0)) {
        const double end = std::min(1.0, next + narrowest);
        out.within_after =
            within_by_closest_points(p.x0, p.x1, 0.5 * next + 0.5 * end, shape, witness_reach);
      }
      return out;
    }
    t = next;
  }
  out.t = t, out.step = max_steps, out.has_next = false;
  return out;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Every pair of `pairs` through both builds against the scalar loop; counts the pairs that
// reached the call cap, those that made several calls and those witnessed after a short
// advance.
void expect_scalar_stops(const std::vector<MovingPair>& pairs, PairShape shape, double h,
                         int max_steps, int& capped, int& several_calls, int& witnessed) {
  std::vector<CornerDifferences> differences;
  differences.reserve(pairs.size());
  for (const MovingPair& p : pairs) differences.emplace_back(p.x0, p.x1, shape);
  std::vector<PairAdvance> wide(pairs.size()), two(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    // Vary the narrowest advance, as the search's speed bound does.
    const double narrowest = i % 3 == 0 ? 1e-6 : i % 3 == 1 ? 1e-3 : 0.05;
    wide[i] = two[i] = {&pairs[i].x0, &pairs[i].x1, &differences[i], narrowest};
  }
  const double reach = h * (1 + 0.9e-6);
  advance_pairs(wide, shape, h, reach, max_steps);
  detail::advance_pairs_two_lanes(two, shape, h, reach, max_steps);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const PairAdvance expected =
        scalar_advance(pairs[i], differences[i], shape, h, reach, wide[i].narrowest, max_steps);
    for (const PairAdvance* got : {&wide[i], &two[i]}) {
      ASSERT_TRUE(same_bits(got->t, expected.t))
          << "pair " << i << " h " << h << ": t " << got->t << " against " << expected.t;
      ASSERT_EQ(got->step, expected.step) << "pair " << i;
      ASSERT_EQ(got->has_next, expected.has_next) << "pair " << i;
      if (expected.has_next) {
        ASSERT_TRUE(same_bits(got->next, expected.next))
            << "pair " << i << ": next " << got->next << " against " << expected.next;
      }
      ASSERT_EQ(got->within_after, expected.within_after) << "pair " << i;
    }
    witnessed += expected.within_after;
    capped += !expected.has_next;
    several_calls += expected.step >= 2;
  }
}

TEST(AdvanceLanes, EveryPairStopsWhereTheScalarLoopStops) {
  const int count = testing::sanitized() ? 400 : 3000;
  for (const PairShape shape : {PairShape::vertex_face, PairShape::edge_edge}) {
    int capped = 0, several_calls = 0, witnessed = 0;
    for (const double scale : {1e-3, 1.0, 1e4}) {
      const std::vector<MovingPair> pairs = random_pairs(count, 7, scale);
      for (const double h_share : {1e-3, 0.05, 0.3}) {
        for (const int max_steps : {3, 200}) {
          expect_scalar_stops(pairs, shape, h_share * scale, max_steps, capped, several_calls,
                              witnessed);
          if (HasFatalFailure()) return;
        }
      }
    }
    // Over 18 runs of `count` pairs: some reach the call cap, a good share make several
    // calls (lanes refilled while others go on), and the witness pass decides many.
    EXPECT_GT(capped, 0);
    EXPECT_GT(several_calls, count / 4);
    EXPECT_GT(witnessed, count / 10);
  }
}

// Pairs whose distance dips smoothly to h (1 + δ) at mid-step, δ from -1e-3 to 1e-3 of h:
// a vertex passing over a triangle's corner, and a segment's end passing over another's,
// each turned and moved at random. The advancement stalls at the dip, where the witness
// decides close to its reach either way.
std::vector<MovingPair> grazing_pairs(int count, PairShape shape, double h, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), exponent(-7, -3);
  std::vector<MovingPair> pairs;
  for (int i = 0; i < count; ++i) {
    const double sign = i % 2 == 0 ? 1 : -1;
    const double gap = h * (1 + sign * std::pow(10.0, exponent(rng)));
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(3 * unit(rng), Vec3(unit(rng), unit(rng), unit(rng)).normalized())
            .toRotationMatrix();
    const Vec3 shift(unit(rng), unit(rng), unit(rng));
    const auto place = [&](const Vec3& x) { return Vec3(turn * x + shift); };
    MovingPair p;
    if (shape == PairShape::vertex_face) {
      // p(t) = (s, -s, gap √2) / √2 with s = 2t - 1: over corner a at t = 1/2.
      const Vec3 corners[3] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
      p.x0[0] = place(Vec3(-1, 1, gap * std::sqrt(2.0)) / std::sqrt(2.0));
      p.x1[0] = place(Vec3(1, -1, gap * std::sqrt(2.0)) / std::sqrt(2.0));
      for (int j = 0; j < 3; ++j) p.x0[j + 1] = p.x1[j + 1] = place(corners[j]);
    } else {
      // The segment from (0, s, gap) straight up, over the end (0, 0, 0) of the other.
      p.x0[0] = p.x1[0] = place(Vec3(0, 0, 0));
      p.x0[1] = p.x1[1] = place(Vec3(1, 0, 0));
      p.x0[2] = place(Vec3(0, -1, gap)), p.x0[3] = place(Vec3(0, -1, gap + 1));
      p.x1[2] = place(Vec3(0, 1, gap)), p.x1[3] = place(Vec3(0, 1, gap + 1));
    }
    pairs.push_back(p);
  }
  return pairs;
}

TEST(AdvanceLanes, GrazingPairsAreWitnessedAsTheScalarDoes) {
  const int count = testing::sanitized() ? 200 : 1000;
  const double h = 0.01;
  for (const PairShape shape : {PairShape::vertex_face, PairShape::edge_edge}) {
    int capped = 0, several_calls = 0, witnessed = 0;
    const std::vector<MovingPair> pairs = grazing_pairs(count, shape, h, 5);
    expect_scalar_stops(pairs, shape, h, 200, capped, several_calls, witnessed);
    if (HasFatalFailure()) return;
    // Both answers of the witness are exercised close to its reach.
    EXPECT_GT(witnessed, count / 10);
    EXPECT_LT(witnessed, count - count / 10);
  }
}

// Each query's batched result against its single one, at several h and both normal tests;
// counts hits and misses.
template <class Query>
void expect_batch_as_single(const std::vector<Query>& queries, int& hits, int& misses) {
  for (const double h : {1e-3, 0.05, 0.3}) {
    for (const NormalTest normal_test : {NormalTest::run, NormalTest::skip}) {
      std::vector<ThicknessResult> batched(queries.size());
      ThicknessResult single;
      if constexpr (std::is_same_v<Query, VertexFaceQuery>) {
        vertex_face_ccd_within(queries, h, normal_test, batched);
      } else {
        edge_edge_ccd_within(queries, h, normal_test, batched);
      }
      for (std::size_t i = 0; i < queries.size(); ++i) {
        if constexpr (std::is_same_v<Query, VertexFaceQuery>) {
          single = vertex_face_ccd_within(queries[i], h, normal_test);
        } else {
          single = edge_edge_ccd_within(queries[i], h, normal_test);
        }
        ASSERT_EQ(batched[i].hit, single.hit) << "query " << i << " h " << h;
        ASSERT_TRUE(same_bits(batched[i].toi, single.toi)) << "query " << i << " h " << h;
        ASSERT_EQ(batched[i].intervals, single.intervals) << "query " << i << " h " << h;
        ASSERT_EQ(batched[i].exhausted, single.exhausted) << "query " << i << " h " << h;
        hits += single.hit;
        misses += !single.hit;
      }
    }
  }
}

TEST(AdvanceLanes, BatchedQueriesAnswerAsSingleQueries) {
  const int count = testing::sanitized() ? 300 : 2000;
  const std::vector<MovingPair> pairs = random_pairs(count, 11, 1.0);
  std::vector<VertexFaceQuery> vertex_face;
  std::vector<EdgeEdgeQuery> edge_edge;
  for (const MovingPair& p : pairs) {
    vertex_face.push_back({p.x0[0], p.x0[1], p.x0[2], p.x0[3], p.x1[0], p.x1[1], p.x1[2], p.x1[3]});
    edge_edge.push_back({p.x0[0], p.x0[1], p.x0[2], p.x0[3], p.x1[0], p.x1[1], p.x1[2], p.x1[3]});
  }
  int hits = 0, misses = 0;
  expect_batch_as_single(vertex_face, hits, misses);
  expect_batch_as_single(edge_edge, hits, misses);
  EXPECT_GT(hits, 200);
  EXPECT_GT(misses, 200);
  std::vector<ThicknessResult> too_few(edge_edge.size() - 1);
  EXPECT_THROW(edge_edge_ccd_within(edge_edge, 0.1, NormalTest::run, too_few),
               std::invalid_argument);
  EXPECT_THROW(vertex_face_ccd_within(vertex_face, 0.1, NormalTest::run, too_few),
               std::invalid_argument);
}

}  // namespace
}  // namespace tailor
