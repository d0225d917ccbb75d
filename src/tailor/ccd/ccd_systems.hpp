#pragma once
/// @file
/// The polynomial systems that define a VF or EE contact (shared by the exact and the
/// certified double path, so both decide the very same formulas). Internal.
///
/// VF (point p, triangle abc): contact at t iff
///   [f = 0, N > 0, E_ab >= 0, E_bc >= 0, E_ca >= 0]  or p on segment ab, bc or ca,
/// with n = (b-a)×(c-a), f = n·(p-a), N = n·n, E_ab = ((b-a)×(p-a))·n (= v N for
/// barycentric p = a + u(b-a) + v(c-a)), E_bc = ((c-b)×(p-b))·n, E_ca = ((a-c)×(p-c))·n.
/// A zero-area triangle is the union of its edges, hence N > 0 plus the edge cases.
/// Point p on segment ab: (p-a)×(b-a) = 0, (p-a)·(b-a) >= 0, (b-p)·((b-a)+(p-a)) >= 0
/// (the last is |b-a|² - |p-a|²; for a = b it forces p = a).
///
/// EE (segments ab, cd): contact at t iff
///   [f = 0, M > 0, S >= 0, M-S >= 0, U >= 0, M-U >= 0] or an endpoint on the other
///   segment, with f = ((b-a)×(c-a))·(d-a), m = (b-a)×(d-c), M = m·m,
///   S = ((c-a)×(d-c))·m (= s M), M-S = ((b-c)×(d-c))·m, U = ((c-a)×(b-a))·m (= u M),
///   M-U = ((b-a)×(d-a))·m. Parallel, collinear and degenerate segments meet iff an
///   endpoint of one lies on the other.
/// Every branch implies f = 0 (the four points are coplanar).
///
/// Projected conditions (what the certified double tier and the exact tier evaluate). At
/// an instant where the four points are coplanar, every vector above that is a cross
/// product of two in-plane vectors is normal to the plane, hence parallel to n (VF) or m
/// (EE) when those are nonzero. So for any axis k with n_k != 0:
///   sign(E_ab) = sign(n_k) sign(((b-a)×(p-a))_k), and likewise E_bc, E_ca,
/// i.e. p is in the closed triangle iff the three 2D orientations
/// ((b-a)×(p-a))_k, ((c-b)×(p-b))_k, ((a-c)×(p-c))_k have n_k's sign or vanish (the
/// projection along k maps the plane one-to-one). N > 0 iff some n_k != 0; when n = 0 only
/// the point-on-segment branches remain. For EE with m_k != 0 the projected segments are
/// not parallel and meet iff ((b-a)×(c-a))_k ((b-a)×(d-a))_k <= 0 and
/// ((d-c)×(a-c))_k ((d-c)×(b-c))_k <= 0; when m = 0, only endpoint-on-segment branches.
/// Each k-component is a quadratic in t, which is what makes the exact tier cheap.

#include <array>

namespace tailor::detail {

/// A 3-vector over a ring-like scalar type S (double intervals or exact polynomials).
template <class S>
struct V3 {
  S x, y, z;
};

template <class S>
V3<S> operator-(const V3<S>& a, const V3<S>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

template <class S>
V3<S> operator+(const V3<S>& a, const V3<S>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}

template <class S>
V3<S> cross(const V3<S>& a, const V3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class S>
S dot(const V3<S>& a, const V3<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// The face system of a VF query, without f (which each path gets its own way).
template <class S>
struct FaceConditions {
  S N, E_ab, E_bc, E_ca;
};

template <class S>
FaceConditions<S> face_conditions(const V3<S>& p, const V3<S>& a, const V3<S>& b, const V3<S>& c) {
  const V3<S> ab = b - a, ac = c - a;
  const V3<S> n = cross(ab, ac);
  return {dot(n, n), dot(cross(ab, p - a), n), dot(cross(c - b, p - b), n),
          dot(cross(a - c, p - c), n)};
}

/// Point p on segment ab: cross = 0, along >= 0, within >= 0.
template <class S>
struct PointSegment {
  V3<S> cross;
  S along, within;
};

template <class S>
PointSegment<S> point_segment(const V3<S>& p, const V3<S>& a, const V3<S>& b) {
  const V3<S> pa = p - a, ba = b - a;
  return {cross(pa, ba), dot(pa, ba), dot(b - p, ba + pa)};
}

/// The main system of an EE query, without f.
template <class S>
struct EdgeConditions {
  S M, S_, M_minus_S, U, M_minus_U;
};

template <class S>
EdgeConditions<S> edge_conditions(const V3<S>& a, const V3<S>& b, const V3<S>& c, const V3<S>& d) {
  const V3<S> ba = b - a, dc = d - c, ca = c - a;
  const V3<S> m = cross(ba, dc);
  return {dot(m, m), dot(cross(ca, dc), m), dot(cross(b - c, dc), m), dot(cross(ca, ba), m),
          dot(cross(ba, d - a), m)};
}

/// The k-th component of x × y (a 2D orientation in the plane normal to axis k).
template <class S>
S cross_component(const V3<S>& x, const V3<S>& y, int k) {
  if (k == 0) return x.y * y.z - x.z * y.y;
  if (k == 1) return x.z * y.x - x.x * y.z;
  return x.x * y.y - x.y * y.x;
}

/// The VF vectors of the projected conditions: n and the three edge orientations.
template <class S>
struct VfProjection {
  V3<S> n, e_ab, e_bc, e_ca;
};

template <class S>
VfProjection<S> vf_projection(const V3<S>& a, const V3<S>& b, const V3<S>& c, const V3<S>& p) {
  return {cross(b - a, c - a), cross(b - a, p - a), cross(c - b, p - b), cross(a - c, p - c)};
}

/// The EE vectors of the projected conditions: m and the four orientations.
template <class S>
struct EeProjection {
  V3<S> m, abc, abd, cda, cdb;
};

template <class S>
EeProjection<S> ee_projection(const V3<S>& a, const V3<S>& b, const V3<S>& c, const V3<S>& d) {
  const V3<S> ba = b - a, dc = d - c;
  return {cross(ba, dc), cross(ba, c - a), cross(ba, d - a), cross(dc, a - c), cross(dc, b - c)};
}

/// The coplanarity function det(b-a, c-a, d-a).
template <class S>
S coplanarity(const V3<S>& a, const V3<S>& b, const V3<S>& c, const V3<S>& d) {
  return dot(cross(b - a, c - a), d - a);
}

}  // namespace tailor::detail
