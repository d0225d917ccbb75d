/// @file
/// Minimum-separation CCD: designed motions whose first time within h is known exactly
/// (falling through a face, crossing edges, touching at t = 0 and t = 1, sliding parallel
/// just outside h, a tiny h beside a large motion), and random motions against a
/// long-double closest-point oracle sampled over the step, with h just above and just below
/// the oracle's minimum distance.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>

#include "support/closest_points.hpp"
#include "support/sanitized.hpp"
#include "tailor/ccd/separating_axes.hpp"
#include "tailor/ccd/thickness_ccd.hpp"

namespace tailor {
namespace {

VertexFaceQuery falling_vertex(double z0, double z1) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  return {Vec3(0.25, 0.25, z0), a, b, c, Vec3(0.25, 0.25, z1), a, b, c};
}

/// A result's time is a lower bound of `first` and within 1e-6 of it.
void expect_first_time(const ThicknessResult& r, double first) {
  ASSERT_TRUE(r.hit);
  EXPECT_FALSE(r.exhausted);
  EXPECT_LE(r.toi, first);
  EXPECT_GE(r.toi, first - 1e-6);
}

TEST(ThicknessCcd, VertexFallingThroughAFaceComesWithinHWhenExpected) {
  // z(t) = 1 - 2t: within 0.5 from t = 0.25.
  expect_first_time(vertex_face_ccd_within(falling_vertex(1, -1), 0.5), 0.25);
  // Stopping at 0.5 exactly touches the thickness at t = 1.
  expect_first_time(vertex_face_ccd_within(falling_vertex(1, 0.5), 0.5), 1.0);
  // Stopping 1e-3 short of it: no hit.
  const ThicknessResult short_of = vertex_face_ccd_within(falling_vertex(1, 0.5005), 0.5);
  EXPECT_FALSE(short_of.hit);
  EXPECT_FALSE(short_of.exhausted);
  // Starting within: at t = 0.
  expect_first_time(vertex_face_ccd_within(falling_vertex(0.25, 2), 0.5), 0.0);
  // A tiny thickness beside a unit motion: the first time is 0.5 - 5e-13.
  expect_first_time(vertex_face_ccd_within(falling_vertex(1, -1), 1e-12), 0.5 - 5e-13);
}

TEST(ThicknessCcd, VertexPassingBesideTheFaceUsesTheEdgesAndCorners) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Moving along y = -0.25 (beside edge ab) at height 0: distance 0.25 while over the edge.
  const VertexFaceQuery beside{Vec3(-2, -0.25, 0), a, b, c, Vec3(2, -0.25, 0), a, b, c};
  // x(t) = -2 + 4t; within 0.25 of corner a from x = 0 on: t = 0.5 (distance to ab is
  // 0.25 exactly on 0 <= x <= 1).
  expect_first_time(vertex_face_ccd_within(beside, 0.25), 0.5);
  EXPECT_FALSE(vertex_face_ccd_within(beside, 0.2499).hit);
}

TEST(ThicknessCcd, EdgesCrossingAndSlidingParallel) {
  // Edge cd crosses over ab from z = 1 to z = -1: distance |1 - 2t|, within 0.25 at 0.375.
  const EdgeEdgeQuery crossing{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 1),  Vec3(0.5, 1, 1),
                               Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, -1), Vec3(0.5, 1, -1)};
  expect_first_time(edge_edge_ccd_within(crossing, 0.25), 0.375);
  // Parallel edges 0.3 apart sliding past each other: within 0.3 the whole time, not within
  // 0.2997 ever.
  const EdgeEdgeQuery sliding{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(-2, 0.3, 0), Vec3(-1, 0.3, 0),
                              Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0.3, 0),  Vec3(3, 0.3, 0)};
  // Overlapping in x only for t in [0.25, 0.75]; before, the ends are farther.
  expect_first_time(edge_edge_ccd_within(sliding, 0.3), 0.25);
  const ThicknessResult outside = edge_edge_ccd_within(sliding, 0.2997);
  EXPECT_FALSE(outside.hit);
  EXPECT_FALSE(outside.exhausted);
}

