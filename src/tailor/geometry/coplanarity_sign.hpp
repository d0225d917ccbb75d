#pragma once
/// @file
/// The non-coplanarity (DNF) filter of Tang, Manocha & Tong 2010 (docs/design.md §3), with a
/// certified floating-point error bound and an exact fallback: no epsilon.
///
/// The coplanarity function f(t) = det(b-a, c-a, d-a)(t) is trilinear in the three
/// (linearly moving) difference vectors u = b-a, v = c-a, w = d-a, so its cubic Bernstein
/// coefficients are the blossom values
///   β0 = det(u0,v0,w0),  β3 = det(u1,v1,w1),
///   3β1 = det(u1,v0,w0) + det(u0,v1,w0) + det(u0,v0,w1),
///   3β2 = det(u0,v1,w1) + det(u1,v0,w1) + det(u1,v1,w0)
/// (equal to A, (2C+F)/3, (2D+E)/3, B of docs/design.md §3). Each is evaluated in double with
/// the forward error bound 16·2^-53·(the same expression on absolute values), valid when
/// every nonzero difference lies in [2^-250, 2^250] (no overflow or underflow); otherwise,
/// or when the bound cannot decide a sign, that sign is computed exactly: in 2048-bit
/// stack integers (geometry/fixed_int.hpp) after a power-of-two scaling, or in GMP
/// rationals when the coordinates span more bits than a product of three differences can
/// hold there (a subnormal beside large values).

#include <array>
#include <cmath>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Sign of the coplanarity function f(t) = n(t)·(d(t) - a(t)) over the whole step,
/// n(t) = (b(t)-a(t)) × (c(t)-a(t)), established from its Bernstein coefficients.
enum class StepSign : signed char {
  negative = -1,  ///< f < 0 for every t in [0, 1]
  mixed = 0,      ///< the coefficients do not all share one strict sign: f may vanish
  positive = 1,   ///< f > 0 for every t in [0, 1]
};

