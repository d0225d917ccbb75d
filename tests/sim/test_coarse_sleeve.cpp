/// @file
/// Coarse sleeves through whole gestures: every resolution a user may pick stays
/// intersection-free, not only the default one (long edges used to cut into the flexed
/// elbow between their vertices), and the face clearance bound behind the arm margin
/// holds against the implicit arm itself.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <utility>

#include "support/sanitized.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/sim/arm_collision.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor {
namespace {

using tailor::testing::sanitized;

struct CoarseRun {
  int rings = 0, segments = 0;
  const char* gesture = "elbow";
  int frames = 80;  // the whole default gesture
};

std::string name_of(const CoarseRun& c) {
  return std::to_string(c.rings) + "x" + std::to_string(c.segments) + " " + c.gesture;
}

/// Runs the default scene (speed, substeps, thickness) with a coarse sleeve and checks
/// every substep: the static check finds nothing, the contact solver certified it.
void expect_intersection_free(const CoarseRun& run) {
  SCOPED_TRACE(name_of(run));
  SceneConfig config;
  config.sleeve.rings = run.rings;
  config.sleeve.segments = run.segments;
  config.gesture.name = run.gesture;
  SimulationOptions options;
  options.check_intersections = true;  // after every substep
  Simulation sim(config, options);
  for (int f = 0; f < run.frames; ++f) {
    for (const StepRecord& r : sim.step_frame()) {
      ASSERT_TRUE(r.checked);
      ASSERT_EQ(r.intersections(), 0) << "frame " << r.frame << " substep " << r.substep;
      ASSERT_EQ(r.contact.unresolved, 0) << "frame " << r.frame << " substep " << r.substep;
      ASSERT_EQ(r.contact.reverted_vertices, 0) << "frame " << r.frame;
    }
  }
  EXPECT_EQ(sim.totals().checked_steps, sim.totals().steps);
  EXPECT_EQ(sim.totals().failed_solves, 0);
  EXPECT_LE(sim.totals().max_strain, 0.10);
}

// Today's failure: 13 × 20 and 10 × 16 ended in intersections from frame 32-35 on (peak
// flexion is at frame 39), so the sanitized run still goes past it.
TEST(CoarseSleeve, ElbowGestureStaysIntersectionFree) {
  const int frames = sanitized() ? 40 : 80;
  expect_intersection_free({13, 20, "elbow", frames});
  expect_intersection_free({10, 16, "elbow", frames});
}

TEST(CoarseSleeve, RaiseAndTwistStayIntersectionFree) {
  if (sanitized()) GTEST_SKIP() << "the elbow runs cover the coarse sleeve under sanitizers";
  expect_intersection_free({10, 16, "raise"});
  expect_intersection_free({10, 16, "twist"});
}

TEST(CoarseSleeve, ArmMarginGrowsWithTheEdgeLength) {
  const double clearance = 3e-3;
  // Fine sleeves keep about the plain vertex margin; coarser ones need more.
  EXPECT_LT(face_clearance_margin(0.027, 1e-3, 0.025, clearance), 1.01 * clearance);
  const double m13 = face_clearance_margin(0.027, 0.05, 0.025, clearance);
  const double m10 = face_clearance_margin(0.027, 0.067, 0.025, clearance);
  EXPECT_GT(m13, clearance);
  EXPECT_GT(m10, m13);
  // The default scene's margin is 1.5 thicknesses or more, and a coarse sleeve's larger.
  SceneConfig fine, coarse;
  coarse.sleeve.rings = 13;
  coarse.sleeve.segments = 20;
  SimulationOptions options;
  options.contact = false;
  const double fine_margin = Simulation(fine, options).arm_margin();
  EXPECT_GE(fine_margin, 1.5 * fine.contact.thickness);
  EXPECT_GT(Simulation(coarse, options).arm_margin(), fine_margin);
}

// Sleeves whose margin would exceed their slack do not provably clear the arm at rest and
// cannot keep the margin without inflating: 2 × 3, 3 × 4, 4 × 6 and 3 × 8 ended in
// intersections. They are refused with a message naming the resolution.
TEST(CoarseSleeve, TooCoarseSleevesAreRejected) {
  SimulationOptions options;
  options.contact = false;
  for (const auto& [rings, segments] : {std::pair{2, 3}, {3, 4}, {4, 6}, {3, 8}}) {
    SceneConfig c;
    c.sleeve.rings = rings;
    c.sleeve.segments = segments;
    try {
      Simulation sim(c, options);
      ADD_FAILURE() << rings << " x " << segments << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::to_string(rings) + " rings"), std::string::npos)
          << e.what();
    }
  }
  SceneConfig c;
  c.sleeve.rings = 9;
  c.sleeve.segments = 12;
  EXPECT_LE(Simulation(c, options).arm_margin(), c.sleeve.slack);
}

