#pragma once
/// @file
/// Cloth against the arm's implicit volume: a cheap projection with Coulomb friction run
/// on the integrator's candidate positions, before the exact contact solver. It keeps
/// cloth vertices a margin outside the implicit arm, which contains the skinned arm mesh,
/// so the contact solver sees few cloth-arm events (Bridson et al. 2002 do the same with
/// a level set of the body).

#include <algorithm>
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

/// The margin (m) at which cloth vertices must be kept outside the implicit arm so that
/// every point of every cloth face, not only its vertices, is at least `clearance` outside.
///
/// Why: a vertex-only margin lets a long edge or a large face cut into a convex part of the
/// arm between its vertices (its sagitta); with a coarse sleeve (13 × 20: 4.4 cm edges
/// along the arm) over the flexed elbow that is several millimetres, the cloth then cuts
/// through the skinned arm mesh faster than the CCD impulses can undo it.
///
/// The bound: the implicit arm is a union of balls of radius at least `min_arm_radius`
/// (each round cone is swept by balls between its end radii). Take one ball (centre c,
/// radius r) and a triangle whose vertices are all at least r + m from c, and a circle of
/// radius ρ around the triangle in its plane (centre o). ψ(x) = |x - c|² - |x - o|² + ρ² is
/// affine in x and at least (r + m)² at every vertex (|v - o| ≤ ρ), hence on the whole
/// triangle, so |x - c|² ≥ (r + m)² - ρ² there. The clearance sqrt((r + m)² - ρ²) - r grows
/// with r, so the smallest ball is the worst, and m = sqrt((r + clearance)² + ρ²) - r
/// gives every face point the clearance. A triangle with longest edge L has an enclosing
/// circle of radius ρ ≤ L / √3 (equilateral is the worst case); with the strain limit
/// the longest deformed edge is (1 + max_strain) times the longest rest edge. The result
/// is at least `clearance` (the vertex margin on its own).
double face_clearance_margin(double min_arm_radius, double longest_rest_edge, double max_strain,
                             double clearance);

/// The implicit arm over one substep: its skeleton at the start and at the end.
struct ArmMotion {
  /// The arm (shape and skinning).
  const Arm& arm;
  /// Skeleton at the start of the substep.
  const ArmSkeleton& skeleton0;
  /// Skeleton at the end of the substep.
  const ArmSkeleton& skeleton1;
};

/// The cloth at the start of a substep, as the arm contacts read it.
struct ClothAtSubstepStart {
  const Positions& x0;            ///< positions
  const Positions& v0;            ///< velocities
  const Eigen::VectorXd& masses;  ///< per vertex
};

/// What the arm contacts keep per cloth vertex from one substep to the next.
struct ArmContactMemory {
  const std::vector<double>& normal_forces;  ///< lagged normal force (N)
  const std::vector<char>& fixed;            ///< pinned vertices (empty: none)
  std::vector<char>& released;               ///< leaving the arm: no spring this substep
};

/// Contact planes for the implicit solve of a substep of length `h`: every cloth vertex
/// not `fixed` and not `released` that is within `margin + activation` of the implicit arm
/// of `skeleton0` gets a plane `margin` outside the arm of `skeleton1`, carried along by the
/// nearer bone's motion, with the bone's velocity there, Coulomb friction, the vertex's
/// lagged normal force and its slip speed at `v0`. Vertices farther away are cleared from
/// `released`.
std::vector<ContactPlane> arm_contact_planes(const ArmMotion& arm_motion,
                                             const ClothAtSubstepStart& cloth, double h,
                                             const ArmContactSettings& settings,
                                             const ArmContactMemory& memory);

/// After the solve: a plane whose spring would pull its vertex towards the arm marks the
/// vertex `released` (it is leaving: the next substep gives it no spring); the others
/// store their normal force at `x1` in `normal_forces` (zero for every other vertex), the
/// lagged normal force of the next substep's friction. Returns the number of pushing
/// contacts.
std::int64_t finish_arm_contacts(const std::vector<ContactPlane>& planes, const Positions& x1,
                                 std::vector<char>& released, std::vector<double>& normal_forces);

/// Per cloth vertex, where its signed distance to one posed implicit arm was last evaluated
/// and by how much it cleared the margin there. The signed distance to the arm is
/// 1-Lipschitz (the minimum of exact distances to two convex round cones), so a vertex that
/// has moved less than that clearance since cannot be within the margin: the repeated
/// projections of the strain limiter's sweeps skip the query for it. Valid for one arm
/// pose and one margin: reset() when either changes.
class ArmClearanceCache {
 public:
  /// Forgets everything; `vertices` cloth vertices.
  void reset(Index vertices);
  /// Whether projecting `p` (vertex `i`) is known to leave it where it is: it is certainly
  /// at least the margin outside the arm, or it is exactly where an earlier projection
  /// found it far enough out (settle()), and the projection decides the same input the
  /// same way. In the strain limiter's sweeps most vertices lying on the arm are not moved
  /// from one sweep to the next.
  bool known_unmoved(Index i, const Vec3& p) const {
    const auto k = static_cast<std::size_t>(i);
    if (m_clearance[k] < 0) return p == m_where[k];
    return (p - m_where[k]).squaredNorm() < m_clearance[k] * m_clearance[k];
  }
  /// Records that the projection leaves vertex `i` at `p` where it is (its distance test at
  /// exactly `p` passed).
  void settle(Index i, const Vec3& p) {
    m_where[static_cast<std::size_t>(i)] = p;
    m_clearance[static_cast<std::size_t>(i)] = -1;
  }
  /// Records that vertex `i` at `p` clears the margin by `clearance` (≥ 0), less a
  /// nanometre so that rounding in the distance cannot make a skipped vertex one the
  /// query would have moved (the projection decides exactly as without the cache).
  void store(Index i, const Vec3& p, double clearance) {
    m_where[static_cast<std::size_t>(i)] = p;
    m_clearance[static_cast<std::size_t>(i)] = std::max(0.0, clearance - kRounding);
  }
  /// Metres: far above the rounding of a distance of metre-sized coordinates.
  static constexpr double kRounding = 1e-9;

 private:
  std::vector<Vec3> m_where;
  std::vector<double> m_clearance;  // 0: nothing known; -1: settled at m_where exactly
};

/// How project_out_of_arm moves the vertices.
struct ArmProjection {
  double margin = 0;    ///< keep every vertex this far outside the implicit arm (m)
  double friction = 0;  ///< reduce tangential slip by at most this times the correction
  const std::vector<char>* fixed = nullptr;     ///< vertices never moved (null: none)
  std::vector<Index>* projected_ids = nullptr;  ///< receives the moved vertices (optional)
  ArmClearanceCache* cache = nullptr;           ///< for skeleton1 and margin (optional)
};

/// Moves every vertex of `x1` not `fixed` to at least `margin` outside the implicit arm of
/// `skeleton1`, and reduces its tangential motion relative to the arm (the rigid motion of
/// the nearer bone from `skeleton0` to `skeleton1`) by at most `friction` times the normal
/// correction. The `cache` skips the vertices it proves clear and learns the others.
ArmCollisionStats project_out_of_arm(const ArmMotion& arm_motion, const Positions& x0,
                                     Positions& x1, const ArmProjection& projection);

}  // namespace tailor
