#pragma once
/// @file
/// Real algebraic numbers of degree <= 3 as the exact tier meets them, and exact signs of
/// integer polynomials at them. Internal to the ccd module.
///
/// A RootPoint is one of
/// - rational: num / den exactly (t = 0, t = 1, dyadic split points, the multiple roots
///   of a cubic, which are always rational);
/// - quadratic: a root (-B ± sqrt(D)) / 2A of an integer quadratic with D > 0;
/// - isolated: the only root of a squarefree integer polynomial P in an open dyadic
///   interval (lo, hi) whose ends are not roots.
/// Every point also carries a certified double enclosure [enc_lo, enc_hi].
///
/// sign_at(q, r) first evaluates q on the enclosure in ball arithmetic; only when that
/// cannot decide does it use exact integer arguments:
/// - rational: the homogenised value of q;
/// - quadratic: q mod the quadratic is alpha t + beta, whose sign at the root is that of
///   X + Y sqrt(D) with integers X, Y (compare X^2 with Y^2 D);
/// - isolated: q(r) = 0 iff r is a root of G = gcd(P, q) (a pseudo-remainder chain); as
///   G's roots are simple roots of P and (lo, hi) holds only r, that is iff G changes sign
///   on (lo, hi). Otherwise q(r) != 0 and narrowing (lo, hi) (exact signs of P at dyadic
///   points) eventually separates r from the roots of q, where the ball test succeeds or
///   q's Bernstein coefficients on [lo, hi] share one strict sign.

#include <cmath>
#include <limits>
#include <utility>

#include "tailor/ccd/ball.hpp"
#include "tailor/geometry/fixed_int.hpp"
#include "tailor/ccd/int_poly.hpp"

namespace tailor::detail {

/// Sign of a - b for dyadics.
template <class Z>
int compare(const Dyadic<Z>& a, const Dyadic<Z>& b) {
  const int e = std::max(a.exp, b.exp);
  return compare(a.num.shifted(e - a.exp), b.num.shifted(e - b.exp));
}

/// A double <= the dyadic value (rigorous; the approximation is 2^-52 relative).
template <class Z>
double dyadic_down(const Dyadic<Z>& x) {
  int e = 0;
  const double m = x.num.approximate(e);
  const double v = std::ldexp(m, e - x.exp);
  return v - (std::fabs(v) * 0x1p-50 + kBallEta);
}

/// A double >= the dyadic value.
template <class Z>
double dyadic_up(const Dyadic<Z>& x) {
  int e = 0;
  const double m = x.num.approximate(e);
  const double v = std::ldexp(m, e - x.exp);
  return v + (std::fabs(v) * 0x1p-50 + kBallEta);
}

/// Sign of X + Y sqrt(D) for D > 0.
template <class Z>
int sign_with_root(const Z& X, const Z& Y, const Z& D) {
  const int sx = X.sign(), sy = Y.sign();
  if (sy == 0) return sx;
  if (sx == 0 || sx == sy) return sy;
  const int c = compare(X * X, Y * Y * D);
  return c > 0 ? sx : (c < 0 ? sy : 0);
}

template <class Z>
struct RootPoint {
  enum class Kind : unsigned char { rational, quadratic, isolated };
  Kind kind = Kind::rational;
  Z num, den;        ///< rational: num / den, den > 0
  Poly<Z> poly;      ///< quadratic: A t^2 + B t + C with D > 0; isolated: squarefree P
  Z discriminant;    ///< quadratic: D = B^2 - 4AC
  int sigma = 1;     ///< quadratic: the root is (-B + sigma sqrt(D)) / 2A
  Dyadic<Z> lo, hi;  ///< isolated: the open isolating interval
  int sign_lo = 0;   ///< isolated: sign of P at lo (P at hi has the opposite sign)
  double enc_lo = -std::numeric_limits<double>::infinity();  ///< certified lower end
  double enc_hi = std::numeric_limits<double>::infinity();   ///< certified upper end

