// Radial-view clusters and whole-cluster certification: what is certified cannot collide,
// and radial view never changes the detector's results.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <random>

#include "culling/radial_view_tubes.hpp"
#include "tailor/culling/radial_view_culling.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

using testing::bend;
using testing::kTubeLength;
using testing::kTubeRadius;
using testing::kTubeRings;
using testing::kTubeSegments;
using testing::tube_observer_loops;
using testing::tube_ring;
using testing::TubeStep;

TubeStep straight_tube() {
  TubeStep step{make_tube(kTubeRings, kTubeSegments, kTubeRadius, kTubeLength), {}, {}};
  step.x1 = step.mesh.vertices;
  step.loops = tube_observer_loops();
  return step;
}

// Small noise on both frames: keeps the exact CCD of brute force off its slow exactly
// degenerate cases (coplanar rings), which are not what these tests are about.
void roughen(TubeStep& step) {
  std::mt19937 rng(1);
  testing::jitter(step.mesh.vertices, rng, 1e-3);
  testing::jitter(step.x1, rng, 1e-3);
}

struct Outcome {
  RadialViewCounts counts;
  std::int64_t ctps = 0;
};

// Runs `paper` with the step's observers, checks its collision sets against brute force
// and returns the radial-view counts of the step.
Outcome expect_detector_matches_brute_force(const TubeStep& step) {
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, step.mesh.vertices, step.x1);
  SelfCollisionDetector detector(mesh, step.mesh.vertices, DetectionConfig::preset("paper"),
                                 step.loops);
  const DetectionResult result = detector.detect(step.mesh.vertices, step.x1);
  EXPECT_EQ(result.collisions.vertex_face.size(), truth.vertex_face.size());
  EXPECT_EQ(result.collisions.edge_edge.size(), truth.edge_edge.size());
  if (result.collisions.vertex_face.size() == truth.vertex_face.size()) {
    for (std::size_t i = 0; i < truth.vertex_face.size(); ++i) {
      EXPECT_EQ(result.collisions.vertex_face[i].vertex, truth.vertex_face[i].vertex);
      EXPECT_EQ(result.collisions.vertex_face[i].face, truth.vertex_face[i].face);
    }
  }
  if (result.collisions.edge_edge.size() == truth.edge_edge.size()) {
    for (std::size_t i = 0; i < truth.edge_edge.size(); ++i) {
      EXPECT_EQ(result.collisions.edge_edge[i].edge_a, truth.edge_edge[i].edge_a);
      EXPECT_EQ(result.collisions.edge_edge[i].edge_b, truth.edge_edge[i].edge_b);
    }
  }
  RadialViewCulling radial(mesh, step.mesh.vertices, step.loops);
  return {radial.classify(step.mesh.vertices, step.x1), result.stats.candidate_triangle_pairs};
}

TEST(RadialView, ClustersOverlapAlongTheTube) {
  const TubeStep step = straight_tube();
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  const RadialViewClusters clusters(mesh, step.mesh.vertices, step.loops);
  ASSERT_EQ(clusters.num_clusters(), 5);  // observers at rings 2, 7, 12, 17, 22
  for (Index c = 0; c < clusters.num_clusters(); ++c) EXPECT_TRUE(clusters.usable(c)) << c;
  // Each vertex is watched by its three nearest observers: the middle observer watches
  // every ring, the end ones the rings up to half-way past their second neighbour.
  EXPECT_EQ(clusters.faces(2).size(), static_cast<std::size_t>(mesh.num_faces()));
  const auto rings_of = [&](Index c) {
    Index lo = kTubeRings, hi = -1;
    for (Index f : clusters.faces(c)) {
      for (int k = 0; k < 3; ++k) {
        lo = std::min(lo, mesh.faces()(f, k) / kTubeSegments);
        hi = std::max(hi, mesh.faces()(f, k) / kTubeSegments);
      }
    }
    return std::pair{lo, hi};
  };
  EXPECT_EQ(rings_of(0), (std::pair<Index, Index>{0, 9}));
  EXPECT_EQ(rings_of(1), (std::pair<Index, Index>{0, 14}));
  EXPECT_EQ(rings_of(3), (std::pair<Index, Index>{10, 23}));
  EXPECT_EQ(rings_of(4), (std::pair<Index, Index>{15, 23}));
  // An inner cluster is closed by two ghost fans, the whole tube by its two open ends.
  EXPECT_EQ(clusters.ghost_loops(1).size(), 2u);
  EXPECT_EQ(clusters.ghost_loops(2).size(), 2u);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const int memberships = std::popcount(clusters.member_mask(f));
    EXPECT_GE(memberships, 1);
    EXPECT_LE(memberships, 3);
  }
}

