/// FixedInt against GMP on random operands of every size up to its capacity, and the
/// capacity limit itself.

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <random>

#include "support/sanitized.hpp"
#include "tailor/geometry/fixed_int.hpp"

namespace tailor::detail {
namespace {

/// Random signed integer of `bits` bits, as both types.
template <int N>
void random_pair(std::mt19937_64& rng, int bits, FixedInt<N>& f, mpz_class& m) {
  f = FixedInt<N>();
  m = 0;
  for (int done = 0; done < bits; done += 50) {
    const int take = std::min(50, bits - done);
    const std::uint64_t chunk = rng() >> (64 - take);
    // value = value 2^take + chunk
    f = f.shifted(take) + FixedInt<N>(static_cast<std::int64_t>(chunk));
    m = (m << take) + mpz_class(static_cast<unsigned long>(chunk));
  }
  if (rng() & 1) {
    f = -f;
    m = -m;
  }
}

/// The FixedInt with the mpz's value, built 50 bits at a time.
template <int N>
FixedInt<N> from_mpz(const mpz_class& m) {
  FixedInt<N> r;
  const std::size_t bits = m == 0 ? 0 : mpz_sizeinbase(m.get_mpz_t(), 2);
  mpz_class a = abs(m);
  for (std::size_t done = 0; done < bits; done += 50) {
    const std::size_t shift = bits - std::min<std::size_t>(bits, done + 50);
    const std::size_t take = std::min<std::size_t>(50, bits - done);
    mpz_class chunk = (a >> shift) & ((mpz_class(1) << take) - 1);
    r = r.shifted(static_cast<int>(take)) + FixedInt<N>(static_cast<std::int64_t>(chunk.get_ui()));
  }
  return m < 0 ? -r : r;
}

/// Same value: sign, bit length, exact equality, and the approximation within 2^-52.
template <int N>
void expect_same(const FixedInt<N>& f, const mpz_class& m) {
  EXPECT_EQ(f.sign(), sgn(m));
  EXPECT_EQ(f.bit_length(), m == 0 ? 0 : static_cast<int>(mpz_sizeinbase(m.get_mpz_t(), 2)));
  EXPECT_TRUE(f == from_mpz<N>(m));
  // The approximation is within 2^-52 relative.
  int e = 0;
  const double a = f.approximate(e);
  if (m != 0) {
    const mpq_class approx = mpq_class(a) * (e >= 0 ? mpq_class(mpz_class(1) << e)
                                                    : mpq_class(mpz_class(1), mpz_class(1) << -e));
    const mpq_class error = abs(approx - mpq_class(m));
    EXPECT_LE(error, abs(mpq_class(m)) / (mpz_class(1) << 52));
  } else {
    EXPECT_EQ(a, 0.0);
  }
}

TEST(FixedInt, ArithmeticMatchesGmp) {
  std::mt19937_64 rng(11);
  const int rounds = tailor::testing::sanitized() ? 300 : 3000;
  for (int i = 0; i < rounds; ++i) {
    FixedInt<8> a, b;
    mpz_class ma, mb;
    // Sizes from zero to half the capacity, so products fit.
    random_pair<8>(rng, static_cast<int>(rng() % 257), a, ma);
    random_pair<8>(rng, static_cast<int>(rng() % 257), b, mb);
    expect_same(a, ma);
    expect_same(a + b, ma + mb);
    expect_same(a - b, ma - mb);
    expect_same(b - a, mb - ma);
    expect_same(a * b, ma * mb);
    expect_same(-a, -ma);
    const int s = static_cast<int>(rng() % 200);
    expect_same(a.shifted(s), ma << s);
    EXPECT_EQ(compare(a, b), sgn(ma - mb));
    if (HasFailure()) return;
  }
  expect_same(FixedInt<8>(0) - FixedInt<8>(0), mpz_class(0));
  expect_same(FixedInt<8>(std::int64_t{-9223372036854775807} - 1),
              mpz_class("-9223372036854775808"));
}

TEST(FixedInt, CarriesAcrossLimbs) {
  // 2^128 - 1 plus one, minus one, times itself.
  FixedInt<8> ones = FixedInt<8>(1).shifted(128) - FixedInt<8>(1);
  const mpz_class m = (mpz_class(1) << 128) - 1;
  expect_same(ones, m);
  expect_same(ones + FixedInt<8>(1), m + 1);
  expect_same(ones * ones, m * m);
  // The two-limb fast paths: a carry into a third limb, exact cancellation, 2x1 products.
  expect_same(ones + ones, m + m);
  expect_same(ones - ones, mpz_class(0));
  expect_same(-ones - ones, -m - m);
  expect_same(ones * FixedInt<8>(-3), m * -3);
  expect_same(FixedInt<8>(std::int64_t{-1} << 62) * ones, mpz_class("-4611686018427387904") * m);
  expect_same(FixedInt<8>::scaled(0xffffffffffffffffu, 63, true),
              -(mpz_class("18446744073709551615") << 63));
}

TEST(FixedInt, ThrowsBeyondCapacity) {
  const FixedInt<4> big = FixedInt<4>(1).shifted(200);  // 201 bits of 256
  EXPECT_THROW((void)(big * big), CapacityExceeded);
  EXPECT_THROW((void)big.shifted(60), CapacityExceeded);
  EXPECT_NO_THROW((void)big.shifted(54));
  const FixedInt<4> top = FixedInt<4>(1).shifted(255);
  EXPECT_THROW((void)(top + top), CapacityExceeded);
  EXPECT_THROW((void)FixedInt<4>::scaled(1, 256, false), CapacityExceeded);
}

}  // namespace
}  // namespace tailor::detail
