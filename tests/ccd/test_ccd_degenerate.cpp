/// Hand-made degenerate cases, each colliding and missing by one ulp (std::nextafter):
/// contact only at t=0 or t=1, coplanar motion, parallel/collinear edges, zero-length edges,
/// zero-area triangles, a vertex sliding on a face or along an edge.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>

#include "ccd_test_support.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/ccd/ccd_double.hpp"
#include "tailor/ccd/ccd_exact.hpp"

namespace tailor {
namespace {

constexpr double kTiny = std::numeric_limits<double>::denorm_min();
double up(double x) {
  return std::nextafter(x, 2.0 * std::fabs(x) + 1.0);
}
double down(double x) {
  return std::nextafter(x, -2.0 * std::fabs(x) - 1.0);
}

/// Checks every tier (public pipeline, certified double tier when it answers, fixed-size
/// exact tier, its GMP instantiation) and the rational oracle on the query and on its
/// scalings by 2^±20, 2^±500 and 2^±1000 (when exact); `toi` is the true earliest contact
/// when `hit`.
template <class Q>
void expect_query(const Q& q, bool hit, double toi) {
  for (int e : {0, 20, -20, 500, -500, 1000, -1000}) {
    const Q s = e ? test::scaled(q, e) : q;
    if (!test::same(test::scaled(s, -e), q)) continue;  // scaling not exact (subnormals)
    const CcdResult answers[4] = {test::public_ccd(s), test::exact_tier(s), test::exact_tier_gmp(s),
                                  test::oracle(s)};
    const char* names[4] = {"public", "exact", "exact gmp", "oracle"};
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(answers[i].hit, hit) << names[i] << ", scale 2^" << e;
      if (hit) {
        EXPECT_LE(answers[i].toi, toi) << names[i] << ", scale 2^" << e;
        EXPECT_GE(answers[i].toi, toi - 1e-6) << names[i] << ", scale 2^" << e;
      } else {
        EXPECT_EQ(answers[i].toi, 1.0) << names[i];
      }
    }
    if (const auto d = test::double_tier(s)) {
      EXPECT_EQ(d->hit, hit) << "double, scale 2^" << e;
      if (hit) {
        EXPECT_LE(d->toi, toi);
        EXPECT_GE(d->toi, toi - 1e-6);
      }
    }
  }
}

void expect_vf(const VertexFaceQuery& q, bool hit, double toi = 0.0) {
  expect_query(q, hit, toi);
}

void expect_ee(const EdgeEdgeQuery& q, bool hit, double toi = 0.0) {
  expect_query(q, hit, toi);
}

/// A fixed unit right triangle in z = 0 and a moving point.
VertexFaceQuery vf_fixed(const Vec3& p0, const Vec3& p1) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  return {p0, a, b, c, p1, a, b, c};
}

TEST(CcdDegenerate, VfContactOnlyAtTimeOne) {
  expect_vf(vf_fixed({0.25, 0.25, 1}, {0.25, 0.25, 0}), true, 1.0);
  expect_vf(vf_fixed({0.25, 0.25, 1}, {0.25, 0.25, kTiny}), false);
  expect_vf(vf_fixed({0.25, 0.25, 1}, {0.25, 0.25, up(0.0)}), false);
  // Reaching the hypotenuse exactly at t = 1, or one ulp outside it.
  expect_vf(vf_fixed({0.5, 0.5, 1}, {0.5, 0.5, 0}), true, 1.0);
  expect_vf(vf_fixed({0.5, 0.5, 1}, {0.5, up(0.5), 0}), false);
}

TEST(CcdDegenerate, VfContactOnlyAtTimeZero) {
  expect_vf(vf_fixed({0.25, 0.25, 0}, {0.25, 0.25, 1}), true, 0.0);
  expect_vf(vf_fixed({0.25, 0.25, kTiny}, {0.25, 0.25, 1}), false);
  // At a triangle vertex at t = 0.
  expect_vf(vf_fixed({1, 0, 0}, {1, 0, 1}), true, 0.0);
  expect_vf(vf_fixed({up(1.0), 0, 0}, {1, 0, 1}), false);
}

