#pragma once
/// @file
/// Rigorous midpoint-radius ("ball") arithmetic in round-to-nearest double: a Ball {m, r}
/// stands for every real in [m - r, m + r], and each operation returns a ball holding every
/// exact result of the operation on members of its operands. Cheaper than endpoint
/// intervals with ulp steps (no bit tricks, no branches), which is what the certified
/// double tier evaluates its conditions with. Internal to the ccd module.
///
/// Why the radii are safe: for a result x computed as fl(x), round-to-nearest gives
/// |fl(x) - x| <= u |fl(x)| + eta (u = 2^-53; any eta >= 2^-1075 covers underflow in
/// products). eta is 2^-600, not the smallest subnormal: radii that start at zero then stay
/// normal numbers, because arithmetic on subnormals is two orders of magnitude slower; the
/// only cost is that quantities below ~2^-600 are never certified (the exact tier decides).
/// Each radius adds such terms to the operands' radii; it is itself a sum of at most eight
/// rounded nonnegative terms, so multiplying it by kInflate = 1 + 2^-48 (>= (1 - u)^-9)
/// makes it an upper bound of its exact value. Overflow gives inf or NaN, and every sign
/// test below is false on those, so an overflowed ball never decides anything.

#include <cmath>

namespace tailor::detail {

/// A closed ball [m - r, m + r] of reals (r >= 0).
struct Ball {
  double m = 0.0, r = 0.0;

  Ball() = default;
  /// The exact point x.
  constexpr Ball(double x) : m(x) {}  // NOLINT(google-explicit-constructor)
  constexpr Ball(double mid, double radius) : m(mid), r(radius) {}

  /// Certainly > 0 (false on NaN).
  bool positive() const { return m > r; }
  /// Certainly < 0 (false on NaN).
  bool negative() const { return -m > r; }
  /// Certainly nonzero.
  bool nonzero() const { return positive() || negative(); }
  /// -1 or 1 when certain, 0 when the ball may hold 0 (or is not finite).
  int sign() const { return positive() ? 1 : (negative() ? -1 : 0); }
};

inline constexpr double kBallU = 0x1p-53;
inline constexpr double kBallEta = 0x1p-600;
inline constexpr double kBallInflate = 1.0 + 0x1p-48;

inline Ball operator+(const Ball& a, const Ball& b) {
  const double m = a.m + b.m;
  return {m, (a.r + b.r + kBallU * std::fabs(m) + kBallEta) * kBallInflate};
}

inline Ball operator-(const Ball& a, const Ball& b) {
  const double m = a.m - b.m;
  return {m, (a.r + b.r + kBallU * std::fabs(m) + kBallEta) * kBallInflate};
}

inline Ball operator-(const Ball& a) {
  return {-a.m, a.r};
}

inline Ball operator*(const Ball& a, const Ball& b) {
  const double m = a.m * b.m;
  const double r =
      std::fabs(a.m) * b.r + a.r * (std::fabs(b.m) + b.r) + kBallU * std::fabs(m) + kBallEta;
  return {m, r * kBallInflate};
}

/// The ball of all reals in [lo, hi] (lo <= hi, both finite).
inline Ball ball_hull(double lo, double hi) {
  const double m = 0.5 * lo + 0.5 * hi;
  const double r = std::fmax(hi - m, m - lo);
  return {m, (r + kBallU * std::fabs(m) + kBallEta) * kBallInflate};
}

/// Rigorous lower and upper ends.
inline double ball_lower(const Ball& x) {
  const double lo = x.m - x.r;
  return lo - (kBallU * std::fabs(lo) + kBallEta) * 2.0;
}
inline double ball_upper(const Ball& x) {
  const double hi = x.m + x.r;
  return hi + (kBallU * std::fabs(hi) + kBallEta) * 2.0;
}

}  // namespace tailor::detail
