#include "tailor/candidates/projection_filter.hpp"

#include <cmath>

#include "tailor/candidates/projection_polynomials.hpp"

namespace tailor {
namespace {

using namespace projection;

// The projection filter for VF, given the coplanarity cubic.
bool vertex_face_apart(const Vec3& p_t0, const Vec3& a_t0, const Vec3& b_t0, const Vec3& c_t0,
                       const Vec3& p_t1, const Vec3& a_t1, const Vec3& b_t1, const Vec3& c_t1,
                       const Cubic& f) {
  const Moving ab = difference(b_t0, a_t0, b_t1, a_t1);
  const Moving bc = difference(c_t0, b_t0, c_t1, b_t1);
  const Moving ac = difference(c_t0, a_t0, c_t1, a_t1);
  const Moving ap = difference(p_t0, a_t0, p_t1, a_t1);
  const Moving bp = difference(p_t0, b_t0, p_t1, b_t1);
  const Moving cp = difference(p_t0, c_t0, p_t1, c_t1);
  // ab, ac, ap passed the cubic's range check.
  if (!in_range(bc) || !in_range(bp) || !in_range(cp)) return false;
  const int d = direction(ab, ac);
  if (d < 0) return false;
  VertexFacePolynomials poly;
  poly.f = f;
  poly.s[0] = bracket(ab, ap, d);
  poly.s[1] = bracket(bc, bp, d);
  poly.s[2] = bracket(negated(ac), cp, d);
  poly.o = bracket(ab, ac, d);
  return excluded_everywhere(poly);
}

// The projection filter for EE, given the coplanarity cubic.
bool edge_edge_apart(const Vec3& a_t0, const Vec3& b_t0, const Vec3& c_t0, const Vec3& d_t0,
                     const Vec3& a_t1, const Vec3& b_t1, const Vec3& c_t1, const Vec3& d_t1,
                     const Cubic& f) {
  const Moving ab = difference(b_t0, a_t0, b_t1, a_t1);
  const Moving cd = difference(d_t0, c_t0, d_t1, c_t1);
  const Moving ac = difference(c_t0, a_t0, c_t1, a_t1);
  const Moving ad = difference(d_t0, a_t0, d_t1, a_t1);
  const Moving cb = difference(b_t0, c_t0, b_t1, c_t1);
  // ab, ac, ad passed the cubic's range check.
  if (!in_range(cd) || !in_range(cb)) return false;
  // Parallel edges: the normal of the plane through ab and c instead (zero if collinear).
  int d = direction(ab, cd);
  if (d < 0) d = direction(ab, ac);
  if (d < 0) return false;
  EdgeEdgePolynomials poly;
  poly.f = f;
  poly.g_c = bracket(ab, ac, d);
  poly.g_d = bracket(ab, ad, d);
  poly.h_a = bracket(cd, negated(ac), d);
  poly.h_b = bracket(cd, cb, d);
  poly.m = bracket(ab, cd, d);
  return excluded_everywhere(poly);
}

// The order of the tests: the cheap certified ones first (the DNF's Bernstein signs in
// double, then the projection filter); the exact evaluation of the DNF (GMP) only for
// pairs that neither settles, which are rare except in exactly degenerate meshes.
template <class Apart, class ExactSign>
PairVerdict verdict(bool f_ok, const Cubic& f, bool undecided, PairFilters filters,
                    const Apart& apart, const ExactSign& exact_sign) {
  if (filters.coplanarity && f_ok && f.sign() != 0) return PairVerdict::never_coplanar;
  if (filters.projection && f_ok && apart()) return PairVerdict::apart_in_projection;
  if (filters.coplanarity && (!f_ok || undecided) && exact_sign() != StepSign::mixed) {
    return PairVerdict::never_coplanar;
  }
  return PairVerdict::may_touch;
}

}  // namespace

PairVerdict vertex_face_verdict(const FourPoints& at_t0, const FourPoints& at_t1,
                                PairFilters filters) {
  const Vec3 &p_t0 = at_t0[0], &a_t0 = at_t0[1], &b_t0 = at_t0[2], &c_t0 = at_t0[3];
  const Vec3 &p_t1 = at_t1[0], &a_t1 = at_t1[1], &b_t1 = at_t1[2], &c_t1 = at_t1[3];
  Cubic f;
  bool undecided = true;
  const bool f_ok =
      coplanarity_cubic({a_t0, b_t0, c_t0, p_t0}, {a_t1, b_t1, c_t1, p_t1}, f, undecided);
  return verdict(
      f_ok, f, undecided, filters,
      [&] { return vertex_face_apart(p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1, f); },
      [&] {
        return coplanarity_sign({a_t0, b_t0, c_t0, p_t0}, {a_t1, b_t1, c_t1, p_t1});
      });
}

PairVerdict edge_edge_verdict(const FourPoints& at_t0, const FourPoints& at_t1,
                              PairFilters filters) {
  const Vec3 &a_t0 = at_t0[0], &b_t0 = at_t0[1], &c_t0 = at_t0[2], &d_t0 = at_t0[3];
  const Vec3 &a_t1 = at_t1[0], &b_t1 = at_t1[1], &c_t1 = at_t1[2], &d_t1 = at_t1[3];
  Cubic f;
  bool undecided = true;
  const bool f_ok = coplanarity_cubic(at_t0, at_t1, f, undecided);
  return verdict(
      f_ok, f, undecided, filters,
      [&] { return edge_edge_apart(a_t0, b_t0, c_t0, d_t0, a_t1, b_t1, c_t1, d_t1, f); },
      [&] { return coplanarity_sign(at_t0, at_t1); });
}

}  // namespace tailor
