/// @file
/// Collisions with a thickness through the detector: every preset equals brute force (the
/// same minimum-separation CCD behind box pruning of its own) as sets with equal times, on
/// random steps (and the step after each, through the same detector) and on the cloth-funnel
/// and cloth-ball steps at h = 1e-3 of their diagonals; more pairs as h grows; and the
/// collision-free step.

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "support/random_steps.hpp"
#include "support/reference_step.hpp"
#include "support/sanitized.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/collision_free_step.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

void expect_same_with_times(const CollisionSet& expected, const CollisionSet& actual,
                            const std::string& what) {
  ASSERT_EQ(expected.vertex_face.size(), actual.vertex_face.size()) << what;
  ASSERT_EQ(expected.edge_edge.size(), actual.edge_edge.size()) << what;
  for (std::size_t i = 0; i < expected.vertex_face.size(); ++i) {
    const auto &e = expected.vertex_face[i], &a = actual.vertex_face[i];
    ASSERT_TRUE(e.vertex == a.vertex && e.face == a.face && e.toi == a.toi) << what << " VF " << i;
  }
  for (std::size_t i = 0; i < expected.edge_edge.size(); ++i) {
    const auto &e = expected.edge_edge[i], &a = actual.edge_edge[i];
    ASSERT_TRUE(e.a0 == a.a0 && e.a1 == a.a1 && e.b0 == a.b0 && e.b1 == a.b1 && e.toi == a.toi)
        << what << " EE " << i;
  }
}

double diagonal(const Positions& x0, const Positions& x1) {
  const Vec3 lo = x0.colwise().minCoeff().cwiseMin(x1.colwise().minCoeff()).transpose();
  const Vec3 hi = x0.colwise().maxCoeff().cwiseMax(x1.colwise().maxCoeff()).transpose();
  return (hi - lo).norm();
}

TEST(ThicknessDetection, EveryPresetEqualsBruteForceOnRandomSteps) {
  int pairs = 0;
  for (const testing::Step& step : testing::make_random_steps(3, testing::sanitized() ? 8 : 16)) {
    const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
    const double size = diagonal(step.mesh.vertices, step.x1);
    for (const double share : {1e-3, 1e-2}) {
      const double h = share * size;
      const CollisionSet truth = brute_force_self_collisions(mesh, step.mesh.vertices, step.x1, h);
      // A second step with the same detector (its trees refitted): the motion continued.
      const Positions x2 = 2 * step.x1 - step.mesh.vertices;
      const CollisionSet next_truth = brute_force_self_collisions(mesh, step.x1, x2, h);
      pairs += static_cast<int>(truth.size() + next_truth.size());
      for (const std::string& preset : DetectionConfig::preset_names()) {
        DetectionConfig config = DetectionConfig::preset(preset);
        config.thickness = h;
        SelfCollisionDetector detector(mesh, step.mesh.vertices, config);
        const std::string what = step.name + " " + preset + " h=" + std::to_string(h);
        expect_same_with_times(truth, detector.detect(step.mesh.vertices, step.x1).collisions,
                               what);
        expect_same_with_times(next_truth, detector.detect(step.x1, x2).collisions,
                               what + ", second step");
      }
    }
  }
  EXPECT_GT(pairs, 0);
}

// A reference step at h = 1e-3 of its diagonal (the paper preset: at h > 0 every preset
// runs the same path, checked preset by preset on the random steps above): the detector
// equals brute force, and every pair of the data set's ground truth (touching) is within h.
void expect_reference_step_at_thickness(const testing::ReferenceStep& step,
                                        const std::string& name) {
  const Positions& x0 = step.t0.vertices;
  const Positions& x1 = step.t1.vertices;
  const double h = 1e-3 * diagonal(x0, x1);
  const CollisionSet truth = brute_force_self_collisions(*step.mesh, x0, x1, h);
  DetectionConfig config;  // paper
  config.thickness = h;
  SelfCollisionDetector detector(*step.mesh, x0, config);
  const CollisionSet found = detector.detect(x0, x1).collisions;
  expect_same_with_times(truth, found, name + " h = 1e-3 diagonal");
  // Every pair that touches (the ground truth at h = 0) comes within h, no later.
  const testing::PairSets within = testing::pair_sets(found);
  for (const auto& p : step.truth.vertex_face) EXPECT_TRUE(within.vertex_face.contains(p));
  for (const auto& p : step.truth.edge_edge) EXPECT_TRUE(within.edge_edge.contains(p));
  EXPECT_GT(found.size(), step.truth.vertex_face.size() + step.truth.edge_edge.size());
}

TEST(ThicknessDetection, ClothFunnelStepEqualsBruteForceAndHoldsEveryTouchingPair) {
  expect_reference_step_at_thickness(
      testing::load_reference_step("cloth-funnel", "227.ply", "228.ply", "227"), "cloth-funnel");
}

// About 980,000 pairs within h; release builds take about 40 s (detector and brute force
// on two threads).
TEST(ThicknessDetection, ClothBallStepEqualsBruteForceAndHoldsEveryTouchingPair) {
  if (testing::sanitized()) GTEST_SKIP() << "11 million thickness queries under the sanitizers";
  expect_reference_step_at_thickness(
      testing::load_reference_step("cloth-ball", "cloth_ball92.ply", "cloth_ball93.ply", "92"),
      "cloth-ball");
}

TEST(ThicknessDetection, CollisionFreeStepStopsAtTheThickness) {
  // Two parallel unit squares 1 apart, the upper one falling by 1: it comes within h at
  // t = 1 - h.
  MeshData square;
  square.vertices.resize(8, 3);
  square.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  square.faces.resize(4, 3);
  square.faces << 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7;
  const TriangleMesh mesh(8, square.faces);
  Positions x1 = square.vertices;
  x1.bottomRows(4).col(2).array() -= 1.0;
  const CollisionFreeStep at_quarter = collision_free_step(mesh, square.vertices, x1, 0.25);
  EXPECT_LE(at_quarter.alpha, 0.75);
  EXPECT_GE(at_quarter.alpha, 0.75 - 1e-6);
  EXPECT_TRUE(at_quarter.vertex_face.has_value() || at_quarter.edge_edge.has_value());
  // Touching (h = 0) happens at t = 1; a thickness of 2 is reached at once.
  const CollisionFreeStep touching = collision_free_step(mesh, square.vertices, x1, 0);
  EXPECT_GE(touching.alpha, 1.0 - 1e-6);
  EXPECT_TRUE(touching.vertex_face.has_value() || touching.edge_edge.has_value());
  EXPECT_EQ(collision_free_step(mesh, square.vertices, x1, 2).alpha, 0.0);
  // Falling half as far never comes within 0.25.
  Positions half = square.vertices;
  half.bottomRows(4).col(2).array() -= 0.5;
  const CollisionFreeStep free = collision_free_step(mesh, square.vertices, half, 0.25);
  EXPECT_EQ(free.alpha, 1.0);
  EXPECT_FALSE(free.vertex_face.has_value() || free.edge_edge.has_value());
  EXPECT_THROW(collision_free_step(mesh, square.vertices, x1, -1), InputError);
}

}  // namespace
}  // namespace tailor
