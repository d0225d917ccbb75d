#pragma once
/// @file
/// Polynomials in t of degree <= 3 with exact integer coefficients (FixedInt or BigInt),
/// dyadic rationals num / 2^exp, exact signs at dyadic points, pseudo-remainders, and
/// rigorous double (Ball) images for filtering. The building blocks of the exact tier.
/// Internal to the ccd module.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

#include "tailor/ccd/ball.hpp"

namespace tailor::detail {

/// c[0] + c[1] t + ... + c[deg] t^deg with c[deg] != 0; deg = -1 for the zero polynomial.
template <class Z>
struct Poly {
  static constexpr int kMaxDegree = 3;
  Z c[kMaxDegree + 1];
  int deg = -1;
  // Cached ball image of the coefficients (ball_image): midpoints and radii, left
  // uninitialised until then (every Poly is finished before it is first evaluated).
  mutable bool image_ready = false;
  mutable double image_mid[kMaxDegree + 1];
  mutable double image_rad[kMaxDegree + 1];

  Poly() = default;
  /// The constant x.
  explicit Poly(const Z& x) {
    c[0] = x;
    deg = x.is_zero() ? -1 : 0;
  }
  /// x0 + x1 t.
  static Poly linear(const Z& x0, const Z& x1) {
    Poly p;
    p.c[0] = x0;
    p.c[1] = x1;
    p.deg = 1;
    p.trim();
    return p;
  }

  bool is_zero() const { return deg < 0; }
  /// Coefficient i (zero above the degree).
  Z at(int i) const { return i <= deg ? c[i] : Z(); }
  const Z& lead() const { return c[deg]; }
  void trim() {
    while (deg >= 0 && c[deg].is_zero()) --deg;
    image_ready = false;
  }

  friend Poly operator+(const Poly& a, const Poly& b) {
    Poly r;
    r.deg = std::max(a.deg, b.deg);
    for (int i = 0; i <= r.deg; ++i) {
      r.c[i] = i > a.deg ? b.c[i] : (i > b.deg ? a.c[i] : a.c[i] + b.c[i]);
    }
    r.trim();
    return r;
  }
  friend Poly operator-(const Poly& a, const Poly& b) {
    Poly r;
    r.deg = std::max(a.deg, b.deg);
    for (int i = 0; i <= r.deg; ++i) {
      r.c[i] = i > a.deg ? -b.c[i] : (i > b.deg ? a.c[i] : a.c[i] - b.c[i]);
    }
    r.trim();
    return r;
  }
  Poly operator-() const {
    Poly r = *this;
    for (int i = 0; i <= deg; ++i) r.c[i] = -c[i];
    r.image_ready = false;
    return r;
  }
  /// Product; the degrees must add up to at most kMaxDegree.
  friend Poly operator*(const Poly& a, const Poly& b) {
    Poly r;
    if (a.deg < 0 || b.deg < 0) return r;
    assert(a.deg + b.deg <= kMaxDegree);
    r.deg = a.deg + b.deg;
    for (int k = 0; k <= r.deg; ++k) {
      // Coefficient k: the sum of a_i b_(k-i), built once.
      const int lo = std::max(0, k - b.deg), hi = std::min(k, a.deg);
      Z sum = a.c[lo] * b.c[k - lo];
      for (int i = lo + 1; i <= hi; ++i) sum = sum + a.c[i] * b.c[k - i];
      r.c[k] = sum;
    }
    r.trim();
    return r;
  }
  /// x p.
  friend Poly operator*(const Z& x, const Poly& p) {
    Poly r;
    if (x.is_zero()) return r;
    r.deg = p.deg;
    for (int i = 0; i <= p.deg; ++i) r.c[i] = x * p.c[i];
    return r;
  }

  Poly derivative() const {
    Poly r;
    for (int i = 1; i <= deg; ++i) r.c[i - 1] = Z(i) * c[i];
    r.deg = deg - 1 < -1 ? -1 : deg - 1;
    r.trim();
    return r;
  }
};

/// The dyadic rational num / 2^exp (exp >= 0).
template <class Z>
struct Dyadic {
  Z num;
  int exp = 0;

