// Every combination of the work-only culling stages (SettingEffect::work_only; the contour
// test stays on: off, it is unsound) reports exactly the brute-force collisions.

#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "support/random_steps.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

using tailor::testing::sanitized;

// All sound combinations of the switchable stages (the contour test is never off here:
// without it the cone theorem does not hold).
std::vector<DetectionConfig> all_stage_combinations() {
  std::vector<DetectionConfig> configs;
  for (int bits = 0; bits < 512; ++bits) {
    DetectionConfig config = DetectionConfig::preset("basic");
    config.normal_cones = bits & 1;
    config.contour_test = true;
    config.adjacency_culling = bits & 2;
    config.feature_assignment = bits & 4;
    config.primitive_boxes = bits & 8;
    config.coplanarity_filter = bits & 16;
    config.projection_filter = bits & 32;
    config.triangle_filter = bits & 64;
    config.direction_filter = bits & 128;
    config.diagonal_bounds = bits & 256;
    configs.push_back(config);
  }
  return configs;
}

std::string describe(const DetectionConfig& c) {
  return "cones=" + std::to_string(c.normal_cones) +
         " adjacency=" + std::to_string(c.adjacency_culling) +
         " assignment=" + std::to_string(c.feature_assignment) +
         " boxes=" + std::to_string(c.primitive_boxes) +
         " filter=" + std::to_string(c.coplanarity_filter) +
         " projection=" + std::to_string(c.projection_filter) +
         " triangle_filter=" + std::to_string(c.triangle_filter) +
         " direction_filter=" + std::to_string(c.direction_filter) +
         " diagonal_bounds=" + std::to_string(c.diagonal_bounds) +
         " threads=" + std::to_string(c.threads);
}

void expect_same(const CollisionSet& expected, const CollisionSet& actual,
                 const std::string& what) {
  ASSERT_EQ(expected.vertex_face.size(), actual.vertex_face.size()) << what;
  ASSERT_EQ(expected.edge_edge.size(), actual.edge_edge.size()) << what;
  for (std::size_t i = 0; i < expected.vertex_face.size(); ++i) {
    const auto& e = expected.vertex_face[i];
    const auto& a = actual.vertex_face[i];
    ASSERT_TRUE(e.vertex == a.vertex && e.face == a.face && e.toi == a.toi)
        << what << ": VF " << i << " expected (" << e.vertex << ", " << e.face << ") got ("
        << a.vertex << ", " << a.face << ")";
  }
  for (std::size_t i = 0; i < expected.edge_edge.size(); ++i) {
    const auto& e = expected.edge_edge[i];
    const auto& a = actual.edge_edge[i];
    ASSERT_TRUE(e.a0 == a.a0 && e.a1 == a.a1 && e.b0 == a.b0 && e.b1 == a.b1 && e.toi == a.toi)
        << what << ": EE " << i;
  }
}

class DetectorVsBruteForce : public ::testing::TestWithParam<unsigned> {};

TEST_P(DetectorVsBruteForce, EveryStageCombinationEqualsBruteForce) {
  // The sanitizer build checks memory safety on one small seed; the release build runs
  // every seed at full size.
  if (sanitized() && GetParam() != 1u) GTEST_SKIP() << "release build covers this seed";
  const int resolution = sanitized() ? 10 : 24;  // ~1.1K triangles on the grids
  std::int64_t total_collisions = 0, total_ctps_basic = 0, total_ctps_culled = 0;
  for (const auto& step : testing::make_random_steps(GetParam(), resolution)) {
    const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
    const CollisionSet truth = brute_force_self_collisions(mesh, step.mesh.vertices, step.x1);
    total_collisions += static_cast<std::int64_t>(truth.size());
    for (DetectionConfig config : all_stage_combinations()) {
      // Thread counts change the order of work, never the result.
      for (int threads : {1, 2}) {
        if (threads == 2 && !(config.normal_cones && config.feature_assignment)) continue;
        config.threads = threads;
        SelfCollisionDetector detector(mesh, step.mesh.vertices, config);
        const DetectionResult result = detector.detect(step.mesh.vertices, step.x1);
        expect_same(truth, result.collisions, step.name + " " + describe(config));
        if (!config.normal_cones && !config.adjacency_culling) {
          total_ctps_basic += result.stats.candidate_triangle_pairs;
        }
        if (config.normal_cones && config.adjacency_culling) {
          total_ctps_culled += result.stats.candidate_triangle_pairs;
        }
      }
    }
  }
  // The steps must exercise collisions, and the high-level stages must cut something.
  EXPECT_GT(total_collisions, 0);
  EXPECT_LT(total_ctps_culled, total_ctps_basic);
}

