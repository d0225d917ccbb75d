/// Ball arithmetic encloses exact results: random operands with random radii (from 0 to
/// the operand's size, magnitudes from 2^-300 to 2^300), exact members at the extremes of
/// each ball, results checked in rationals.

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <random>

#include "ccd_test_support.hpp"
#include "tailor/ccd/ball.hpp"

namespace tailor::detail {
namespace {

/// Exact [m - r, m + r] membership of a rational.
bool contains(const Ball& b, const mpq_class& x) {
  return mpq_class(b.m) - mpq_class(b.r) <= x && x <= mpq_class(b.m) + mpq_class(b.r);
}

Ball random_ball(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int e = static_cast<int>(rng() % 601) - 300;
  const double m = std::ldexp(unit(rng), e);
  const int kind = static_cast<int>(rng() % 3);
  const double r =
      kind == 0 ? 0.0
                : std::fabs(m) * std::ldexp(std::fabs(unit(rng)), -(static_cast<int>(rng() % 60)));
  return {m, r};
}

TEST(Ball, OperationsEncloseExactResults) {
  std::mt19937_64 rng(17);
  const int rounds = test::sanitized() ? 2000 : 40000;
  for (int i = 0; i < rounds; ++i) {
    const Ball a = random_ball(rng), b = random_ball(rng);
    // Members at the ends and the middle of each ball.
    for (int ia = -1; ia <= 1; ++ia) {
      for (int ib = -1; ib <= 1; ++ib) {
        const mpq_class x = mpq_class(a.m) + ia * mpq_class(a.r);
        const mpq_class y = mpq_class(b.m) + ib * mpq_class(b.r);
        ASSERT_TRUE(contains(a + b, x + y)) << i;
        ASSERT_TRUE(contains(a - b, x - y)) << i;
        ASSERT_TRUE(contains(a * b, x * y)) << i;
      }
    }
    const double lo = std::fmin(a.m, b.m), hi = std::fmax(a.m, b.m);
    const Ball h = ball_hull(lo, hi);
    ASSERT_TRUE(contains(h, mpq_class(lo)) && contains(h, mpq_class(hi))) << i;
    ASSERT_LE(ball_lower(a), a.m - a.r);
    ASSERT_GE(ball_upper(a), a.m + a.r);
  }
}

TEST(Ball, SignsAreCertainOnlyWhenTrue) {
  EXPECT_EQ(Ball(1.0, 0.5).sign(), 1);
  EXPECT_EQ(Ball(-1.0, 0.5).sign(), -1);
  EXPECT_EQ(Ball(1.0, 1.0).sign(), 0);
  EXPECT_EQ(Ball(0.0).sign(), 0);
  // Overflow never decides.
  const Ball huge(1e300);
  EXPECT_EQ((huge * huge).sign(), 0);
  EXPECT_EQ((huge * huge - huge * huge).sign(), 0);
  // Underflow is covered: a product below the subnormal range is not called zero or signed
  // wrongly.
  const Ball tiny(1e-200);
  EXPECT_GE((tiny * tiny).r, 0.0);
  EXPECT_TRUE(contains(tiny * tiny, mpq_class(1e-200) * mpq_class(1e-200)));
}

}  // namespace
}  // namespace tailor::detail