TEST(CcdDegenerate, VfCoplanarWholeStep) {
  // p moves in the triangle's plane and enters through the hypotenuse at t = 5/6.
  expect_vf(vf_fixed({2, 2, 0}, {0.2, 0.2, 0}), true, 5.0 / 6.0);
  // Ends exactly on the hypotenuse, or one ulp outside it.
  expect_vf(vf_fixed({2, 2, 0}, {0.5, 0.5, 0}), true, 1.0);
  expect_vf(vf_fixed({2, 2, 0}, {0.5, up(0.5), 0}), false);
}

TEST(CcdDegenerate, VfVertexSlidingOnFace) {
  expect_vf(vf_fixed({0.1, 0.1, 0}, {0.3, 0.4, 0}), true, 0.0);
  // Sliding one ulp above the face.
  expect_vf(vf_fixed({0.1, 0.1, kTiny}, {0.3, 0.4, kTiny}), false);
  expect_vf(vf_fixed({0.1, 0.1, up(0.0)}, {0.3, 0.4, up(0.0)}), false);
  // Moving triangle and point together (translation): contact all the time.
  const Vec3 d(0.5, -0.25, 3);
  VertexFaceQuery q = vf_fixed({0.25, 0.5, 0}, {0.25, 0.5, 0});
  q.p_t1 += d;
  q.a_t1 += d;
  q.b_t1 += d;
  q.c_t1 += d;
  expect_vf(q, true, 0.0);
}

TEST(CcdDegenerate, VfVertexSlidingAlongEdge) {
  // Along the line of edge ab (y = 0), reaching a at t = 2/3... p.x = -1 + 1.5 t = 0.
  expect_vf(vf_fixed({-1, 0, 0}, {0.5, 0, 0}), true, 2.0 / 3.0);
  expect_vf(vf_fixed({-1, down(0.0), 0}, {0.5, down(0.0), 0}), false);
  expect_vf(vf_fixed({-1, -kTiny, 0}, {0.5, -kTiny, 0}), false);
  // Along the edge line but stopping one ulp before a.
  expect_vf(vf_fixed({-1, 0, 0}, {down(0.0), 0, 0}), false);
  expect_vf(vf_fixed({-1, 0, 0}, {0.0, 0, 0}), true, 1.0);
}

TEST(CcdDegenerate, VfZeroAreaTriangle) {
  // Collinear a, b, c on the x axis: the triangle is the segment [0, 2].
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);
  expect_vf({{0.5, 1, 1}, a, b, c, {0.5, -1, -1}, a, b, c}, true, 0.5);
  expect_vf({{1.5, 1, 1}, a, b, c, {1.5, -1, -1}, a, b, c}, true, 0.5);  // beyond ab
  expect_vf({{0, 1, 1}, a, b, c, {0, -1, -1}, a, b, c}, true, 0.5);
  expect_vf({{-kTiny, 1, 1}, a, b, c, {-kTiny, -1, -1}, a, b, c}, false);
  expect_vf({{down(0.0), 1, 1}, a, b, c, {down(0.0), -1, -1}, a, b, c}, false);
  expect_vf({{2, 1, 1}, a, b, c, {2, -1, -1}, a, b, c}, true, 0.5);
  expect_vf({{up(2.0), 1, 1}, a, b, c, {up(2.0), -1, -1}, a, b, c}, false);
  // All three vertices at one point.
  const Vec3 o(0, 0, 0);
  expect_vf({{1, 1, 1}, o, o, o, {-1, -1, -1}, o, o, o}, true, 0.5);
  expect_vf({{1, 1, 1}, o, o, o, {-1, -1, down(-1.0)}, o, o, o}, false);
  expect_vf({{1, 1, 1}, o, o, o, {-1, -1, up(-1.0)}, o, o, o}, false);
}

