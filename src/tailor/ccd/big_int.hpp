#pragma once
/// @file
/// GMP integers behind the FixedInt interface: the exact tier's last resort for queries
/// whose numbers do not fit the fixed size (exponent spreads of hundreds of bits, or
/// adversarially close roots). Same algorithm, unbounded integers, heap allocation.
/// Internal to the ccd module.

#include <gmpxx.h>

#include <cmath>
#include <cstdint>

namespace tailor::detail {

/// An unbounded signed integer with the FixedInt interface.
class BigInt {
 public:
  /// Never runs out of room (only of memory).
  static constexpr bool kBounded = false;
  BigInt() = default;
  BigInt(std::int64_t v) : m_value(static_cast<long>(v)) {}  // NOLINT(google-explicit-constructor)

  /// mantissa 2^shift (shift >= 0), negated when `negative`.
  static BigInt scaled(std::uint64_t mantissa, int shift, bool negative) {
    BigInt r;
    mpz_import(r.m_value.get_mpz_t(), 1, 1, sizeof(mantissa), 0, 0, &mantissa);
    mpz_mul_2exp(r.m_value.get_mpz_t(), r.m_value.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
    if (negative) mpz_neg(r.m_value.get_mpz_t(), r.m_value.get_mpz_t());
    return r;
  }

  int sign() const { return mpz_sgn(m_value.get_mpz_t()); }
  bool is_zero() const { return sign() == 0; }
  int bit_length() const {
    return is_zero() ? 0 : static_cast<int>(mpz_sizeinbase(m_value.get_mpz_t(), 2));
  }

  /// x ≈ m 2^e with |x - m 2^e| <= 2^-52 |m 2^e| (mpz_get_d_2exp truncates to 53 bits).
  double approximate(int& e) const {
    long exponent = 0;
    const double m = mpz_get_d_2exp(&exponent, m_value.get_mpz_t());
    e = static_cast<int>(exponent);
    return m;
  }

  BigInt operator-() const {
    BigInt r;
    r.m_value = -m_value;
    return r;
  }
  friend BigInt operator+(const BigInt& a, const BigInt& b) {
    BigInt r;
    r.m_value = a.m_value + b.m_value;
    return r;
  }
  friend BigInt operator-(const BigInt& a, const BigInt& b) {
    BigInt r;
    r.m_value = a.m_value - b.m_value;
    return r;
  }
  friend BigInt operator*(const BigInt& a, const BigInt& b) {
    BigInt r;
    r.m_value = a.m_value * b.m_value;
    return r;
  }
  BigInt& operator+=(const BigInt& b) {
    m_value += b.m_value;
    return *this;
  }
  BigInt& operator-=(const BigInt& b) {
    m_value -= b.m_value;
    return *this;
  }
  BigInt& operator*=(const BigInt& b) {
    m_value *= b.m_value;
    return *this;
  }

  /// x 2^bits (bits >= 0).
  BigInt shifted(int bits) const {
    BigInt r;
    mpz_mul_2exp(r.m_value.get_mpz_t(), m_value.get_mpz_t(), static_cast<mp_bitcnt_t>(bits));
    return r;
  }

  friend int compare(const BigInt& a, const BigInt& b) {
    const int c = cmp(a.m_value, b.m_value);
    return (c > 0) - (c < 0);
  }
  friend bool operator==(const BigInt& a, const BigInt& b) { return a.m_value == b.m_value; }

  /// The value as a GMP integer (tests).
  const mpz_class& value() const { return m_value; }

 private:
  mpz_class m_value;
};

}  // namespace tailor::detail
