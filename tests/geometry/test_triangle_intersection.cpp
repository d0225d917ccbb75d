/// @file
/// Exact static triangle-triangle intersection and the orientation predicates under it.

#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "tailor/geometry/orientation_predicates.hpp"
#include "tailor/geometry/triangle_intersection.hpp"

namespace tailor {
namespace {

using tailor::testing::sanitized;

Triangle tri(Vec3 a, Vec3 b, Vec3 c) {
  return {a, b, c};
}

/// Every symmetry the answer must not depend on: order of the triangles, order of the
/// corners, swapping or negating axes, exact translations and power-of-two scalings.
void expect_intersect(const Triangle& t, const Triangle& u, bool expected) {
  const auto check = [&](const Triangle& a, const Triangle& b, const char* what) {
    EXPECT_EQ(triangles_intersect(a, b), expected) << what;
    EXPECT_EQ(triangles_intersect(b, a), expected) << what << " (swapped)";
  };
  check(t, u, "as given");
  check({t[1], t[2], t[0]}, {u[2], u[1], u[0]}, "corners permuted");
  const auto map = [](const Triangle& a, auto f) { return Triangle{f(a[0]), f(a[1]), f(a[2])}; };
  const auto axes = [](const Vec3& p) { return Vec3(p.z(), p.x(), p.y()); };
  const auto negate = [](const Vec3& p) { return Vec3(-p.x(), p.y(), -p.z()); };
  const auto scale = [](const Vec3& p) {
    return Vec3(std::ldexp(p.x(), 7), std::ldexp(p.y(), 7), std::ldexp(p.z(), 7));
  };
  const auto shift = [](const Vec3& p) { return Vec3(p.x() + 4.0, p.y() - 8.0, p.z() + 2.0); };
  check(map(t, axes), map(u, axes), "axes rotated");
  check(map(t, negate), map(u, negate), "mirrored");
  check(map(t, scale), map(u, scale), "scaled");
  // A translation is a symmetry only where every shifted coordinate is exact.
  const auto exact_sum = [](double a, double b) {
    const double s = a + b, bb = s - a;
    return (a - (s - bb)) + (b - bb) == 0.0;
  };
  bool shift_exact = true;
  for (const Triangle* tr : {&t, &u}) {
    for (const Vec3& p : *tr) {
      shift_exact =
          shift_exact && exact_sum(p.x(), 4.0) && exact_sum(p.y(), -8.0) && exact_sum(p.z(), 2.0);
    }
  }
  if (shift_exact) check(map(t, shift), map(u, shift), "translated");
}

const Triangle kBase = tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});

TEST(OrientationPredicates, SignsAndConvention) {
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), 1);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}), -1);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.7, 0}), 0);
  EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {3, 3}), 0);
  // Tiny and huge magnitudes go to the exact path and keep their signs.
  const double tiny = std::nextafter(0.0, 1.0);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, tiny}), 1);
  EXPECT_EQ(orient3d({0, 0, 0}, {tiny, 0, 0}, {0, tiny, 0}, {0, 0, tiny}), 1);
  EXPECT_EQ(orient3d({0, 0, 0}, {1e300, 0, 0}, {0, 1e300, 0}, {0, 0, -1e300}), -1);
  EXPECT_EQ(orient2d({0, 0}, {1e-310, 0}, {0, 1e-310}), 1);
}

TEST(OrientationPredicates, OneUlpOffThePlane) {
  // Plane z = x through (0,0,0), (1,0,1), (0,1,0); (0.3, 0.3, 0.3) is exactly on it.
  const Vec3 a(0, 0, 0), b(1, 0, 1), c(0, 1, 0);
  EXPECT_EQ(orient3d(a, b, c, {0.3, 0.3, 0.3}), 0);
  const double up = std::nextafter(0.3, 1.0), down = std::nextafter(0.3, 0.0);
  const int s_up = orient3d(a, b, c, {0.3, 0.3, up});
  const int s_down = orient3d(a, b, c, {0.3, 0.3, down});
  EXPECT_NE(s_up, 0);
  EXPECT_EQ(s_down, -s_up);
  EXPECT_FALSE(orient3d_filter(a, b, c, {0.3, 0.3, up}).has_value());  // needs the fallback
}

