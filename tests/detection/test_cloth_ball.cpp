// The cloth-ball step (92 -> 93): dense contact (about 40 candidate triangle pairs and
// 1.2 collisions per triangle) against its exact ground truth (mma_bool).

#include <gtest/gtest.h>

#include "support/reference_step.hpp"
#include "support/sanitized.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"

namespace tailor {
namespace {

using testing::pair_sets;
using testing::PairSets;

const testing::ReferenceStep& cloth_ball() {
  static const testing::ReferenceStep step =
      testing::load_reference_step("cloth-ball", "cloth_ball92.ply", "cloth_ball93.ply", "92");
  return step;
}

TEST(ClothBall, GroundTruthHasTheDocumentedPairs) {
  const testing::ReferenceStep& step = cloth_ball();
  ASSERT_EQ(step.t0.vertices.rows(), 46598);
  ASSERT_EQ(step.mesh->num_faces(), 92230);
  EXPECT_EQ(step.truth.vertex_face.size(), 19032u);
  EXPECT_EQ(step.truth.edge_edge.size(), 94822u);
}

// Every preset, on one and on two threads (the paper preset only under the sanitizers:
// the others test millions more pairs there).
TEST(ClothBall, EveryPresetReportsExactlyTheTruePairs) {
  const testing::ReferenceStep& step = cloth_ball();
  const std::vector<std::string> methods =
      testing::sanitized() ? std::vector<std::string>{"paper"} : DetectionConfig::preset_names();
  for (const std::string& method : methods) {
    for (int threads : {1, 2}) {
      DetectionConfig config = DetectionConfig::preset(method);
      config.threads = threads;
      SelfCollisionDetector detector(*step.mesh, step.t0.vertices, config);
      const DetectionResult result = detector.detect(step.t0.vertices, step.t1.vertices);
      const PairSets found = pair_sets(result.collisions);
      EXPECT_EQ(found.vertex_face, step.truth.vertex_face) << method << ", threads " << threads;
      EXPECT_EQ(found.edge_edge, step.truth.edge_edge) << method << ", threads " << threads;
    }
  }
}

// The oracle agrees with the data set's exact truth (release builds: about ten seconds).
TEST(ClothBall, BruteForceReportsExactlyTheTruePairs) {
  if (testing::sanitized()) GTEST_SKIP() << "brute force over 92K triangles under the sanitizers";
  const testing::ReferenceStep& step = cloth_ball();
  const PairSets brute =
      pair_sets(brute_force_self_collisions(*step.mesh, step.t0.vertices, step.t1.vertices));
  EXPECT_EQ(brute.vertex_face, step.truth.vertex_face);
  EXPECT_EQ(brute.edge_edge, step.truth.edge_edge);
}

}  // namespace
}  // namespace tailor
