#pragma once
/// @file
/// Exact signed integers of at most N 64-bit limbs, on the stack (no heap, no GMP): the
/// number type of the exact predicates (the coplanarity filter's exact signs) and of the
/// exact CCD tier. Sign-magnitude with a used-limb count, so small values cost little
/// whatever N is. A result that does not fit in N limbs throws CapacityExceeded; callers
/// then fall back to GMP (the exact CCD tier reruns on BigInt, ccd/big_int.hpp, which has
/// the same interface). Internal.

#include <bit>
#include <cmath>
#include <cstdint>

namespace tailor::detail {

/// Thrown by FixedInt when a result needs more limbs than it has.
struct CapacityExceeded {};

/// |v| = mantissa 2^exponent with an odd mantissa (v finite and nonzero): the exact
/// integer view of a double. Scaling every coordinate of a query by 2^-(lowest exponent)
/// makes them all integers (common_scale_integers.hpp).
inline void decompose_double(double v, std::uint64_t& mantissa, int& exponent) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  mantissa = biased == 0 ? fraction : (fraction | (std::uint64_t{1} << 52));
  exponent = biased == 0 ? -1074 : biased - 1075;
  const int zeros = std::countr_zero(mantissa);
  mantissa >>= zeros;
  exponent += zeros;
}

__extension__ using Limb2 = unsigned __int128;

/// A signed integer |x| < 2^(64 N).
template <int N>
class FixedInt {
 public:
  static_assert(N >= 2);
  /// Results beyond the capacity throw CapacityExceeded.
  static constexpr bool kBounded = true;

  FixedInt() = default;
  FixedInt(std::int64_t v) {  // NOLINT(google-explicit-constructor): integers convert
    if (v != 0) {
      m_size = 1;
      m_negative = v < 0;
      m_limb[0] = v < 0 ? ~static_cast<std::uint64_t>(v) + 1 : static_cast<std::uint64_t>(v);
    }
  }
  // Copies move only the used limbs.
  FixedInt(const FixedInt& o) : m_size(o.m_size), m_negative(o.m_negative) {
    copy_limbs(m_limb, o.m_limb, m_size);
  }
  FixedInt& operator=(const FixedInt& o) {
    m_size = o.m_size;
    m_negative = o.m_negative;
    copy_limbs(m_limb, o.m_limb, m_size);
    return *this;
  }

  /// mantissa 2^shift (shift >= 0), negated when `negative`.
  static FixedInt scaled(std::uint64_t mantissa, int shift, bool negative) {
    FixedInt r;
    if (mantissa == 0) return r;
    const int word = shift / 64, bit = shift % 64;
    const std::uint64_t spill = bit == 0 ? 0 : mantissa >> (64 - bit);
    const int size = word + 1 + (spill != 0 ? 1 : 0);
    if (size > N) throw CapacityExceeded{};
    for (int i = 0; i < word; ++i) r.m_limb[i] = 0;
    r.m_limb[word] = mantissa << bit;
    if (spill != 0) r.m_limb[word + 1] = spill;
    r.m_size = size;
    r.m_negative = negative;
    return r;
  }

  /// -1, 0 or 1.
  int sign() const { return m_size == 0 ? 0 : (m_negative ? -1 : 1); }
  bool is_zero() const { return m_size == 0; }

  /// Number of bits of |x| (0 for zero).
  int bit_length() const {
    return m_size == 0 ? 0 : 64 * (m_size - 1) + 64 - std::countl_zero(m_limb[m_size - 1]);
  }

  /// x ≈ m 2^e with |x - m 2^e| <= 2^-52 |m 2^e|; m = 0 for zero. Never overflows (the
  /// exponent is returned separately).
  double approximate(int& e) const {
    if (m_size == 0) {
      e = 0;
      return 0.0;
    }
    // The top two limbs (or one): at most two roundings and the dropped lower limbs.
    const std::uint64_t hi = m_limb[m_size - 1];
    const std::uint64_t lo = m_size >= 2 ? m_limb[m_size - 2] : 0;
    const Limb2 top = (static_cast<Limb2>(hi) << 64) | lo;
    const int z = std::countl_zero(hi);  // normalise so that the top bit is bit 127
    const Limb2 norm = top << z;
    // Truncating to the top 64 bits (relative error < 2^-63, the dropped limbs < 2^-64),
    // then rounding to double (<= 2^-53): < 2^-52 relative overall.
    const auto high64 = static_cast<std::uint64_t>(norm >> 64);
    e = 64 * (m_size - 2) + 64 - z;
    const double m = static_cast<double>(high64);
    return m_negative ? -m : m;
  }