INSTANTIATE_TEST_SUITE_P(Seeds, DetectorVsBruteForce, ::testing::Values(1u, 2u, 3u));

TEST(DetectorVsBruteForce, LargerMeshesWithPresets) {
  const int resolution = sanitized() ? 12 : 50;  // ~5K triangles on the grids
  for (const auto& step : testing::make_random_steps(7, resolution)) {
    const TriangleMesh mesh(static_cast<Index>(step.mesh.vertices.rows()), step.mesh.faces);
    const CollisionSet truth = brute_force_self_collisions(mesh, step.mesh.vertices, step.x1);
    for (const std::string& method : DetectionConfig::preset_names()) {
      SelfCollisionDetector detector(mesh, step.mesh.vertices, DetectionConfig::preset(method));
      expect_same(truth, detector.detect(step.mesh.vertices, step.x1).collisions,
                  step.name + " " + method);
    }
  }
}

// The contact-heavy step (a cloth folded onto itself on a sphere, the layers passing
// through each other, a plateau where pairs stay coplanar): every preset, 1 and 2 threads,
// and every stage combination on one thread.
TEST(DetectorVsBruteForce, FoldedClothEveryPresetAndStage) {
  const ProceduralStep step = make_folded_cloth_on_sphere(sanitized() ? 400 : 3000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, step.x0, step.x1);
  EXPECT_GT(truth.size(), sanitized() ? 50u : 1000u);
  for (const std::string& method : DetectionConfig::preset_names()) {
    for (int threads : {1, 2}) {
      DetectionConfig config = DetectionConfig::preset(method);
      config.threads = threads;
      SelfCollisionDetector detector(mesh, step.x0, config);
      const DetectionResult result = detector.detect(step.x0, step.x1);
      expect_same(truth, result.collisions, "folded " + method + " " + describe(config));
      if (method == "paper") {
        // The low-level filters send few pairs per real collision to the exact CCD.
        EXPECT_LT(result.stats.vf_tested + result.stats.ee_tested,
                  3 * static_cast<std::int64_t>(truth.size()));
      }
    }
  }
  if (sanitized()) return;
  for (DetectionConfig config : all_stage_combinations()) {
    SelfCollisionDetector detector(mesh, step.x0, config);
    expect_same(truth, detector.detect(step.x0, step.x1).collisions, "folded " + describe(config));
  }
}

// The dense step (a cloth pleated into layers heaving through one another: the contact
// density of real steps): every preset, 1 and 2 threads, against brute force.
TEST(DetectorVsBruteForce, PleatedClothEveryPreset) {
  const ProceduralStep step = make_pleated_cloth(sanitized() ? 400 : 3000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, step.x0, step.x1);
  EXPECT_GT(truth.size(), static_cast<std::size_t>(mesh.num_faces()));  // dense: > 1 a face
  for (const std::string& method : DetectionConfig::preset_names()) {
    for (int threads : {1, 2}) {
      DetectionConfig config = DetectionConfig::preset(method);
      config.threads = threads;
      SelfCollisionDetector detector(mesh, step.x0, config);
      expect_same(truth, detector.detect(step.x0, step.x1).collisions,
                  "pleated " + method + " " + describe(config));
    }
  }
}

// A crumpling height field: no collision, and every normal has n·z > 0 over the step, so
// the direction masks certify the root (the contour test passes on the square's boundary)
// and the paper preset emits no candidate pair at all; every preset agrees with brute force.
TEST(DetectorVsBruteForce, CrumplingHeightFieldIsCertifiedAtTheRoot) {
  const ProceduralStep step = make_crumpling_cloth_step(sanitized() ? 800 : 8000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, step.x0, step.x1);
  EXPECT_EQ(truth.size(), 0u);
  for (const std::string& method : DetectionConfig::preset_names()) {
    SelfCollisionDetector detector(mesh, step.x0, DetectionConfig::preset(method));
    const DetectionResult result = detector.detect(step.x0, step.x1);
    expect_same(truth, result.collisions, "crumpling " + method);
    if (method == "paper") {
      EXPECT_EQ(result.stats.candidate_triangle_pairs, 0);
      EXPECT_EQ(result.stats.nodes_culled_by_cones, 1);  // the root
      // The certified root vouches for the isolated set's pairs too: none is generated.
      EXPECT_GT(result.stats.isolated_vf_pairs + result.stats.isolated_ee_pairs, 0);
      EXPECT_EQ(result.stats.vf_generated, 0);
      EXPECT_EQ(result.stats.ee_generated, 0);
    }
  }
}