TEST(CcdDegenerate, VfThroughVertexAndEdge) {
  // Straight through vertex b = (1, 0, 0), and one ulp beside it.
  expect_vf(vf_fixed({1, 0, 1}, {1, 0, -1}), true, 0.5);
  expect_vf(vf_fixed({up(1.0), 0, 1}, {up(1.0), 0, -1}), false);
  expect_vf(vf_fixed({1, down(0.0), 1}, {1, down(0.0), -1}), false);
  // Through the middle of edge ab, and one ulp outside.
  expect_vf(vf_fixed({0.5, 0, 1}, {0.5, 0, -1}), true, 0.5);
  expect_vf(vf_fixed({0.5, down(0.0), 1}, {0.5, down(0.0), -1}), false);
  // Through the hypotenuse x + y = 1.
  expect_vf(vf_fixed({0.25, 0.75, 1}, {0.25, 0.75, -1}), true, 0.5);
  expect_vf(vf_fixed({0.25, up(0.75), 1}, {0.25, up(0.75), -1}), false);
}

TEST(CcdDegenerate, VfMovingTriangleGeneric) {
  // Triangle rises through a fixed point: contact at t = 0.25 exactly.
  const Vec3 a0(0, 0, -1), b0(1, 0, -1), c0(0, 1, -1);
  const Vec3 lift(0, 0, 4);
  expect_vf({{0.2, 0.2, 0}, a0, b0, c0, {0.2, 0.2, 0}, a0 + lift, b0 + lift, c0 + lift}, true,
            0.25);
  expect_vf({{0.2, 0.2, 0}, a0, b0, c0, {0.2, 0.2, 0}, a0, b0, c0}, false);
}

EdgeEdgeQuery ee(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0, const Vec3& a1,
                 const Vec3& b1, const Vec3& c1, const Vec3& d1) {
  return {a0, b0, c0, d0, a1, b1, c1, d1};
}

TEST(CcdDegenerate, EeContactOnlyAtTimeOneOrZero) {
  const Vec3 a(-1, 0, 0), b(1, 0, 0);
  // cd along y, descending onto ab.
  expect_ee(ee(a, b, {0, -1, 1}, {0, 1, 1}, a, b, {0, -1, 0}, {0, 1, 0}), true, 1.0);
  expect_ee(ee(a, b, {0, -1, 1}, {0, 1, 1}, a, b, {0, -1, kTiny}, {0, 1, kTiny}), false);
  expect_ee(ee(a, b, {0, -1, 1}, {0, 1, 1}, a, b, {0, -1, up(0.0)}, {0, 1, 0}), false);
  expect_ee(ee(a, b, {0, -1, 0}, {0, 1, 0}, a, b, {0, -1, 1}, {0, 1, 1}), true, 0.0);
  expect_ee(ee(a, b, {0, -1, kTiny}, {0, 1, 0}, a, b, {0, -1, 1}, {0, 1, 1}), false);
}

TEST(CcdDegenerate, EeParallelAndCollinear) {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  // Collinear: cd slides along the x axis and overlaps ab from t = 2/3 on.
  expect_ee(ee(a, b, {2, 0, 0}, {3, 0, 0}, a, b, {0.5, 0, 0}, {1.5, 0, 0}), true, 2.0 / 3.0);
  // Parallel one ulp away (coplanar for the whole step, never touching).
  expect_ee(ee(a, b, {2, kTiny, 0}, {3, kTiny, 0}, a, b, {0.5, kTiny, 0}, {1.5, kTiny, 0}), false);
  expect_ee(ee(a, b, {2, up(0.0), 0}, {3, up(0.0), 0}, a, b, {0.5, up(0.0), 0}, {1.5, up(0.0), 0}),
            false);
  // Collinear, stopping one ulp short of touching at t = 1, or touching exactly.
  expect_ee(ee(a, b, {2, 0, 0}, {3, 0, 0}, a, b, {up(1.0), 0, 0}, {2, 0, 0}), false);
  expect_ee(ee(a, b, {2, 0, 0}, {3, 0, 0}, a, b, {1, 0, 0}, {2, 0, 0}), true, 1.0);
  // Parallel, in parallel planes approaching: touch at t = 1 only.
  expect_ee(ee(a, b, {0.5, 1, 1}, {1.5, 1, 1}, a, b, {0.5, 0, 0}, {1.5, 0, 0}), true, 1.0);
  expect_ee(ee(a, b, {0.5, 1, 1}, {1.5, 1, 1}, a, b, {0.5, 0, kTiny}, {1.5, 0, kTiny}), false);
}

