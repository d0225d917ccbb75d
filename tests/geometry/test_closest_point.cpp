/// @file
/// Closest points against dense sampling of the triangle and the segments.

#include <gtest/gtest.h>

#include <random>

#include "tailor/geometry/closest_point.hpp"

namespace tailor {
namespace {

TEST(ClosestPoint, PointTriangleMatchesDenseSampling) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vec3 p(2 * u(rng), 2 * u(rng), 2 * u(rng));
    const Vec3 w = closest_point_barycentric(p, a, b, c);
    EXPECT_NEAR(w.sum(), 1.0, 1e-12);
    EXPECT_GE(w.minCoeff(), 0.0);
    const double d = (p - (w[0] * a + w[1] * b + w[2] * c)).norm();
    double best = 1e300;
    const int k = 60;
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; i + j <= k; ++j) {
        const double s = double(i) / k, t = double(j) / k;
        best = std::min(best, (p - ((1 - s - t) * a + s * b + t * c)).norm());
      }
    }
    EXPECT_LE(d, best + 1e-12);
    EXPECT_GE(d, best - 0.05);  // the sampling is at most one grid cell away
  }
}

TEST(ClosestPoint, SegmentsMatchDenseSamplingAndHandleDegenerateOnes) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 p0(u(rng), u(rng), u(rng)), p1(u(rng), u(rng), u(rng));
    const Vec3 q0(u(rng), u(rng), u(rng)), q1(u(rng), u(rng), u(rng));
    const auto [s, t] = closest_segment_parameters(p0, p1, q0, q1);
    EXPECT_GE(s, 0.0);
    EXPECT_LE(s, 1.0);
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
    const double d = ((p0 + s * (p1 - p0)) - (q0 + t * (q1 - q0))).norm();
    double best = 1e300;
    for (int i = 0; i <= 200; ++i) {
      for (int j = 0; j <= 200; ++j) {
        best = std::min(best, ((p0 + i / 200.0 * (p1 - p0)) - (q0 + j / 200.0 * (q1 - q0))).norm());
      }
    }
    EXPECT_LE(d, best + 1e-12);
  }
  // A point (zero-length segment) against a segment.
  const auto [s, t] =
      closest_segment_parameters(Vec3(0.5, 1, 0), Vec3(0.5, 1, 0), Vec3(0, 0, 0), Vec3(1, 0, 0));
  EXPECT_DOUBLE_EQ(t, 0.5);
  EXPECT_DOUBLE_EQ(s, 0.0);
}

}  // namespace
}  // namespace tailor
