/// @file
/// Edge strain limiting: every edge ends within the limit, pinned vertices stay, edges
/// within the limit and compressed edges are left alone; the strain statistics.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "tailor/geometry/error.hpp"
#include "tailor/sim/strain_limiter.hpp"

namespace tailor {
namespace {

/// A strip of 2 × n vertices along x, spacing `step`.
struct Strip {
  Positions rest;
  std::unique_ptr<TriangleMesh> mesh;
};

Strip make_strip(int n, double step) {
  Strip s;
  s.rest.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    s.rest.row(i) << step * i, 0, 0;
    s.rest.row(n + i) << step * i, 0, step;
  }
  FaceArray f(2 * (n - 1), 3);
  for (int i = 0; i + 1 < n; ++i) {
    f.row(2 * i) << i, i + 1, n + i;
    f.row(2 * i + 1) << i + 1, n + i + 1, n + i;
  }
  s.mesh = std::make_unique<TriangleMesh>(2 * n, f);
  return s;
}

Eigen::VectorXd masses_with_pins(Index n, std::initializer_list<Index> pins) {
  Eigen::VectorXd m = Eigen::VectorXd::Constant(n, 1e-3);
  for (Index p : pins) m[p] = std::numeric_limits<double>::infinity();
  return m;
}

TEST(StrainLimiter, PulledStripEndsWithinTheLimitAndPinsStay) {
  const int n = 20;
  const Strip s = make_strip(n, 0.01);
  const Eigen::VectorXd m = masses_with_pins(2 * n, {0, n});
  const StrainLimiter limiter(*s.mesh, s.rest, m, 0.03);
  // The free end pulled 50 % beyond the strip's length, with some noise.
  Positions x = s.rest;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.002, 0.002);
  for (int i = 0; i < n; ++i) {
    for (const Index v : {i, n + i}) {
      x(v, 0) *= 1.5;
      if (v != 0 && v != n) x.row(v) += Eigen::RowVector3d(u(rng), u(rng), u(rng));
    }
  }
  const Positions pinned_before = x;
  const StrainLimitStats stats = limiter.apply(x, 10000);
  EXPECT_GT(stats.max_strain_before, 0.3);
  EXPECT_LE(stats.max_strain_after, 0.03 + 1e-9);
  for (const double strain : edge_strains(*s.mesh, s.rest, x)) EXPECT_LE(strain, 0.03 + 1e-9);
  EXPECT_EQ(x.row(0), pinned_before.row(0));
  EXPECT_EQ(x.row(n), pinned_before.row(n));
}

TEST(StrainLimiter, OverRelaxedCorrectionsNeverShortenAnEdgeBelowItsRestLength) {
  // A straight chain pulled to twice its length from a pinned end: the first sweeps are
  // over-relaxed (strain far above the limit); no edge along the chain may end up
  // shorter than at rest, and every edge ends within the limit.
  const int n = 12;
  const Strip s = make_strip(n, 0.01);
  const StrainLimiter limiter(*s.mesh, s.rest, masses_with_pins(2 * n, {0, n}), 0.025);
  Positions x = s.rest;
  x.col(0) *= 2.0;
  const StrainLimitStats stats = limiter.apply(x, 10000);
  EXPECT_GT(stats.max_strain_before, 0.9);
  EXPECT_LE(stats.max_strain_after, 0.025 + 1e-9);
  for (int row : {0, n}) {
    for (int i = 0; i + 1 < n; ++i) {
      const double length = (x.row(row + i + 1) - x.row(row + i)).norm();
      EXPECT_GE(length, 0.01 * (1 - 1e-12)) << "edge " << row + i;
    }
  }
}

TEST(StrainLimiter, LeavesStatesWithinTheLimitAndCompressionAlone) {
  const Strip s = make_strip(6, 0.01);
  const StrainLimiter limiter(*s.mesh, s.rest, masses_with_pins(12, {0}), 0.05);
  Positions x = s.rest;
  x.col(0) *= 0.7;   // compressed along the strip
  x.col(2) *= 1.04;  // stretched across it by 4 %, within 5 %
  const Positions before = x;
  const StrainLimitStats stats = limiter.apply(x);
  EXPECT_EQ(stats.corrections, 0);
  EXPECT_EQ(stats.sweeps, 1);
  EXPECT_EQ(x, before);
}

TEST(StrainLimiter, ConstraintRunsAfterEverySweepUntilBothHold) {
  // The constraint keeps every vertex at z ≤ 0.5 cm; both hold at the end.
  const int n = 10;
  const Strip s = make_strip(n, 0.01);
  const StrainLimiter limiter(*s.mesh, s.rest, masses_with_pins(2 * n, {0, n}), 0.02);
  Positions x = s.rest;
  x.col(0) *= 1.3;
  int calls = 0;
  const auto clamp_z = [&](Positions& y) {
    ++calls;
    std::int64_t moved = 0;
    for (Eigen::Index i = 0; i < y.rows(); ++i) {
      if (i != n && y(i, 2) > 0.015) {
        y(i, 2) = 0.015;
        ++moved;
      }
    }
    return moved;
  };
  const StrainLimitStats stats = limiter.apply(x, 1000, clamp_z);
  EXPECT_EQ(calls, stats.sweeps);
  EXPECT_LE(stats.max_strain_after, 0.02 + 1e-9);
}

TEST(StrainLimiter, SummaryMaxAndNinetyNinthPercentile) {
  const Strip s = make_strip(51, 0.01);
  Positions x = s.rest;
  for (const double e : edge_strains(*s.mesh, s.rest, x)) EXPECT_NEAR(e, 0.0, 1e-12);
  // Stretch the last cell: its two edges along x get strain 0.5, its diagonal less.
  x(50, 0) += 0.005;
  x(101, 0) += 0.005;
  std::vector<double> sorted = edge_strains(*s.mesh, s.rest, x);
  std::sort(sorted.begin(), sorted.end());
  const StrainSummary summary = strain_summary(*s.mesh, s.rest, x);
  EXPECT_NEAR(summary.max, 0.5, 1e-12);
  // Nearest rank: the smallest strain with at least 99 % of the edges at or below it.
  const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(sorted.size())));
  EXPECT_EQ(summary.p99, sorted[rank - 1]);
  EXPECT_LT(summary.p99, summary.max);
}

TEST(StrainLimiter, RejectsBadInput) {
  const Strip s = make_strip(4, 0.01);
  EXPECT_THROW(StrainLimiter(*s.mesh, s.rest, Eigen::VectorXd::Ones(3), 0.1), InputError);
  EXPECT_THROW(StrainLimiter(*s.mesh, s.rest, Eigen::VectorXd::Ones(8), -0.1), InputError);
  EXPECT_THROW(StrainLimiter(*s.mesh, s.rest, Eigen::VectorXd::Zero(8), 0.1), InputError);
}

}  // namespace
}  // namespace tailor
