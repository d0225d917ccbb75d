#include "tailor/geometry/triangle_intersection.hpp"

#include <algorithm>

#include "tailor/geometry/orientation_predicates.hpp"

namespace tailor {
namespace {

/// Drops coordinate `axis` (an exact projection onto an axis plane).
Vec2 drop(const Vec3& p, int axis) {
  switch (axis) {
    case 0:
      return {p.y(), p.z()};
    case 1:
      return {p.z(), p.x()};
    default:
      return {p.x(), p.y()};
  }
}

/// An axis whose projection keeps the non-degenerate triangle non-degenerate, and the
/// sign of the projected triangle's orientation there.
std::pair<int, int> projection_axis(const Triangle& t) {
  for (int axis = 2; axis >= 0; --axis) {
    const int s = orient2d(drop(t[0], axis), drop(t[1], axis), drop(t[2], axis));
    if (s != 0) return {axis, s};
  }
  return {-1, 0};  // degenerate triangle
}

/// `r` lies in the axis-aligned box of `p, q` (for points known to be collinear).
bool in_box(const Vec2& p, const Vec2& q, const Vec2& r) {
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
         std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
}

/// Closed 2D segments `[p, q]`, `[r, s]` share a point (zero-length segments allowed).
bool segments_intersect_2d(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const int o1 = orient2d(p, q, r), o2 = orient2d(p, q, s);
  const int o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && in_box(p, q, r)) return true;
  if (o2 == 0 && in_box(p, q, s)) return true;
  if (o3 == 0 && in_box(r, s, p)) return true;
  if (o4 == 0 && in_box(r, s, q)) return true;
  return false;
}

/// Closed 2D triangle with orientation sign `s != 0` holds `p`.
bool point_in_triangle_2d(const Vec2& a, const Vec2& b, const Vec2& c, int s, const Vec2& p) {
  return s * orient2d(a, b, p) >= 0 && s * orient2d(b, c, p) >= 0 && s * orient2d(c, a, p) >= 0;
}

/// Segment-triangle test for a non-degenerate triangle, given the orientations of the
/// segment's endpoints against the triangle's plane.
bool segment_triangle_signs(const Vec3& p, const Vec3& q, const Triangle& t, int sp, int sq) {
  if (sp == sq && sp != 0) return false;  // both strictly on one side
  if (sp == 0 && sq == 0) {
    // Coplanar: project to a plane where the triangle stays non-degenerate (injective on
    // the common plane, so the 2D answer is the 3D answer).
    const auto [axis, s] = projection_axis(t);
    const Vec2 a = drop(t[0], axis), b = drop(t[1], axis), c = drop(t[2], axis);
    const Vec2 p2 = drop(p, axis), q2 = drop(q, axis);
    return point_in_triangle_2d(a, b, c, s, p2) || point_in_triangle_2d(a, b, c, s, q2) ||
           segments_intersect_2d(p2, q2, a, b) || segments_intersect_2d(p2, q2, b, c) ||
           segments_intersect_2d(p2, q2, c, a);
  }
  // The segment meets the plane in exactly one point; it lies in the closed triangle iff
  // the line pq passes on no strictly different sides of the three edges.
  const int e0 = orient3d(p, q, t[0], t[1]);
  const int e1 = orient3d(p, q, t[1], t[2]);
  const int e2 = orient3d(p, q, t[2], t[0]);
  const bool has_pos = e0 > 0 || e1 > 0 || e2 > 0;
  const bool has_neg = e0 < 0 || e1 < 0 || e2 < 0;
  return !(has_pos && has_neg);
}

/// The far end `b` of an edge `ab` leaves `a` into the non-degenerate triangle
/// `u = (a, d, e)` (so `[a, b]` meets `u` in more than `a`).
bool edge_enters_corner(const Vec3& b, const Triangle& u) {
  if (orient3d(u[0], u[1], u[2], b) != 0) return false;
  const auto [axis, s] = projection_axis(u);
  const Vec2 a2 = drop(u[0], axis), d2 = drop(u[1], axis), e2 = drop(u[2], axis);
  const Vec2 b2 = drop(b, axis);
  if (b2 == a2) return false;  // cannot happen for a non-degenerate (a, b, .), kept for safety
  // b - a = λ (d - a) + μ (e - a) with λ, μ >= 0.
  return s * orient2d(a2, d2, b2) >= 0 && s * orient2d(a2, b2, e2) >= 0;
}

}  // namespace

bool is_degenerate_triangle(const Triangle& t) {
  // Collinear iff the cross product vanishes iff every axis projection is degenerate.
  return projection_axis(t).first < 0;
}

bool segments_intersect(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  if (orient3d(p, q, r, s) != 0) return false;
  // Coplanar (or collinear) points: some axis projection is injective on a common plane,
  // and a 3D intersection shows in every projection, so "meet in all three projections"
  // is exact.
  for (int axis = 0; axis < 3; ++axis) {
    if (!segments_intersect_2d(drop(p, axis), drop(q, axis), drop(r, axis), drop(s, axis))) {
      return false;
    }
  }
  return true;
}