  static RootPoint rational(const Z& n, const Z& d) {
    RootPoint r;
    r.kind = Kind::rational;
    r.num = d.sign() < 0 ? -n : n;
    r.den = d.sign() < 0 ? -d : d;
    r.enclose_rational();
    return r;
  }
  static RootPoint dyadic(const Dyadic<Z>& x) { return rational(x.num, Z(1).shifted(x.exp)); }

  /// The smaller (`larger` false) or larger root of the quadratic g (degree 2, D > 0).
  static RootPoint quadratic(const Poly<Z>& g, const Z& D, bool larger) {
    RootPoint r;
    r.kind = Kind::quadratic;
    r.poly = g;
    r.discriminant = D;
    const int sa = g.c[2].sign();
    r.sigma = larger ? sa : -sa;
    r.enclose_quadratic();
    return r;
  }

  /// The root of squarefree p in (lo, hi) (p changes sign there and has no other root).
  static RootPoint isolated(const Poly<Z>& p, const Dyadic<Z>& lo, const Dyadic<Z>& hi,
                            int sign_lo) {
    RootPoint r;
    r.kind = Kind::isolated;
    r.poly = p;
    r.lo = lo;
    r.hi = hi;
    r.sign_lo = sign_lo;
    r.set_isolated_ends();
    return r;
  }

  /// Intersects the enclosure with [0, 1]; only for points known to lie in [0, 1].
  void clamp_to_unit() {
    enc_lo = std::fmax(enc_lo, 0.0);
    enc_hi = std::fmin(enc_hi, 1.0);
    if (!(enc_lo <= enc_hi)) {
      enc_lo = 0.0;
      enc_hi = 1.0;
    }
  }

  /// Sign of (this - x), exactly.
  int compare_to(const Dyadic<Z>& x) const {
    switch (kind) {
      case Kind::rational:
        // num / den - xn / 2^e  ~  num 2^e - xn den.
        return compare(num.shifted(x.exp), x.num * den);
      case Kind::quadratic: {
        // (-B + s sqrt(D)) / 2A - xn / 2^e = (-B 2^e - 2A xn + s 2^e sqrt(D)) / (2A 2^e).
        const Z X = -(poly.c[1].shifted(x.exp)) - (poly.c[2] * x.num).shifted(1);
        const Z Y = Z(sigma).shifted(x.exp);
        return poly.c[2].sign() * sign_with_root(X, Y, discriminant);
      }
      case Kind::isolated:
        if (compare(x, lo) <= 0) return 1;
        if (compare(x, hi) >= 0) return -1;
        {
          const int s = sign_at(poly, x);
          if (s == 0) return 0;
          return s == sign_lo ? 1 : -1;  // x is left of the root iff p has lo's sign there
        }
    }
    return 0;
  }

  /// Narrows the enclosure towards `width` (an isolated root narrows its interval; a
  /// dyadic point that hits the root makes the point rational). Stops early when double
  /// resolution is exhausted.
  void tighten(double width) {
    for (int guard = 0; enc_hi - enc_lo > width && guard < 200; ++guard) {
      const double before = enc_hi - enc_lo;
      if (kind == Kind::isolated) {
        if (!newton_step(width)) bisect_exact();
      } else {
        // Bisect the enclosure with exact comparisons.
        const double mid = 0.5 * enc_lo + 0.5 * enc_hi;
        if (!(mid > enc_lo && mid < enc_hi)) return;  // adjacent doubles (or unbounded)
        const int c = compare_to(Dyadic<Z>::from_double(mid));
        if (c == 0) {
          enc_lo = enc_hi = mid;
        } else if (c > 0) {
          enc_lo = mid;
        } else {
          enc_hi = mid;
        }
      }
      if (kind == Kind::isolated && !(enc_hi - enc_lo < before)) return;
    }
  }

