// The one-off detect_self_collisions, through the front door alone (tailor/tailor.hpp): the
// same collisions and counts as a SelfCollisionDetector's step, exactly brute force.

#include "tailor/tailor.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/random_steps.hpp"

namespace tailor {
namespace {

nlohmann::json step_counts(const DetectionStats& stats) {
  nlohmann::json json = stats;
  for (const DetectionStatField& field : kDetectionStatFields) {
    if (field.is_time()) json.erase(std::string(field.name));
  }
  return json;
}

TEST(DetectSelfCollisions, IsOneStepOfTheDetector) {
  std::size_t collisions = 0;
  for (const auto& step : testing::make_random_steps(5, 16)) {
    const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
    const CollisionSet truth = brute_force_self_collisions(mesh, step.mesh.vertices, step.x1);
    for (const std::string& method : DetectionConfig::preset_names()) {
      const DetectionConfig config = DetectionConfig::preset(method);
      const DetectionResult once =
          detect_self_collisions(mesh, step.mesh.vertices, step.x1, config);
      SelfCollisionDetector detector(mesh, step.mesh.vertices, config);
      const DetectionResult repeated = detector.detect(step.mesh.vertices, step.x1);
      EXPECT_EQ(once.collisions.size(), truth.size()) << step.name << " " << method;
      EXPECT_EQ(once.collisions.size(), repeated.collisions.size()) << step.name << " " << method;
      EXPECT_EQ(step_counts(once.stats), step_counts(repeated.stats)) << step.name << " " << method;
    }
    // The default is the paper preset.
    EXPECT_EQ(step_counts(detect_self_collisions(mesh, step.mesh.vertices, step.x1).stats),
              step_counts(detect_self_collisions(mesh, step.mesh.vertices, step.x1,
                                                 DetectionConfig::preset("paper"))
                              .stats));
    collisions += truth.size();
  }
  EXPECT_GT(collisions, 0u);
}

TEST(DetectSelfCollisions, RefusesPositionsOfAnotherMesh) {
  const MeshData grid = make_grid(4, 4, 1.0, 1.0);
  const TriangleMesh mesh(static_cast<Index>(grid.vertices.rows()), grid.faces);
  const Positions fewer = grid.vertices.topRows(3);
  EXPECT_THROW(detect_self_collisions(mesh, grid.vertices, fewer), InputError);
}

}  // namespace
}  // namespace tailor
