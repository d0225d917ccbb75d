// The cloth-funnel step (227 -> 228) against its exact ground truth (mma_bool).

#include <gtest/gtest.h>

#include "support/reference_step.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"

namespace tailor {
namespace {

using testing::pair_sets;
using testing::PairSets;

TEST(ClothFunnel, EveryPresetReportsExactlyTheTruePairs) {
  const testing::ReferenceStep step =
      testing::load_reference_step("cloth-funnel", "227.ply", "228.ply", "227");
  ASSERT_EQ(step.t0.vertices.rows(), 9450);
  const PairSets& truth = step.truth;
  EXPECT_EQ(truth.vertex_face.size(), 27u);
  EXPECT_EQ(truth.edge_edge.size(), 107u);

  const PairSets brute =
      pair_sets(brute_force_self_collisions(*step.mesh, step.t0.vertices, step.t1.vertices));
  EXPECT_EQ(brute.vertex_face, truth.vertex_face);
  EXPECT_EQ(brute.edge_edge, truth.edge_edge);
  for (const std::string& method : DetectionConfig::preset_names()) {
    SelfCollisionDetector detector(*step.mesh, step.t0.vertices, DetectionConfig::preset(method));
    const PairSets found =
        pair_sets(detector.detect(step.t0.vertices, step.t1.vertices).collisions);
    EXPECT_EQ(found.vertex_face, truth.vertex_face) << method;
    EXPECT_EQ(found.edge_edge, truth.edge_edge) << method;
  }
}

}  // namespace
}  // namespace tailor