  /// One exact bisection of an isolated root's interval (it may become rational).
  void bisect_exact() {
    const Dyadic<Z> mid = Dyadic<Z>::midpoint(lo, hi);
    const int s = sign_at(poly, mid);
    if (s == 0) {
      *this = dyadic(mid);
      return;
    }
    if (s == sign_lo) {
      lo = mid;
    } else {
      hi = mid;
    }
    set_isolated_ends();
  }

 private:
  void enclose_rational() {
    int en = 0, ed = 0;
    const double mn = num.approximate(en), md = den.approximate(ed);
    const double v = std::ldexp(mn / md, en - ed);
    const double margin = std::fabs(v) * 0x1p-49 + kBallEta;
    enc_lo = v - margin;
    enc_hi = v + margin;
    if (num.is_zero()) enc_lo = enc_hi = 0.0;
  }

  /// Ball evaluation of (-B + sigma sqrt(D)) / 2A; when the balls cannot decide, the
  /// enclosure stays [-inf, inf] (see clamp_to_unit).
  void enclose_quadratic() {
    const int shift = scale_exponent(poly);
    const Ball A = coefficient_ball(poly.c[2], shift), B = coefficient_ball(poly.c[1], shift),
               C = coefficient_ball(poly.c[0], shift);
    const Ball D = B * B - Ball(4.0) * A * C;
    const double dlo = ball_lower(D), dhi = ball_upper(D);
    const Ball two_a = Ball(2.0) * A;
    if (!(dlo > 0.0) || !std::isfinite(dhi) || !two_a.nonzero()) return;
    const Ball root_d =
        ball_hull(std::sqrt(dlo) * (1.0 - 0x1p-50), std::sqrt(dhi) * (1.0 + 0x1p-50));
    const Ball numer = sigma > 0 ? root_d - B : -(B + root_d);
    // numer / two_a with two_a of one strict sign: the extreme quotients of the ends.
    const double nl = ball_lower(numer), nh = ball_upper(numer);
    const double al = ball_lower(two_a), ah = ball_upper(two_a);
    const double q[4] = {nl / al, nl / ah, nh / al, nh / ah};
    double lo_v = q[0], hi_v = q[0];
    for (double x : q) {
      lo_v = std::fmin(lo_v, x);
      hi_v = std::fmax(hi_v, x);
    }
    if (!std::isfinite(lo_v) || !std::isfinite(hi_v)) return;
    enc_lo = lo_v - (std::fabs(lo_v) * 0x1p-50 + kBallEta);
    enc_hi = hi_v + (std::fabs(hi_v) * 0x1p-50 + kBallEta);
  }

  void set_isolated_ends() {
    enc_lo = dyadic_down(lo);
    enc_hi = dyadic_up(hi);
    m_lo_up = dyadic_up(lo);
    m_hi_down = dyadic_down(hi);
  }

  /// Newton in double from the middle of the enclosure, then an exact check of a small
  /// bracket around the estimate; false when the bracket does not verify.
  bool newton_step(double width) {
    make_ball_image(poly);  // the coefficients in double (scaled): enough for Newton
    const double* coeff = poly.image_mid;
    auto value = [&](double t) {
      double v = 0.0;
      for (int i = poly.deg; i >= 0; --i) v = v * t + coeff[i];
      return v;
    };
    auto slope = [&](double t) {
      double v = 0.0;
      for (int i = poly.deg; i >= 1; --i) v = v * t + i * coeff[i];
      return v;
    };
    const double a = std::fmax(enc_lo, 0.0), b = std::fmin(enc_hi, 1.0);
    double t = 0.5 * (a + b);
    for (int i = 0; i < 8; ++i) {
      const double d = slope(t);
      if (!(d != 0.0)) break;
      const double next = t - value(t) / d;
      if (!(next >= a && next <= b)) break;
      if (next == t) break;
      t = next;
    }
    const double delta = std::fmax(width * 0.25, std::fabs(t) * 0x1p-50 + 0x1p-1000);
    bool moved = false;
    for (const double x : {t - delta, t + delta}) {
      // Inside (lo, hi)? The doubles around the ends decide unless x is that close.
      bool inside = x > m_lo_up && x < m_hi_down;
      const bool outside = x <= enc_lo || x >= enc_hi;
      const Dyadic<Z> d = Dyadic<Z>::from_double(x);
      if (!inside && !outside) inside = compare(d, lo) > 0 && compare(d, hi) < 0;
      if (!inside) continue;
      const int s = sign_at(poly, d);
      if (s == 0) {
        *this = dyadic(d);
        return true;
      }
      (s == sign_lo ? lo : hi) = d;
      moved = true;
      set_isolated_ends();
    }
    return moved;
  }

