// Radial-view culling: certifies only what cannot collide, and never changes results.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tailor/culling/radial_view.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

constexpr int kRings = 24, kSegments = 20;

std::vector<Index> ring(int r) {
  std::vector<Index> loop;
  for (int s = 0; s < kSegments; ++s) loop.push_back(r * kSegments + s);
  return loop;
}

struct TubeStep {
  MeshData mesh;
  Positions x1;
};

TubeStep tube() {
  TubeStep step{make_tube(kRings, kSegments, 0.3, 2.0), {}};
  step.x1 = step.mesh.vertices;
  return step;
}

// Bends a tube along z into an arc of `angle` radians of radius `bend_radius`.
Positions bend(const Positions& straight, double angle, double bend_radius, double length) {
  Positions x = straight;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double theta = angle * straight(i, 2) / length;
    const Vec3 radial(std::cos(theta), 0, std::sin(theta));
    const Vec3 p = Vec3(bend_radius, 0, 0) - bend_radius * radial + straight(i, 0) * radial +
                   straight(i, 1) * Vec3::UnitY();
    x.row(i) = p.transpose();
  }
  return x;
}

void expect_detector_matches_brute_force(const TubeStep& step,
                                         const std::vector<std::vector<Index>>& loops,
                                         std::int64_t* certified = nullptr) {
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, step.mesh.vertices, step.x1);
  SelfCollisionDetector detector(mesh, step.mesh.vertices, DetectionConfig::preset("paper"), loops);
  const DetectionResult result = detector.detect(step.mesh.vertices, step.x1);
  ASSERT_EQ(result.collisions.vertex_face.size(), truth.vertex_face.size());
  ASSERT_EQ(result.collisions.edge_edge.size(), truth.edge_edge.size());
  for (std::size_t i = 0; i < truth.vertex_face.size(); ++i) {
    EXPECT_EQ(result.collisions.vertex_face[i].vertex, truth.vertex_face[i].vertex);
    EXPECT_EQ(result.collisions.vertex_face[i].face, truth.vertex_face[i].face);
  }
  for (std::size_t i = 0; i < truth.edge_edge.size(); ++i) {
    EXPECT_EQ(result.collisions.edge_edge[i].edge_a, truth.edge_edge[i].edge_a);
    EXPECT_EQ(result.collisions.edge_edge[i].edge_b, truth.edge_edge[i].edge_b);
  }
  if (certified != nullptr) *certified = result.stats.clusters_certified;
}

TEST(RadialView, ClustersSplitTheTubeByNearestObserver) {
  const TubeStep step = tube();
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  const RadialViewClusters clusters(mesh, step.mesh.vertices, {ring(5), ring(18)});
  ASSERT_EQ(clusters.num_clusters(), 2);
  EXPECT_EQ(clusters.faces(0).size() + clusters.faces(1).size(),
            static_cast<std::size_t>(mesh.num_faces()));
  EXPECT_TRUE(clusters.certifiable(0));
  EXPECT_TRUE(clusters.certifiable(1));
}

TEST(RadialView, RigidlyMovingTubeIsCertified) {
  TubeStep step = tube();
  step.x1.col(0).array() += 0.05;
  step.x1.col(2).array() += 0.02;
  std::int64_t certified = 0;
  expect_detector_matches_brute_force(step, {ring(5), ring(18)}, &certified);
  EXPECT_EQ(certified, 2);
}

TEST(RadialView, BentTubeStaysCertifiedAndExact) {
  TubeStep step = tube();
  const Positions straight = step.mesh.vertices;
  step.mesh.vertices = bend(straight, 0.5, 1.5, 2.0);
  step.x1 = bend(straight, 0.8, 1.5, 2.0);
  std::int64_t certified = 0;
  expect_detector_matches_brute_force(step, {ring(5), ring(18)}, &certified);
  EXPECT_EQ(certified, 2);
}

TEST(RadialView, ClusterFoldedOntoItselfIsNotCertified) {
  TubeStep step = tube();
  step.mesh.vertices.col(1) *= 0.05;  // squashed flat...
  step.x1.col(1) *= -0.05;            // ...and through itself
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  ASSERT_GT(brute_force_self_collisions(mesh, step.mesh.vertices, step.x1).size(), 0u);
  std::int64_t certified = -1;
  expect_detector_matches_brute_force(step, {ring(5), ring(18)}, &certified);
  EXPECT_EQ(certified, 0);
}

TEST(RadialView, ObserverOutsideTheTubeIsNotCertified) {
  // A U-bent tube; the section loop takes a vertex from each leg, so its centroid (the
  // observer) lies in the gap between the legs, outside the tube.
  TubeStep step = tube();
  const Positions straight = step.mesh.vertices;
  step.mesh.vertices = bend(straight, std::numbers::pi, 0.7, 2.0);
  step.x1 = bend(straight, 1.05 * std::numbers::pi, 0.7, 2.0);
  const std::vector<Index> outside{2 * kSegments, (kRings - 3) * kSegments};
  std::int64_t certified = -1;
  expect_detector_matches_brute_force(step, {outside}, &certified);
  EXPECT_EQ(certified, 0);
}

TEST(RadialView, LoopPinchedToAPointIsNotCertified) {
  TubeStep step = tube();
  for (Index v : ring(kRings - 1)) {  // the open end closes to a point on the axis
    step.x1(v, 0) = 0;
    step.x1(v, 1) = 0;
  }
  std::int64_t certified = -1;
  expect_detector_matches_brute_force(step, {ring(5), ring(18)}, &certified);
  EXPECT_LE(certified, 1);  // the cluster holding the pinched end must not be certified
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  const RadialViewClusters clusters(mesh, step.mesh.vertices, {ring(5), ring(18)});
  RadialViewCounts counts;
  const std::vector<char> result = clusters.certify(step.mesh.vertices, step.x1, counts);
  EXPECT_FALSE(result[1]);
  EXPECT_GT(counts.triangles_undetermined, 0);
}

TEST(RadialView, BadSectionLoopsAreRejected) {
  const TubeStep step = tube();
  const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
  EXPECT_THROW(RadialViewClusters(mesh, step.mesh.vertices, {{}}), std::exception);
  EXPECT_THROW(RadialViewClusters(mesh, step.mesh.vertices, {{0, mesh.num_vertices()}}),
               std::exception);
}

}  // namespace
}  // namespace tailor