TEST(RadialView, RigidlyMovingTubeIsCertifiedWhole) {
  TubeStep step = straight_tube();
  step.x1.col(0).array() += 0.05;
  step.x1.col(2).array() += 0.02;
  const Outcome outcome = expect_detector_matches_brute_force(step);
  EXPECT_EQ(outcome.counts.clusters_certified, 5);
  EXPECT_EQ(outcome.counts.triangles_negative + outcome.counts.triangles_undetermined, 0);
  EXPECT_EQ(outcome.ctps, 0);  // every pair lies in a certified cluster
}

TEST(RadialView, InwardOrientedTubeIsCertifiedToo) {
  // Faces reversed: the winding number is -1 and "positive" flips with it.
  TubeStep step = straight_tube();
  step.mesh.faces.col(1).swap(step.mesh.faces.col(2));
  step.x1.col(1).array() -= 0.03;
  const Outcome outcome = expect_detector_matches_brute_force(step);
  EXPECT_EQ(outcome.counts.clusters_certified, 5);
  EXPECT_EQ(outcome.ctps, 0);
}

TEST(RadialView, BentTubeStaysExactAndCuts) {
  TubeStep step = straight_tube();
  const Positions straight = step.mesh.vertices;
  step.mesh.vertices = bend(straight, 0.5, 1.5, kTubeLength);
  step.x1 = bend(straight, 0.8, 1.5, kTubeLength);
  roughen(step);
  const Outcome outcome = expect_detector_matches_brute_force(step);
  EXPECT_GT(outcome.counts.faces_clean, 0);
  EXPECT_GE(outcome.counts.clusters_certified, 1);
}

TEST(RadialView, TubeSquashedThroughItselfIsNotCertified) {
  TubeStep step = straight_tube();
  step.mesh.vertices.col(1) *= 0.05;  // squashed flat...
  step.x1.col(1) *= -0.05;            // ...and through itself
  roughen(step);
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  ASSERT_GT(brute_force_self_collisions(mesh, step.mesh.vertices, step.x1).size(), 0u);
  const Outcome outcome = expect_detector_matches_brute_force(step);
  EXPECT_EQ(outcome.counts.clusters_certified, 0);
  EXPECT_GT(outcome.counts.triangles_undetermined, 0);
}

TEST(RadialView, LoopPinchedToAPointIsNotCertified) {
  TubeStep step = straight_tube();
  roughen(step);
  for (Index v : tube_ring(kTubeRings - 1)) {  // the open end closes to a point on the axis
    step.x1(v, 0) = 0;
    step.x1(v, 1) = 0;
  }
  const Outcome outcome = expect_detector_matches_brute_force(step);
  // The clusters holding the pinched end (observers 2, 3, 4) see its ghost fan collapse.
  EXPECT_LE(outcome.counts.clusters_certified, 2);
  EXPECT_GT(outcome.counts.triangles_undetermined, 0);
}

TEST(RadialView, BadSectionLoopsAreRejected) {
  const TubeStep step = straight_tube();
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  const Positions& x = step.mesh.vertices;
  EXPECT_THROW(RadialViewClusters(mesh, x, {}), InputError);
  EXPECT_THROW(RadialViewClusters(mesh, x, {{}}), InputError);
  EXPECT_THROW(RadialViewClusters(mesh, x, {{0, mesh.num_vertices()}}), InputError);
  EXPECT_THROW(RadialViewClusters(mesh, x, {{-1}}), InputError);
  const std::vector<std::vector<Index>> too_many(RadialViewClusters::kMaxObservers + 1, {0});
  EXPECT_THROW(RadialViewClusters(mesh, x, too_many), InputError);
}

TEST(RadialView, NonManifoldClusterIsNotUsable) {
  // A fin glued to an edge of the tube makes that edge non-manifold: the clusters that
  // hold it cannot be closed, are never used, and the results still equal brute force.
  TubeStep step = straight_tube();
  const Index fin = static_cast<Index>(step.mesh.vertices.rows());
  step.mesh.vertices.conservativeResize(fin + 1, 3);
  step.mesh.vertices.row(fin) << 0.6, 0.0, 1.0;
  step.x1.conservativeResize(fin + 1, 3);
  step.x1.row(fin) << 0.7, 0.0, 1.0;
  const Index a = 12 * kTubeSegments, b = 12 * kTubeSegments + 1;
  step.mesh.faces.conservativeResize(step.mesh.faces.rows() + 1, 3);
  step.mesh.faces.row(step.mesh.faces.rows() - 1) << a, b, fin;
  const TriangleMesh mesh(fin + 1, step.mesh.faces);
  const RadialViewClusters clusters(mesh, step.mesh.vertices, step.loops);
  EXPECT_FALSE(clusters.usable(2));
  expect_detector_matches_brute_force(step);
}

}  // namespace
}  // namespace tailor