TEST(CcdDegenerate, EeZeroLengthEdges) {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  // c = d: a point crossing segment ab at t = 0.5, and one ulp beside its end.
  expect_ee(ee(a, b, {0.5, 1, 1}, {0.5, 1, 1}, a, b, {0.5, -1, -1}, {0.5, -1, -1}), true, 0.5);
  expect_ee(ee(a, b, {1, 1, 1}, {1, 1, 1}, a, b, {1, -1, -1}, {1, -1, -1}), true, 0.5);
  expect_ee(ee(a, b, {up(1.0), 1, 1}, {up(1.0), 1, 1}, a, b, {up(1.0), -1, -1}, {up(1.0), -1, -1}),
            false);
  // Both edges points, meeting at t = 0.5 or missing by one ulp.
  const Vec3 o(0, 0, 0);
  expect_ee(ee(o, o, {1, 1, 1}, {1, 1, 1}, o, o, {-1, -1, -1}, {-1, -1, -1}), true, 0.5);
  expect_ee(ee(o, o, {1, 1, 1}, {1, 1, 1}, o, o, {-1, -1, down(-1.0)}, {-1, -1, down(-1.0)}),
            false);
}

TEST(CcdDegenerate, EeEndpointTouching) {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  // c slides down onto b exactly at t = 1 (T-shape), or one ulp beside it.
  expect_ee(ee(a, b, {1, 0, 1}, {1, 0, 2}, a, b, {1, 0, 0}, {1, 0, 1}), true, 1.0);
  expect_ee(ee(a, b, {up(1.0), 0, 1}, {up(1.0), 0, 2}, a, b, {up(1.0), 0, 0}, {up(1.0), 0, 1}),
            false);
  // Endpoint to endpoint crossing at t = 0.5.
  expect_ee(ee(a, b, {1, 1, 1}, {2, 1, 1}, a, b, {1, -1, -1}, {2, -1, -1}), true, 0.5);
  expect_ee(ee(a, b, {up(1.0), 1, 1}, {2, 1, 1}, a, b, {up(1.0), -1, -1}, {2, -1, -1}), false);
}

TEST(CcdDegenerate, EeCoplanarCrossing) {
  // Both edges in z = 0 for the whole step; cd (vertical) moves left and meets ab's end
  // at t = 2/3.
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  expect_ee(ee(a, b, {2, -1, 0}, {2, 1, 0}, a, b, {0.5, -1, 0}, {0.5, 1, 0}), true, 2.0 / 3.0);
  expect_ee(ee(a, b, {2, 0, 0}, {2, 1, 0}, a, b, {0.5, 0, 0}, {0.5, 1, 0}), true, 2.0 / 3.0);
  expect_ee(ee(a, b, {2, kTiny, 0}, {2, 1, 0}, a, b, {0.5, kTiny, 0}, {0.5, 1, 0}), false);
  expect_ee(ee(a, b, {2, up(0.0), 0}, {2, 1, 0}, a, b, {0.5, up(0.0), 0}, {0.5, 1, 0}), false);
}

TEST(CcdDegenerate, EeGenericCrossing) {
  const Vec3 a(-1, 0, 0), b(1, 0, 0);
  expect_ee(ee(a, b, {0.25, -1, 1}, {0.25, 1, 1}, a, b, {0.25, -1, -3}, {0.25, 1, -3}), true, 0.25);
  expect_ee(ee(a, b, {0.25, -1, 1}, {0.25, 1, 1}, a, b, {0.25, -1, 0.5}, {0.25, 1, 0.5}), false);
}

TEST(CcdDegenerate, VfCoplanarRotatingPlane) {
  // An affine motion keeps the four points coplanar while their plane turns from z = 0 to
  // x = 0: (X, Y, 0) -> (0, Y, X). Contact status never changes.
  auto turn = [](double x, double y) { return Vec3(0.0, y, x); };
  auto query = [&](double px, double py) {
    return VertexFaceQuery{{px, py, 0},  {0, 0, 0},  {1, 0, 0},  {0, 1, 0},
                           turn(px, py), turn(0, 0), turn(1, 0), turn(0, 1)};
  };
  expect_vf(query(0.25, 0.25), true, 0.0);  // inside throughout
  expect_vf(query(0.5, 0.5), true, 0.0);    // on the hypotenuse throughout
  expect_vf(query(0.5, up(0.5)), false);    // one ulp outside it
  expect_vf(query(-kTiny, 0.25), false);    // a subnormal outside edge ca
  expect_vf(query(0.0, 0.0), true, 0.0);    // at a vertex
}

