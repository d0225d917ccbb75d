#pragma once
/// @file
/// Polynomials on the step [0, 1] in Bernstein form with a certified error bound per
/// coefficient, and the certified strict sign of such a polynomial on a dyadic piece of
/// the step. Shared by the contour test and the low-level filters: every sign they act
/// on is established this way, never against an epsilon.

#include <algorithm>
#include <array>
#include <cmath>

namespace tailor {

/// A polynomial p(t) = Σ value[i]·B(i, N)(t) known up to |error of value[i]| <= bound[i].
///
/// sign_on(lo, hi) restricts p to [lo, hi] by de Casteljau's algorithm (the control
/// points on the piece are blossom values, convex combinations of the coefficients), so
/// the propagated coefficient error is at most max(bound). With lo and hi dyadic (at
/// most 8 bits after the point, so 1-s and s are exact), each of the N levels rounds a
/// product pair and a sum (3 roundings of terms bounded by M = max(|value| + bound)):
/// the rounding adds at most 3N·u·M(1+u)^(3N) < 8N·u·M (u = 2^-53), plus 2^-1000 for the
/// absolute error of any underflow. All coefficients certainly of one strict sign give
/// that sign on the whole piece (the convex-hull property of Bernstein polynomials).
template <int N>
struct CertifiedBernstein {
  // Left uninitialised by default: filled by aggregate initialisation or split() (the
  // filters build millions of these per step).
  std::array<double, N + 1> value;  ///< Bernstein coefficients, as computed
  std::array<double, N + 1> bound;  ///< bound[i] >= |error of value[i]| (>= 0)

  /// +1 / -1 when p is certainly of that strict sign on all of [lo, hi] (dyadic, within
  /// [0, 1], at most 8 fraction bits), 0 when this cannot be certified.
  int sign_on(double lo, double hi) const {
    double magnitude = 0, error = 0;
    for (int i = 0; i <= N; ++i) {
      magnitude = std::max(magnitude, std::fabs(value[i]) + bound[i]);
      error = std::max(error, bound[i]);
    }
    std::array<double, N + 1> piece = value;
    if (lo != 0.0 || hi != 1.0) {
      for (int k = 0; k <= N; ++k) piece[k] = blossom(lo, hi, N - k);
    }
    const double slack = error + 8 * N * 0x1p-53 * magnitude + 0x1p-1000;
    bool positive = true, negative = true;
    for (double c : piece) {
      positive &= c > slack;
      negative &= c < -slack;
    }
    return positive ? 1 : (negative ? -1 : 0);
  }

  /// +1 / -1 when every coefficient is certainly of that strict sign (then p is, on the
  /// whole domain), else 0.
  int sign() const {
    bool positive = true, negative = true;
    for (int i = 0; i <= N; ++i) {
      positive &= value[i] > bound[i];
      negative &= value[i] < -bound[i];
    }
    return positive ? 1 : (negative ? -1 : 0);
  }

  /// The same polynomial on the two halves of its domain (de Casteljau at 1/2), each
  /// reparametrised to [0, 1]. Every new coefficient is a chain of at most N averages
  /// (x + y)·0.5 of old ones, each rounding once by at most 2^-53 of a value bounded by
  /// M = max(|value| + bound) (times 1 + 2^-50 over the chain), plus 2^-1075 on underflow;
  /// the new bound, max(bound) + 2N·2^-53·M + 2^-1000, covers it all twice over.
  void split(CertifiedBernstein& left, CertifiedBernstein& right) const {
    double magnitude = 0, error = 0;
    for (int i = 0; i <= N; ++i) {
      magnitude = std::max(magnitude, std::fabs(value[i]) + bound[i]);
      error = std::max(error, bound[i]);
    }
    std::array<double, N + 1> x = value;
    left.value[0] = x[0];
    right.value[N] = x[N];
    for (int level = 1; level <= N; ++level) {
      for (int i = 0; i <= N - level; ++i) x[i] = (x[i] + x[i + 1]) * 0.5;
      left.value[level] = x[0];
      right.value[N - level] = x[N - level];
    }
    const double new_bound = error + 2 * N * 0x1p-53 * magnitude + 0x1p-1000;
    left.bound.fill(new_bound);
    right.bound.fill(new_bound);
  }

 private:
  // The blossom B(lo, ..., lo, hi, ..., hi) with `lows` arguments lo (de Casteljau).
  double blossom(double lo, double hi, int lows) const {
    std::array<double, N + 1> x = value;
    for (int level = 0; level < N; ++level) {
      const double s = level < lows ? lo : hi;
      for (int i = 0; i < N - level; ++i) x[i] = (1 - s) * x[i] + s * x[i + 1];
    }
    return x[0];
  }
};

/// True when `holds(lo, hi)` is established on every piece of a dyadic subdivision of
/// [0, 1] at most `max_depth` (<= 8) levels deep: a condition may hold on the whole step
/// only piecewise (a sign that changes once, a turn through 90 degrees).
template <class Condition>
bool holds_piecewise(const Condition& holds, int max_depth, double lo = 0, double hi = 1,
                     int depth = 0) {
  if (holds(lo, hi)) return true;
  if (depth >= max_depth) return false;
  const double mid = 0.5 * (lo + hi);
  return holds_piecewise(holds, max_depth, lo, mid, depth + 1) &&
         holds_piecewise(holds, max_depth, mid, hi, depth + 1);
}

}  // namespace tailor
