// Batch bounds: every lane's bounds hold its six corners and equal the rounding of
// float_box.hpp (within 3 float ulps), beyond the float range they clamp and keep every
// overlap, padding lanes change nothing, and the two-, four- and eight-lane paths agree.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "tailor/bvh/batch_bounds.hpp"
#include "tailor/bvh/float_box.hpp"

namespace tailor {
namespace {

constexpr float kFloatMax = std::numeric_limits<float>::max();

// A batch of `count` random moving triangles at `scale`, with its corners.
MovingTriangleBatch random_batch(std::mt19937_64& rng, int count, double scale,
                                 std::vector<std::array<Vec3, 6>>& corners) {
  std::uniform_real_distribution<double> uniform(-1, 1);
  MovingTriangleBatch batch;
  corners.clear();
  for (int i = 0; i < count; ++i) {
    std::array<Vec3, 6> c;
    for (Vec3& p : c) p = scale * Vec3(uniform(rng), uniform(rng), uniform(rng));
    batch.add(c[0].data(), c[1].data(), c[2].data(), c[3].data(), c[4].data(), c[5].data());
    corners.push_back(c);
  }
  batch.pad();
  return batch;
}

TEST(BatchBounds, HoldEveryCornerAndRoundLikeFloatBoxes) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> count_of(1, MovingTriangleBatch::kCapacity);
  std::vector<std::array<Vec3, 6>> corners;
  for (int trial = 0; trial < 2000; ++trial) {
    // 2^-140 to 2^120: subnormal-range coordinates to nearly the largest float.
    const double scale = std::ldexp(1.0, (trial % 27) * 10 - 140);
    const int count = count_of(rng);
    const MovingTriangleBatch batch = random_batch(rng, count, scale, corners);
    BatchBounds bounds;
    batch_bounds(batch, bounds);
    for (int i = 0; i < count; ++i) {
      for (int k = 0; k < 3; ++k) {
        double lo = corners[i][0][k], hi = lo;
        for (const Vec3& p : corners[i]) lo = std::min(lo, p[k]), hi = std::max(hi, p[k]);
        ASSERT_LE(bounds.low[k][i], lo) << "trial " << trial << " lane " << i;
        ASSERT_GE(bounds.high[k][i], hi) << "trial " << trial << " lane " << i;
        ASSERT_EQ(bounds.low[k][i], float_at_most(lo)) << "trial " << trial;
        ASSERT_EQ(bounds.high[k][i], float_at_least(hi)) << "trial " << trial;
      }
    }
  }
}

TEST(BatchBounds, BeyondTheFloatRangeClampAndKeepOverlaps) {
  // One triangle far beyond the float range, one reaching from the origin to it: their
  // bounds clamp to the largest float on that side, so the boxes still overlap.
  const Vec3 far(1e300, -1e300, 0), near = far;
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  MovingTriangleBatch batch;
  batch.add(far.data(), far.data(), far.data(), far.data(), far.data(), far.data());
  batch.add(a.data(), b.data(), near.data(), a.data(), b.data(), near.data());
  batch.pad();
  BatchBounds bounds;
  batch_bounds(batch, bounds);
  EXPECT_EQ(bounds.low[0][0], kFloatMax);
  EXPECT_EQ(bounds.high[0][0], kFloatMax);
  EXPECT_EQ(bounds.high[0][1], kFloatMax);
  EXPECT_EQ(bounds.low[1][0], -kFloatMax);
  EXPECT_EQ(bounds.low[1][1], -kFloatMax);
  EXPECT_LE(bounds.low[0][1], 0.0f);
}

TEST(BatchBounds, TwoFourAndEightLanePathsAgree) {
  if (!detail::direction_mask_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor";
  const bool eight = detail::direction_mask_has_avx512();
  if (!eight) std::cout << "no AVX-512 on this processor: eight-lane path not compared\n";
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int> count_of(1, MovingTriangleBatch::kCapacity);
  std::vector<std::array<Vec3, 6>> corners;
  for (int trial = 0; trial < 1000; ++trial) {
    const int count = count_of(rng);
    const MovingTriangleBatch batch =
        random_batch(rng, count, std::ldexp(1.0, (trial % 60) * 20 - 600), corners);
    BatchBounds two, four, eight_lanes;
    detail::batch_bounds_two_lanes(batch, two);
    detail::batch_bounds_four_lanes(batch, four);
    if (eight) detail::batch_bounds_eight_lanes(batch, eight_lanes);
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < batch.padded_count(); ++i) {
        ASSERT_EQ(two.low[k][i], four.low[k][i]) << "trial " << trial;
        ASSERT_EQ(two.high[k][i], four.high[k][i]) << "trial " << trial;
        if (!eight) continue;
        ASSERT_EQ(two.low[k][i], eight_lanes.low[k][i]) << "trial " << trial;
        ASSERT_EQ(two.high[k][i], eight_lanes.high[k][i]) << "trial " << trial;
      }
    }
  }
}

}  // namespace
}  // namespace tailor
