/// @file
/// Radial-view culling on the sleeve during the gestures, against brute force at every
/// substep: the detector's collision sets with radial view equal brute force's, no culled
/// pair of faces holds a collision, and the culling cuts most of Tang's pairs.

#include <gtest/gtest.h>

#include "culling/radial_view_checks.hpp"
#include "sim/small_scene.hpp"
#include "support/sanitized.hpp"
#include "tailor/culling/radial_view_culling.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor {
namespace {

using tailor::testing::culled_colliding_pairs;
using tailor::testing::expect_same_collisions;
using tailor::testing::sanitized;

/// A small, fast version of the default scene (the gesture played twice as fast), one
/// substep per frame so that every substep can be checked.
SceneConfig one_substep_scene(const std::string& gesture) {
  SceneConfig c = testing::small_fast_scene(gesture);
  c.time_step = c.time_step / c.substeps;
  c.substeps = 1;
  return c;
}

// Plays the gesture and checks every substep: the step the cloth took, and the same
// motion stretched 4x (the cloth then passes through itself at the folds, so there are
// collisions to lose).
void check_gesture(const std::string& gesture) {
  const SceneConfig scene = one_substep_scene(gesture);
  Simulation simulation(scene);
  const TriangleMesh& mesh = simulation.cloth_mesh();
  const Positions& rest = simulation.scene().sleeve().rest;
  const auto loops = simulation.scene().observer_loops();
  DetectionConfig tang = DetectionConfig::preset("tang");
  tang.keep_candidate_pairs = true;
  DetectionConfig cones_radial = DetectionConfig::preset("basic");
  cones_radial.normal_cones = cones_radial.contour_test = cones_radial.radial_view = true;
  SelfCollisionDetector paper(mesh, rest, DetectionConfig::preset("paper"), loops);
  SelfCollisionDetector radial_stage(mesh, rest, cones_radial, loops);
  SelfCollisionDetector without(mesh, rest, tang);
  RadialViewCulling radial(mesh, rest, loops);

  // Every substep up to the peak of the gesture (0.6 s), every third under sanitizers.
  const int substeps = static_cast<int>(0.6 / scene.time_step);
  const int stride = sanitized() ? 3 : 1;
  std::int64_t steps = 0, collisions = 0, ctps_tang = 0, ctps_radial = 0;
  Positions x0 = simulation.cloth_positions();
  for (int substep = 0; substep < substeps; ++substep) {
    simulation.step_frame();
    const Positions x1 = simulation.cloth_positions();
    if (substep % stride == 0) {
      for (const double stretch : {1.0, 4.0}) {
        SCOPED_TRACE(::testing::Message() << gesture << " substep " << substep << " x" << stretch);
        const Positions target = x0 + stretch * (x1 - x0);
        const CollisionSet truth = brute_force_self_collisions(mesh, x0, target);
        collisions += static_cast<std::int64_t>(truth.size());
        expect_same_collisions(paper.detect(x0, target).collisions, truth, "paper");
        expect_same_collisions(radial_stage.detect(x0, target).collisions, truth, "radial stage");
        radial.classify(x0, target);
        EXPECT_EQ(culled_colliding_pairs(mesh, truth, radial), 0);
        std::vector<TrianglePair> pairs = without.detect(x0, target).candidate_triangle_pairs;
        ctps_tang += static_cast<std::int64_t>(pairs.size());
        radial.cull(pairs);
        ctps_radial += static_cast<std::int64_t>(pairs.size());
        ++steps;
      }
    }
    x0 = x1;
  }
  EXPECT_GT(collisions, 0) << gesture;
  EXPECT_LT(2 * ctps_radial, ctps_tang) << gesture << ": radial view cut too little";
  EXPECT_GT(steps, 0);
}

TEST(RadialViewGestures, Elbow) {
  check_gesture("elbow");
}
TEST(RadialViewGestures, Raise) {
  check_gesture("raise");
}
TEST(RadialViewGestures, Twist) {
  check_gesture("twist");
}

}  // namespace
}  // namespace tailor