  FixedInt operator-() const {
    FixedInt r(*this);
    if (r.m_size != 0) r.m_negative = !r.m_negative;
    return r;
  }

  [[gnu::always_inline]] friend FixedInt operator+(const FixedInt& a, const FixedInt& b) {
    if (a.m_size <= 1 && b.m_size <= 1) return from_small(a.small() + b.small());
    if (a.m_size <= 2 && b.m_size <= 2) return add_two_limbs(a, b, b.m_negative);
    return add(a, b, false);
  }
  [[gnu::always_inline]] friend FixedInt operator-(const FixedInt& a, const FixedInt& b) {
    if (a.m_size <= 1 && b.m_size <= 1) return from_small(a.small() - b.small());
    if (a.m_size <= 2 && b.m_size <= 2) return add_two_limbs(a, b, b.m_size != 0 && !b.m_negative);
    return add(a, b, true);
  }
  [[gnu::always_inline]] friend FixedInt operator*(const FixedInt& a, const FixedInt& b) {
    if (a.m_size == 1 && b.m_size == 1) {  // the common case: one 64x64 -> 128 product
      FixedInt r;
      r.m_negative = a.m_negative != b.m_negative;
      const Limb2 t = static_cast<Limb2>(a.m_limb[0]) * b.m_limb[0];
      r.m_limb[0] = static_cast<std::uint64_t>(t);
      r.m_limb[1] = static_cast<std::uint64_t>(t >> 64);
      r.m_size = r.m_limb[1] != 0 ? 2 : 1;
      return r;
    }
    if ((a.m_size == 2 && b.m_size == 1) || (a.m_size == 1 && b.m_size == 2)) {
      // Two limbs by one: two products, at most three limbs.
      const FixedInt& two = a.m_size == 2 ? a : b;
      const Limb2 one = (a.m_size == 2 ? b : a).m_limb[0];
      FixedInt r;
      r.m_negative = a.m_negative != b.m_negative;
      const Limb2 lo = one * two.m_limb[0];
      const Limb2 hi = one * two.m_limb[1] + static_cast<std::uint64_t>(lo >> 64);
      r.m_limb[0] = static_cast<std::uint64_t>(lo);
      r.m_limb[1] = static_cast<std::uint64_t>(hi);
      r.m_limb[2] = static_cast<std::uint64_t>(hi >> 64);
      r.m_size = r.m_limb[2] != 0 ? 3 : 2;
      return r;
    }
    return multiply(a, b);
  }
  FixedInt& operator+=(const FixedInt& b) { return *this = *this + b; }
  FixedInt& operator-=(const FixedInt& b) { return *this = *this - b; }
  FixedInt& operator*=(const FixedInt& b) { return *this = *this * b; }

  /// x 2^bits (bits >= 0).
  FixedInt shifted(int bits) const {
    FixedInt r;
    if (m_size == 0) return r;
    const int word = bits / 64, bit = bits % 64;
    int size = m_size + word;
    const std::uint64_t spill = bit == 0 ? 0 : m_limb[m_size - 1] >> (64 - bit);
    if (spill != 0) ++size;
    if (size > N) throw CapacityExceeded{};
    for (int i = 0; i < word; ++i) r.m_limb[i] = 0;
    if (bit == 0) {
      for (int i = 0; i < m_size; ++i) r.m_limb[i + word] = m_limb[i];
    } else {
      std::uint64_t carry = 0;
      for (int i = 0; i < m_size; ++i) {
        r.m_limb[i + word] = (m_limb[i] << bit) | carry;
        carry = m_limb[i] >> (64 - bit);
      }
      if (spill != 0) r.m_limb[m_size + word] = spill;
    }
    r.m_size = size;
    r.m_negative = m_negative;
    return r;
  }