TEST(CcdDegenerate, EeCoplanarRotatingPlane) {
  auto turn = [](double x, double y) { return Vec3(0.0, y, x); };
  auto query = [&](double cx, double cy, double dx, double dy) {
    return EdgeEdgeQuery{{0, 0, 0},  {1, 0, 0},  {cx, cy, 0},  {dx, dy, 0},
                         turn(0, 0), turn(1, 0), turn(cx, cy), turn(dx, dy)};
  };
  expect_ee(query(0.5, -1, 0.5, 1), true, 0.0);   // crossing throughout
  expect_ee(query(0.5, 0, 0.5, 1), true, 0.0);    // endpoint on the edge
  expect_ee(query(0.5, up(0.0), 0.5, 1), false);  // a subnormal above it
  expect_ee(query(1, 0, 2, 0), true, 0.0);        // collinear, touching at b
  expect_ee(query(up(1.0), 0, 2, 0), false);      // collinear, one ulp apart
}

TEST(CcdDegenerate, ExtremeExponentSpread) {
  // Issue 17: coordinates from a subnormal (1e-309) to 1e148 in one query. The exact
  // integers then need ~1600 bits per coordinate: the exact tier's GMP last resort decides,
  // and must agree with the rational oracle. c crosses the x axis at t = 1/2 at x = 1e-309,
  // inside segment [0, 1e148] (a hit), or at -1e-309 (a miss by a subnormal), or the
  // segment starts at +1e-309 while c crosses at 0 (a miss).
  const double huge = 1e148, tiny = 1e-309;
  auto query = [&](double a_x, double c_x) {
    return EdgeEdgeQuery{{a_x, 0, 0}, {huge, 0, 0}, {c_x, 1, 1},   {c_x, 1, 2},
                         {a_x, 0, 0}, {huge, 0, 0}, {c_x, -1, -1}, {c_x, -1, 0}};
  };
  for (const auto& [a_x, c_x, hit] : {std::tuple{0.0, tiny, true}, std::tuple{0.0, -tiny, false},
                                      std::tuple{tiny, 0.0, false}, std::tuple{tiny, tiny, true}}) {
    const EdgeEdgeQuery q = query(a_x, c_x);
    const CcdResult r = edge_edge_ccd(q);
    EXPECT_EQ(r.hit, hit) << a_x << " " << c_x;
    EXPECT_EQ(test::oracle(q).hit, hit);
    EXPECT_TRUE(r.path == CcdPath::exact || r.path == CcdPath::gmp) << ccd_path_name(r.path);
    if (hit) {
      EXPECT_LE(r.toi, 0.5);
      EXPECT_GE(r.toi, 0.5 - 1e-6);
    }
  }
  // The same with a vertex and a triangle spanning 1e148.
  const VertexFaceQuery vf{{tiny, tiny, 1},  {0, 0, 0}, {huge, 0, 0}, {0, huge, 0},
                           {tiny, tiny, -1}, {0, 0, 0}, {huge, 0, 0}, {0, huge, 0}};
  EXPECT_TRUE(vertex_face_ccd(vf).hit);
  EXPECT_TRUE(test::oracle(vf).hit);
  const VertexFaceQuery vf_out{{-tiny, tiny, 1},  {0, 0, 0}, {huge, 0, 0}, {0, huge, 0},
                               {-tiny, tiny, -1}, {0, 0, 0}, {huge, 0, 0}, {0, huge, 0}};
  EXPECT_FALSE(vertex_face_ccd(vf_out).hit);
  EXPECT_FALSE(test::oracle(vf_out).hit);
}

TEST(CcdDegenerate, NonFiniteInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(vertex_face_ccd(vf_fixed({nan, 0, 1}, {0, 0, -1})), std::invalid_argument);
}

}  // namespace
}  // namespace tailor
