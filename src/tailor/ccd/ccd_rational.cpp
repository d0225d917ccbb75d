#include "tailor/ccd/ccd_rational.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "tailor/ccd/ccd_systems.hpp"
#include "tailor/ccd/rational_polynomial.hpp"

namespace tailor::detail {

namespace {

using PV = V3<RationalPoly>;

/// The power of two that makes every coordinate an integer: scaling all positions by a
/// common positive factor scales every polynomial by a positive constant (signs and roots
/// unchanged), and integer coefficients keep the rational arithmetic cheap.
long integer_scale(std::initializer_list<const Vec3*> points) {
  long k = 0;
  for (const Vec3* x : points) {
    for (int i = 0; i < 3; ++i) {
      const double v = (*x)[i];
      if (v == 0.0) continue;
      int e = 0;
      const double m = std::frexp(v, &e);  // v = m 2^e, 0.5 <= |m| < 1
      // m 2^53 is an integer; drop its trailing zero bits.
      auto mi = static_cast<long long>(std::ldexp(m, 53));
      long shift = 53 - e;
      while ((mi & 1) == 0) {
        mi >>= 1;
        --shift;
      }
      k = std::max(k, shift);
    }
  }
  return k;
}

/// The linearly moving point (x0 + t (x1 - x0)) 2^scale, exactly.
PV moving_point(const Vec3& x0, const Vec3& x1, long scale) {
  auto coord = [&](int k) {
    mpq_class a(x0[k]), b(x1[k]);
    mpq_mul_2exp(a.get_mpq_t(), a.get_mpq_t(), static_cast<mp_bitcnt_t>(scale));
    mpq_mul_2exp(b.get_mpq_t(), b.get_mpq_t(), static_cast<mp_bitcnt_t>(scale));
    return RationalPoly::linear(a, b - a);
  };
  return {coord(0), coord(1), coord(2)};
}

void check_finite(std::initializer_list<const Vec3*> points) {
  for (const Vec3* x : points) {
    if (!x->allFinite()) throw std::invalid_argument("ccd: non-finite coordinate");
  }
}

/// 2^-21 < 1e-6 / 2: the lower bounds are within it of the infimum.
const mpq_class& tolerance() {
  static const mpq_class tol(mpz_class(1), mpz_class(1) << 21);
  return tol;
}

/// Earliest t where p lies on the closed segment ab.
std::optional<mpq_class> point_on_segment(const PV& p, const PV& a, const PV& b) {
  const PointSegment<RationalPoly> s = point_segment(p, a, b);
  // The cross product vanishes exactly at the common roots of its three components.
  const RationalPoly common = poly_gcd(poly_gcd(s.cross.x, s.cross.y), s.cross.z);
  return earliest_solution(common, {{s.along, false}, {s.within, false}}, tolerance());
}

/// f (nonzero) vanishes somewhere in [0, 1]: otherwise no branch can hold, and the
/// conditions need not be built.
bool has_root_in_unit(const RationalPoly& f) {
  return f.degree() > 0 && !isolate_roots_unit(squarefree_part(f)).empty();
}

void keep_min(std::optional<mpq_class>& best, const std::optional<mpq_class>& x) {
  if (x && (!best || *x < *best)) best = x;
}

CcdResult to_result(const std::optional<mpq_class>& toi) {
  CcdResult r;
  r.path = CcdPath::exact;
  if (toi) {
    r.hit = true;
    r.toi = toi->get_d();  // truncates toward zero: never later than the bound (>= 0)
  }
  return r;
}

/// Point p on closed segment ab at root r of squarefree fs (f != 0).
bool point_on_segment_at(const RationalPoly& fs, RealRoot& r, const PointSegment<RationalPoly>& s) {
  return sign_at_root(fs, r, s.cross.x) == 0 && sign_at_root(fs, r, s.cross.y) == 0 &&
         sign_at_root(fs, r, s.cross.z) == 0 && sign_at_root(fs, r, s.along) >= 0 &&
         sign_at_root(fs, r, s.within) >= 0;
}

/// f != 0: every contact is at a root of f, so walk its roots in increasing order and stop
/// at the first one where the main system or an endpoint-on-segment branch holds.
/// `main` lists the main system's conditions; `segments(i)` gives branch i (0..n-1).
template <class Segments>
std::optional<mpq_class> first_root_contact(const RationalPoly& f,
                                            const std::vector<SignCondition>& main,
                                            int segment_count, Segments&& segments) {
  const RationalPoly fs = squarefree_part(f);
  std::vector<RealRoot> roots = isolate_roots_unit(fs);
  std::vector<std::optional<PointSegment<RationalPoly>>> cache(segment_count);
  for (RealRoot& r : roots) {
    bool ok = true;
    for (const auto& c : main) {
      if (!holds(sign_at_root(fs, r, c.poly), c.strict)) {
        ok = false;
        break;
      }
    }
    for (int i = 0; !ok && i < segment_count; ++i) {
      if (!cache[i]) cache[i] = segments(i);
      ok = point_on_segment_at(fs, r, *cache[i]);
    }
    if (ok) return root_lower_bound(fs, r, tolerance());
  }
  return std::nullopt;
}

}  // namespace

CcdResult vertex_face_ccd_rational(const VertexFaceQuery& q) {
  check_finite({&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1});
  const long s =
      integer_scale({&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1});
  const PV p = moving_point(q.p_t0, q.p_t1, s), a = moving_point(q.a_t0, q.a_t1, s),
           b = moving_point(q.b_t0, q.b_t1, s), c = moving_point(q.c_t0, q.c_t1, s);
  // Every branch needs f = 0 (p coplanar with the triangle).
  const RationalPoly f = coplanarity(a, b, c, p);
  if (!f.is_zero() && !has_root_in_unit(f)) return to_result({});
  const FaceConditions<RationalPoly> fc = face_conditions(p, a, b, c);
  const std::vector<SignCondition> main{
      {fc.N, true}, {fc.E_ab, false}, {fc.E_bc, false}, {fc.E_ca, false}};
  if (!f.is_zero()) {
    const PV* ends[3][2] = {{&a, &b}, {&b, &c}, {&c, &a}};
    return to_result(first_root_contact(
        f, main, 3, [&](int i) { return point_segment(p, *ends[i][0], *ends[i][1]); }));
  }
  std::optional<mpq_class> best = earliest_solution(f, main, tolerance());
  keep_min(best, point_on_segment(p, a, b));
  keep_min(best, point_on_segment(p, b, c));
  keep_min(best, point_on_segment(p, c, a));
  return to_result(best);
}

CcdResult edge_edge_ccd_rational(const EdgeEdgeQuery& q) {
  check_finite(
      {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1});
  const long s = integer_scale(
      {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1});
  const PV a = moving_point(q.ea0_t0, q.ea0_t1, s), b = moving_point(q.ea1_t0, q.ea1_t1, s),
           c = moving_point(q.eb0_t0, q.eb0_t1, s), d = moving_point(q.eb1_t0, q.eb1_t1, s);
  const RationalPoly f = coplanarity(a, b, c, d);
  if (!f.is_zero() && !has_root_in_unit(f)) return to_result({});
  const EdgeConditions<RationalPoly> ec = edge_conditions(a, b, c, d);
  const std::vector<SignCondition> main{
      {ec.M, true}, {ec.S_, false}, {ec.M_minus_S, false}, {ec.U, false}, {ec.M_minus_U, false}};
  if (!f.is_zero()) {
    // Endpoint on the other segment: a and b on cd, c and d on ab.
    const PV* cases[4][3] = {{&a, &c, &d}, {&b, &c, &d}, {&c, &a, &b}, {&d, &a, &b}};
    return to_result(first_root_contact(f, main, 4, [&](int i) {
      return point_segment(*cases[i][0], *cases[i][1], *cases[i][2]);
    }));
  }
  std::optional<mpq_class> best = earliest_solution(f, main, tolerance());
  keep_min(best, point_on_segment(a, c, d));
  keep_min(best, point_on_segment(b, c, d));
  keep_min(best, point_on_segment(c, a, b));
  keep_min(best, point_on_segment(d, a, b));
  return to_result(best);
}

}  // namespace tailor::detail