TEST(OrientationPredicates, FilterAgreesWithExact) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = sanitized() ? 2000 : 50000;
  int decided = 0, undecided = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    Vec3 d(u(rng), u(rng), u(rng));
    if (i % 2 == 1) {
      // Nearly coplanar: a rounded point of the plane, sometimes nudged by a few ulps.
      const double s = u(rng), t = u(rng);
      d = a + s * (b - a) + t * (c - a);
      if (i % 4 == 1) d.z() = std::nextafter(d.z(), 2.0);
    }
    const int exact = orient3d_exact(a, b, c, d);
    if (const auto f = orient3d_filter(a, b, c, d)) {
      ASSERT_EQ(*f, exact) << i;
      ++decided;
    } else {
      ++undecided;
    }
    ASSERT_EQ(orient3d(a, b, c, d), exact);
    const Vec2 a2 = a.head<2>(), b2 = b.head<2>();
    Vec2 c2 = c.head<2>();
    if (i % 2 == 1) c2 = a2 + u(rng) * (b2 - a2);
    const int exact2 = orient2d_exact(a2, b2, c2);
    if (const auto f = orient2d_filter(a2, b2, c2)) {
      ASSERT_EQ(*f, exact2) << i;
    }
    ASSERT_EQ(orient2d(a2, b2, c2), exact2);
  }
  EXPECT_GT(decided, n / 2);  // random inputs are decided by the filter
  EXPECT_GT(undecided, 0);    // the near-coplanar ones exercise the fallback
}

TEST(TriangleIntersection, DisjointAndCrossing) {
  expect_intersect(kBase, tri({0, 0, 1}, {1, 0, 1}, {0, 1, 1}), false);                // parallel
  expect_intersect(kBase, tri({0.25, 0.25, -1}, {0.25, 0.25, 1}, {2, 2, 0.5}), true);  // pierce
  expect_intersect(kBase, tri({2, 2, -1}, {2, 2, 1}, {3, 3, 0}), false);  // plane crossing, outside
  // Through each other like two links of a chain.
  expect_intersect(tri({-1, 0, 0}, {1, 0, 0}, {0, 2, 0}), tri({0, 1, -1}, {0, 1, 1}, {0, -1, 0}),
                   true);
}

TEST(TriangleIntersection, TouchingAtAPointOrAnEdge) {
  // A corner on the face interior; on an edge; at a corner.
  expect_intersect(kBase, tri({0.25, 0.25, 0}, {0, 0, 1}, {1, 1, 1}), true);
  expect_intersect(kBase, tri({0.5, 0, 0}, {0, -1, 1}, {1, -1, 1}), true);
  expect_intersect(kBase, tri({1, 0, 0}, {2, 0, 1}, {2, 1, 1}), true);
  // An edge lying in the face, the rest above.
  expect_intersect(kBase, tri({0.125, 0.125, 0}, {0.5, 0.125, 0}, {0.25, 0.25, 1}), true);
  // Edge against edge, crossing at one point (non-coplanar triangles).
  expect_intersect(kBase, tri({0.5, -0.5, 0}, {0.5, 0.5, 0}, {0.5, 0, 1}), true);
  // Same, but the tip stops one ulp before the face.
  const double above = std::nextafter(0.0, 1.0);
  expect_intersect(kBase, tri({0.25, 0.25, above}, {0, 0, 1}, {1, 1, 1}), false);
  expect_intersect(kBase, tri({0.25, 0.25, -above}, {0, 0, 1}, {1, 1, 1}), true);
}

TEST(TriangleIntersection, OneUlpOnATiltedPlane) {
  const Triangle t = tri({0, 0, 0}, {1, 0, 1}, {0, 1, 0});  // plane z = x
  const double p = 0.3;
  const double up = std::nextafter(p, 1.0), down = std::nextafter(p, 0.0);
  // A triangle whose lowest corner sits exactly on, one ulp above, one ulp below.
  EXPECT_TRUE(triangles_intersect(t, tri({p, 0.3, p}, {p, 0.3, 2}, {p + 0.1, 0.2, 2})));
  const bool above_hits = triangles_intersect(t, tri({p, 0.3, up}, {p, 0.3, 2}, {p + 0.1, 0.2, 2}));
  const bool below_hits =
      triangles_intersect(t, tri({p, 0.3, down}, {p, 0.3, 2}, {p + 0.1, 0.2, 2}));
  EXPECT_FALSE(above_hits);
  EXPECT_TRUE(below_hits);
}