  double m_lo_up = 0.0, m_hi_down = 0.0;  ///< isolated: doubles >= lo and <= hi
};

/// Exact sign of q at r.
template <class Z>
int sign_at(const Poly<Z>& q, RootPoint<Z>& r);

namespace algebraic_detail {

/// Bernstein coefficients of q (degree <= 3) on [lo, hi] all of one strict sign: that sign,
/// else 0.
template <class Z>
int bernstein_sign(const Poly<Z>& q, const Dyadic<Z>& lo, const Dyadic<Z>& hi) {
  // Common exponent e: lo = L / 2^e, hi = H / 2^e, w = H - L; x = (L + w s) / 2^e.
  const int e = std::max(lo.exp, hi.exp);
  const Z L = lo.num.shifted(e - lo.exp), W = hi.num.shifted(e - hi.exp) - L;
  const int d = q.deg;
  // a_j: monomial coefficients in s of 2^(e d) q((L + W s) / 2^e).
  Z a[4];
  for (int i = 0; i <= d; ++i) {
    // c_i 2^(e (d - i)) (L + W s)^i = c_i 2^(e(d-i)) sum_j C(i, j) L^(i-j) W^j s^j.
    const Z ci = q.c[i].shifted(e * (d - i));
    Z lpow[4] = {Z(1), L, L * L, Z()};
    if (i == 3) lpow[3] = lpow[2] * L;
    Z wpow(1);
    for (int j = 0; j <= i; ++j) {
      static constexpr int kBinom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
      a[j] += ci * Z(kBinom[i][j]) * lpow[i - j] * wpow;
      wpow = wpow * W;
    }
  }
  // 6 b_k = sum_{j <= k} 6 C(k, j) / C(d, j) a_j (integers for d <= 3).
  static constexpr int kBinom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  int common = 0;
  for (int k = 0; k <= d; ++k) {
    Z b;
    for (int j = 0; j <= k; ++j) b += Z(6 * kBinom[k][j] / kBinom[d][j]) * a[j];
    const int s = b.sign();
    if (s == 0) return 0;
    if (k == 0) {
      common = s;
    } else if (s != common) {
      return 0;
    }
  }
  return common;
}

/// gcd(p, q) up to a constant factor, by pseudo-remainders (degrees <= 3).
template <class Z>
Poly<Z> gcd(Poly<Z> a, Poly<Z> b) {
  if (a.deg < b.deg) std::swap(a, b);
  while (!b.is_zero()) {
    if (b.deg == 0) return b;  // a nonzero constant divides everything: gcd 1
    Poly<Z> r = pseudo_remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

}  // namespace algebraic_detail

template <class Z>
int sign_at(const Poly<Z>& q, RootPoint<Z>& r) {
  using Kind = typename RootPoint<Z>::Kind;
  if (q.deg < 0) return 0;
  if (q.deg == 0) return q.c[0].sign();
  // Filter: q on the enclosure in ball arithmetic.
  auto ball_sign = [&]() {
    if (!(r.enc_lo <= r.enc_hi) || !std::isfinite(r.enc_lo) || !std::isfinite(r.enc_hi)) return 0;
    return detail::ball_sign(q, ball_hull(r.enc_lo, r.enc_hi));
  };
  if (const int s = ball_sign()) return s;
  switch (r.kind) {
    case Kind::rational:
      return sign_at_rational(q, r.num, r.den);
    case Kind::quadratic: {
      // g_2^k q = Q g + R with R = alpha t + beta; q(r) has the sign of R(r) sign(g_2)^k.
      int steps = 0;
      const Poly<Z> rem = pseudo_remainder(q, r.poly, &steps);
      const int factor = (steps % 2 == 1) ? r.poly.c[2].sign() : 1;
      // alpha r + beta = (X + Y sqrt(D)) / 2A with X = 2A beta - alpha B, Y = sigma alpha.
      const Z alpha = rem.at(1), beta = rem.at(0);
      const Z X = (r.poly.c[2] * beta).shifted(1) - alpha * r.poly.c[1];
      const Z Y = r.sigma > 0 ? alpha : -alpha;
      return factor * r.poly.c[2].sign() * sign_with_root(X, Y, r.discriminant);
    }
    case Kind::isolated: {
      // Most nonzero values separate once the root is known to ~2^-44: narrow first
      // (shared by every later condition at this root), and only then test for zero.
      if (r.enc_hi - r.enc_lo > 0x1p-40) {
        r.tighten(0x1p-44);
        if (r.kind != Kind::isolated) return sign_at(q, r);
        if (const int s = ball_sign()) return s;
      }
      const Poly<Z> g = algebraic_detail::gcd(r.poly, q);
      if (g.deg >= 1 && sign_at(g, r.lo) * sign_at(g, r.hi) < 0) return 0;
      // q(r) != 0: narrow until the ball test decides; once double resolution is
      // exhausted, bisect exactly and test q's Bernstein signs on [lo, hi].
      for (int round = 0; round < 4000; ++round) {
        if (r.kind != Kind::isolated) return sign_at(q, r);  // became rational
        if (const int s = ball_sign()) return s;
        const double before = r.enc_hi - r.enc_lo;
        r.tighten(before * 0x1p-16);
        if (r.kind != Kind::isolated) continue;
        if (r.enc_hi - r.enc_lo < before) continue;
        if (const int s = algebraic_detail::bernstein_sign(q, r.lo, r.hi)) return s;
        r.bisect_exact();
      }
      throw CapacityExceeded{};  // unreachable for exact integers; keeps the loop bounded
    }
  }
  return 0;
}

/// True iff q(r) = 0, for an isolated root r (gcd test only, no narrowing): the cheap
/// exact check for a value the ball test could not separate from zero.
template <class Z>
bool vanishes_at_isolated(const Poly<Z>& q, const RootPoint<Z>& r) {
  if (q.deg <= 0) return q.deg < 0;
  const Poly<Z> g = algebraic_detail::gcd(r.poly, q);
  return g.deg >= 1 && sign_at(g, r.lo) * sign_at(g, r.hi) < 0;
}

/// Sign of q just right of r (q's first nonvanishing derivative at r).
template <class Z>
int right_sign(const Poly<Z>& q, RootPoint<Z>& r) {
  Poly<Z> d = q;
  while (d.deg >= 0) {
    if (const int s = sign_at(d, r)) return s;
    d = d.derivative();
  }
  return 0;
}

/// A double within 2^-22 below r, for r in [0, 1] (then >= 0): the time of impact of a
/// contact at r.
template <class Z>
double lower_bound(RootPoint<Z>& r) {
  r.clamp_to_unit();
  r.tighten(0x1p-22);
  if (r.enc_hi - r.enc_lo > 0x1p-22) {
    // Double resolution near r is finer than that, so this only happens to a point whose
    // enclosure could not shrink; bisecting its exact representation always can.
    for (int i = 0; i < 200 && r.enc_hi - r.enc_lo > 0x1p-22; ++i) {
      if (r.kind == RootPoint<Z>::Kind::isolated) {
        r.bisect_exact();
      } else {
        break;
      }
    }
  }
  return std::fmax(r.enc_lo, 0.0);
}

}  // namespace tailor::detail
