// Direction masks: every bit they set is true for the whole step (checked exactly: n(t)·d is
// a quadratic in t with rational coefficients, positive on [0, 1] or not), on random,
// near-degenerate, tiny and huge triangles (at and beyond the ends of the float range the
// masks are computed in), and normals a hair from perpendicular to a direction; and they
// are not vacuous (a static triangle gets every direction clearly on its side).

#include "support/sanitized.hpp"
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "tailor/bvh/direction_mask.hpp"

namespace tailor {
namespace {

using Q3 = std::array<mpq_class, 3>;

Q3 exact(const Vec3& v) {
  return {mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2])};
}
Q3 minus(const Q3& a, const Q3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Q3 cross(const Q3& u, const Q3& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
mpq_class dot(const Q3& a, const Vec3& d) {
  return a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
}

// Whether n(t)·d > 0 for every t in [0, 1], exactly: q(t) = n(t)·d in Bernstein form
// (c0, cX, c1) is the quadratic c0 (1-t)² + 2 cX t(1-t) + c1 t².
bool positive_over_step(const std::array<Vec3, 6>& corners, const Vec3& d) {
  const Q3 a0 = exact(corners[0]), b0 = exact(corners[1]), c0 = exact(corners[2]);
  const Q3 a1 = exact(corners[3]), b1 = exact(corners[4]), c1 = exact(corners[5]);
  const Q3 u0 = minus(b0, a0), v0 = minus(c0, a0), u1 = minus(b1, a1), v1 = minus(c1, a1);
  const mpq_class q0 = dot(cross(u0, v0), d), q1 = dot(cross(u1, v1), d);
  const Q3 m1 = cross(u0, v1), m2 = cross(u1, v0);
  const mpq_class qx = (dot(m1, d) + dot(m2, d)) / 2;
  if (q0 <= 0 || q1 <= 0) return false;
  // Power form: q(t) = q0 + 2(qx - q0) t + (q0 - 2qx + q1) t².
  const mpq_class a = q0 - 2 * qx + q1, b = 2 * (qx - q0);
  if (a <= 0) return true;  // concave or linear: the minimum is at an end
  const mpq_class vertex = -b / (2 * a);
  if (vertex <= 0 || vertex >= 1) return true;
  return q0 + b * vertex + a * vertex * vertex > 0;
}

::testing::AssertionResult mask_is_true(const std::array<Vec3, 6>& c) {
  const DirectionMask mask = direction_mask(c[0], c[1], c[2], c[3], c[4], c[5]);
  for (int bit = 0; bit < kMaskDirections; ++bit) {
    if ((mask >> bit & 1) && !positive_over_step(c, mask_direction(bit))) {
      return ::testing::AssertionFailure() << "bit " << bit << " is set but false";
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(DirectionMask, EveryDirectionItHoldsIsTrueOverTheWholeStep) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const int trials = tailor::testing::sanitized() ? 3000 : 30000;
  int bits_set = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const int kind = trial % 7;
    // Scales from underflowing to overflowing products (in float: edges of 2^±62 give
    // products at the ends of its range), and motions from none to large (the normal may
    // turn through more than 90 degrees).
    const double scale = std::ldexp(1.0, std::array{0, -500, 480, -1000, 20, -62, 62}[kind]);
    const double motion = std::array{1e-3, 0.5, 2.0, 1e-9, 0.0}[trial / 7 % 5];
    std::array<Vec3, 6> c;
    for (int k = 0; k < 3; ++k) c[k] = scale * Vec3(uniform(rng), uniform(rng), uniform(rng));
    if (trial % 3 == 0) {
      // Nearly in a coordinate plane: its normal is within about 10^-5 of perpendicular
      // to the other axes, around the bound's relative size.
      c[1] = c[0] + scale * Vec3(1, 0, 1e-5 * uniform(rng));
      c[2] = c[0] + scale * Vec3(0, 1, 1e-5 * uniform(rng));
    } else if (trial % 3 == 1) {
      // A normal component that is a difference of nearly equal products: n_z = (1 + ε2)
      // - (1 + ε1) with ε below float precision, so its sign is lost in rounding.
      c[1] = c[0] + scale * Vec3(1, 1 + 0x1p-23 * uniform(rng), 0);
      c[2] = c[0] + scale * Vec3(1, 1 + 0x1p-23 * uniform(rng), 1);
    }
    for (int k = 0; k < 3; ++k) {
      c[3 + k] = c[k] + motion * scale * Vec3(uniform(rng), uniform(rng), uniform(rng));
    }
    if (trial % 11 == 0) c[2] = c[0] + 1e-12 * (c[1] - c[0]);  // nearly degenerate at t = 0
    ASSERT_TRUE(mask_is_true(c)) << "trial " << trial;
    bits_set += __builtin_popcount(direction_mask(c[0], c[1], c[2], c[3], c[4], c[5]));
  }
  EXPECT_GT(bits_set, trials);  // not vacuous
}

TEST(DirectionMask, StaticTriangleHoldsEveryDirectionClearlyOnItsSide) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a(uniform(rng), uniform(rng), uniform(rng));
    const Vec3 b(uniform(rng), uniform(rng), uniform(rng));
    const Vec3 c(uniform(rng), uniform(rng), uniform(rng));
    const Vec3 n = (b - a).cross(c - a);
    const DirectionMask mask = direction_mask(a, b, c, a, b, c);
    for (int bit = 0; bit < kMaskDirections; ++bit) {
      const Vec3 d = mask_direction(bit);
      const double cosine = n.dot(d) / (n.norm() * d.norm());
      if (cosine > 1e-9) {
        EXPECT_TRUE(mask >> bit & 1) << trial << " bit " << bit;
      } else if (cosine <= 0) {
        EXPECT_FALSE(mask >> bit & 1) << trial << " bit " << bit;
      }
    }
  }
}

TEST(DirectionMask, DegenerateOverflowingOrBatchedTrianglesAreHandled) {
  const Vec3 zero = Vec3::Zero(), x = Vec3::UnitX(), y = Vec3::UnitY();
  // A degenerate triangle has no normal: no direction.
  EXPECT_EQ(direction_mask(zero, x, 2 * x, zero, x, 2 * x), 0u);
  // Products that overflow: no direction (never a wrong one).
  const double huge = 1e300;
  EXPECT_EQ(direction_mask(zero, huge * x, huge * y, zero, huge * x, huge * y), 0u);
  // The triangle in the xy plane facing +z holds +z (bit 4), not -z (bit 5).
  const DirectionMask up = direction_mask(zero, x, y, zero, x, y);
  EXPECT_TRUE(up >> 4 & 1);
  EXPECT_FALSE(up >> 5 & 1);
  EXPECT_EQ(mask_axis(DirectionMask{1} << 4), Vec3(0, 0, 1));
  // The whole mask holds the 9 directions with a positive z component, symmetric about
  // z: their sum is along +z.
  EXPECT_EQ(std::popcount(up), 9);
  EXPECT_EQ(mask_axis(up), Vec3(0, 0, 9));
  // A batch is the and of its triangles: +z and -z together leave nothing about z.
  MovingTriangleBatch batch;
  batch.add(zero.data(), x.data(), y.data(), zero.data(), x.data(), y.data());
  batch.add(zero.data(), y.data(), x.data(), zero.data(), y.data(), x.data());
  batch.pad();
  const DirectionMask both = direction_mask(batch);
  EXPECT_FALSE(both >> 4 & 1);
  EXPECT_FALSE(both >> 5 & 1);
  EXPECT_EQ(both, up & direction_mask(zero, y, x, zero, y, x));
}

TEST(DirectionMask, Sse2Avx2AndAvx512PathsAgreeBitForBit) {
  // Batches of 1-16 random triangles over many scales (across both ends of the float
  // range) and motions (near-degenerate and overflowing ones too): the SSE2, AVX2 and
  // AVX-512 paths of the dispatch give the same mask in every lane, which is that
  // triangle's own mask, and the batch's mask is their and.
  if (!detail::direction_mask_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor";
  const bool avx512 = detail::direction_mask_has_avx512();
  if (!avx512) std::cout << "no AVX-512 on this processor: its path not compared\n";
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::uniform_int_distribution<int> count_of(1, MovingTriangleBatch::kCapacity);
  int nonzero = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = std::ldexp(1.0, (trial % 40) * 4 - 80);
    const double motion = trial % 3 == 0 ? 1e-3 : trial % 3 == 1 ? 0.3 : 2.0;
    MovingTriangleBatch batch;
    DirectionMask expected = kAllDirections;
    LaneMasks own;
    const int count = count_of(rng);
    const Vec3 shared = Vec3(uniform(rng), uniform(rng), 1);  // a common tilt: masks survive
    for (int i = 0; i < count; ++i) {
      std::array<Vec3, 6> c;
      c[0] = scale * Vec3(uniform(rng), uniform(rng), uniform(rng));
      c[1] = c[0] + scale * Vec3(1, 0, 0.1 * uniform(rng));
      c[2] = c[0] + scale * (shared.cross(Vec3(1, 0, 0)).cross(shared).normalized() * -1 +
                             0.1 * Vec3(uniform(rng), uniform(rng), uniform(rng)));
      if (trial % 50 == 0) c[2] = c[0] + 2 * (c[1] - c[0]);  // degenerate
      for (int k = 0; k < 3; ++k) {
        c[3 + k] = c[k] + motion * scale * Vec3(uniform(rng), uniform(rng), uniform(rng));
      }
      batch.add(c[0].data(), c[1].data(), c[2].data(), c[3].data(), c[4].data(), c[5].data());
      own[static_cast<std::size_t>(i)] = direction_mask(c[0], c[1], c[2], c[3], c[4], c[5]);
      expected &= own[static_cast<std::size_t>(i)];
    }
    batch.pad();
    LaneMasks sse2, avx2, avx512_masks;
    detail::lane_masks_sse2(batch, sse2);
    detail::lane_masks_avx2(batch, avx2);
    if (avx512) detail::lane_masks_avx512(batch, avx512_masks);
    for (int i = 0; i < count; ++i) {
      const auto lane = static_cast<std::size_t>(i);
      ASSERT_EQ(sse2[lane], own[lane]) << "trial " << trial << " lane " << i;
      ASSERT_EQ(avx2[lane], own[lane]) << "trial " << trial << " lane " << i;
      if (avx512) {
        ASSERT_EQ(avx512_masks[lane], own[lane]) << "trial " << trial << " lane " << i;
      }
    }
    ASSERT_EQ(direction_mask(batch), expected) << "trial " << trial;
    ASSERT_EQ(and_of_masks(sse2, 0, count), expected) << "trial " << trial;
    nonzero += expected != 0;
  }
  EXPECT_GT(nonzero, 500);  // the comparison is not only of empty masks
}

TEST(DirectionMask, LanesPastThePaddedBatchAreNeverRead) {
  // The wide paths cover more lanes than a short batch holds (sixteen at once with
  // AVX-512, eight with AVX2): lanes past padded_count() hold NaN here, which would clear
  // every bit if a path read them.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> uniform(-0.2, 0.2);
  for (int count = 1; count <= MovingTriangleBatch::kCapacity; ++count) {
    MovingTriangleBatch batch;
    for (auto& row : batch.coordinate) {
      for (double& value : row) value = std::numeric_limits<double>::quiet_NaN();
    }
    DirectionMask expected = kAllDirections;
    for (int i = 0; i < count; ++i) {
      // Facing +z, tilted a little: every mask holds +z.
      const Vec3 a(i, uniform(rng), uniform(rng)), b = a + Vec3(1, uniform(rng), uniform(rng)),
                                                   c = a + Vec3(uniform(rng), 1, uniform(rng));
      batch.add(a.data(), b.data(), c.data(), a.data(), b.data(), c.data());
      expected &= direction_mask(a, b, c, a, b, c);
    }
    batch.pad();
    ASSERT_NE(expected & (DirectionMask{1} << 4), 0u);
    const auto and_of_path = [&](void (*path)(const MovingTriangleBatch&, LaneMasks&)) {
      LaneMasks masks;
      path(batch, masks);
      return and_of_masks(masks, 0, count);
    };
    EXPECT_EQ(and_of_path(detail::lane_masks_sse2), expected) << count << " triangles";
    if (detail::direction_mask_has_avx2()) {
      EXPECT_EQ(and_of_path(detail::lane_masks_avx2), expected) << count << " triangles";
    }
    if (detail::direction_mask_has_avx512()) {
      EXPECT_EQ(and_of_path(detail::lane_masks_avx512), expected) << count << " triangles";
    }
  }
}

}  // namespace
}  // namespace tailor