TEST(TriangleIntersection, Coplanar) {
  expect_intersect(kBase, tri({0.25, 0.25, 0}, {2, 0.25, 0}, {0.25, 2, 0}), true);  // overlap
  expect_intersect(kBase, tri({0.125, 0.125, 0}, {0.25, 0.125, 0}, {0.125, 0.25, 0}),
                   true);                                               // inside
  expect_intersect(kBase, tri({1, 0, 0}, {2, 0, 0}, {1, 1, 0}), true);  // touch at a corner
  expect_intersect(kBase, tri({0.5, 0.5, 0}, {1, 1, 0}, {0, 1, 0}),
                   true);                                               // corner on the hypotenuse
  expect_intersect(kBase, tri({1, 0, 0}, {0, 1, 0}, {1, 1, 0}), true);  // share the hypotenuse
  expect_intersect(kBase, tri({0.75, 0.75, 0}, {2, 0.75, 0}, {0.75, 2, 0}), false);  // just outside
  // Star of David: no corner inside the other, edges cross.
  expect_intersect(tri({0, 0, 0}, {4, 0, 0}, {2, 3, 0}), tri({0, 2, 0}, {4, 2, 0}, {2, -1, 0}),
                   true);
  // One ulp off the hypotenuse, inside the plane.
  const double off = std::nextafter(0.5, 1.0);
  expect_intersect(kBase, tri({off, 0.5, 0}, {1, 1, 0}, {0.75, 2, 0}), false);
}

TEST(TriangleIntersection, DegenerateTriangles) {
  // A segment (collinear corners) piercing the face, lying outside, lying in the plane.
  expect_intersect(kBase, tri({0.25, 0.25, -1}, {0.25, 0.25, 1}, {0.25, 0.25, 0.5}), true);
  expect_intersect(kBase, tri({2, 2, -1}, {2, 2, 1}, {2, 2, 0}), false);
  expect_intersect(kBase, tri({-1, 0.25, 0}, {2, 0.25, 0}, {0.5, 0.25, 0}), true);
  expect_intersect(kBase, tri({-1, 2, 0}, {2, 2, 0}, {0.5, 2, 0}), false);
  // A point (all corners equal) inside, on the boundary, outside, above.
  expect_intersect(kBase, tri({0.25, 0.25, 0}, {0.25, 0.25, 0}, {0.25, 0.25, 0}), true);
  expect_intersect(kBase, tri({0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 0}), true);
  expect_intersect(kBase, tri({0.75, 0.75, 0}, {0.75, 0.75, 0}, {0.75, 0.75, 0}), false);
  expect_intersect(kBase, tri({0.25, 0.25, 1}, {0.25, 0.25, 1}, {0.25, 0.25, 1}), false);
  // Two degenerate triangles: collinear overlapping, collinear apart, skew segments.
  const Triangle s1 = tri({0, 0, 0}, {2, 2, 2}, {1, 1, 1});
  expect_intersect(s1, tri({1.5, 1.5, 1.5}, {3, 3, 3}, {4, 4, 4}), true);
  expect_intersect(s1, tri({2.5, 2.5, 2.5}, {3, 3, 3}, {4, 4, 4}), false);
  expect_intersect(s1, tri({1, 0, 1}, {1, 2, 1}, {1, 1, 1}), true);   // cross at (1,1,1)
  expect_intersect(s1, tri({1, 0, 2}, {1, 2, 2}, {1, 1, 2}), false);  // skew
  EXPECT_TRUE(is_degenerate_triangle(s1));
  EXPECT_FALSE(is_degenerate_triangle(kBase));
  EXPECT_TRUE(is_degenerate_triangle(tri({1, 2, 3}, {1, 2, 3}, {1, 2, 3})));
}

