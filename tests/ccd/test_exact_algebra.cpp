/// The exact tier's algebra (roots in [0, 1] of integer polynomials of degree <= 3, exact
/// signs at those roots) against the rational reference implementation, on polynomials
/// built with multiple roots, roots at 0, 1 and dyadic points, shared factors, and random
/// coefficients; with fixed-size and GMP integers.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "ccd_test_support.hpp"
#include "tailor/ccd/algebraic_point.hpp"
#include "tailor/ccd/big_int.hpp"
#include "tailor/geometry/fixed_int.hpp"
#include "tailor/ccd/rational_polynomial.hpp"
#include "tailor/ccd/unit_roots.hpp"

namespace tailor::detail {
namespace {

using Fixed = FixedInt<32>;

/// Integer coefficients, lowest degree first.
using Coefficients = std::vector<long>;

template <class Z>
Poly<Z> make_poly(const Coefficients& c) {
  Poly<Z> p;
  p.deg = static_cast<int>(c.size()) - 1;
  for (std::size_t i = 0; i < c.size(); ++i) p.c[i] = Z(static_cast<std::int64_t>(c[i]));
  p.trim();
  return p;
}

RationalPoly rational(const Coefficients& c) {
  std::vector<mpq_class> q;
  for (long x : c) q.emplace_back(x);
  return RationalPoly(std::move(q));
}

Coefficients multiply(const Coefficients& a, const Coefficients& b) {
  Coefficients r(a.size() + b.size() - 1, 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  }
  return r;
}

/// The rational reference: sorted distinct roots in [0, 1] with exact lower bounds.
std::vector<double> reference_roots(const Coefficients& c) {
  const RationalPoly p = squarefree_part(rational(c));
  std::vector<double> out;
  const mpq_class tol(mpz_class(1), mpz_class(1) << 40);
  for (RealRoot r : isolate_roots_unit(p)) out.push_back(root_lower_bound(p, r, tol).get_d());
  return out;
}

template <class Z>
void expect_same_roots(const Coefficients& c) {
  const Poly<Z> p = make_poly<Z>(c);
  UnitRoots<Z> roots;
  roots_in_unit(p, roots);
  const std::vector<double> want = reference_roots(c);
  ASSERT_EQ(roots.count, static_cast<int>(want.size()));
  for (int i = 0; i < roots.count; ++i) {
    const double lb = lower_bound(roots.root[i]);
    EXPECT_LE(lb, want[i] + 1e-12) << "root " << i;
    EXPECT_GE(lb, want[i] - 0x1p-21) << "root " << i;
    // The root of p: p vanishes there exactly, and the enclosure holds it.
    EXPECT_EQ(sign_at(p, roots.root[i]), 0);
  }
}

/// Random factors: (d t - n) with n/d in or near [0, 1], or quadratics without real roots.
Coefficients random_factor(std::mt19937_64& rng) {
  const int kind = static_cast<int>(rng() % 5);
  if (kind == 4) {  // t^2 + b t + c with negative discriminant
    const long b = static_cast<long>(rng() % 5) - 2;
    return {b * b + 1 + static_cast<long>(rng() % 5), b, 1};
  }
  const long d = kind == 0 ? 1 : static_cast<long>(1 + rng() % 16);
  const long n = static_cast<long>(rng() % (2 * d + 1)) - d / 2;
  return {-n, d};
}

TEST(ExactAlgebra, RootsInUnitMatchRationalReference) {
  std::mt19937_64 rng(3);
  const int rounds = test::sanitized() ? 200 : 2000;
  for (int i = 0; i < rounds; ++i) {
    Coefficients c{static_cast<long>(1 + rng() % 3) * ((rng() & 1) ? 1 : -1)};
    int degree = 0;
    while (degree < 3) {
      Coefficients f = random_factor(rng);
      if (degree + static_cast<int>(f.size()) - 1 > 3) break;
      degree += static_cast<int>(f.size()) - 1;
      c = multiply(c, f);
      if (rng() % 4 == 0 && degree + static_cast<int>(f.size()) - 1 <= 3) {  // a repeated factor
        degree += static_cast<int>(f.size()) - 1;
        c = multiply(c, f);
      }
    }
    if (degree == 0) continue;
    expect_same_roots<Fixed>(c);
    if (i % 8 == 0) expect_same_roots<BigInt>(c);
    if (HasFailure()) {
      ADD_FAILURE() << "polynomial " << i;
      return;
    }
  }
}

TEST(ExactAlgebra, RootsOfRandomAndSpecialPolynomials) {
  // Roots at both ends, a triple root, a double root at a dyadic point, irrational roots,
  // roots 2^-31 apart (deep subdivision; coefficients stay below 2^63).
  expect_same_roots<Fixed>({0, -1, 1});        // t (t - 1)
  expect_same_roots<Fixed>({-1, 3, -3, 1});    // (t - 1)^3
  expect_same_roots<Fixed>({-1, 6, -12, 8});   // (2t - 1)^3
  expect_same_roots<Fixed>({1, -4, 4});        // (2t - 1)^2
  expect_same_roots<Fixed>({-1, 0, 2});        // 1/sqrt(2)
  expect_same_roots<Fixed>({1, -5, 5});        // (5 ± sqrt 5) / 10, both in (0, 1)
  expect_same_roots<Fixed>({-3, 11, -13, 5});  // (t - 1)^2 (5t - 3)
  const long two30 = 1L << 30;
  expect_same_roots<Fixed>(multiply({-two30, 2 * two30}, {-(two30 + 1), 2 * two30}));
  std::mt19937_64 rng(9);
  for (int i = 0; i < (test::sanitized() ? 100 : 1000); ++i) {
    Coefficients c(4);
    for (long& x : c) x = static_cast<long>(rng() % 2001) - 1000;
    if (c[3] == 0) c[3] = 1;
    expect_same_roots<Fixed>(c);
    if (HasFailure()) return;
  }
}

TEST(ExactAlgebra, SignsAtRootsMatchRationalReference) {
  std::mt19937_64 rng(21);
  const int rounds = test::sanitized() ? 200 : 2000;
  int zeros = 0, nonzero = 0;
  for (int i = 0; i < rounds; ++i) {
    // p = f g with a quadratic or linear g that q shares half of the time.
    const Coefficients f = random_factor(rng), g = random_factor(rng);
    Coefficients pc = multiply(f, g);
    if (pc.size() < 4 && rng() % 2) pc = multiply(pc, random_factor(rng));
    if (pc.size() > 4) continue;
    Coefficients qc;
    if (rng() % 2) {
      qc = multiply(g, {static_cast<long>(rng() % 7) - 3, 1 + static_cast<long>(rng() % 3)});
    } else {
      qc = {static_cast<long>(rng() % 21) - 10, static_cast<long>(rng() % 21) - 10,
            static_cast<long>(rng() % 21) - 10};
    }
    if (qc.size() > 3) qc.resize(3);
    const Poly<Fixed> p = make_poly<Fixed>(pc), q = make_poly<Fixed>(qc);
    if (p.deg < 1) continue;
    UnitRoots<Fixed> roots;
    roots_in_unit(p, roots);
    const RationalPoly rp = squarefree_part(rational(pc)), rq = rational(qc);
    std::vector<RealRoot> ref = isolate_roots_unit(rp);
    ASSERT_EQ(roots.count, static_cast<int>(ref.size()));
    for (int k = 0; k < roots.count; ++k) {
      const int want = sign_at_root(rp, ref[k], rq);
      EXPECT_EQ(sign_at(q, roots.root[k]), want) << "case " << i << " root " << k;
      (want == 0 ? zeros : nonzero) += 1;
      // Just right of the root: the first nonvanishing derivative's sign.
      int right = want;
      for (RationalPoly d = rq.derivative(); right == 0 && !d.is_zero(); d = d.derivative()) {
        right = sign_at_root(rp, ref[k], d);
      }
      EXPECT_EQ(right_sign(q, roots.root[k]), right) << "case " << i << " root " << k;
    }
    if (HasFailure()) return;
  }
  // Both kinds of answer were exercised.
  EXPECT_GT(zeros, 0);
  EXPECT_GT(nonzero, 0);
}

TEST(ExactAlgebra, IsolatedRootBecomesRationalOnDyadicHit) {
  // (4t - 1)(t^2 - 2): root 1/4 is dyadic; narrowing may land on it exactly.
  const Poly<Fixed> p = make_poly<Fixed>(multiply({-1, 4}, {-2, 0, 1}));
  UnitRoots<Fixed> roots;
  roots_in_unit(p, roots);
  ASSERT_EQ(roots.count, 1);
  EXPECT_EQ(sign_at(make_poly<Fixed>({-1, 4}), roots.root[0]), 0);
  EXPECT_EQ(sign_at(make_poly<Fixed>({-1, 5}), roots.root[0]), 1);   // 5/4 - 1 > 0
  EXPECT_EQ(sign_at(make_poly<Fixed>({-1, 3}), roots.root[0]), -1);  // 3/4 - 1 < 0
  EXPECT_LE(lower_bound(roots.root[0]), 0.25);
  EXPECT_GE(lower_bound(roots.root[0]), 0.25 - 0x1p-21);
}

}  // namespace
}  // namespace tailor::detail