// The bound against the implicit arm itself (union of two round cones, elbow bent 130°):
// random triangles with edges up to (1 + strain) × L whose vertices were pushed out to a
// margin; returns the closest any sampled point of any triangle came (dense sampling is
// the oracle). Vertices start near the wrist's and the elbow's balls, the tightest parts.
double closest_face_point(const std::function<double(double)>& margin_of, int triangles) {
  const Arm arm;
  ArmPose pose;
  pose.elbow_flexion = 130.0 * M_PI / 180.0;
  const ArmSkeleton skeleton = arm.skeleton(pose);
  const double strain = 0.025;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_direction = [&] {
    Vec3 d;
    do d = Vec3(unit(rng), unit(rng), unit(rng));
    while (d.norm() < 0.1 || d.norm() > 1.0);
    return Vec3(d.normalized());
  };
  const Vec3 centres[2] = {skeleton.wrist(arm.params().forearm_length), skeleton.elbow()};
  double worst = 1e9;
  for (int t = 0; t < triangles; ++t) {
    const double longest = 0.01 + 0.03 * (1 + unit(rng));
    const double margin = margin_of(longest);
    const auto on_margin = [&](Vec3 p) {
      for (int it = 0; it < 20; ++it) {
        const ArmDistance d = arm.distance(skeleton, p);
        if (d.distance >= margin) break;
        p += (margin - d.distance + 1e-9) * d.normal;
      }
      return p;
    };
    const Vec3 p0 = on_margin(centres[t % 2] + 0.03 * random_direction());
    const Vec3 p1 = on_margin(p0 + longest * random_direction());
    const Vec3 p2 = on_margin(p0 + longest * random_direction());
    const double max_edge = (1 + strain) * longest;
    if ((p1 - p0).norm() > max_edge || (p2 - p0).norm() > max_edge || (p2 - p1).norm() > max_edge) {
      continue;  // outside the premise of the bound
    }
    const int n = 16;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const double u = double(i) / n, v = double(j) / n;
        worst = std::min(worst, arm.signed_distance(skeleton, (1 - u - v) * p0 + u * p1 + v * p2));
      }
    }
  }
  return worst;
}

constexpr double kClearance = 3e-3;

TEST(CoarseSleeve, FaceClearanceBoundHoldsAgainstTheImplicitArm) {
  const int triangles = sanitized() ? 300 : 2000;
  const ArmParams a;
  const double min_radius = std::min({a.shoulder_radius, a.elbow_radius, a.wrist_radius});
  const double with_bound = closest_face_point(
      [&](double longest) { return face_clearance_margin(min_radius, longest, 0.025, kClearance); },
      triangles);
  EXPECT_GE(with_bound, kClearance * (1 - 1e-6));
  // The oracle can tell: with the vertex margin alone, faces come much closer.
  const double vertex_margin_only =
      closest_face_point([](double) { return kClearance; }, triangles);
  EXPECT_LT(vertex_margin_only, 0.5 * kClearance);
}

}  // namespace
}  // namespace tailor
