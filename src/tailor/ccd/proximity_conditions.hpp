#pragma once
/// @file
/// The proximity conditions of ccd/proximity_predicates.hpp written once over a number type
/// T: detail::Ball (certified signs, or undecided; also over boxes of positions, which is
/// how the thickness CCD bounds a time interval) and mpq_class (exact). Internal to the
/// ccd module; the vectors are ccd_systems.hpp's V3.

#include <gmpxx.h>

#include <array>

#include "tailor/ccd/ball.hpp"
#include "tailor/ccd/ccd_systems.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor::detail {

/// Three-valued truth: a ball may leave a sign undecided.
enum class Truth : unsigned char { no, yes, unknown };

inline Truth operator&&(Truth a, Truth b) {
  if (a == Truth::no || b == Truth::no) return Truth::no;
  return a == Truth::yes && b == Truth::yes ? Truth::yes : Truth::unknown;
}
inline Truth operator||(Truth a, Truth b) {
  if (a == Truth::yes || b == Truth::yes) return Truth::yes;
  return a == Truth::no && b == Truth::no ? Truth::no : Truth::unknown;
}

/// x ≥ 0 and x > 0, certified (a ball of radius 0 is exact).
inline Truth at_least_zero(const Ball& x) {
  if (x.positive() || (x.m == 0 && x.r == 0)) return Truth::yes;
  return x.negative() ? Truth::no : Truth::unknown;
}
inline Truth above_zero(const Ball& x) {
  if (x.positive()) return Truth::yes;
  return x.negative() || (x.m == 0 && x.r == 0) ? Truth::no : Truth::unknown;
}
inline Truth at_least_zero(const mpq_class& x) {
  return sgn(x) >= 0 ? Truth::yes : Truth::no;
}
inline Truth above_zero(const mpq_class& x) {
  return sgn(x) > 0 ? Truth::yes : Truth::no;
}

/// Four points given exactly: d(i, j) = x[i] - x[j].
template <class T>
struct PointSet {
  std::array<V3<T>, 4> x;  ///< the points
  /// The vector from point j to point i.
  V3<T> d(int i, int j) const { return x[i] - x[j]; }
};

/// Features known in advance never to exist (for the whole step): a segment whose two ends
/// coincide has no interior, and a triangle (or pair of edges) whose normal vanishes has no
/// face (interior-interior) case. Certified balls cannot see an exact zero; telling the
/// conditions spares the thickness CCD a search for a case that cannot occur. All false
/// for the static predicates (their exact fallback sees every zero).
struct NeverPresent {
  bool normal = false;            ///< the normal n is zero
  std::array<bool, 4> segment{};  ///< per point_segment call, in the order made below
};

/// Point p within h of the closed segment ab (h2 = h²), points by index into `pts`. The
/// conditions are evaluated in order and stop once the answer is settled (a `yes` of an
/// alternative, a `no` of a conjunction): the same answer as evaluating them all.
template <class T, class Points>
inline Truth point_segment(const Points& pts, int p, int a, int b, const T& h2, bool no_interior) {
  const V3<T> w = pts.d(p, a);
  const T ww = dot(w, w);
  Truth ends = at_least_zero(T(h2 - ww));
  if (ends == Truth::yes) return ends;
  const V3<T> pb = pts.d(p, b);
  ends = ends || at_least_zero(T(h2 - dot(pb, pb)));
  if (ends == Truth::yes || no_interior) return ends;
  const V3<T> u = pts.d(b, a);
  const T uu = dot(u, u), wu = dot(w, u);
  Truth between = above_zero(uu) && at_least_zero(wu);
  if (between != Truth::no) between = between && at_least_zero(T(uu - wu));
  if (between != Truth::no) between = between && at_least_zero(T(h2 * uu - (ww * uu - wu * wu)));
  return ends || between;
}

/// Vertex 0 within h of the closed triangle (1, 2, 3).
template <class T, class Points>
inline Truth vertex_face(const Points& pts, const T& h2, const NeverPresent& never = {}) {
  const V3<T> ab = pts.d(2, 1), ac = pts.d(3, 1);
  const V3<T> n = cross(ab, ac);
  const T nn = dot(n, n);
  const V3<T> ap = pts.d(0, 1);
  const T along = dot(ap, n);
  const T plane_gap = along * along - h2 * nn;
  // Farther than h from the triangle's plane: farther from the triangle (most candidates).
  if (above_zero(plane_gap) == Truth::yes) return Truth::no;
  Truth within = Truth::no;
  if (!never.normal) {
    Truth inside = above_zero(nn) && at_least_zero(T(-plane_gap));
    if (inside != Truth::no) inside = inside && at_least_zero(dot(n, cross(ab, ap)));
    if (inside != Truth::no) {
      inside = inside && at_least_zero(dot(n, cross(pts.d(3, 2), pts.d(0, 2))));
    }
    if (inside != Truth::no) {
      inside = inside && at_least_zero(dot(n, cross(pts.d(1, 3), pts.d(0, 3))));
    }
    if (inside == Truth::yes) return inside;
    within = inside;
  }
  const std::array<std::array<int, 2>, 3> sides{{{1, 2}, {2, 3}, {3, 1}}};
  for (std::size_t k = 0; k < sides.size() && within != Truth::yes; ++k) {
    within = within || point_segment(pts, 0, sides[k][0], sides[k][1], h2, never.segment[k]);
  }
  return within;
}

/// Segment (0, 1) within h of segment (2, 3).
template <class T, class Points>
inline Truth edge_edge(const Points& pts, const T& h2, const NeverPresent& never = {}) {
  const V3<T> u = pts.d(1, 0), v = pts.d(3, 2), w = pts.d(2, 0);
  const V3<T> n = cross(u, v);
  const T nn = dot(n, n);
  const T along = dot(w, n);
  const T line_gap = along * along - h2 * nn;
  // The lines are farther than h apart (n ≠ 0 here): so are the segments (most candidates).
  if (above_zero(line_gap) == Truth::yes) return Truth::no;
  Truth within = Truth::no;
  if (!never.normal) {
    Truth interior = above_zero(nn) && at_least_zero(T(-line_gap));
    if (interior != Truth::no) {
      const T s = dot(cross(w, v), n);
      interior = interior && at_least_zero(s) && at_least_zero(T(nn - s));
    }
    if (interior != Truth::no) {
      const T t = dot(cross(w, u), n);
      interior = interior && at_least_zero(t) && at_least_zero(T(nn - t));
    }
    if (interior == Truth::yes) return interior;
    within = interior;
  }
  // Each end against the other segment: (point, segment ends), in the order of
  // NeverPresent::segment.
  const std::array<std::array<int, 3>, 4> ends{{{0, 2, 3}, {1, 2, 3}, {2, 0, 1}, {3, 0, 1}}};
  for (std::size_t k = 0; k < ends.size() && within != Truth::yes; ++k) {
    within = within || point_segment(pts, ends[k][0], ends[k][1], ends[k][2], h2, never.segment[k]);
  }
  return within;
}

/// A point as a V3 over T (exact conversion of each coordinate).
template <class T>
inline V3<T> as(const Vec3& p) {
  return {T(p.x()), T(p.y()), T(p.z())};
}

}  // namespace tailor::detail
