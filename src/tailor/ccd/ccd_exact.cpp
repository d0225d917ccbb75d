#include "tailor/ccd/ccd_exact.hpp"

#include <gmpxx.h>

#include <optional>
#include <stdexcept>
#include <vector>

#include "tailor/ccd/ccd_systems.hpp"
#include "tailor/ccd/exact_polynomial.hpp"

namespace tailor::detail {

namespace {

using PV = V3<ExactPoly>;

/// The linearly moving point x0 + t (x1 - x0), exactly.
PV moving_point(const Vec3& x0, const Vec3& x1) {
  auto coord = [&](int k) {
    const mpq_class a(x0[k]), b(x1[k]);
    return ExactPoly::linear(a, b - a);
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
  const PointSegment<ExactPoly> s = point_segment(p, a, b);
  // The cross product vanishes exactly at the common roots of its three components.
  const ExactPoly common = poly_gcd(poly_gcd(s.cross.x, s.cross.y), s.cross.z);
  return earliest_solution(common, {{s.along, false}, {s.within, false}}, tolerance());
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

}  // namespace

CcdResult vertex_face_ccd_exact(const VertexFaceQuery& q) {
  check_finite({&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1});
  const PV p = moving_point(q.p_t0, q.p_t1), a = moving_point(q.a_t0, q.a_t1),
           b = moving_point(q.b_t0, q.b_t1), c = moving_point(q.c_t0, q.c_t1);
  const ExactPoly f = coplanarity(a, b, c, p);
  // Every branch needs f = 0: a nonzero f without a root in [0, 1] means no contact.
  if (!f.is_zero() && isolate_roots_unit(squarefree_part(f)).empty()) return to_result({});
  const FaceConditions<ExactPoly> fc = face_conditions(p, a, b, c);
  std::optional<mpq_class> best = earliest_solution(
      f, {{fc.N, true}, {fc.E_ab, false}, {fc.E_bc, false}, {fc.E_ca, false}}, tolerance());
  keep_min(best, point_on_segment(p, a, b));
  keep_min(best, point_on_segment(p, b, c));
  keep_min(best, point_on_segment(p, c, a));
  return to_result(best);
}

CcdResult edge_edge_ccd_exact(const EdgeEdgeQuery& q) {
  check_finite({&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1,
                &q.eb1_t1});
  const PV a = moving_point(q.ea0_t0, q.ea0_t1), b = moving_point(q.ea1_t0, q.ea1_t1),
           c = moving_point(q.eb0_t0, q.eb0_t1), d = moving_point(q.eb1_t0, q.eb1_t1);
  const ExactPoly f = coplanarity(a, b, c, d);
  if (!f.is_zero() && isolate_roots_unit(squarefree_part(f)).empty()) return to_result({});
  const EdgeConditions<ExactPoly> ec = edge_conditions(a, b, c, d);
  std::optional<mpq_class> best = earliest_solution(
      f,
      {{ec.M, true}, {ec.S_, false}, {ec.M_minus_S, false}, {ec.U, false}, {ec.M_minus_U, false}},
      tolerance());
  keep_min(best, point_on_segment(a, c, d));
  keep_min(best, point_on_segment(b, c, d));
  keep_min(best, point_on_segment(c, a, b));
  keep_min(best, point_on_segment(d, a, b));
  return to_result(best);
}

}  // namespace tailor::detail