TEST(ThicknessCcd, NothingMovingIsOneExactDecision) {
  const ThicknessResult still = vertex_face_ccd_within(falling_vertex(0.5, 0.5), 0.5);
  EXPECT_TRUE(still.hit);
  EXPECT_EQ(still.toi, 0.0);
  EXPECT_FALSE(vertex_face_ccd_within(falling_vertex(0.5, 0.5), std::nextafter(0.5, 0)).hit);
}

TEST(ThicknessCcd, BadInputIsRefused) {
  EXPECT_THROW(vertex_face_ccd_within(falling_vertex(1, -1), 0), std::invalid_argument);
  EXPECT_THROW(vertex_face_ccd_within(falling_vertex(1, std::nan("")), 0.1), std::invalid_argument);
  EdgeEdgeQuery bad{};
  bad.ea0_t1.x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(edge_edge_ccd_within(bad, 0.1), std::invalid_argument);
}

/// The oracle's distance over the step, sampled: its minimum and the first sample within h.
struct Sampled {
  long double minimum = 1e300L;
  double first_within = 2;  // > 1: never
};

template <class Distance>
Sampled sample(Distance&& distance, long double h, int samples) {
  Sampled s;
  for (int i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / samples;
    const long double d = distance(t);
    s.minimum = std::min(s.minimum, d);
    if (d <= h && s.first_within > 1) s.first_within = t;
  }
  return s;
}

/// The sampled distances over the step of the four points as a vertex-face pair and as an
/// edge-edge pair (their minima are upper bounds of the true ones).
std::pair<Sampled, Sampled> sampled_minima(const FourPoints& x0, const FourPoints& x1,
                                           int samples) {
  const auto at = [&](int j, double t) { return testing::wide(Vec3((1 - t) * x0[j] + t * x1[j])); };
  const Sampled vf = sample(
      [&](double t) {
        return testing::point_triangle_distance(at(0, t), at(1, t), at(2, t), at(3, t));
      },
      0, samples);
  const Sampled ee = sample(
      [&](double t) { return testing::segment_distance(at(0, t), at(1, t), at(2, t), at(3, t)); },
      0, samples);
  return {vf, ee};
}

TEST(ThicknessCcd, RandomMotionsAgreeWithTheSampledOracle) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-1, 1), step(-0.5, 0.5);
  const auto point = [&] { return Vec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  const auto moved = [&](const Vec3& p) { return Vec3(p + Vec3(step(rng), step(rng), step(rng))); };
  const int runs = testing::sanitized() ? 100 : 1000, samples = 4000;
  int hits = 0, exhausted = 0;
  for (int i = 0; i < runs; ++i) {
    const FourPoints x0{point(), point(), point(), point()};
    const FourPoints x1{moved(x0[0]), moved(x0[1]), moved(x0[2]), moved(x0[3])};
    const auto at = [&](int k, double t) {
      return testing::wide(Vec3((1 - t) * x0[k] + t * x1[k]));
    };
    const auto vf = [&](double t) {
      return testing::point_triangle_distance(at(0, t), at(1, t), at(2, t), at(3, t));
    };
    const auto ee = [&](double t) {
      return testing::segment_distance(at(0, t), at(1, t), at(2, t), at(3, t));
    };
    const VertexFaceQuery vq{x0[0], x0[1], x0[2], x0[3], x1[0], x1[1], x1[2], x1[3]};
    const EdgeEdgeQuery eq{x0[0], x0[1], x0[2], x0[3], x1[0], x1[1], x1[2], x1[3]};
    for (const bool face : {true, false}) {
      const Sampled s0 = face ? sample(vf, 0, samples) : sample(ee, 0, samples);
      if (s0.minimum < 1e-3) continue;  // the pair touches: h = 0 is the exact CCD's job
      // Just above the sampled minimum: within h, at or before the first sample within h.
      const double above = static_cast<double>(s0.minimum * (1 + 1e-3L));
      const Sampled s = face ? sample(vf, above, samples) : sample(ee, above, samples);
      const ThicknessResult r =
          face ? vertex_face_ccd_within(vq, above) : edge_edge_ccd_within(eq, above);
      ASSERT_TRUE(r.hit) << i << (face ? " vf" : " ee");
      EXPECT_LE(r.toi, s.first_within + 1e-12) << i;
      ++hits;
      exhausted += r.exhausted;
      // Below the true minimum (the sampled one is an upper bound of it): the sampled
      // minimum can only overestimate by the sampling gap, far below 1e-3 relative here.
      const double under = static_cast<double>(s0.minimum * (1 - 1e-3L));
      const ThicknessResult miss =
          face ? vertex_face_ccd_within(vq, under) : edge_edge_ccd_within(eq, under);
      EXPECT_FALSE(miss.hit && !miss.exhausted) << i << (face ? " vf" : " ee");
      exhausted += miss.exhausted;
    }
  }
  EXPECT_GT(hits, runs);  // most motions were tested both ways
  EXPECT_EQ(exhausted, 0);
}

