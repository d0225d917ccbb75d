#pragma once
/// @file
/// The polynomials of the projection filter (projection_filter.hpp) and their exclusion
/// test over dyadic pieces of the step, shared by the one-pair filters and their batch
/// form (batch_pair_filters.hpp), which must decide bit for bit alike. Internal to the
/// candidates module.

#include <cmath>

#include "tailor/culling/certified_bernstein.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor::projection {

/// A quadratic on the step in certified Bernstein form (a bracket of two moving differences).
using Quadratic = CertifiedBernstein<2>;
/// A cubic on the step in certified Bernstein form (the coplanarity function f).
using Cubic = CertifiedBernstein<3>;

/// Depth of the dyadic subdivision of the step (at most 2^kDepth pieces).
constexpr int kDepth = 3;

/// A difference of two moving points, rounded once per coordinate, at t=0 and t=1.
struct Moving {
  ///@{
  /// Coordinates at t=0 and at t=1.
  double t0[3], t1[3];
  ///@}
};

/// The moving difference `to - from`, each coordinate rounded once.
inline Moving difference(const Vec3& to_t0, const Vec3& from_t0, const Vec3& to_t1,
                         const Vec3& from_t1) {
  Moving d;
  for (int k = 0; k < 3; ++k) {
    d.t0[k] = to_t0[k] - from_t0[k];
    d.t1[k] = to_t1[k] - from_t1[k];
  }
  return d;
}

/// The moving difference `-m` (exact).
inline Moving negated(const Moving& m) {
  Moving d;
  for (int k = 0; k < 3; ++k) d.t0[k] = -m.t0[k], d.t1[k] = -m.t1[k];
  return d;
}

/// Nonzero magnitudes within [2^-250, 2^250] (NaN fails), as the error bound requires.
inline bool in_range(const Moving& m) {
  bool ok = true;
  for (int k = 0; k < 3; ++k) {
    for (double x : {m.t0[k], m.t1[k]}) {
      const double a = std::fabs(x);
      ok &= (a == 0.0) | ((a >= 0x1p-250) & (a <= 0x1p250));
    }
  }
  return ok;
}

/// The projection direction: the coordinate axis k along which (e × w) at mid-step has its
/// largest component (so the projection keeps the pair's shape), as the index of the
/// axis; -1 when that cross product is zero.
inline int direction(const Moving& e, const Moving& w) {
  double em[3], wm[3];
  for (int k = 0; k < 3; ++k) em[k] = e.t0[k] + e.t1[k], wm[k] = w.t0[k] + w.t1[k];
  const double n[3] = {std::fabs(em[1] * wm[2] - em[2] * wm[1]),
                       std::fabs(em[2] * wm[0] - em[0] * wm[2]),
                       std::fabs(em[0] * wm[1] - em[1] * wm[0])};
  const int k = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
  return n[k] > 0 ? k : -1;
}

/// [e, w, axis k] = (e × w)_k = e_i w_j - e_j w_i ((i, j, k) cyclic), and the same with
/// absolute values. Differences (1 rounding each), products, difference: 4 roundings.
inline void triple(const double* e, const double* w, int i, int j, double& value,
                   double& magnitude) {
  value = e[i] * w[j] - e[j] * w[i];
  magnitude = std::fabs(e[i] * w[j]) + std::fabs(e[j] * w[i]);
}

/// The quadratic [e(t), w(t), axis k] in Bernstein form (blossom values) with certified
/// bounds: at most 5 roundings along any term (the middle coefficient adds a sum), so
/// 16·2^-53 times the magnitude (computed with 3 more roundings) is a safe bound.
inline Quadratic bracket(const Moving& e, const Moving& w, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  double v00, m00, v01, m01, v10, m10, v11, m11;
  triple(e.t0, w.t0, i, j, v00, m00);
  triple(e.t0, w.t1, i, j, v01, m01);
  triple(e.t1, w.t0, i, j, v10, m10);
  triple(e.t1, w.t1, i, j, v11, m11);
  return {{v00, 0.5 * (v01 + v10), v11}, {0x1p-49 * m00, 0x1p-50 * (m01 + m10), 0x1p-49 * m11}};
}