namespace detail {

/// Exact sign (-1, 0, 1) of the Bernstein coefficient `index` (0..3) of f, up to the
/// positive factor 3 for indices 1 and 2. Slow path (stack integers, GMP only for extreme
/// exponent spreads); defined in the .cpp.
int coplanarity_coefficient_sign_exact(int index, const FourPoints& at_t0, const FourPoints& at_t1);

/// The four Bernstein coefficients of f in double, `value[i]` (times 3 for i = 1, 2), each
/// with a certified bound `bound[i]` on its absolute error. Returns false (and leaves the
/// outputs unspecified) when an input difference is out of the guarded range or not
/// finite; then the bound does not hold and the caller must use exact arithmetic.
inline bool coplanarity_bernstein_double(const FourPoints& at_t0, const FourPoints& at_t1,
                                         double value[4], double bound[4]) {
  const Vec3 &a_t0 = at_t0[0], &b_t0 = at_t0[1], &c_t0 = at_t0[2], &d_t0 = at_t0[3];
  const Vec3 &a_t1 = at_t1[0], &b_t1 = at_t1[1], &c_t1 = at_t1[2], &d_t1 = at_t1[3];
  // The 18 differences; one rounding each.
  double u0[3], v0[3], w0[3], u1[3], v1[3], w1[3];
  for (int k = 0; k < 3; ++k) {
    u0[k] = b_t0[k] - a_t0[k];
    v0[k] = c_t0[k] - a_t0[k];
    w0[k] = d_t0[k] - a_t0[k];
    u1[k] = b_t1[k] - a_t1[k];
    v1[k] = c_t1[k] - a_t1[k];
    w1[k] = d_t1[k] - a_t1[k];
  }
  // Range guard: nonzero differences in [2^-250, 2^250] keep every product of three
  // normal and finite, so the relative error model holds (NaN fails the guard too).
  constexpr double kLo = 0x1p-250, kHi = 0x1p250;
  bool in_range = true;
  const double* all[6] = {u0, v0, w0, u1, v1, w1};
  for (const double* x : all) {
    for (int k = 0; k < 3; ++k) {
      const double m = std::fabs(x[k]);
      in_range &= (m == 0.0) | ((m >= kLo) & (m <= kHi));
    }
  }
  if (!in_range) return false;

  auto cross = [](const double* p, const double* q, double* r) {
    r[0] = p[1] * q[2] - p[2] * q[1];
    r[1] = p[2] * q[0] - p[0] * q[2];
    r[2] = p[0] * q[1] - p[1] * q[0];
  };
  auto cross_abs = [](const double* p, const double* q, double* r) {
    r[0] = std::fabs(p[1] * q[2]) + std::fabs(p[2] * q[1]);
    r[1] = std::fabs(p[2] * q[0]) + std::fabs(p[0] * q[2]);
    r[2] = std::fabs(p[0] * q[1]) + std::fabs(p[1] * q[0]);
  };
  auto dot = [](const double* p, const double* q) {
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  };
  auto dot_abs = [](const double* p, const double* q) {
    return std::fabs(p[0]) * q[0] + std::fabs(p[1]) * q[1] + std::fabs(p[2]) * q[2];
  };
  double c00[3], c11[3], c01[3], c10[3];  // v_i × w_j
  cross(v0, w0, c00);
  cross(v1, w1, c11);
  cross(v0, w1, c01);
  cross(v1, w0, c10);
  double m00[3], m11[3], m01[3], m10[3];
  cross_abs(v0, w0, m00);
  cross_abs(v1, w1, m11);
  cross_abs(v0, w1, m01);
  cross_abs(v1, w0, m10);
  value[0] = dot(u0, c00);
  value[1] = dot(u1, c00) + dot(u0, c10) + dot(u0, c01);
  value[2] = dot(u0, c11) + dot(u1, c01) + dot(u1, c10);
  value[3] = dot(u1, c11);
  // At most 10 roundings along any term: |error| <= (10u + O(u^2)) * magnitude < 16u *
  // magnitude (u = 2^-53); 16u * magnitude is computed exactly (a power-of-two scaling of
  // a normal number). A zero magnitude means every term is exactly zero.
  bound[0] = 0x1p-49 * dot_abs(u0, m00);
  bound[1] = 0x1p-49 * (dot_abs(u1, m00) + dot_abs(u0, m10) + dot_abs(u0, m01));
  bound[2] = 0x1p-49 * (dot_abs(u0, m11) + dot_abs(u1, m01) + dot_abs(u1, m10));
  bound[3] = 0x1p-49 * dot_abs(u1, m11);
  return true;
}

/// Certified signs of the four Bernstein coefficients of f in double: each entry is -1,
/// 0 (exactly zero) or 1 when certain, 2 when the error bound cannot decide.
inline std::array<int, 4> coplanarity_coefficient_signs_double(const FourPoints& at_t0,
                                                               const FourPoints& at_t1) {
  double value[4], bound[4];
  if (!coplanarity_bernstein_double(at_t0, at_t1, value, bound)) {
    return {2, 2, 2, 2};
  }
  std::array<int, 4> sign{};
  for (int i = 0; i < 4; ++i) {
    if (bound[i] == 0.0) {
      sign[i] = 0;
    } else if (value[i] > bound[i]) {
      sign[i] = 1;
    } else if (value[i] < -bound[i]) {
      sign[i] = -1;
    } else {
      sign[i] = 2;
    }
  }
  return sign;
}

}  // namespace detail

/// Bernstein sign test of f over [0, 1] for points a, b, c, d moving linearly.
/// The answer is exact: positive/negative only when all four Bernstein coefficients are
/// strictly of that sign in exact arithmetic.
inline StepSign coplanarity_sign(const FourPoints& at_t0, const FourPoints& at_t1) {
  std::array<int, 4> s = detail::coplanarity_coefficient_signs_double(at_t0, at_t1);
  // Two certain opposite signs, or a certain zero, decide "mixed" without exact work.
  bool has_pos = false, has_neg = false, has_zero = false, has_unknown = false;
  for (int x : s) {
    has_pos |= x == 1;
    has_neg |= x == -1;
    has_zero |= x == 0;
    has_unknown |= x == 2;
  }
  if ((has_pos && has_neg) || has_zero) return StepSign::mixed;
  if (has_unknown) {
    for (int i = 0; i < 4; ++i) {
      if (s[i] != 2) continue;
      s[i] = detail::coplanarity_coefficient_sign_exact(i, at_t0, at_t1);
      if (s[i] == 0) return StepSign::mixed;
      has_pos |= s[i] == 1;
      has_neg |= s[i] == -1;
      if (has_pos && has_neg) return StepSign::mixed;
    }
  }
  return has_pos ? StepSign::positive : StepSign::negative;
}

/// True when the four points may become coplanar during the step (the pair survives the
/// filter); false when they certainly never do.
inline bool may_become_coplanar(const FourPoints& at_t0, const FourPoints& at_t1) {
  return coplanarity_sign(at_t0, at_t1) == StepSign::mixed;
}

}  // namespace tailor