// The crumpling cloth, mirrored across the vertical plane x = `fold` where x > fold, and
// raised by `lift`: its right half folded over its left half.
Positions folded_over(const Positions& x, double fold, double lift) {
  Positions y = x;
  for (Index v = 0; v < x.rows(); ++v) {
    if (x(v, 0) > fold) y(v, 0) = 2 * fold - x(v, 0), y(v, 2) += lift;
  }
  return y;
}

// After a certified step the detector refits the masks alone and skips the boxes while the
// root stays certified. A step whose root then fails must still find every collision:
// here the cloth moves far away and folds through itself, so boxes left from an earlier
// step would miss every pair of the fold. Every step equals brute force, for every preset.
TEST(DetectorVsBruteForce, BoxesSkippedWhileTheRootStaysCertifiedAreRefittedWhenItFails) {
  const ProceduralStep step = make_crumpling_cloth_step(sanitized() ? 800 : 2000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  const double fold = 0.5 * (step.x0.col(0).minCoeff() + step.x0.col(0).maxCoeff());
  const double depth = std::max(step.x0.col(2).maxCoeff(), step.x1.col(2).maxCoeff()) -
                       std::min(step.x0.col(2).minCoeff(), step.x1.col(2).minCoeff());
  Positions far0 = step.x1, far1 = step.x1;
  far0.col(0).array() += 10.0, far1.col(0).array() += 10.0;
  // The right half passes from above the left half to below it.
  const Positions through0 = folded_over(far0, fold + 10.0, 2 * depth + 0.01);
  const Positions through1 = folded_over(far1, fold + 10.0, -(2 * depth + 0.01));
  struct Step {
    const Positions &x0, &x1;
    std::int64_t boxes_refitted;  // by the paper preset
  };
  const std::vector<Step> steps = {{step.x0, step.x1, 1},    // no certified step before
                                   {step.x0, step.x1, 0},    // certified again: masks only
                                   {through0, through1, 1},  // the root fails
                                   {step.x0, step.x1, 1},
                                   {step.x0, step.x1, 0}};
  std::vector<CollisionSet> truths;
  for (const Step& s : steps) truths.push_back(brute_force_self_collisions(mesh, s.x0, s.x1));
  EXPECT_EQ(truths[0].size(), 0u);
  ASSERT_GT(truths[2].size(), 10u) << "the fold must collide";
  for (const std::string& method : DetectionConfig::preset_names()) {
    SelfCollisionDetector detector(mesh, step.x0, DetectionConfig::preset(method));
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const DetectionResult result = detector.detect(steps[k].x0, steps[k].x1);
      expect_same(truths[k], result.collisions, method + " step " + std::to_string(k));
      if (method == "paper") {
        EXPECT_EQ(result.stats.boxes_refitted, steps[k].boxes_refitted) << "step " << k;
      }
    }
  }
}

TEST(DetectorVsBruteForce, IsolatedPairCollisionsAreFoundWhenTheRootIsNotCertified) {
  // Two triangles hinged on edge (0, 1); vertex 3 of the second passes through the first.
  // Its only face shares vertices with the first, so (3, first) is in the isolated set
  // and no triangle pair covers it: only the isolated set can find this collision. The
  // hinge folds through, so the normals leave every half-space and the root has no cone.
  Positions x0(4, 3), x1(4, 3);
  x0 << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, 0.8, 0.3;
  x1 = x0;
  x1(3, 2) = -0.3;
  FaceArray faces(2, 3);
  faces << 0, 1, 2, 1, 0, 3;
  const TriangleMesh mesh(4, faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, x0, x1);
  ASSERT_EQ(truth.vertex_face.size(), 1u);
  EXPECT_EQ(truth.vertex_face[0].vertex, 3);
  EXPECT_EQ(truth.vertex_face[0].face, 0);
  for (const std::string& method : DetectionConfig::preset_names()) {
    SelfCollisionDetector detector(mesh, x0, DetectionConfig::preset(method));
    const DetectionResult result = detector.detect(x0, x1);
    expect_same(truth, result.collisions, "hinge " + method);
    EXPECT_EQ(result.stats.nodes_culled_by_cones, 0) << method;
  }
}

TEST(DetectorVsBruteForce, ThickCloth) {
  const std::string dir = std::string(TAILOR_DATA_DIR) + "/thick-cloth/";
  const MeshData t0 = read_mesh(dir + "t0.ply");
  const MeshData t1 = read_mesh(dir + "t1.ply");
  const TriangleMesh mesh(static_cast<Index>(t0.vertices.rows()), t0.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, t0.vertices, t1.vertices);
  for (DetectionConfig config : all_stage_combinations()) {
    SelfCollisionDetector detector(mesh, t0.vertices, config);
    expect_same(truth, detector.detect(t0.vertices, t1.vertices).collisions,
                "thick-cloth " + describe(config));
  }
}

}  // namespace
}  // namespace tailor
