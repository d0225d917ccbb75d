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
#include "tailor/sim/cloth_model.hpp"

namespace tailor {

/// What one projection did.
struct ArmCollisionStats {
  std::int64_t projected = 0;  ///< vertices moved out of the arm
  double max_depth = 0;        ///< deepest penetration below the margin (m)
};

/// How cloth vertices touch the implicit arm in the solve.
struct ArmContactSettings {
  double margin = 0;           ///< planes sit this far outside the implicit arm (m)
  double activation = 0;       ///< vertices within margin + activation at x0 get a plane (m)
  double stiffness_ratio = 0;  ///< spring stiffness in units of a vertex's m / h²
  double friction = 0;         ///< Coulomb coefficient cloth-skin
};

/// Contact planes for the implicit solve of a substep of length `h`: every vertex not
/// `fixed` and not `released` that is within `margin + activation` of the implicit arm of
/// `skeleton0` gets a plane `margin` outside the arm of `skeleton1`, carried along by the
/// nearer bone's motion, with the bone's velocity there, Coulomb friction, the vertex's
/// lagged normal force `normal_forces[i]` (N) and its slip speed at `v0`. Vertices farther
/// away are cleared from `released`.
std::vector<ContactPlane> arm_contact_planes(const Arm& arm, const ArmSkeleton& skeleton0,
                                             const ArmSkeleton& skeleton1, const Positions& x0,
                                             const Positions& v0, const Eigen::VectorXd& masses,
                                             double h, const ArmContactSettings& settings,
                                             const std::vector<double>& normal_forces,
                                             const std::vector<char>& fixed,
                                             std::vector<char>& released);

/// After the solve: a plane whose spring would pull its vertex towards the arm marks the
/// vertex `released` (it is leaving: the next substep gives it no spring); the others
/// store their normal force at `x1` in `normal_forces` (zero for every other vertex), the
/// lagged normal force of the next substep's friction. Returns the number of pushing
/// contacts.
std::int64_t finish_arm_contacts(const std::vector<ContactPlane>& planes, const Positions& x1,
                                 std::vector<char>& released, std::vector<double>& normal_forces);

/// Moves every vertex of `x1` not flagged in `fixed` (may be empty) to at least
/// `margin` outside the implicit arm of `skeleton1`, and reduces its tangential motion
/// relative to the arm (the rigid motion of the nearer bone from `skeleton0` to
/// `skeleton1`) by at most `friction` times the normal correction.
ArmCollisionStats project_out_of_arm(const Arm& arm, const ArmSkeleton& skeleton0,
                                     const ArmSkeleton& skeleton1, const Positions& x0,
                                     Positions& x1, double margin, double friction,
                                     const std::vector<char>& fixed,
                                     std::vector<Index>* projected_ids = nullptr);

}  // namespace tailor