TEST(TriangleIntersection, SegmentsAndSegmentTriangle) {
  EXPECT_TRUE(segments_intersect({0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_FALSE(segments_intersect({0, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}));
  EXPECT_TRUE(segments_intersect({0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}));  // end to end
  EXPECT_FALSE(segments_intersect({0, 0, 0}, {1, 0, 0}, {1.5, 0, 0}, {2, 0, 0}));
  EXPECT_TRUE(segments_intersect({0.5, 0, 0}, {0.5, 0, 0}, {0, 0, 0}, {1, 0, 0}));  // a point
  EXPECT_TRUE(segment_triangle_intersect({0.25, 0.25, 1}, {0.25, 0.25, 0}, kBase));
  EXPECT_FALSE(segment_triangle_intersect({0.25, 0.25, 1}, {0.25, 0.25, 0.5}, kBase));
  EXPECT_TRUE(segment_triangle_intersect({-1, 0.5, 0}, {2, 0.5, 0}, kBase));
}

TEST(TriangleIntersection, SharedVertex) {
  const Vec3 a(0, 0, 0);
  const Triangle t = tri(a, {1, 0, 0}, {0, 1, 0});
  // A fan around a out of the plane: touches only at a.
  EXPECT_FALSE(triangles_intersect_except_shared_vertex(t, tri(a, {0, 0, 1}, {-1, -1, 1})));
  // Coplanar, in the opposite quadrant: only a.
  EXPECT_FALSE(triangles_intersect_except_shared_vertex(t, tri(a, {-1, 0, 0}, {0, -1, 0})));
  // Coplanar and overlapping near a (a folded fan): the edges at a enter each other.
  EXPECT_TRUE(triangles_intersect_except_shared_vertex(t, tri(a, {1, 1, 0}, {2, 0.5, 0})));
  // Coplanar, sharing the direction of an edge at a.
  EXPECT_TRUE(triangles_intersect_except_shared_vertex(t, tri(a, {2, 0, 0}, {1, -1, 0})));
  // Coplanar, touching only along... the opposite edge crossing the other triangle.
  EXPECT_TRUE(triangles_intersect_except_shared_vertex(t, tri(a, {0.25, -1, 1}, {0.25, 1, -1})));
  // The opposite edge pierces the other triangle, edges at a stay outside.
  EXPECT_TRUE(triangles_intersect_except_shared_vertex(t, tri(a, {0.3, 0.3, 1}, {0.3, 0.3, -1})));
  // Close but apart: the far edge passes one ulp above the face.
  const double up = std::nextafter(0.0, 1.0);
  EXPECT_FALSE(triangles_intersect_except_shared_vertex(t, tri(a, {0.3, 0.3, 1}, {0.4, 0.3, up})));
  // The ordinary test sees the shared vertex.
  EXPECT_TRUE(triangles_intersect(t, tri(a, {0, 0, 1}, {-1, -1, 1})));
}

TEST(TriangleIntersection, SharedEdge) {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  const Triangle t = tri(a, b, {0, 1, 0});
  EXPECT_FALSE(triangles_intersect_except_shared_edge(t, tri(a, b, {0, 1, 1})));   // hinge
  EXPECT_FALSE(triangles_intersect_except_shared_edge(t, tri(a, b, {0, -1, 0})));  // flat
  EXPECT_TRUE(triangles_intersect_except_shared_edge(t, tri(a, b, {0.5, 2, 0})));  // folded flat
  const double up = std::nextafter(0.0, 1.0);
  EXPECT_FALSE(triangles_intersect_except_shared_edge(t, tri(a, b, {0.5, 2, up})));  // almost
}

TEST(TriangleIntersection, ClassifyFacePair) {
  Positions x(6, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 2, 0, 0, 0, 1, -1, -1, 0;
  using V = TrianglePairVerdict;
  EXPECT_EQ(classify_face_pair(x, {0, 1, 2}, {1, 0, 4}), V::disjoint);      // hinge
  EXPECT_EQ(classify_face_pair(x, {0, 1, 2}, {3, 1, 0}), V::intersecting);  // folded, ids rotated
  EXPECT_EQ(classify_face_pair(x, {0, 1, 2}, {5, 0, 4}), V::disjoint);      // shared vertex 0
  EXPECT_EQ(classify_face_pair(x, {0, 1, 2}, {2, 1, 0}), V::disjoint);      // same face
  Positions y = x;
  y.row(4) << 0.5, 0, 0;  // face (1, 0, 4) becomes a segment on the shared edge
  EXPECT_EQ(classify_face_pair(y, {0, 1, 2}, {1, 0, 4}), V::degenerate_adjacent);
  // No shared id but coinciding positions still intersect.
  Positions z = x;
  z.row(5) = z.row(2);
  EXPECT_EQ(classify_face_pair(z, {0, 1, 2}, {5, 4, 3}), V::intersecting);
}

TEST(TriangleIntersection, RandomSmallGridIsConsistent) {
  // Coordinates on a 3-point grid: nearly every case is degenerate or coplanar. The answer
  // must not depend on triangle order, corner order or exact symmetries of space, and a
  // pair of triangles must intersect whenever one corner lies in the other triangle.
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> g(0, 2);
  const auto rp = [&] { return Vec3(g(rng) * 0.5, g(rng) * 0.5, g(rng) * 0.5); };
  const int n = sanitized() ? 300 : 5000;
  int hits = 0;
  for (int i = 0; i < n; ++i) {
    const Triangle t{rp(), rp(), rp()}, u{rp(), rp(), rp()};
    const bool r = triangles_intersect(t, u);
    hits += r ? 1 : 0;
    expect_intersect(t, u, r);
    for (const Vec3& p : u) {
      if (segment_triangle_intersect(p, p, t)) {
        ASSERT_TRUE(r);
      }
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, n);
}

}  // namespace
}  // namespace tailor
