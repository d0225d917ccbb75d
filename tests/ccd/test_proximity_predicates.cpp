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

#include "support/closest_points.hpp"
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

TEST(ProximityPredicates, RandomConfigurationsAgreeWithTheClosestPointOracle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  const auto point = [&] { return Vec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  const int runs = testing::sanitized() ? 2000 : 20000;
  for (int i = 0; i < runs; ++i) {
    const FourPoints q{point(), point(), point(), point()};
    const long double vf = testing::point_triangle_distance(
        testing::wide(q[0]), testing::wide(q[1]), testing::wide(q[2]), testing::wide(q[3]));
    const long double ee = testing::segment_distance(testing::wide(q[0]), testing::wide(q[1]),
                                                     testing::wide(q[2]), testing::wide(q[3]));
    for (const double side : {1 + 1e-9, 1 - 1e-9}) {
      EXPECT_EQ(vertex_face_within(q, static_cast<double>(vf * side)), side > 1) << i;
      EXPECT_EQ(edge_edge_within(q, static_cast<double>(ee * side)), side > 1) << i;
    }
  }
}

}  // namespace
}  // namespace tailor
