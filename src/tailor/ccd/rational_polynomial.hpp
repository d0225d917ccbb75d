#pragma once
/// @file
/// Exact univariate polynomials over the rationals (GMP) and the generic decision
/// procedure of the rational reference CCD (ccd_rational.hpp): "the earliest t in [0, 1] with P(t)
/// = 0 and sign conditions Q_i(t) >= 0 or > 0". Internal to the ccd module (and its tests).

#include <gmpxx.h>

#include <optional>
#include <vector>

namespace tailor::detail {

/// A polynomial in t with rational coefficients, lowest degree first, no trailing zeros
/// (the zero polynomial has no coefficients).
class RationalPoly {
 public:
  RationalPoly() = default;
  /// The constant polynomial `c`.
  explicit RationalPoly(const mpq_class& c);
  /// The polynomial with these coefficients (lowest degree first).
  explicit RationalPoly(std::vector<mpq_class> coefficients);
  /// The linear polynomial `c0 + c1 t`.
  static RationalPoly linear(const mpq_class& c0, const mpq_class& c1);

  /// Degree; -1 for the zero polynomial.
  int degree() const { return static_cast<int>(m_c.size()) - 1; }
  /// True for the zero polynomial.
  bool is_zero() const { return m_c.empty(); }
  /// Coefficients, lowest degree first.
  const std::vector<mpq_class>& coefficients() const { return m_c; }
  /// Value at `t`.
  mpq_class operator()(const mpq_class& t) const;
  /// Sign (-1, 0, 1) of the value at `t`.
  int sign_at(const mpq_class& t) const;
  /// Derivative.
  RationalPoly derivative() const;

  friend RationalPoly operator+(const RationalPoly& a, const RationalPoly& b);
  friend RationalPoly operator-(const RationalPoly& a, const RationalPoly& b);
  friend RationalPoly operator*(const RationalPoly& a, const RationalPoly& b);

 private:
  void trim();
  std::vector<mpq_class> m_c;
};

/// Remainder of `a` divided by nonzero `b`.
RationalPoly poly_remainder(const RationalPoly& a, const RationalPoly& b);
/// Quotient of `a` divided by nonzero `b` (exact division assumed or not).
RationalPoly poly_quotient(const RationalPoly& a, const RationalPoly& b);
/// Monic greatest common divisor (zero when both are zero).
RationalPoly poly_gcd(const RationalPoly& a, const RationalPoly& b);
/// Squarefree part p / gcd(p, p') of a nonzero polynomial.
RationalPoly squarefree_part(const RationalPoly& p);

/// A real root of a squarefree polynomial: either exactly `lo` (== `hi`), or the only root
/// in the open interval (lo, hi), whose endpoints are not roots (the sign changes).
struct RealRoot {
  mpq_class lo, hi;
  bool exact = false;
};

/// The real roots in [0, 1] of squarefree nonzero `p`, sorted, with disjoint isolating
/// intervals inside [0, 1].
std::vector<RealRoot> isolate_roots_unit(const RationalPoly& p);

/// Halves the isolating interval of `root` of squarefree `p` (it may become exact).
void refine_root(const RationalPoly& p, RealRoot& root);

/// Exact sign of `q` at `root` of squarefree `p` (refines the root as needed).
int sign_at_root(const RationalPoly& p, RealRoot& root, const RationalPoly& q);

/// A rational lower bound of `root` of squarefree `p` within `tolerance` of it.
mpq_class root_lower_bound(const RationalPoly& p, RealRoot root, const mpq_class& tolerance);

/// One sign condition `poly > 0` (strict) or `poly >= 0`.
struct SignCondition {
  RationalPoly poly;
  bool strict = false;
};

/// Whether a value of sign `sign` (-1, 0, 1) satisfies a condition that is `strict` (> 0)
/// or not (>= 0).
inline bool holds(int sign, bool strict) {
  return strict ? sign > 0 : sign >= 0;
}

/// The infimum of {t in [0, 1] : p(t) = 0 and every condition holds} (p may be the zero
/// polynomial), returned as a rational lower bound within `tolerance` of it; nullopt when
/// the set is empty.
std::optional<mpq_class> earliest_solution(const RationalPoly& p,
                                           const std::vector<SignCondition>& conditions,
                                           const mpq_class& tolerance);

}  // namespace tailor::detail