bool vertex_face_apart(const VertexFaceQuery& q, double h) {
  return apart_along_a_coordinate_axis({q.p_t0, q.a_t0, q.b_t0, q.c_t0},
                                       {q.p_t1, q.a_t1, q.b_t1, q.c_t1}, PairShape::vertex_face, h);
}

bool edge_edge_apart(const EdgeEdgeQuery& q, double h) {
  return apart_along_a_coordinate_axis({q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0},
                                       {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1},
                                       PairShape::edge_edge, h);
}

TEST(ThicknessCcd, AxisTestKeepsPairsExactlyHApartAndThoseThatCloseIn) {
  // The triangle exactly h beyond p along x at both ends: within h (distance = h).
  const double h = 0.1;
  const Vec3 a(h, -1, -1), b(h, 1, -1), c(h, 0, 1);
  const VertexFaceQuery level{Vec3::Zero(), a, b, c, Vec3::Zero(), a, b, c};
  EXPECT_FALSE(vertex_face_apart(level, h));
  EXPECT_TRUE(vertex_face_apart(level, 0.99 * h));
  EXPECT_TRUE(vertex_face_ccd_within(level, h).hit);
  // Far apart at t = 0, through each other at t = 1: no axis holds over the step.
  const Vec3 shift(2, 0, 0);
  const VertexFaceQuery closing{Vec3::Zero(), a + shift, b + shift, c + shift,
                                Vec3::Zero(), a - shift, b - shift, c - shift};
  EXPECT_FALSE(vertex_face_apart(closing, h));
  // Edges: cd exactly h above ab along z at t = 1, farther at t = 0.
  const EdgeEdgeQuery edges{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1), Vec3(0, 1, 1),
                            Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, h), Vec3(0, 1, h)};
  EXPECT_FALSE(edge_edge_apart(edges, h));
  EXPECT_TRUE(edge_edge_apart(edges, 0.99 * h));
}

