/// @file
/// Exact proximity predicates: distances that are exactly h (in and just out), every
/// feature region of a triangle and of two segments, degenerate primitives, scale
/// invariance down to subnormal-adjacent scales, and random configurations against an
/// independent long-double closest-point oracle probed 1e-9 on each side of the distance.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "support/sanitized.hpp"
#include "tailor/ccd/proximity_predicates.hpp"

namespace tailor {
namespace {

double below(double h) {
  return std::nextafter(h, 0.0);
}

TEST(ProximityPredicates, VertexFaceIsExactAtTheDistanceInEveryRegion) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Above the interior, beyond an edge, beyond a vertex: distance 0.5, 0.5 and 1.25.
  const FourPoints over{Vec3(0.25, 0.25, 0.5), a, b, c};
  EXPECT_TRUE(vertex_face_within(over, 0.5));
  EXPECT_FALSE(vertex_face_within(over, below(0.5)));
  const FourPoints beside_edge{Vec3(0.5, -0.5, 0), a, b, c};
  EXPECT_TRUE(vertex_face_within(beside_edge, 0.5));
  EXPECT_FALSE(vertex_face_within(beside_edge, below(0.5)));
  const FourPoints beyond_vertex{Vec3(-0.75, -1, 0), a, b, c};
  EXPECT_TRUE(vertex_face_within(beyond_vertex, 1.25));
  EXPECT_FALSE(vertex_face_within(beyond_vertex, below(1.25)));
  // On the triangle: within 0; just above it: not.
  EXPECT_TRUE(vertex_face_within({Vec3(0.5, 0.5, 0), a, b, c}, 0.0));
  EXPECT_FALSE(vertex_face_within({Vec3(0.25, 0.25, 0x1p-60), a, b, c}, 0.0));
  EXPECT_TRUE(vertex_face_within({Vec3(0.25, 0.25, 0x1p-60), a, b, c}, 0x1p-60));
  // The plane is close but the projection is outside: the distance is to the edge.
  const FourPoints outside{Vec3(2, 2, 0.1), a, b, c};
  EXPECT_FALSE(vertex_face_within(outside, 0.2));
}

TEST(ProximityPredicates, DegenerateTriangleIsItsEdges) {
  // Collinear corners: the segment from (0,0,0) to (2,0,0).
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);
  EXPECT_TRUE(vertex_face_within({Vec3(1.5, 0.25, 0), a, b, c}, 0.25));
  EXPECT_FALSE(vertex_face_within({Vec3(1.5, 0.25, 0), a, b, c}, below(0.25)));
  // All three corners at one point.
  EXPECT_TRUE(vertex_face_within({Vec3(0, 0, 0.75), a, a, a}, 0.75));
  EXPECT_FALSE(vertex_face_within({Vec3(0, 0, 0.75), a, a, a}, below(0.75)));
}

TEST(ProximityPredicates, EdgeEdgeIsExactAtTheDistanceInEveryRegion) {
  // Skew segments crossing over each other at distance 0.5.
  const FourPoints skew{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 0.5), Vec3(0.5, 1, 0.5)};
  EXPECT_TRUE(edge_edge_within(skew, 0.5));
  EXPECT_FALSE(edge_edge_within(skew, below(0.5)));
  // The lines cross, but beyond the end of one segment: endpoint (1,0,0) to the other.
  const FourPoints past_end{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.5, -1, 0.5), Vec3(1.5, 1, 0.5)};
  const double d = std::sqrt(0.25 + 0.25);
  EXPECT_FALSE(edge_edge_within(past_end, 0.5));
  EXPECT_TRUE(edge_edge_within(past_end, std::nextafter(d, 1.0)));
  // Parallel, overlapping in x, 0.3 apart; collinear and overlapping: distance 0.
  const FourPoints parallel{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.3, 0), Vec3(2, 0.3, 0)};
  EXPECT_TRUE(edge_edge_within(parallel, 0.3));
  EXPECT_FALSE(edge_edge_within(parallel, below(0.3)));
  const FourPoints collinear{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0), Vec3(2, 0, 0)};
  EXPECT_TRUE(edge_edge_within(collinear, 0.0));
  // Crossing exactly: within 0.
  EXPECT_TRUE(edge_edge_within({Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 1, 0)}, 0));
  // A degenerate segment (a point) against a segment.
  EXPECT_TRUE(edge_edge_within({Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(1, 0, 0)}, 1));
  EXPECT_FALSE(
      edge_edge_within({Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(1, 0, 0)}, below(1)));
}