bool segment_triangle_intersect(const Vec3& p, const Vec3& q, const Triangle& t) {
  if (is_degenerate_triangle(t)) {
    // A degenerate triangle is the union of its edges.
    return segments_intersect(p, q, t[0], t[1]) || segments_intersect(p, q, t[1], t[2]) ||
           segments_intersect(p, q, t[2], t[0]);
  }
  return segment_triangle_signs(p, q, t, orient3d(t[0], t[1], t[2], p),
                                orient3d(t[0], t[1], t[2], q));
}

bool triangles_intersect(const Triangle& t, const Triangle& u) {
  const bool t_flat = is_degenerate_triangle(t), u_flat = is_degenerate_triangle(u);
  std::array<int, 3> su{}, st{};  // u's corners against t's plane, t's against u's
  if (!t_flat) {
    for (int i = 0; i < 3; ++i) su[i] = orient3d(t[0], t[1], t[2], u[i]);
    if ((su[0] > 0 && su[1] > 0 && su[2] > 0) || (su[0] < 0 && su[1] < 0 && su[2] < 0)) {
      return false;
    }
  }
  if (!u_flat) {
    for (int i = 0; i < 3; ++i) st[i] = orient3d(u[0], u[1], u[2], t[i]);
    if ((st[0] > 0 && st[1] > 0 && st[2] > 0) || (st[0] < 0 && st[1] < 0 && st[2] < 0)) {
      return false;
    }
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const bool hit_u = u_flat ? segment_triangle_intersect(t[i], t[j], u)
                              : segment_triangle_signs(t[i], t[j], u, st[i], st[j]);
    if (hit_u) return true;
    const bool hit_t = t_flat ? segment_triangle_intersect(u[i], u[j], t)
                              : segment_triangle_signs(u[i], u[j], t, su[i], su[j]);
    if (hit_t) return true;
  }
  return false;
}

bool triangles_intersect_except_shared_vertex(const Triangle& t, const Triangle& u) {
  return segment_triangle_intersect(t[1], t[2], u) || segment_triangle_intersect(u[1], u[2], t) ||
         edge_enters_corner(t[1], u) || edge_enters_corner(t[2], u) ||
         edge_enters_corner(u[1], t) || edge_enters_corner(u[2], t);
}

bool triangles_intersect_except_shared_edge(const Triangle& t, const Triangle& u) {
  if (orient3d(t[0], t[1], t[2], u[2]) != 0) return false;
  const auto [axis, s] = projection_axis(t);
  const int side_d = orient2d(drop(t[0], axis), drop(t[1], axis), drop(u[2], axis));
  return side_d == s;  // same side as c (side_d is non-zero when u is non-degenerate)
}

TrianglePairVerdict classify_face_pair(const Positions& x, const std::array<Index, 3>& f,
                                       const std::array<Index, 3>& g) {
  const auto point = [&x](Index v) { return position(x, v); };
  // Which corners of f appear in g, and where.
  std::array<int, 3> in_g{-1, -1, -1};
  int shared = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (f[i] == g[j]) {
        in_g[i] = j;
        ++shared;
      }
    }
  }
  if (shared == 0) {
    const Triangle t{point(f[0]), point(f[1]), point(f[2])};
    const Triangle u{point(g[0]), point(g[1]), point(g[2])};
    return triangles_intersect(t, u) ? TrianglePairVerdict::intersecting
                                     : TrianglePairVerdict::disjoint;
  }
  if (shared == 3) return TrianglePairVerdict::disjoint;
  const Triangle tf{point(f[0]), point(f[1]), point(f[2])};
  const Triangle tg{point(g[0]), point(g[1]), point(g[2])};
  if (is_degenerate_triangle(tf) || is_degenerate_triangle(tg)) {
    return TrianglePairVerdict::degenerate_adjacent;
  }
  const auto others_of_g = [&](std::initializer_list<int> used) {
    std::array<Index, 3> rest{};
    int n = 0;
    for (int j = 0; j < 3; ++j) {
      if (std::find(used.begin(), used.end(), j) == used.end()) rest[n++] = g[j];
    }
    return rest;
  };
  bool hit = false;
  if (shared == 1) {
    const int i = static_cast<int>(
        std::find_if(in_g.begin(), in_g.end(), [](int j) { return j >= 0; }) - in_g.begin());
    const auto rest = others_of_g({in_g[i]});
    const Triangle t{point(f[i]), point(f[(i + 1) % 3]), point(f[(i + 2) % 3])};
    const Triangle u{point(f[i]), point(rest[0]), point(rest[1])};
    hit = triangles_intersect_except_shared_vertex(t, u);
  } else {
    int k = 0;  // the corner of f not in g
    while (in_g[k] >= 0) ++k;
    const Index a = f[(k + 1) % 3], b = f[(k + 2) % 3];
    const auto rest = others_of_g({in_g[(k + 1) % 3], in_g[(k + 2) % 3]});
    const Triangle t{point(a), point(b), point(f[k])};
    const Triangle u{point(a), point(b), point(rest[0])};
    hit = triangles_intersect_except_shared_edge(t, u);
  }
  return hit ? TrianglePairVerdict::intersecting : TrianglePairVerdict::disjoint;
}

}  // namespace tailor