  /// Sign of a - b.
  friend int compare(const FixedInt& a, const FixedInt& b) { return (a - b).sign(); }
  friend bool operator==(const FixedInt& a, const FixedInt& b) {
    if (a.m_size != b.m_size || a.m_negative != b.m_negative) return false;
    for (int i = 0; i < a.m_size; ++i) {
      if (a.m_limb[i] != b.m_limb[i]) return false;
    }
    return true;
  }

 private:
  /// The general product (out of line).
  [[gnu::noinline]] static FixedInt multiply(const FixedInt& a, const FixedInt& b) {
    FixedInt r;
    if (a.m_size == 0 || b.m_size == 0) return r;
    r.m_negative = a.m_negative != b.m_negative;
    const int n = a.m_size + b.m_size;
    if (n - 1 > N) throw CapacityExceeded{};
    std::uint64_t out[2 * N];  // no clearing: row 0 writes, later rows add
    {
      std::uint64_t carry = 0;
      const Limb2 a0 = a.m_limb[0];
      for (int j = 0; j < b.m_size; ++j) {
        const Limb2 t = a0 * b.m_limb[j] + carry;
        out[j] = static_cast<std::uint64_t>(t);
        carry = static_cast<std::uint64_t>(t >> 64);
      }
      out[b.m_size] = carry;
    }
    for (int i = 1; i < a.m_size; ++i) {
      std::uint64_t carry = 0;
      const Limb2 ai = a.m_limb[i];
      for (int j = 0; j < b.m_size; ++j) {
        const Limb2 t = ai * b.m_limb[j] + out[i + j] + carry;
        out[i + j] = static_cast<std::uint64_t>(t);
        carry = static_cast<std::uint64_t>(t >> 64);
      }
      out[i + b.m_size] = carry;
    }
    int size = n;
    while (size > 0 && out[size - 1] == 0) --size;
    if (size > N) throw CapacityExceeded{};
    copy_limbs(r.m_limb, out, size);
    r.m_size = size;
    return r;
  }

  /// a + b, or a - b when `subtract` (out of line: the general case).
  [[gnu::noinline]] static FixedInt add(const FixedInt& a, const FixedInt& b, bool subtract) {
    const bool b_negative = b.m_negative != subtract;
    return a.m_negative == b_negative ? add_magnitudes(a, b, a.m_negative)
                                      : subtract_signed(a, b, b_negative);
  }

  /// a + b where b enters with sign `b_negative`, both of at most two limbs.
  static FixedInt add_two_limbs(const FixedInt& a, const FixedInt& b, bool b_negative) {
    auto magnitude = [](const FixedInt& x) {
      Limb2 v = 0;
      for (int i = x.m_size - 1; i >= 0; --i) v = (v << 64) | x.m_limb[i];
      return v;
    };
    const Limb2 ma = magnitude(a), mb = magnitude(b);
    FixedInt r;
    Limb2 m = 0;
    if (a.m_size == 0 || b.m_size == 0 || a.m_negative == b_negative) {
      m = ma + mb;
      r.m_negative = a.m_size != 0 ? a.m_negative : b_negative;
      if (m < ma) {  // carry into a third limb
        r.m_limb[0] = static_cast<std::uint64_t>(m);
        r.m_limb[1] = static_cast<std::uint64_t>(m >> 64);
        r.m_limb[2] = 1;
        r.m_size = 3;
        return r;
      }
    } else if (ma >= mb) {
      m = ma - mb;
      r.m_negative = a.m_negative;
    } else {
      m = mb - ma;
      r.m_negative = b_negative;
    }
    r.m_limb[0] = static_cast<std::uint64_t>(m);
    r.m_limb[1] = static_cast<std::uint64_t>(m >> 64);
    r.m_size = r.m_limb[1] != 0 ? 2 : (r.m_limb[0] != 0 ? 1 : 0);
    if (r.m_size == 0) r.m_negative = false;
    return r;
  }

