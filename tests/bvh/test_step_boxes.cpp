// Boxes at both ends of a step: two sets that move far together are kept apart although their
// swept boxes overlap, two that swap sides along an axis may meet, every pair the swept boxes
// keep apart is kept apart, and on random moving triangle pairs (a large shared motion, a
// relative one from small to larger than the gap, a quarter of the pairs swapping sides) no
// pair said not to meet intersects at any of 257 sampled times (exact triangle intersection
// on the positions at t).

#include <gtest/gtest.h>

#include <array>
#include <random>

#include "tailor/bvh/step_boxes.hpp"
#include "tailor/geometry/triangle_intersection.hpp"

namespace tailor {
namespace {

using Corners = std::array<Vec3, 3>;

FloatBox box_of(const Corners& c) {
  FloatBox box;
  for (const Vec3& p : c) {
    for (int k = 0; k < 3; ++k) {
      box.min[k] = std::min(box.min[k], float_at_most(p[k]));
      box.max[k] = std::max(box.max[k], float_at_least(p[k]));
    }
  }
  return box;
}

Corners moved(const Corners& c, const Vec3& by) {
  return {c[0] + by, c[1] + by, c[2] + by};
}

bool may_meet(const Corners& a0, const Corners& a1, const Corners& b0, const Corners& b1) {
  return may_meet_over_step(box_of(a0), box_of(a1), box_of(b0), box_of(b1));
}

TEST(StepBoxes, SetsMovingFarTogetherStayApart) {
  const Corners a{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const Corners b = moved(a, Vec3(0, 0, 0.1));  // a layer 0.1 above
  const Vec3 carried(3, -2, 5);
  FloatBox swept_a = box_of(a), swept_b = box_of(b);
  swept_a.extend(box_of(moved(a, carried)));
  swept_b.extend(box_of(moved(b, carried)));
  ASSERT_TRUE(swept_a.overlaps(swept_b));
  EXPECT_FALSE(may_meet(a, moved(a, carried), b, moved(b, carried)));
  // The layers touch at t = 1: they may meet.
  EXPECT_TRUE(may_meet(a, moved(a, carried), b, moved(a, carried)));
}

TEST(StepBoxes, SetsSwappingSidesMayMeet) {
  // b starts beyond a along x and ends before it: apart at both ends, in opposite orders.
  const Corners a{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const Corners b = moved(a, Vec3(2, 0, 0));
  EXPECT_TRUE(may_meet(a, a, b, moved(a, Vec3(-2, 0, 0))));
  EXPECT_TRUE(may_meet(b, moved(a, Vec3(-2, 0, 0)), a, a));
}

TEST(StepBoxes, RandomMovingTrianglesSaidApartNeverIntersect) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto point = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  double relative = 0;  // how far the corners move relative to the shared motion
  const auto wobble = [&](std::mt19937_64&) { return relative * unit(rng); };
  const auto shaken = [&](const Vec3& p) {
    return Vec3(p + Vec3(wobble(rng), wobble(rng), wobble(rng)));
  };
  int apart = 0, swept_apart = 0, intersecting = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    relative = std::array{0.05, 0.3, 1.5}[trial % 3];
    const Corners a0{point(), point(), point()};
    const Vec3 offset = 1.5 * point();
    const Corners b0{point() + offset, point() + offset, point() + offset};
    const Vec3 carried = 4 * point();
    // Every fourth pair swaps sides: b ends as far on the other side of a as it started.
    const Vec3 swap = trial % 4 == 0 ? Vec3(-2 * offset) : Vec3::Zero();
    const Corners a1{shaken(a0[0]) + carried, shaken(a0[1]) + carried, shaken(a0[2]) + carried};
    const Corners b1{shaken(b0[0]) + carried + swap, shaken(b0[1]) + carried + swap,
                     shaken(b0[2]) + carried + swap};
    FloatBox swept_a = box_of(a0), swept_b = box_of(b0);
    swept_a.extend(box_of(a1));
    swept_b.extend(box_of(b1));
    const bool meet = may_meet(a0, a1, b0, b1);
    if (!swept_a.overlaps(swept_b)) {
      ++swept_apart;
      ASSERT_FALSE(meet) << trial << ": the swept boxes are apart";
    }
    bool touched = false;
    for (int i = 0; i <= 256 && !touched; ++i) {
      const double t = i / 256.0;
      const auto at = [t](const Corners& c0, const Corners& c1) {
        Triangle tri;
        for (int k = 0; k < 3; ++k) tri[k] = (1 - t) * c0[k] + t * c1[k];
        return tri;
      };
      touched = triangles_intersect(at(a0, a1), at(b0, b1));
    }
    intersecting += touched;
    if (!meet) {
      ++apart;
      ASSERT_FALSE(touched) << trial << ": said apart, intersecting";
    }
  }
  // Not vacuous: many pairs said apart beyond those the swept boxes part, and some that meet.
  EXPECT_GT(apart, swept_apart + 400);
  EXPECT_GT(intersecting, 100);
}

TEST(StepBoxes, FloatBoxesHoldTheDoubleOnesAndPartOnlyWhatTheyPart) {
  // StepBox::holding rounds double boxes outward to floats: each float box holds its double
  // box, and a pair the float boxes part is parted by the double boxes too (along an axis at
  // both ends, in one order); on coordinates that are floats, the two verdicts agree.
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> coordinate(-4, 4);
  std::uniform_int_distribution<int> grid(-4, 4);
  const auto exact_apart = [](const Aabb(&a)[2], const Aabb(&b)[2]) {
    bool apart = false;
    for (int k = 0; k < 3; ++k) {
      apart |= a[0].max[k] < b[0].min[k] && a[1].max[k] < b[1].min[k];
      apart |= b[0].max[k] < a[0].min[k] && b[1].max[k] < a[1].min[k];
    }
    return apart;
  };
  int apart = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const bool on_floats = trial % 2 == 0;
    const auto value = [&] { return on_floats ? double(grid(rng)) : coordinate(rng); };
    const auto box = [&] {
      Aabb b;
      b.extend(Vec3(value(), value(), value()));
      b.extend(Vec3(value(), value(), value()));
      return b;
    };
    const Aabb a[2] = {box(), box()}, b[2] = {box(), box()};
    const StepBox fa = StepBox::holding(a[0], a[1]), fb = StepBox::holding(b[0], b[1]);
    for (int k = 0; k < 3; ++k) {
      ASSERT_LE(fa.start.min[k], a[0].min[k]);
      ASSERT_GE(fa.start.max[k], a[0].max[k]);
      ASSERT_LE(fa.end.min[k], a[1].min[k]);
      ASSERT_GE(fa.end.max[k], a[1].max[k]);
    }
    const bool meet = fa.overlaps(fb);
    ASSERT_EQ(meet, fb.overlaps(fa)) << trial;
    if (!meet) {
      ASSERT_TRUE(exact_apart(a, b)) << trial;
    }
    if (on_floats) {
      ASSERT_EQ(meet, !exact_apart(a, b)) << trial;
    }
    apart += !meet;
  }
  EXPECT_GT(apart, 2000);
  EXPECT_LT(apart, 18000);
}

}  // namespace
}  // namespace tailor
