// The separating-direction filter: a pair it keeps apart never holds a collision of the
// exact CCD among its fifteen vertex-face and edge-edge pairs (on pairs built to touch
// exactly, to pass through each other during the step, and to lie apart at one end only),
// every build agrees, and it drops a good share of the pairs that are in fact apart.

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "support/sanitized.hpp"
#include "support/triangle_pairs.hpp"
#include "tailor/candidates/step_separating_direction.hpp"

namespace tailor {
namespace {

using testing::TrianglePairs;

// The second triangle of pair i is a copy of the first moved by `shift0` at t = 0 and by
// `shift1` at t = 1, then jittered (or not: on the dyadic lattice, copies touch exactly).
TrianglePairs make_shifted_pairs(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> cell(-4, 4);
  std::uniform_real_distribution<double> uniform(-1, 1);
  TrianglePairs t;
  t.faces.resize(2 * count, 3);
  t.x0.resize(6 * count, 3);
  t.x1.resize(6 * count, 3);
  for (int i = 0; i < count; ++i) {
    const bool lattice = i % 2 == 0;
    const auto point = [&] {
      return lattice ? Vec3(cell(rng), cell(rng), cell(rng)) / 4.0
                     : Vec3(uniform(rng), uniform(rng), uniform(rng));
    };
    const Vec3 motion = 0.25 * point();  // the first triangle's own motion over the step
    Vec3 shift0 = point(), shift1 = point();
    switch (i % 4) {
      case 1:  // apart at t = 0, through at t = 1: the direction must hold at both ends
        shift1 = -shift0;
        break;
      case 2:  // the same offset at both ends, on the lattice often an exact touch
        shift1 = shift0;
        break;
      case 3:  // a short offset: the triangles overlap or touch
        shift0 *= 0.25;
        shift1 *= 0.25;
        break;
      default:
        break;
    }
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = point(), jitter = lattice ? Vec3::Zero() : Vec3(0.1 * point());
      t.x0.row(6 * i + k) = p;
      t.x1.row(6 * i + k) = p + motion;
      t.x0.row(6 * i + 3 + k) = p + shift0 + jitter;
      t.x1.row(6 * i + 3 + k) = p + motion + shift1 + jitter;
    }
    if (i % 17 == 5) {  // beyond the certified range
      t.x0.middleRows(6 * i, 6) *= 0x1p500;
      t.x1.middleRows(6 * i, 6) *= 0x1p500;
    }
    t.faces.row(2 * i) << 6 * i, 6 * i + 1, 6 * i + 2;
    t.faces.row(2 * i + 1) << 6 * i + 3, 6 * i + 4, 6 * i + 5;
    t.pairs.push_back({2 * i, 2 * i + 1});
  }
  return t;
}

// Whether any vertex-face or edge-edge pair of the two faces of pair i collides.
bool any_collision(const TrianglePairs& t, std::size_t i) {
  for (int side = 0; side < 2; ++side) {
    for (int k = 0; k < 3; ++k) {
      if (testing::vertex_face_collides(t, i, side, k)) return true;
    }
  }
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      if (testing::edge_edge_collides(t, i, a, b)) return true;
    }
  }
  return false;
}

TEST(StepSeparatingDirection, ApartPairsNeverCollideAndEveryBuildAgrees) {
  const int count = testing::sanitized() ? 4000 : 40000;
  const TrianglePairs t = make_shifted_pairs(count, 3);
  std::vector<TrianglePairSides> widest(t.pairs.size()), two_lanes(t.pairs.size());
  mark_pairs_apart(t.faces, t.x0, t.x1, t.pairs, widest);
  detail::mark_pairs_apart_two_lanes(t.faces, t.x0, t.x1, t.pairs, two_lanes);
  std::int64_t apart = 0, colliding = 0, free = 0, out_of_range_apart = 0;
  std::int64_t by_case[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < t.pairs.size(); ++i) {
    ASSERT_EQ(widest[i].apart, two_lanes[i].apart) << "pair " << i;
    const bool hit = any_collision(t, i);
    ASSERT_FALSE(hit && widest[i].apart) << "pair " << i << " collides but was kept apart";
    apart += widest[i].apart;
    colliding += hit;
    free += !hit;
    by_case[i % 4] += widest[i].apart;
    if (i % 17 == 5) out_of_range_apart += widest[i].apart;
  }
  EXPECT_EQ(out_of_range_apart, 0);
  // Not vacuous: many pairs collide, the filter keeps apart a good share of the others, and
  // some pairs of every kind.
  EXPECT_GT(colliding, count / 10);
  EXPECT_GT(apart, free / 4);
  for (const std::int64_t n : by_case) EXPECT_GT(n, count / 1000);
}

// A pair the plane filter already separated is left alone; the others get the filter.
TEST(StepSeparatingDirection, OnlyPairsNotYetSeparatedAreTested) {
  const TrianglePairs t = make_shifted_pairs(64, 4);
  std::vector<TrianglePairSides> sides(t.pairs.size());
  mark_pairs_apart(t.faces, t.x0, t.x1, t.pairs, sides);
  std::vector<TrianglePairSides> marked(t.pairs.size());
  for (std::size_t i = 0; i < marked.size(); i += 2) marked[i].above = 7;  // "separated"
  mark_pairs_apart(t.faces, t.x0, t.x1, t.pairs, marked);
  int tested_apart = 0;
  for (std::size_t i = 0; i < marked.size(); ++i) {
    EXPECT_EQ(marked[i].apart, i % 2 == 0 ? 0 : sides[i].apart) << "pair " << i;
    tested_apart += i % 2 == 1 && sides[i].apart;
  }
  EXPECT_GT(tested_apart, 0);
  std::vector<TrianglePairSides> wrong_size(3);
  EXPECT_THROW(mark_pairs_apart(t.faces, t.x0, t.x1, t.pairs, wrong_size), std::invalid_argument);
}

// A NaN or an infinity anywhere in a pair that is otherwise apart: never certified.
TEST(StepSeparatingDirection, NonFiniteCornersAreNeverApart) {
  TrianglePairs t = make_shifted_pairs(1, 5);
  t.x0.setZero();
  t.x0.topRows(3) << 0, 0, 0, 1, 0, 0, 0, 1, 0;     // A in z = 0
  t.x0.bottomRows(3) << 0, 0, 1, 1, 0, 1, 0, 1, 1;  // B a unit above it, crossed edges apart
  t.x0(4, 0) = 0.5;
  t.x1 = t.x0;
  std::vector<TrianglePairSides> sides(1);
  mark_pairs_apart(t.faces, t.x0, t.x1, t.pairs, sides);
  ASSERT_EQ(sides[0].apart, 1);
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    for (Positions* x : {&t.x0, &t.x1}) {
      for (Index v = 0; v < 6; ++v) {
        for (int k = 0; k < 3; ++k) {
          const double kept = (*x)(v, k);
          (*x)(v, k) = bad;
          mark_pairs_apart(t.faces, t.x0, t.x1, t.pairs, sides);
          EXPECT_EQ(sides[0].apart, 0) << bad << " at vertex " << v << ", coordinate " << k;
          (*x)(v, k) = kept;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tailor
