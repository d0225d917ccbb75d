#pragma once
/// @file
/// Cloth against the arm's implicit volume: a cheap projection with Coulomb friction run
/// on the integrator's candidate positions, before the exact contact solver. It keeps
/// cloth vertices a margin outside the implicit arm, which contains the skinned arm mesh,
/// so the contact solver sees few cloth-arm events (Bridson et al. 2002 do the same with
/// a level set of the body).

#include <cstdint>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/scene/arm.hpp"

namespace tailor {

/// What one projection did.
struct ArmCollisionStats {
  std::int64_t projected = 0;  ///< vertices moved out of the arm
  double max_depth = 0;        ///< deepest penetration below the margin (m)
};

/// Moves every vertex of `x1` not flagged in `fixed` (may be empty) to at least
/// `margin` outside the implicit arm of `skeleton1`, and reduces its tangential motion
/// relative to the arm (the rigid motion of the nearer bone from `skeleton0` to
/// `skeleton1`) by at most `friction` times the normal correction.
ArmCollisionStats project_out_of_arm(const Arm& arm, const ArmSkeleton& skeleton0,
                                     const ArmSkeleton& skeleton1, const Positions& x0,
                                     Positions& x1, double margin, double friction,
                                     const std::vector<char>& fixed);

}  // namespace tailor