TEST(ThicknessCcd, AxisTestNeverClaimsAPairTheOracleSeesWithinH) {
  // Layers sliding together: the second primitive a random gap beyond the first along a
  // random axis, both carried by one large motion plus a small relative one, so the
  // swept boxes overlap while an axis often separates the pair. Whenever the test claims
  // "more than h apart", the sampled distance (an upper bound of the true minimum) must
  // exceed h; and it must claim it for some pairs, or this test would show nothing.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> coordinate(-1, 1), gap(0, 0.5), wobble(-0.05, 0.05);
  std::uniform_int_distribution<int> axis(0, 2);
  const auto point = [&] { return Vec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  const int runs = testing::sanitized() ? 200 : 2000, samples = 2000;
  int claimed = 0;
  for (int i = 0; i < runs; ++i) {
    const int k = axis(rng);
    FourPoints x0{point(), point(), point(), point()};
    // Corners 1-3 lie beyond corner 0 along k (a layer above the other); for the edge
    // pair, corners 2-3 beyond 0-1.
    for (int j = 1; j < 4; ++j) x0[j][k] = x0[0][k] + gap(rng);
    x0[1][k] = x0[0][k] + wobble(rng);  // the edge pair's first edge: roughly level
    const Vec3 carried = 3 * point();
    FourPoints x1;
    for (int j = 0; j < 4; ++j) {
      x1[j] = x0[j] + carried + Vec3(wobble(rng), wobble(rng), wobble(rng));
    }
    const auto [vf, ee] = sampled_minima(x0, x1, samples);
    const VertexFaceQuery vq{x0[0], x0[1], x0[2], x0[3], x1[0], x1[1], x1[2], x1[3]};
    const EdgeEdgeQuery eq{x0[0], x0[1], x0[2], x0[3], x1[0], x1[1], x1[2], x1[3]};
    for (const double share : {0.25, 0.5, 0.9, 1.0, 1.1}) {
      const double hv = static_cast<double>(vf.minimum) * share + 1e-9;
      const double he = static_cast<double>(ee.minimum) * share + 1e-9;
      if (vertex_face_apart(vq, hv)) {
        ++claimed;
        EXPECT_GT(vf.minimum, hv) << i;
        EXPECT_FALSE(vertex_face_ccd_within(vq, hv).hit) << i;
      }
      if (edge_edge_apart(eq, he)) {
        ++claimed;
        EXPECT_GT(ee.minimum, he) << i;
        EXPECT_FALSE(edge_edge_ccd_within(eq, he).hit) << i;
      }
    }
  }
  EXPECT_GT(claimed, runs);
}

bool apart_along_normals(const FourPoints& x0, const FourPoints& x1, PairShape shape, double h) {
  return apart_along_normals(x0, x1, CornerDifferences(x0, x1, shape), shape, h);
}

TEST(ThicknessCcd, NormalTestKeepsPairsExactlyHApart) {
  // A tilted face exactly h beyond p along its normal at both ends (p above its interior):
  // within h, so not claimed; with 0.99 h claimed. The same for two edges h apart along
  // their cross product.
  const double h = 0.1;
  const Vec3 n = Vec3(1, 2, 2) / 3;
  const Vec3 e1 = Vec3(2, -1, 0) / std::sqrt(5.0), e2 = n.cross(e1);
  const Vec3 p = Vec3(0.3, -0.2, 0.5), q = p + h * n;
  const FourPoints face{p, q - e1 - e2, q + e1 - e2, q + e2};
  EXPECT_FALSE(apart_along_normals(face, face, PairShape::vertex_face, h));
  EXPECT_TRUE(apart_along_normals(face, face, PairShape::vertex_face, 0.99 * h));
  const FourPoints edges{p - e1, p + e1, q - e2, q + e2};
  EXPECT_FALSE(apart_along_normals(edges, edges, PairShape::edge_edge, h));
  EXPECT_TRUE(apart_along_normals(edges, edges, PairShape::edge_edge, 0.99 * h));
  // Beyond at t = 0, through the face at t = 1: not claimed for any h.
  FourPoints through = face;
  through[0] = p + 2 * h * n;
  EXPECT_FALSE(apart_along_normals(face, through, PairShape::vertex_face, 1e-6));
}

TEST(ThicknessCcd, NormalTestNeverClaimsAPairTheOracleSeesWithinH) {
  // Layers along a random direction: the second primitive a random gap beyond the first,
  // the whole pair turned by a random small rotation over the step and moved, with a
  // relative motion that brings a third of the pairs through each other. Whenever the
  // normal test claims "more than h apart", the sampled distance (an upper bound of the
  // true minimum) must exceed h; it must claim some pairs; and at h above the sampled
  // minimum it must claim none.
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> coordinate(-1, 1), gap(0.01, 0.4), angle(-0.3, 0.3),
      closing(-0.6, 0.1);
  const auto point = [&] { return Vec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  const int runs = testing::sanitized() ? 200 : 2000, samples = 2000;
  int claimed = 0;
  for (int i = 0; i < runs; ++i) {
    const Vec3 n = point().normalized();
    FourPoints x0{point(), point(), point(), point()};
    const auto lift = [&](int j, double by) { x0[j] += (by - n.dot(x0[j] - x0[0])) * n; };
    lift(1, 0.02 * coordinate(rng));  // the edge pair's first edge: roughly level with corner 0
    for (int j = 2; j < 4; ++j) lift(j, gap(rng));
    if (i % 2 == 0) lift(1, gap(rng));  // vertex-face: the whole face beyond p
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(angle(rng), point().normalized()).toRotationMatrix();
    const Vec3 carried = point(), relative = closing(rng) * n;
    FourPoints x1;
    for (int j = 0; j < 4; ++j)
      x1[j] = turn * (x0[j] + (j >= 2 ? relative : Vec3::Zero())) + carried;
    const auto [vf, ee] = sampled_minima(x0, x1, samples);
    for (const double share : {0.25, 0.5, 0.9, 1.0, 1.01}) {
      for (const auto& [shape, s] :
           {std::pair{PairShape::vertex_face, vf}, std::pair{PairShape::edge_edge, ee}}) {
        const double h = static_cast<double>(s.minimum) * share + 1e-12;
        if (apart_along_normals(x0, x1, shape, h)) {
          ++claimed;
          EXPECT_GT(s.minimum, h) << i << " share " << share;
        }
      }
    }
  }
  EXPECT_GT(claimed, runs / 2);
}

TEST(ThicknessCcd, WitnessClaimsOnlyPairsWithinH) {
  // Random configurations at three scales, alone and as the time t of a random step: the
  // witness "within h at this instant" may claim a pair only when the long-double
  // distance is at most h, must claim nearly every pair 1e-9 relative above its distance,
  // and none 1e-12 below it.
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> coordinate(-1, 1), time(0, 1);
  const int runs = testing::sanitized() ? 300 : 3000;
  int claimed = 0, tried = 0;
  for (const double scale : {1.0, 0x1p-200, 0x1p200}) {
    const auto point = [&] {
      return Vec3(scale * coordinate(rng), scale * coordinate(rng), scale * coordinate(rng));
    };
    for (int i = 0; i < runs; ++i) {
      const FourPoints x0{point(), point(), point(), point()};
      const FourPoints x1{point(), point(), point(), point()};
      const bool in_step = i % 2 == 1;
      const double t = in_step ? time(rng) : 0.0;
      const auto w = [&](int k) {
        return testing::L3(testing::wide(x0[k]) +
                           static_cast<long double>(t) *
                               (testing::wide(x1[k]) - testing::wide(x0[k])));
      };
      for (const PairShape shape : {PairShape::vertex_face, PairShape::edge_edge}) {
        const long double d = shape == PairShape::vertex_face
                                  ? testing::point_triangle_distance(w(0), w(1), w(2), w(3))
                                  : testing::segment_distance(w(0), w(1), w(2), w(3));
        if (!(d > 0)) continue;
        const auto claims = [&](double h) {
          return in_step ? within_by_closest_points(x0, x1, t, shape, h)
                         : within_by_closest_points(x0, shape, h);
        };
        ++tried;
        if (claims(static_cast<double>(d * (1 + 1e-9L)))) ++claimed;
        EXPECT_FALSE(claims(static_cast<double>(d * (1 - 1e-12L))))
            << i << " at scale " << scale << ", t = " << t;
      }
    }
  }
  EXPECT_GT(claimed, tried * 99 / 100);
}

TEST(ThicknessCcd, AdvanceFromStartWeightsIsTheAdvanceFromZero) {
  // The search's first advancement reuses the closest weights the witness at t = 0 formed:
  // it must clear exactly what the advancement from t = 0 clears, and the witness must say
  // what it says without them, for random pairs near each other (most advance part way).
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> coordinate(-1, 1), motion(-0.3, 0.3);
  int advanced = 0;
  for (int i = 0; i < 2000; ++i) {
    FourPoints x0, x1;
    for (int k = 0; k < 4; ++k) {
      x0[k] = Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
      x1[k] = x0[k] + Vec3(motion(rng), motion(rng), motion(rng));
    }
    for (const PairShape shape : {PairShape::vertex_face, PairShape::edge_edge}) {
      const double h = 0.05;
      const ClosestWeights weights = closest_weights(x0, shape);
      const ClosestDirectionAdvance advance(x0, x1, shape, h);
      const double from_zero = advance.clear_from(0);
      EXPECT_EQ(advance.clear_from_start(weights), from_zero) << i;
      EXPECT_EQ(within_by_closest_points(x0, shape, h, weights),
                within_by_closest_points(x0, shape, h))
          << i;
      advanced += from_zero > 0 && from_zero < 1;
    }
  }
  EXPECT_GT(advanced, 100);
}

TEST(ThicknessCcd, NearlyParallelEdgesAgreeWithTheSampledOracle) {
  // Two edges at a small angle (1e-7 to 1e-2) a random gap apart, carried by one large
  // motion and turning a little relative to each other: nearly parallel closest points
  // (the segment parameters are ill-conditioned, so the advancement's direction is
  // rough) and distances that are ratios of small numbers. h just above the sampled
  // minimum must hit (at or before the first sampled time within h); h below the minimum
  // must not.
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> unit(-1, 1), gap(1e-3, 0.2), exponent(-7, -2);
  const int runs = testing::sanitized() ? 100 : 1000, samples = 4000;
  int hits = 0;
  for (int i = 0; i < runs; ++i) {
    const double angle = std::pow(10.0, exponent(rng)), g = gap(rng);
    const Vec3 along = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    const Vec3 across = along.cross(Vec3(unit(rng), unit(rng), unit(rng))).normalized();
    const Vec3 side = along.cross(across);
    const Vec3 turned = (along + angle * side).normalized();
    const Vec3 offset = 0.3 * unit(rng) * along + g * across;
    const FourPoints x0{-along, along, offset - turned, offset + turned};
    const Vec3 carried = 2 * Vec3(unit(rng), unit(rng), unit(rng));
    const Vec3 twist = 0.5 * g * Vec3(unit(rng), unit(rng), unit(rng));
    const FourPoints x1{x0[0] + carried, x0[1] + carried, x0[2] + carried - twist,
                        x0[3] + carried + twist};
    const auto at = [&](int k, double t) {
      return testing::wide(Vec3((1 - t) * x0[k] + t * x1[k]));
    };
    const auto ee = [&](double t) {
      return testing::segment_distance(at(0, t), at(1, t), at(2, t), at(3, t));
    };
    const EdgeEdgeQuery q{x0[0], x0[1], x0[2], x0[3], x1[0], x1[1], x1[2], x1[3]};
    const Sampled s0 = sample(ee, 0, samples);
    const double above = static_cast<double>(s0.minimum * (1 + 1e-3L));
    const ThicknessResult r = edge_edge_ccd_within(q, above);
    ASSERT_TRUE(r.hit) << i;
    EXPECT_LE(r.toi, sample(ee, above, samples).first_within + 1e-12) << i;
    ++hits;
    const double under = static_cast<double>(s0.minimum * (1 - 1e-3L));
    EXPECT_FALSE(edge_edge_ccd_within(q, under).hit) << i;
  }
  EXPECT_EQ(hits, runs);
}

}  // namespace
}  // namespace tailor
