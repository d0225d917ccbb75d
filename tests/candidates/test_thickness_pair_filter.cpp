// The thickness pairs' normal filter: on layered triangle pairs that turn and close in over
// the step, every pair it drops stays more than h apart (a long-double distance sampled
// over the step), it drops many, the pairs it keeps stay in order, and the SSE2 build
// agrees with the widest; a pair exactly h apart along its normal is kept, one 1 % farther
// is dropped; a corner that is not finite, or too large to bound, is never dropped.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "support/closest_points.hpp"
#include "support/sanitized.hpp"
#include "tailor/candidates/thickness_pair_filter.hpp"

namespace tailor {
namespace {

// `count` separate triangle pairs (faces 2i, 2i + 1), each pair's every vertex-face pair
// across the two faces and every edge pair across them.
struct LayeredPairs {
  FaceArray faces;
  Positions x0, x1;
  FeaturePairs pairs;
};

FeaturePairs all_pairs_across(const TriangleMesh& mesh) {
  FeaturePairs pairs;
  for (Index f = 0; f < mesh.num_faces(); f += 2) {
    for (const auto& [vertex_face, face] : {std::pair{f, f + 1}, std::pair{f + 1, f}}) {
      for (int i = 0; i < 3; ++i) pairs.vertex_face.push_back({mesh.faces()(vertex_face, i), face});
    }
  }
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    for (Index g = e + 1; g < mesh.num_edges(); ++g) {
      const auto a = mesh.edges().row(e), b = mesh.edges().row(g);
      // Edges of the two faces of one pair: vertex ids 6i .. 6i + 5, the faces' 0-2 and 3-5.
      if (a[0] / 6 == b[0] / 6 && a[0] % 6 / 3 != b[0] % 6 / 3) pairs.edge_edge.push_back({e, g});
    }
  }
  return pairs;
}

// The second triangle of each pair a random gap beyond the first along its normal; over the
// step the whole pair turns by up to 0.3 rad and the second closes in by up to 0.6 (many
// pass through each other).
LayeredPairs layered_pairs(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-1, 1), gap(0.01, 0.4), angle(-0.3, 0.3),
      closing(-0.6, 0.1), wobble(-0.05, 0.05);
  const auto point = [&] { return Vec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  LayeredPairs out;
  out.faces.resize(2 * count, 3);
  out.x0.resize(6 * count, 3);
  out.x1.resize(6 * count, 3);
  for (int i = 0; i < count; ++i) {
    const Vec3 a = point(), b = point(), c = point(), n = (b - a).cross(c - a).normalized();
    const double lift = gap(rng);
    // Beyond the first triangle's plane by the lift (give or take a wobble), shifted in it.
    const auto above = [&](const Vec3& corner) {
      const Vec3 shift = 0.3 * point();
      return Vec3(corner + shift - n.dot(shift) * n + (lift + wobble(rng)) * n);
    };
    const Vec3 corners[6] = {a, b, c, above(a), above(b), above(c)};
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(angle(rng), point().normalized()).toRotationMatrix();
    const Vec3 carried = point(), relative = closing(rng) * n;
    for (int j = 0; j < 6; ++j) {
      out.x0.row(6 * i + j) = corners[j].transpose();
      out.x1.row(6 * i + j) =
          (turn * (corners[j] + (j >= 3 ? relative : Vec3::Zero())) + carried).transpose();
    }
    out.faces.row(2 * i) << 6 * i, 6 * i + 1, 6 * i + 2;
    out.faces.row(2 * i + 1) << 6 * i + 3, 6 * i + 4, 6 * i + 5;
  }
  return out;
}

long double sampled_distance(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                             const VertexFacePair& pair, double t) {
  const auto at = [&](Index v) {
    return testing::wide(Vec3((1 - t) * x0.row(v).transpose() + t * x1.row(v).transpose()));
  };
  const auto f = mesh.faces().row(pair.face);
  return testing::point_triangle_distance(at(pair.vertex), at(f[0]), at(f[1]), at(f[2]));
}

long double sampled_distance(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                             const EdgeEdgePair& pair, double t) {
  const auto at = [&](Index v) {
    return testing::wide(Vec3((1 - t) * x0.row(v).transpose() + t * x1.row(v).transpose()));
  };
  const auto a = mesh.edges().row(pair.edge_a), b = mesh.edges().row(pair.edge_b);
  return testing::segment_distance(at(a[0]), at(a[1]), at(b[0]), at(b[1]));
}

template <class Pair>
long double minimum_over_step(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                              const Pair& pair) {
  long double least = std::numeric_limits<long double>::infinity();
  for (int i = 0; i <= 400; ++i) {
    least = std::min(least, sampled_distance(mesh, x0, x1, pair, i / 400.0));
  }
  return least;
}

// The pairs of `all` not in `kept`, checking that `kept` is a subsequence of `all`.
template <class Pair>
std::vector<Pair> dropped_from(const std::vector<Pair>& all, const std::vector<Pair>& kept) {
  std::vector<Pair> dropped;
  std::size_t next = 0;
  for (const Pair& pair : all) {
    const auto same = [&](const Pair& p) { return std::memcmp(&p, &pair, sizeof(Pair)) == 0; };
    if (next < kept.size() && same(kept[next])) {
      ++next;
    } else {
      dropped.push_back(pair);
    }
  }
  EXPECT_EQ(next, kept.size()) << "the kept pairs are not in their order";
  return dropped;
}

TEST(ThicknessPairFilter, DropsOnlyPairsThatStayMoreThanHApart) {
  const int count = testing::sanitized() ? 300 : 1500;
  const LayeredPairs layers = layered_pairs(count, 41);
  const TriangleMesh mesh(layers.x0.rows(), layers.faces);
  const FeaturePairs all = all_pairs_across(mesh);
  ASSERT_GT(all.vertex_face.size() + all.edge_edge.size(), 4096u);  // more than one block
  int dropped_pairs = 0;
  for (const double h : {1e-3, 0.05, 0.2}) {
    FeaturePairs kept = all, kept_two_lanes = all;
    const std::size_t dropped = drop_pairs_kept_apart(mesh, layers.x0, layers.x1, h, kept);
    detail::drop_pairs_kept_apart_two_lanes(mesh, layers.x0, layers.x1, h, kept_two_lanes);
    EXPECT_EQ(dropped, all.vertex_face.size() + all.edge_edge.size() - kept.vertex_face.size() -
                           kept.edge_edge.size());
    for (const VertexFacePair& pair : dropped_from(all.vertex_face, kept.vertex_face)) {
      EXPECT_GT(minimum_over_step(mesh, layers.x0, layers.x1, pair), h)
          << "vertex " << pair.vertex << " face " << pair.face << " h " << h;
      ++dropped_pairs;
    }
    for (const EdgeEdgePair& pair : dropped_from(all.edge_edge, kept.edge_edge)) {
      EXPECT_GT(minimum_over_step(mesh, layers.x0, layers.x1, pair), h)
          << "edges " << pair.edge_a << " " << pair.edge_b << " h " << h;
      ++dropped_pairs;
    }
    ASSERT_EQ(kept.vertex_face.size(), kept_two_lanes.vertex_face.size());
    ASSERT_EQ(kept.edge_edge.size(), kept_two_lanes.edge_edge.size());
    for (std::size_t i = 0; i < kept.vertex_face.size(); ++i) {
      EXPECT_EQ(kept.vertex_face[i].vertex, kept_two_lanes.vertex_face[i].vertex);
      EXPECT_EQ(kept.vertex_face[i].face, kept_two_lanes.vertex_face[i].face);
    }
    for (std::size_t i = 0; i < kept.edge_edge.size(); ++i) {
      EXPECT_EQ(kept.edge_edge[i].edge_a, kept_two_lanes.edge_edge[i].edge_a);
      EXPECT_EQ(kept.edge_edge[i].edge_b, kept_two_lanes.edge_edge[i].edge_b);
    }
  }
  EXPECT_GT(dropped_pairs, count);  // it has something to drop
}

// One vertex over a face and two crossing edges, both exactly `gap` apart along the normal
// (a tilted frame), not moving.
struct OnePairEach {
  TriangleMesh mesh;
  Positions x;
  FeaturePairs pairs;
};

OnePairEach exactly_apart(double gap) {
  const Vec3 n = Vec3(1, 2, 2) / 3;
  const Vec3 e1 = Vec3(2, -1, 0) / std::sqrt(5.0), e2 = n.cross(e1);
  const Vec3 p(0.3, -0.2, 0.5), q = p + gap * n;
  FaceArray faces(2, 3);
  faces << 0, 1, 2, 3, 4, 5;
  Positions x(6, 3);
  // No edge of one face parallel to one of the other (a zero cross product proves nothing).
  const Vec3 corners[6] = {p - e1, p + e1, p + e2, q - e1 - e2, q + e1 - 0.5 * e2, q + 2 * e2};
  for (int j = 0; j < 6; ++j) x.row(j) = corners[j].transpose();
  OnePairEach out{TriangleMesh(6, faces), x, {}};
  // Vertex 2 (= p + e2) lies over face 1's interior at distance gap; the faces lie in
  // parallel planes gap apart, so every edge pair is at least gap apart and the crossing
  // ones exactly.
  out.pairs.vertex_face.push_back({2, 1});
  for (Index e = 0; e < out.mesh.num_edges(); ++e) {
    for (Index g = e + 1; g < out.mesh.num_edges(); ++g) {
      const auto a = out.mesh.edges().row(e), b = out.mesh.edges().row(g);
      if ((a[0] < 3) != (b[0] < 3)) out.pairs.edge_edge.push_back({e, g});
    }
  }
  return out;
}

TEST(ThicknessPairFilter, KeepsPairsExactlyHApartAndDropsFartherOnes) {
  const double h = 0.1;
  OnePairEach level = exactly_apart(h);
  FeaturePairs kept = level.pairs;
  drop_pairs_kept_apart(level.mesh, level.x, level.x, h, kept);
  EXPECT_EQ(kept.vertex_face.size(), 1u);
  // The edge pairs exactly h apart (those that cross in projection) stay; the others are
  // farther and may go.
  int exactly_h = 0;
  for (const EdgeEdgePair& pair : level.pairs.edge_edge) {
    if (sampled_distance(level.mesh, level.x, level.x, pair, 0.0) > h * (1 + 1e-9)) continue;
    ++exactly_h;
    EXPECT_TRUE(std::any_of(
        kept.edge_edge.begin(), kept.edge_edge.end(),
        [&](const auto& k) { return k.edge_a == pair.edge_a && k.edge_b == pair.edge_b; }))
        << "edges " << pair.edge_a << " and " << pair.edge_b << " are h apart but were dropped";
  }
  EXPECT_GT(exactly_h, 0);
  OnePairEach farther = exactly_apart(1.01 * h);
  kept = farther.pairs;
  drop_pairs_kept_apart(farther.mesh, farther.x, farther.x, h, kept);
  EXPECT_TRUE(kept.vertex_face.empty());
  EXPECT_TRUE(kept.edge_edge.empty());
}

TEST(ThicknessPairFilter, CornersNotFiniteOrTooLargeAreNeverDropped) {
  OnePairEach far = exactly_apart(10.0);
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 1e300}) {
    Positions x1 = far.x;
    x1(4, 1) = bad;
    FeaturePairs kept = far.pairs;
    drop_pairs_kept_apart(far.mesh, far.x, x1, 0.1, kept);
    EXPECT_EQ(kept.vertex_face.size(), 1u) << bad;
  }
  FeaturePairs kept = far.pairs;
  EXPECT_THROW(drop_pairs_kept_apart(far.mesh, far.x, far.x, 0.0, kept), std::invalid_argument);
}

}  // namespace
}  // namespace tailor
