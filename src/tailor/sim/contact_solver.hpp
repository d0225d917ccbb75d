#pragma once
/// @file
/// Intersection-free contact handling for one cloth substep (docs/design.md §4): proximity
/// repulsion, CCD impulses iterated (Bridson, Fedkiw & Anderson 2002), rigid impact
/// zones as the fail-safe (Provot 1997; Harmon et al. 2008), against the cloth itself
/// and a moving kinematic obstacle (the arm).

#include <functional>
#include <memory>
#include <vector>

#include "tailor/detection/collision.hpp"
#include "tailor/detection/detection_config.hpp"
#include "tailor/detection/detection_stats.hpp"
#include "tailor/mesh/triangle_mesh.hpp"
#include "tailor/scene/contact_params.hpp"
#include "tailor/sim/kinematic_obstacle.hpp"

namespace tailor {

/// What one call to ContactSolver::resolve did.
struct ContactStats {
  std::int64_t self_collisions = 0;         ///< cloth-cloth VF+EE collisions found (first pass)
  std::int64_t obstacle_collisions = 0;     ///< cloth-arm collisions found (first pass)
  std::int64_t repulsions = 0;              ///< proximity repulsion impulses applied
  std::int64_t impulses = 0;                ///< CCD impulses applied over all passes
  std::int64_t impulse_iterations = 0;      ///< CCD passes run
  std::int64_t impact_zones = 0;            ///< rigid impact zones formed
  std::int64_t zone_iterations = 0;         ///< impact-zone passes run
  bool last_resort = false;                 ///< positions were reverted to keep the invariant
  std::int64_t reverted_vertices = 0;       ///< last resort: vertices put back to x0
  std::int64_t arm_following_vertices = 0;  ///< last resort / zones: vertices moved with the arm
  /// Collisions still present when the last resort could change nothing more (0 means the
  /// substep is certified collision-free; see contact_solver.cpp for when it can be > 0).
  std::int64_t unresolved = 0;
  DetectionStats detection;  ///< self-collision detection stats of the first pass
  /// Self-collisions of the first pass (filled only when the detector keeps candidate
  /// pairs, DetectionConfig::keep_candidate_pairs, for the per-frame contact files).
  CollisionSet first_pass_collisions;
  /// Sorted unique cloth faces in a candidate triangle pair of the first pass (same condition).
  std::vector<Index> candidate_faces;
  ///@{
  /// Time in collision detection and in the response (ms).
  double detection_ms = 0, response_ms = 0;
  ///@}
};

/// Makes a cloth substep intersection-free: given intersection-free start positions `x0`
/// and candidate end positions `x1` from the integrator, modifies `x1` so that no
/// cloth-cloth or cloth-obstacle contact happens over the substep.
class ContactSolver {
 public:
  /// `masses` per cloth vertex (kg); a vertex with infinite mass (pinned) is never moved.
  /// `section_loops`: rings of cloth vertices, one per radial-view observer (optional;
  /// see SelfCollisionDetector).
  ContactSolver(const TriangleMesh& cloth, const Positions& x_build, Eigen::VectorXd masses,
                DetectionConfig detection, ContactParams params,
                std::vector<std::vector<Index>> section_loops = {});
  ~ContactSolver();
  /// Moves the solver; the moved-from one may only be destroyed or assigned to.
  ContactSolver(ContactSolver&&) noexcept;
  /// Move assignment (as the move constructor).
  ContactSolver& operator=(ContactSolver&&) noexcept;

  /// A change of the end positions that the solver interleaves with its own (e.g. strain
  /// limiting): run after the proximity pass and after every CCD impulse pass, each time
  /// before the detection that certifies the pass, so it can never leave a collision.
  using PositionFilter = std::function<void(Positions& x1)>;
  /// Sets (or clears, when empty) the position filter.
  void set_position_filter(PositionFilter filter);

  /// Resolves contacts over the substep of length `dt` (s); `x1` is modified in place.
  ContactStats resolve(const Positions& x0, Positions& x1, const KinematicObstacle& obstacle,
                       double dt);

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tailor
