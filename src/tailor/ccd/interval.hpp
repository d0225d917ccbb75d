#pragma once
/// @file
/// A minimal rigorous interval type for the certified double path of the CCD: every
/// operation rounds to nearest and then widens each end by one ulp, which encloses the
/// exact result of the operation on the (exact) interval ends, underflow included.
/// Overflow or NaN makes comparisons fail, so decisions stay "undecided". Internal.

#include <bit>
#include <cstdint>
#include <limits>

namespace tailor::detail {

/// Next double above `x` (x itself for NaN and +inf).
inline double next_up(double x) {
  if (!(x < std::numeric_limits<double>::infinity())) return x;
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  std::uint64_t b = std::bit_cast<std::uint64_t>(x);
  b = x > 0.0 ? b + 1 : b - 1;
  return std::bit_cast<double>(b);
}

/// Next double below `x` (x itself for NaN and -inf).
inline double next_down(double x) {
  return -next_up(-x);
}

/// A closed interval [lo, hi] of reals.
struct Interval {
  double lo = 0.0, hi = 0.0;

  Interval() = default;
  /// The point interval [x, x] (x must be exact).
  constexpr Interval(double x) : lo(x), hi(x) {}  // NOLINT(google-explicit-constructor)
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  /// Certainly > 0 on the whole interval.
  bool positive() const { return lo > 0.0; }
  /// Certainly < 0 on the whole interval.
  bool negative() const { return hi < 0.0; }
  /// Certainly nonzero on the whole interval.
  bool nonzero() const { return lo > 0.0 || hi < 0.0; }
};

inline Interval operator+(const Interval& a, const Interval& b) {
  return {next_down(a.lo + b.lo), next_up(a.hi + b.hi)};
}

inline Interval operator-(const Interval& a, const Interval& b) {
  return {next_down(a.lo - b.hi), next_up(a.hi - b.lo)};
}

inline Interval operator*(const Interval& a, const Interval& b) {
  const double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
  double lo = p0 < p1 ? p0 : p1, hi = p0 < p1 ? p1 : p0;
  lo = lo < p2 ? lo : p2;
  hi = hi < p2 ? p2 : hi;
  lo = lo < p3 ? lo : p3;
  hi = hi < p3 ? p3 : hi;
  return {next_down(lo), next_up(hi)};
}

/// Smallest interval holding both.
inline Interval hull(const Interval& a, const Interval& b) {
  return {a.lo < b.lo ? a.lo : b.lo, a.hi > b.hi ? a.hi : b.hi};
}

}  // namespace tailor::detail
