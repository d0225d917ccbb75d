/// The exact decision procedure behind the exact CCD path: root isolation, signs at
/// algebraic roots, and the earliest solution of P = 0 with sign conditions.

#include <gtest/gtest.h>

#include <cmath>

#include "tailor/ccd/rational_polynomial.hpp"

namespace tailor::detail {
namespace {

mpq_class q(long n, long d = 1) {
  mpq_class r(n, d);
  r.canonicalize();
  return r;
}

/// (t - r1)(t - r2)...
RationalPoly from_roots(std::initializer_list<mpq_class> roots) {
  RationalPoly p(mpq_class(1));
  for (const auto& r : roots) p = p * RationalPoly::linear(-r, 1);
  return p;
}

const mpq_class kTol(mpz_class(1), mpz_class(1) << 21);

TEST(RationalPolynomial, IsolatesRootsInUnitInterval) {
  const RationalPoly p = from_roots({q(1, 3), q(1, 2), q(2, 3), q(3, 2), q(-1, 5)});
  auto roots = isolate_roots_unit(p);
  ASSERT_EQ(roots.size(), 3u);
  const double expect[3] = {1.0 / 3, 0.5, 2.0 / 3};
  for (int i = 0; i < 3; ++i) {
    const double lb = root_lower_bound(p, roots[i], kTol).get_d();
    EXPECT_LE(lb, expect[i] + 1e-15);
    EXPECT_GE(lb, expect[i] - 1e-6);
  }
  const auto ends = isolate_roots_unit(from_roots({q(0), q(1), q(1, 7)}));
  ASSERT_EQ(ends.size(), 3u);
  EXPECT_TRUE(ends[0].exact);
  EXPECT_EQ(ends[0].lo, 0);
  EXPECT_TRUE(ends[2].exact);
  EXPECT_EQ(ends[2].lo, 1);
  EXPECT_TRUE(isolate_roots_unit(RationalPoly({q(-2), q(0), q(1)})).empty());  // t^2 - 2
}

TEST(RationalPolynomial, SignAtIrrationalRoot) {
  const RationalPoly p({q(-1), q(0), q(2)});  // 2 t^2 - 1, root 1/sqrt(2) ~ 0.70710678
  auto roots = isolate_roots_unit(p);
  ASSERT_EQ(roots.size(), 1u);
  EXPECT_EQ(sign_at_root(p, roots[0], RationalPoly::linear(q(-7, 10), 1)), 1);
  EXPECT_EQ(sign_at_root(p, roots[0], RationalPoly::linear(q(-71, 100), 1)), -1);
  // q = 4 t^4 - 1 = (2t^2 - 1)(2t^2 + 1) vanishes at the root.
  EXPECT_EQ(sign_at_root(p, roots[0], RationalPoly({q(-1), q(0), q(0), q(0), q(4)})), 0);
  EXPECT_EQ(sign_at_root(p, roots[0], RationalPoly()), 0);
}

TEST(RationalPolynomial, EarliestSolutionWithRoots) {
  const RationalPoly p({q(-1), q(0), q(2)});
  const auto hit = earliest_solution(p, {{RationalPoly::linear(q(-7, 10), 1), true}}, kTol);
  ASSERT_TRUE(hit.has_value());
  EXPECT_LE(hit->get_d(), std::sqrt(0.5));
  EXPECT_GE(hit->get_d(), std::sqrt(0.5) - 1e-6);
  EXPECT_FALSE(earliest_solution(p, {{RationalPoly::linear(q(-71, 100), 1), false}}, kTol));
  // The first root fails a condition, the second passes.
  const RationalPoly two = from_roots({q(1, 4), q(3, 4)});
  const auto second = earliest_solution(two, {{RationalPoly::linear(q(-1, 2), 1), false}}, kTol);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(*second, q(3, 4));
  // A non-strict condition that is exactly zero at the root holds; a strict one fails.
  const RationalPoly half = RationalPoly::linear(q(-1, 2), 1);
  EXPECT_TRUE(earliest_solution(half, {{half, false}}, kTol).has_value());
  EXPECT_FALSE(earliest_solution(half, {{half, true}}, kTol).has_value());
  EXPECT_FALSE(earliest_solution(RationalPoly(q(3)), {}, kTol).has_value());
}

TEST(RationalPolynomial, EarliestSolutionWithZeroPolynomial) {
  const RationalPoly zero;
  const RationalPoly half = RationalPoly::linear(q(-1, 2), 1);  // t - 1/2
  const auto closed = earliest_solution(zero, {{half, false}}, kTol);
  ASSERT_TRUE(closed.has_value());
  EXPECT_EQ(*closed, q(1, 2));
  // Open set (1/2, 1]: the infimum 1/2 is not attained but is the answer.
  const auto open = earliest_solution(zero, {{half, true}}, kTol);
  ASSERT_TRUE(open.has_value());
  EXPECT_EQ(*open, q(1, 2));
  // -(t - 1/2)^2 >= 0 only at t = 1/2; strict never.
  const RationalPoly neg_sq = RationalPoly() - half * half;
  EXPECT_EQ(earliest_solution(zero, {{neg_sq, false}}, kTol).value_or(q(-1)), q(1, 2));
  EXPECT_FALSE(earliest_solution(zero, {{neg_sq, true}}, kTol).has_value());
  // Everything from t = 0: 1 - t >= 0.
  EXPECT_EQ(
      earliest_solution(zero, {{RationalPoly::linear(q(1), -1), false}}, kTol).value_or(q(-1)),
      q(0));
  // Intersection of [1/3, 1] and [0, 1/4]: empty; of t >= 1/3 and t <= 2/3 with (t-1/2)^2 > 0.
  const RationalPoly third = RationalPoly::linear(q(-1, 3), 1);
  const RationalPoly quarter = RationalPoly::linear(q(1, 4), -1);
  EXPECT_FALSE(earliest_solution(zero, {{third, false}, {quarter, false}}, kTol).has_value());
  const auto mixed = earliest_solution(
      zero, {{third, false}, {RationalPoly::linear(q(2, 3), -1), false}, {half * half, true}},
      kTol);
  ASSERT_TRUE(mixed.has_value());
  EXPECT_LE(*mixed, q(1, 3));  // a lower bound within the tolerance (1/3 is not dyadic)
  EXPECT_GE(*mixed, q(1, 3) - kTol);
  // Only at t = 1.
  EXPECT_EQ(
      earliest_solution(zero, {{RationalPoly::linear(q(-1), 1), false}}, kTol).value_or(q(-1)),
      q(1));
}

}  // namespace
}  // namespace tailor::detail
