// Batch bounds: every lane's bounds hold its three corners at each end of the step and equal the
// rounding of float_box.hpp (within 3 float ulps), beyond the float range they clamp and keep every
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
    BatchBounds frames[2];
    batch_bounds(batch, frames[0], frames[1]);
    for (int frame = 0; frame < 2; ++frame) {
      const BatchBounds& bounds = frames[frame];
      for (int i = 0; i < count; ++i) {
        for (int k = 0; k < 3; ++k) {
          double lo = corners[i][3 * frame][k], hi = lo;
          for (int corner = 3 * frame; corner < 3 * frame + 3; ++corner) {
            lo = std::min(lo, corners[i][corner][k]), hi = std::max(hi, corners[i][corner][k]);
          }
          ASSERT_LE(bounds.low[k][i], lo) << "trial " << trial << " lane " << i;
          ASSERT_GE(bounds.high[k][i], hi) << "trial " << trial << " lane " << i;
          ASSERT_EQ(bounds.low[k][i], float_at_most(lo)) << "trial " << trial;
          ASSERT_EQ(bounds.high[k][i], float_at_least(hi)) << "trial " << trial;
        }
      }
    }
  }
}

TEST(BatchBounds, BeyondTheFloatRangeClampAndKeepOverlaps) {
  // One triangle far beyond the float range, one reaching from the origin to it: their
  // bounds clamp to the largest float on that side, so the boxes still overlap (at both
  // ends of the step: they do not move).
  const Vec3 far(1e300, -1e300, 0), near = far;
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  MovingTriangleBatch batch;
  batch.add(far.data(), far.data(), far.data(), far.data(), far.data(), far.data());
  batch.add(a.data(), b.data(), near.data(), a.data(), b.data(), near.data());
  batch.pad();
  BatchBounds start, end;
  batch_bounds(batch, start, end);
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(start.low[k][0], end.low[k][0]);
    ASSERT_EQ(start.high[k][1], end.high[k][1]);
  }
  const BatchBounds& bounds = start;
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
    BatchBounds two[2], four[2], eight_lanes[2];
    detail::batch_bounds_two_lanes(batch, two[0], two[1]);
    detail::batch_bounds_four_lanes(batch, four[0], four[1]);
    if (eight) detail::batch_bounds_eight_lanes(batch, eight_lanes[0], eight_lanes[1]);
    for (int frame = 0; frame < 2; ++frame) {
      for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < batch.padded_count(); ++i) {
          ASSERT_EQ(two[frame].low[k][i], four[frame].low[k][i]) << "trial " << trial;
          ASSERT_EQ(two[frame].high[k][i], four[frame].high[k][i]) << "trial " << trial;
          if (!eight) continue;
          ASSERT_EQ(two[frame].low[k][i], eight_lanes[frame].low[k][i]) << "trial " << trial;
          ASSERT_EQ(two[frame].high[k][i], eight_lanes[frame].high[k][i]) << "trial " << trial;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tailor
