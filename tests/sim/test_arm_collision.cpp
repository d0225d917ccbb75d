/// @file
/// The projection out of the implicit arm: the clearance cache (a Lipschitz bound, and the
/// vertices left unmoved where a projection settled them) must decide exactly as the
/// uncached projection, over repeated perturb-and-project rounds;
/// and projecting a projected state again moves nothing.

#include <gtest/gtest.h>

#include <random>

#include "support/sanitized.hpp"
#include "tailor/sim/arm_collision.hpp"

namespace tailor {
namespace {

/// `n` random points along the bones of the arm in skeleton `s`, each coordinate up to
/// `spread` from the bone's axis.
Positions points_around_arm(const ArmSkeleton& s, Eigen::Index n, double spread,
                            std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Positions x(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double along = 0.55 * (0.5 + 0.5 * unit(rng));
    const Vec3 axis = along < 0.3 ? Vec3(s.upper_arm * Vec3(along, 0, 0))
                                  : Vec3(s.forearm * Vec3(along - 0.3, 0, 0));
    x.row(i) = (axis + spread * Vec3(unit(rng), unit(rng), unit(rng))).transpose();
  }
  return x;
}

TEST(ArmCollision, ClearanceCacheDecidesExactlyAsTheQueries) {
  const Arm arm;
  ArmPose pose0, pose1;
  pose0.elbow_flexion = 1.0;
  pose1.elbow_flexion = 1.02;
  const ArmSkeleton s0 = arm.skeleton(pose0), s1 = arm.skeleton(pose1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Index n = tailor::testing::sanitized() ? 300 : 2000;
  // Points around the arm, many within a few centimetres of its surface.
  const Positions x0 = points_around_arm(s1, n, 0.07, rng);
  const double margin = 0.008;
  Positions plain = x0, cached = x0;
  ArmClearanceCache cache;
  cache.reset(n);
  std::int64_t projected = 0;
  for (int round = 0; round < 30; ++round) {
    // The same small random motion for both (as a strain-limiting sweep would make); in odd
    // rounds only about half of the vertices move (a sweep corrects some edges only), so
    // vertices the last projection settled on the margin are met again unmoved.
    const double step = round % 3 == 0 ? 2e-3 : 2e-4;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::RowVector3d d(unit(rng), unit(rng), unit(rng));
      if (round % 2 == 1 && d.x() < 0) continue;
      plain.row(i) += step * d;
      cached.row(i) += step * d;
    }
    std::vector<Index> ids_plain, ids_cached;
    const ArmCollisionStats a = project_out_of_arm({arm, s0, s1}, x0, plain,
                                                   {.margin = margin, .projected_ids = &ids_plain});
    const ArmCollisionStats b =
        project_out_of_arm({arm, s0, s1}, x0, cached,
                           {.margin = margin, .projected_ids = &ids_cached, .cache = &cache});
    ASSERT_EQ(a.projected, b.projected) << "round " << round;
    ASSERT_EQ(ids_plain, ids_cached) << "round " << round;
    ASSERT_TRUE(plain == cached) << "round " << round;  // bit-identical positions
    projected += a.projected;
  }
  EXPECT_GT(projected, 0);  // the rounds did move vertices out of the arm
}

TEST(ArmCollision, ProjectingAProjectedStateAgainMovesNothing) {
  // The strain limiter stops only when a sweep corrects no edge and the projection that
  // follows moves no vertex: a vertex just projected onto the margin (up to rounding)
  // must not count as inside it the next time.
  const Arm arm;
  ArmPose pose;
  pose.elbow_flexion = 1.2;
  const ArmSkeleton s = arm.skeleton(pose);
  std::mt19937 rng(5);
  const Eigen::Index n = tailor::testing::sanitized() ? 500 : 5000;
  Positions x = points_around_arm(s, n, 0.06, rng);
  const double margin = 0.003;
  const Positions x0 = x;
  const ArmCollisionStats first = project_out_of_arm({arm, s, s}, x0, x, {.margin = margin});
  ASSERT_GT(first.projected, n / 4);  // most points started inside the arm
  const Positions projected = x;
  const ArmCollisionStats again = project_out_of_arm({arm, s, s}, x0, x, {.margin = margin});
  EXPECT_EQ(again.projected, 0);
  EXPECT_TRUE(x == projected);
}

}  // namespace
}  // namespace tailor