  /// A double in [0, 1] (or any double with a finite binary expansion at exponent <= 0),
  /// exactly.
  static Dyadic from_double(double t) {
    Dyadic d;
    if (t == 0.0) return d;
    int e = 0;
    const double m = std::frexp(std::fabs(t), &e);  // |t| = m 2^e, m in [0.5, 1)
    auto mantissa = static_cast<std::uint64_t>(std::ldexp(m, 53));
    int exponent = 53 - e;  // |t| = mantissa / 2^exponent
    while ((mantissa & 1u) == 0 && exponent > 0) {
      mantissa >>= 1;
      --exponent;
    }
    int shift = 0;
    if (exponent < 0) {
      shift = -exponent;
      exponent = 0;
    }
    d.num = Z::scaled(mantissa, shift, t < 0.0);
    d.exp = exponent;
    return d;
  }
  /// The midpoint of [a, b].
  static Dyadic midpoint(const Dyadic& a, const Dyadic& b) {
    const int e = std::max(a.exp, b.exp);
    Dyadic d;
    d.num = a.num.shifted(e - a.exp) + b.num.shifted(e - b.exp);
    d.exp = e + 1;
    return d;
  }
};

/// The monomial p(x) scaled to an integer: 2^(exp deg) p(num / 2^exp).
template <class Z>
Z scaled_value(const Poly<Z>& p, const Dyadic<Z>& x) {
  if (p.deg < 0) return Z();
  // Horner in homogeneous form: sum c_i num^i 2^(exp (deg - i)).
  Z acc = p.c[p.deg];
  for (int i = p.deg - 1; i >= 0; --i) acc = acc * x.num + p.c[i].shifted(x.exp * (p.deg - i));
  return acc;
}

/// Exact sign of p at the dyadic x.
template <class Z>
int sign_at(const Poly<Z>& p, const Dyadic<Z>& x) {
  return scaled_value(p, x).sign();
}

/// Exact sign of p at the rational num / den (den > 0).
template <class Z>
int sign_at_rational(const Poly<Z>& p, const Z& num, const Z& den) {
  if (p.deg < 0) return 0;
  // sum c_i num^i den^(deg - i), Horner: acc = acc * num + c_i den^(deg - i).
  Z acc = p.c[p.deg];
  Z den_power(1);
  for (int i = p.deg - 1; i >= 0; --i) {
    den_power = den_power * den;
    acc = acc * num + p.c[i] * den_power;
  }
  return acc.sign();
}

/// Pseudo-remainder of a by b (deg b >= 0): lc(b)^k a = q b + r with deg r < deg b, where
/// k = max(deg a - deg b + 1, 0) is stored in `steps`.
template <class Z>
Poly<Z> pseudo_remainder(const Poly<Z>& a, const Poly<Z>& b, int* steps = nullptr) {
  Poly<Z> r = a;
  int k = 0;
  while (r.deg >= b.deg && r.deg >= 0) {
    const int shift = r.deg - b.deg;
    const Z lr = r.lead();
    Poly<Z> next;
    next.deg = r.deg;
    for (int i = 0; i <= r.deg; ++i) next.c[i] = b.lead() * r.c[i];
    for (int j = 0; j <= b.deg; ++j) next.c[j + shift] -= lr * b.c[j];
    next.trim();
    r = next;
    ++k;
  }
  // Make the multiplier exactly lc(b)^(deg a - deg b + 1) so that callers can rely on it.
  const int want = a.deg >= b.deg ? a.deg - b.deg + 1 : 0;
  for (; k < want; ++k) r = b.lead() * r;
  if (steps != nullptr) *steps = want;
  return r;
}

/// A power-of-two scale for p's coefficients: 2^-scale_exponent(p) brings the largest
/// near 1, so the Ball images below neither overflow nor underflow.
template <class Z>
int scale_exponent(const Poly<Z>& p) {
  int best = std::numeric_limits<int>::min();
  for (int i = 0; i <= p.deg; ++i) {
    int e = 0;
    if (p.c[i].is_zero()) continue;
    const double m = p.c[i].approximate(e);
    best = std::max(best, e + std::ilogb(m));
  }
  return best == std::numeric_limits<int>::min() ? 0 : best;
}

/// The coefficient x 2^-shift as a ball (rigorous: the approximation error is at most
/// 2^-52 relative, and ldexp is exact unless it underflows, which eta covers).
template <class Z>
Ball coefficient_ball(const Z& x, int shift) {
  int e = 0;
  const double m = x.approximate(e);
  const double v = std::ldexp(m, e - shift);
  return {v, (std::fabs(v) * 0x1p-51 + kBallEta) * kBallInflate};
}

/// p(t) 2^-shift for t in the ball, in ball arithmetic (Horner).
template <class Z>
Ball evaluate_ball(const Poly<Z>& p, const Ball& t, int shift) {
  if (p.deg < 0) return Ball(0.0);
  Ball acc = coefficient_ball(p.c[p.deg], shift);
  for (int i = p.deg - 1; i >= 0; --i) acc = acc * t + coefficient_ball(p.c[i], shift);
  return acc;
}

/// Fills p's cached ball image: coefficients scaled by 2^-scale_exponent(p), computed
/// once per polynomial (sign tests evaluate the same polynomial at many points).
template <class Z>
void make_ball_image(const Poly<Z>& p) {
  if (p.image_ready) return;
  const int shift = scale_exponent(p);
  for (int i = 0; i <= p.deg; ++i) {
    const Ball b = coefficient_ball(p.c[i], shift);
    p.image_mid[i] = b.m;
    p.image_rad[i] = b.r;
  }
  p.image_ready = true;
}

/// The sign of p on the ball t when certain, else 0 (p's cached ball image, Horner).
template <class Z>
int ball_sign(const Poly<Z>& p, const Ball& t) {
  if (p.deg < 0) return 0;
  make_ball_image(p);
  Ball acc(p.image_mid[p.deg], p.image_rad[p.deg]);
  for (int i = p.deg - 1; i >= 0; --i) acc = acc * t + Ball(p.image_mid[i], p.image_rad[i]);
  return acc.sign();
}

}  // namespace tailor::detail
