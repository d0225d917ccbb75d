/// @file
/// Projection of cloth vertices out of the implicit arm.

#include "tailor/sim/arm_collision.hpp"

#include <algorithm>

namespace tailor {

ArmCollisionStats project_out_of_arm(const Arm& arm, const ArmSkeleton& skeleton0,
                                     const ArmSkeleton& skeleton1, const Positions& x0,
                                     Positions& x1, double margin, double friction,
                                     const std::vector<char>& fixed) {
  ArmCollisionStats stats;
  const std::array<Eigen::Isometry3d, 2> motion = {
      skeleton1.upper_arm * skeleton0.upper_arm.inverse(),
      skeleton1.forearm * skeleton0.forearm.inverse()};
  for (Eigen::Index i = 0; i < x1.rows(); ++i) {
    if (!fixed.empty() && fixed[static_cast<std::size_t>(i)] != 0) continue;
    Vec3 p = x1.row(i).transpose();
    bool moved = false;
    // A few passes: in the elbow crease, leaving one cone can enter the other.
    for (int pass = 0; pass < 4; ++pass) {
      const ArmDistance d = arm.distance(skeleton1, p);
      if (d.distance >= margin) break;
      const double depth = margin - d.distance;
      stats.max_depth = std::max(stats.max_depth, depth);
      p += depth * d.normal;
      if (pass == 0 && friction > 0) {
        // Tangential slip relative to the moving arm, reduced by at most μ·depth.
        const Vec3 carried = motion[static_cast<std::size_t>(d.bone)] * Vec3(x0.row(i).transpose());
        Vec3 slip = p - carried;
        slip -= slip.dot(d.normal) * d.normal;
        const double s = slip.norm();
        if (s > 0) p -= std::min(1.0, friction * depth / s) * slip;
      }
      moved = true;
    }
    if (moved) {
      ++stats.projected;
      x1.row(i) = p.transpose();
    }
  }
  return stats;
}

}  // namespace tailor
