#pragma once
/// @file
/// Exact static intersection tests of closed triangles and segments in 3D, on the input
/// doubles (orientation predicates with a certified filter and an exact fallback), with
/// coplanar and degenerate (zero-area, zero-length) cases handled; plus variants for
/// triangles of one mesh that share a vertex or an edge.

#include <array>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A triangle as its three corner points.
using Triangle = std::array<Vec3, 3>;

/// True when the three corners are collinear (or coincide): the triangle has zero area.
bool is_degenerate_triangle(const Triangle& t);

/// Do the closed segments `[p, q]` and `[r, s]` share a point? Zero-length segments allowed.
bool segments_intersect(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s);

/// Does the closed segment `[p, q]` meet the closed triangle `t`? Degenerate triangles
/// (a segment or a point) and zero-length segments are allowed.
bool segment_triangle_intersect(const Vec3& p, const Vec3& q, const Triangle& t);

/// Do the two closed triangles share at least one point? Touching at a vertex or along an
/// edge counts; degenerate triangles are allowed.
///
/// Why testing edges suffices: if the triangles meet, their intersection is a compact
/// convex set, and an extreme point of it lies on the boundary of one of the triangles
/// (a point inside both relative interiors has a neighbourhood of the line or plane
/// common to both affine hulls inside the intersection; a degenerate triangle is the
/// union of its edges). So they meet iff an edge of one meets the other.
bool triangles_intersect(const Triangle& t, const Triangle& u);

/// Triangles `t = (a, b, c)` and `u = (a, d, e)` with the same first corner `a` (a shared
/// mesh vertex): do they meet anywhere other than `a`? Both must be non-degenerate.
///
/// The intersection is convex and holds `a`; it holds another point iff it has an extreme
/// point other than `a`, which lies on an edge of `t` or `u` (argument as above). So:
/// `bc` meets `u`, or `de` meets `t` (neither segment contains `a`), or one of the edges
/// at `a` (`ab`, `ac`, `ad`, `ae`) enters the other triangle from `a`, which happens iff
/// the edge's far end is coplanar with the other triangle and inside its angle at `a`.
bool triangles_intersect_except_shared_vertex(const Triangle& t, const Triangle& u);

/// Triangles `t = (a, b, c)` and `u = (a, b, d)` sharing the edge `ab` (same first two
/// corners): do they meet anywhere other than the segment `ab`? Both must be
/// non-degenerate. They do iff the four points are coplanar and `c`, `d` lie on the same
/// side of the line `ab` (the triangles fold onto each other).
bool triangles_intersect_except_shared_edge(const Triangle& t, const Triangle& u);

/// The verdict on a pair of triangles of meshes.
enum class TrianglePairVerdict {
  disjoint,      ///< no intersection (beyond the shared vertices/edge, if any)
  intersecting,  ///< they intersect (beyond the shared vertices/edge, if any)
  /// They share a vertex or an edge and one of them is degenerate: not decided (the
  /// shared-feature variants need non-degenerate triangles).
  degenerate_adjacent,
};

/// Classifies two faces of one mesh (`f`, `g` are vertex ids into `x`): faces with no
/// common vertex must not intersect at all; faces sharing one vertex or one edge must not
/// meet beyond it; identical faces (three shared ids) are reported disjoint.
TrianglePairVerdict classify_face_pair(const Positions& x, const std::array<Index, 3>& f,
                                       const std::array<Index, 3>& g);

}  // namespace tailor