/// The coplanarity cubic f = [b-a, c-a, d-a] with its certified bounds, from the DNF
/// filter's evaluation (whose middle coefficients are 3β1, 3β2). False when out of range.
/// `undecided` tells whether a coefficient's sign is beyond the bound.
inline bool coplanarity_cubic(const FourPoints& at_t0, const FourPoints& at_t1, Cubic& f,
                              bool& undecided) {
  double value[4], bound[4];
  if (!detail::coplanarity_bernstein_double(at_t0, at_t1, value, bound)) {
    return false;
  }
  undecided = false;
  for (int i = 0; i < 4; ++i) undecided |= bound[i] > 0 && std::fabs(value[i]) <= bound[i];
  f.value = {value[0], value[1] / 3, value[2] / 3, value[3]};
  // |fl(v/3) - V/3| <= |v|u/3 + bound/3, below bound/2 + u|v| even after rounding.
  f.bound = {bound[0], 0.5 * bound[1] + 0x1p-53 * std::fabs(value[1]),
             0.5 * bound[2] + 0x1p-53 * std::fabs(value[2]), bound[3]};
  return true;
}

/// A piece of the step is excluded when the polynomials' signs on it rule a contact out;
/// otherwise it is halved, down to 2^-kDepth of the step.
template <class Polynomials>
inline bool excluded_everywhere(const Polynomials& p, int depth = 0);

/// Whether both halves of the piece of `p` (at `depth`) are excluded everywhere: what
/// excluded_everywhere() decides once p.excluded() failed.
template <class Polynomials>
inline bool halves_excluded(const Polynomials& p, int depth = 0) {
  if (depth == kDepth) return false;
  Polynomials left, right;
  p.split(left, right);
  return excluded_everywhere(left, depth + 1) && excluded_everywhere(right, depth + 1);
}

template <class Polynomials>
inline bool excluded_everywhere(const Polynomials& p, int depth) {
  return p.excluded() || halves_excluded(p, depth);
}

/// Vertex-face: f and s_ab, s_bc, s_ca, o of the header.
struct VertexFacePolynomials {
  /// The coplanarity cubic [b-a, c-a, p-a].
  Cubic f;
  ///@{
  /// The brackets s_ab, s_bc, s_ca of the vertex against the three edges, and o of the face.
  Quadratic s[3], o;
  ///@}

  /// Whether the signs on this piece rule a contact out: f of strict sign, two of s of
  /// opposite strict signs, or an s of the strict sign opposite to o.
  bool excluded() const {
    if (f.sign() != 0) return true;  // never coplanar on this piece
    const int s1 = s[0].sign(), s2 = s[1].sign(), s3 = s[2].sign();
    const bool positive = s1 > 0 || s2 > 0 || s3 > 0, negative = s1 < 0 || s2 < 0 || s3 < 0;
    if (positive && negative) return true;
    if (!positive && !negative) return false;
    const int orientation = o.sign();
    return (orientation > 0 && negative) || (orientation < 0 && positive);
  }
  /// The polynomials restricted to the two halves of this piece.
  void split(VertexFacePolynomials& left, VertexFacePolynomials& right) const {
    f.split(left.f, right.f);
    for (int i = 0; i < 3; ++i) s[i].split(left.s[i], right.s[i]);
    o.split(left.o, right.o);
  }
};

/// Edge-edge: f and g_c, g_d, h_a, h_b, m of the header.
struct EdgeEdgePolynomials {
  /// The coplanarity cubic [b-a, c-a, d-a].
  Cubic f;
  ///@{
  /// The brackets g_c, g_d (c, d against line ab), h_a, h_b (a, b against line cd) and m.
  Quadratic g_c, g_d, h_a, h_b, m;
  ///@}

  /// Whether the signs on this piece rule a contact out: f of strict sign, c and d (or a and
  /// b) strictly on one side, or a sign pattern m forbids.
  bool excluded() const {
    if (f.sign() != 0) return true;
    const int c = g_c.sign(), d = g_d.sign();
    if (c != 0 && c == d) return true;  // c and d strictly on one side of line ab
    const int a = h_a.sign(), b = h_b.sign();
    if (a != 0 && a == b) return true;  // a and b strictly on one side of line cd
    if (c == 0 && d == 0 && a == 0 && b == 0) return false;
    const int s = m.sign();
    return s != 0 && (c == s || d == -s || a == -s || b == s);
  }
  /// The polynomials restricted to the two halves of this piece.
  void split(EdgeEdgePolynomials& left, EdgeEdgePolynomials& right) const {
    f.split(left.f, right.f);
    g_c.split(left.g_c, right.g_c);
    g_d.split(left.g_d, right.g_d);
    h_a.split(left.h_a, right.h_a);
    h_b.split(left.h_b, right.h_b);
    m.split(left.m, right.m);
  }
};

}  // namespace tailor::projection
