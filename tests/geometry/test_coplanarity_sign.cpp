/// coplanarity_sign against an exact evaluation of the docs/design.md §3 formula (A, (2C+F)/3,
/// (2D+E)/3, B with n0, n1, nX) on random, near-degenerate and extreme-scale inputs.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "ccd/ccd_test_support.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {
namespace {

using test::Q3;

Q3 q3(const Vec3& v) {
  return {mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2])};
}

/// The docs/design.md formula, exactly.
StepSign reference_sign(const std::array<Vec3, 8>& x) {
  const Q3 a0 = q3(x[0]), b0 = q3(x[1]), c0 = q3(x[2]), d0 = q3(x[3]);
  const Q3 a1 = q3(x[4]), b1 = q3(x[5]), c1 = q3(x[6]), d1 = q3(x[7]);
  using test::crs;
  using test::dt;
  using test::sub;
  const Q3 n0 = crs(sub(b0, a0), sub(c0, a0)), n1 = crs(sub(b1, a1), sub(c1, a1));
  const Q3 da = sub(a1, a0), db = sub(b1, b0), dc = sub(c1, c0);
  const Q3 delta = crs(sub(db, da), sub(dc, da));
  Q3 nx;
  for (int k = 0; k < 3; ++k) nx[k] = (n0[k] + n1[k] - delta[k]) / 2;
  const mpq_class A = dt(n0, sub(d0, a0)), B = dt(n1, sub(d1, a1)), C = dt(nx, sub(d0, a0)),
                  D = dt(nx, sub(d1, a1)), E = dt(n1, sub(d0, a0)), F = dt(n0, sub(d1, a1));
  const mpq_class coeff[4] = {A, (2 * C + F) / 3, (2 * D + E) / 3, B};
  bool pos = true, neg = true;
  for (const auto& c : coeff) {
    pos &= c > 0;
    neg &= c < 0;
  }
  return pos ? StepSign::positive : (neg ? StepSign::negative : StepSign::mixed);
}

StepSign tested_sign(const std::array<Vec3, 8>& x) {
  return coplanarity_sign({x[0], x[1], x[2], x[3]}, {x[4], x[5], x[6], x[7]});
}

TEST(CoplanarityFilter, MatchesExactFormulaOnRandomAndDegenerateInputs) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::uniform_int_distribution<int> small(-2, 2), pick8(0, 7), pick3(0, 2), coin(0, 1);
  const int n = test::sanitized() ? 3000 : 30000;
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    std::array<Vec3, 8> x;
    const int mode = i % 6;
    for (auto& v : x) {
      if (mode == 0 || mode == 4) {
        v = {uni(rng), uni(rng), uni(rng)};
      } else {
        v = {double(small(rng)), double(small(rng)), double(small(rng))};
      }
      if (mode == 2) v[2] = 0.0;  // coplanar for the whole step
    }
    if (mode == 3 || mode == 5) {  // one-ulp nudges of degenerate configurations
      for (int j = 0; j < 2; ++j) {
        const int p = pick8(rng), k = pick3(rng);
        x[p][k] = std::nextafter(x[p][k], coin(rng) ? 10.0 : -10.0);
      }
    }
    if (mode == 4) {  // extreme scales: beyond the double range guard, exact fallback
      const int e = (i % 12 < 6) ? 700 : -800;
      for (auto& v : x) v = test::scaled(v, e);
    }
    const StepSign expect = reference_sign(x);
    ASSERT_EQ(tested_sign(x), expect) << "case " << i;
    ++counts[static_cast<int>(expect) + 1];
    // Scale invariance (when the scaling is exact).
    for (int e : {20, -20}) {
      std::array<Vec3, 8> y;
      bool exact = true;
      for (int j = 0; j < 8; ++j) {
        y[j] = test::scaled(x[j], e);
        exact &= test::scaled(y[j], -e) == x[j];
      }
      if (exact) {
        ASSERT_EQ(tested_sign(y), expect) << "case " << i << " scaled 2^" << e;
      }
    }
    EXPECT_EQ(may_become_coplanar({x[0], x[1], x[2], x[3]}, {x[4], x[5], x[6], x[7]}),
              expect == StepSign::mixed);
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

TEST(CoplanarityFilter, HandMadeCases) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // d stays above the plane: positive; crosses it: mixed; touches it at t = 1: mixed.
  EXPECT_EQ(coplanarity_sign({a, b, c, {0, 0, 1}}, {a, b, c, {5, 5, 2}}), StepSign::positive);
  EXPECT_EQ(coplanarity_sign({a, b, c, {0, 0, -1}}, {a, b, c, {5, 5, -2}}), StepSign::negative);
  EXPECT_EQ(coplanarity_sign({a, b, c, {0, 0, 1}}, {a, b, c, {0, 0, -1}}), StepSign::mixed);
  EXPECT_EQ(coplanarity_sign({a, b, c, {0, 0, 1}}, {a, b, c, {0, 0, 0}}), StepSign::mixed);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(coplanarity_sign({a, b, c, {0, 0, 1}}, {a, b, c, {0, 0, tiny}}), StepSign::positive);
  // A huge coordinate next to a tiny one (cancellation beyond the double bound).
  const double big = 0x1p40;
  const FourPoints still{Vec3(big, 0, 0), Vec3(big + 1, 0, 0), Vec3(big, 1, 0),
                         Vec3(big + 1, 1, 0x1p-40)};
  EXPECT_EQ(coplanarity_sign(still, still), StepSign::positive);
}

TEST(CoplanarityFilter, ExactSignsFromStackIntegersAndGmp) {
  // The exact fallback agrees with the exact formula whether the coordinates fit the
  // stack integers (spreads of ~100 bits) or need GMP (a subnormal beside 2^600: a product
  // of three differences then needs ~5000 bits).
  for (const double far : {0x1p40, 0x1p600}) {
    for (const double tiny : {0x1p-60, std::numeric_limits<double>::denorm_min()}) {
      for (const double z : {tiny, -tiny, 0.0}) {
        const std::array<Vec3, 8> x{Vec3(far, 0, 0),   Vec3(2 * far, 0, 0), Vec3(far, far, 0),
                                    Vec3(far, 1, z),   Vec3(far, 0, 0),     Vec3(2 * far, 0, 0),
                                    Vec3(far, far, 0), Vec3(far, 1, z)};
        EXPECT_EQ(tested_sign(x), reference_sign(x)) << far << " " << tiny << " " << z;
        for (int i = 0; i < 4; ++i) {
          const int exact = detail::coplanarity_coefficient_sign_exact(i, {x[0], x[1], x[2], x[3]},
                                                                       {x[4], x[5], x[6], x[7]});
          EXPECT_EQ(exact, z > 0 ? 1 : (z < 0 ? -1 : 0)) << far << " " << tiny << " " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tailor
