/// BigInt (GMP behind the FixedInt interface, the exact tier's last resort) gives the
/// same results as FixedInt and GMP.

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <random>

#include "ccd_test_support.hpp"
#include "tailor/ccd/big_int.hpp"
#include "tailor/geometry/fixed_int.hpp"

namespace tailor::detail {
namespace {

TEST(BigInt, SameResultsAsFixedIntAndGmp) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < (test::sanitized() ? 100 : 1000); ++i) {
    const std::uint64_t ma = rng() >> 11, mb = rng() >> 11;
    const int sa = static_cast<int>(rng() % 300), sb = static_cast<int>(rng() % 300);
    const bool na = rng() & 1, nb = rng() & 1;
    const BigInt a = BigInt::scaled(ma, sa, na), b = BigInt::scaled(mb, sb, nb);
    const FixedInt<16> fa = FixedInt<16>::scaled(ma, sa, na), fb = FixedInt<16>::scaled(mb, sb, nb);
    mpz_class za = mpz_class(static_cast<unsigned long>(ma)) << sa;
    mpz_class zb = mpz_class(static_cast<unsigned long>(mb)) << sb;
    if (na) za = -za;
    if (nb) zb = -zb;
    EXPECT_EQ(a.value(), za);
    EXPECT_EQ((a + b).value(), za + zb);
    EXPECT_EQ((a - b).value(), za - zb);
    EXPECT_EQ((a * b).value(), za * zb);
    EXPECT_EQ((-a).value(), -za);
    EXPECT_EQ(a.shifted(70).value(), za << 70);
    EXPECT_EQ(a.sign(), sgn(za));
    EXPECT_EQ(compare(a, b), compare(fa, fb));
    EXPECT_EQ((a * b).sign(), (fa * fb).sign());
    EXPECT_EQ((a * b).bit_length(), (fa * fb).bit_length());
    int e = 0;
    const double m = a.approximate(e);
    if (za != 0) {
      EXPECT_NEAR(std::ldexp(m, e - sa) / std::ldexp(static_cast<double>(ma) * (na ? -1 : 1), 0),
                  1.0, 1e-15);
    } else {
      EXPECT_EQ(m, 0.0);
    }
  }
}

}  // namespace
}  // namespace tailor::detail