  __extension__ using Signed2 = __int128;

// Only the first m_size limbs are ever read; the rest stay uninitialized on purpose (this
// is the exact CCD's inner loop), which GCC's flow analysis cannot see through.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
  /// The value of a number of at most one limb (|x| < 2^64) as a 128-bit integer.
  Signed2 small() const {
    if (m_size == 0) return 0;
    const auto v = static_cast<Signed2>(m_limb[0]);
    return m_negative ? -v : v;
  }
  /// A number |v| < 2^127 (sums and differences of one-limb numbers).
  static FixedInt from_small(Signed2 v) {
    FixedInt r;
    if (v == 0) return r;
    r.m_negative = v < 0;
    const auto m = static_cast<Limb2>(v < 0 ? -v : v);
    r.m_limb[0] = static_cast<std::uint64_t>(m);
    r.m_limb[1] = static_cast<std::uint64_t>(m >> 64);
    r.m_size = r.m_limb[1] != 0 ? 2 : 1;
    return r;
  }

  /// Copies n limbs; small counts without a string-copy instruction's start-up cost.
  [[gnu::always_inline]] static void copy_limbs(std::uint64_t* to, const std::uint64_t* from,
                                                int n) {
    switch (n) {
      case 4:
        to[3] = from[3];
        [[fallthrough]];
      case 3:
        to[2] = from[2];
        [[fallthrough]];
      case 2:
        to[1] = from[1];
        [[fallthrough]];
      case 1:
        to[0] = from[0];
        [[fallthrough]];
      case 0:
        return;
      default:
        for (int i = 0; i < n; ++i) to[i] = from[i];
    }
  }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

  /// Sign of |a| - |b|.
  static int compare_magnitudes(const FixedInt& a, const FixedInt& b) {
    if (a.m_size != b.m_size) return a.m_size < b.m_size ? -1 : 1;
    for (int i = a.m_size - 1; i >= 0; --i) {
      if (a.m_limb[i] != b.m_limb[i]) return a.m_limb[i] < b.m_limb[i] ? -1 : 1;
    }
    return 0;
  }

  /// |a| + |b| with the given sign.
  static FixedInt add_magnitudes(const FixedInt& a, const FixedInt& b, bool negative) {
    const FixedInt& big = a.m_size >= b.m_size ? a : b;
    const FixedInt& small = a.m_size >= b.m_size ? b : a;
    FixedInt r;
    std::uint64_t carry = 0;
    for (int i = 0; i < big.m_size; ++i) {
      const Limb2 t =
          static_cast<Limb2>(big.m_limb[i]) + (i < small.m_size ? small.m_limb[i] : 0) + carry;
      r.m_limb[i] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    r.m_size = big.m_size;
    if (carry != 0) {
      if (r.m_size == N) throw CapacityExceeded{};
      r.m_limb[r.m_size++] = carry;
    }
    r.m_negative = r.m_size != 0 && negative;
    return r;
  }

  /// |a| - |b| where a has sign `a.m_negative` and b enters with sign `b_negative`
  /// opposite to a's: the result is a + b.
  static FixedInt subtract_signed(const FixedInt& a, const FixedInt& b, bool b_negative) {
    const int c = compare_magnitudes(a, b);
    if (c == 0) return FixedInt();
    const FixedInt& big = c > 0 ? a : b;
    const FixedInt& small = c > 0 ? b : a;
    FixedInt r;
    std::uint64_t borrow = 0;
    for (int i = 0; i < big.m_size; ++i) {
      const std::uint64_t s = i < small.m_size ? small.m_limb[i] : 0;
      const std::uint64_t d1 = big.m_limb[i] - s;
      const std::uint64_t b1 = big.m_limb[i] < s;
      const std::uint64_t d2 = d1 - borrow;
      const std::uint64_t b2 = d1 < borrow;
      r.m_limb[i] = d2;
      borrow = b1 | b2;
    }
    int size = big.m_size;
    while (size > 0 && r.m_limb[size - 1] == 0) --size;
    r.m_size = size;
    r.m_negative = c > 0 ? a.m_negative : b_negative;
    return r;
  }

  // The header first: small numbers then touch a single cache line.
  int m_size = 0;
  bool m_negative = false;
  std::uint64_t m_limb[N];
};

}  // namespace tailor::detail