TEST(ProximityPredicates, AnswersDoNotChangeWithAPowerOfTwoScale) {
  const FourPoints vf{Vec3(0.25, 0.25, 0.5), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const FourPoints ee{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 0.5), Vec3(0.5, 1, 0.5)};
  for (const int e : {-500, -200, -30, 0, 30, 200, 400}) {
    const double s = std::ldexp(1.0, e);
    FourPoints svf = vf, see = ee;
    for (Vec3& p : svf) p *= s;
    for (Vec3& p : see) p *= s;
    EXPECT_TRUE(vertex_face_within(svf, 0.5 * s)) << e;
    EXPECT_FALSE(vertex_face_within(svf, below(0.5 * s))) << e;
    EXPECT_TRUE(edge_edge_within(see, 0.5 * s)) << e;
    EXPECT_FALSE(edge_edge_within(see, below(0.5 * s))) << e;
  }
}

TEST(ProximityPredicates, BadInputIsRefused) {
  const FourPoints ok{Vec3(0, 0, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_THROW(vertex_face_within(ok, -1), std::invalid_argument);
  EXPECT_THROW(edge_edge_within(ok, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  FourPoints bad = ok;
  bad[2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(vertex_face_within(bad, 1), std::invalid_argument);
  EXPECT_THROW(edge_edge_within(bad, 1), std::invalid_argument);
}

// The oracle: closest points in long double (Ericson, Real-Time Collision Detection, 5.1.5
// and 5.1.9), independent of the predicates' feature conditions.
using L3 = Eigen::Matrix<long double, 3, 1>;

L3 wide(const Vec3& p) {
  return p.cast<long double>();
}

long double point_triangle_distance(const L3& p, const L3& a, const L3& b, const L3& c) {
  const L3 ab = b - a, ac = c - a, ap = p - a;
  const long double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const L3 bp = p - b;
  const long double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const long double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const L3 cp = p - c;
  const long double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const long double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const long double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const long double denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

long double segment_distance(const L3& p1, const L3& q1, const L3& p2, const L3& q2) {
  const L3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const long double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  const long double c = d1.dot(r), b = d1.dot(d2), denom = a * e - b * b;
  long double s = denom != 0 ? std::clamp((b * f - c * e) / denom, 0.0L, 1.0L) : 0.0L;
  long double t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0L, 1.0L);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0L, 1.0L);
  }
  return ((p1 + d1 * s) - (p2 + d2 * t)).norm();
}

TEST(ProximityPredicates, RandomConfigurationsAgreeWithTheClosestPointOracle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  const auto point = [&] { return Vec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  const int runs = testing::sanitized() ? 2000 : 20000;
  for (int i = 0; i < runs; ++i) {
    const FourPoints q{point(), point(), point(), point()};
    const long double vf = point_triangle_distance(wide(q[0]), wide(q[1]), wide(q[2]), wide(q[3]));
    const long double ee = segment_distance(wide(q[0]), wide(q[1]), wide(q[2]), wide(q[3]));
    for (const double side : {1 + 1e-9, 1 - 1e-9}) {
      EXPECT_EQ(vertex_face_within(q, static_cast<double>(vf * side)), side > 1) << i;
      EXPECT_EQ(edge_edge_within(q, static_cast<double>(ee * side)), side > 1) << i;
    }
  }
}

}  // namespace
}  // namespace tailor
