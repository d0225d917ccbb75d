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

TEST(StepBoxes, DoubleAndFloatBoxesGiveTheSameVerdict) {
  // StepAabb (the thickness trees') and may_meet_over_step (the MeshBvh's) are one test:
  // on boxes whose bounds are floats (so both hold the same numbers), including touching
  // and equal bounds, they agree, and both parts of each order are needed.
  std::mt19937_64 rng(43);
  std::uniform_int_distribution<int> grid(-4, 4);
  const auto boxes = [&] {
    StepAabb d;
    FloatBox start, end;
    for (int k = 0; k < 3; ++k) {
      const int a = grid(rng), b = grid(rng), c = grid(rng), e = grid(rng);
      start.min[k] = static_cast<float>(std::min(a, b)),
      start.max[k] = static_cast<float>(std::max(a, b));
      end.min[k] = static_cast<float>(std::min(c, e)),
      end.max[k] = static_cast<float>(std::max(c, e));
      d.start.min[k] = start.min[k], d.start.max[k] = start.max[k];
      d.end.min[k] = end.min[k], d.end.max[k] = end.max[k];
    }
    return std::pair{d, std::array{start, end}};
  };
  int apart = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const auto [a, fa] = boxes();
    const auto [b, fb] = boxes();
    const bool meet = may_meet_over_step(fa[0], fa[1], fb[0], fb[1]);
    ASSERT_EQ(a.overlaps(b), meet) << trial;
    ASSERT_EQ(b.overlaps(a), meet) << trial;
    apart += !meet;
  }
  EXPECT_GT(apart, 2000);
  EXPECT_LT(apart, 18000);
}

}  // namespace
}  // namespace tailor
