#pragma once
/// @file
/// The arm-sleeve simulation driver (docs/design.md §4, docs/simulation.md). Per substep:
/// forces and implicit solve with the arm's contact springs and Coulomb friction ->
/// candidate x1 -> strain limiting together with the projection out of the implicit arm ->
/// ContactSolver::resolve (cloth-cloth and cloth-arm mesh, strain limiting between its
/// passes) -> v = (x1 - x0) / h -> optional static intersection check.

#include <cstdint>
#include <memory>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "tailor/detection/detection_config.hpp"
#include "tailor/scene/scene.hpp"
#include "tailor/sim/cloth_model.hpp"
#include "tailor/sim/contact_solver.hpp"
#include "tailor/sim/strain_limiter.hpp"

namespace tailor {

/// How to run a scene.
struct SimulationOptions {
  /// Self-collision detection settings of the contact solver.
  DetectionConfig detection = DetectionConfig::preset("paper");
  bool check_intersections = false;  ///< run check_intersections() after every substep
  bool check_frames = false;         ///< run it after the last substep of every frame
  bool contact = true;               ///< run the ContactSolver (off: cloth model and arm only)
  ClothSolver solver = ClothSolver::automatic;  ///< linear solver of the implicit step
  double cg_tolerance = 1e-4;                   ///< relative residual for the iterative solver
  /// Coulomb friction of the cloth on the implicit arm (inside the implicit solve, see
  /// ContactPlane); negative: ContactParams::friction.
  double arm_friction = -1.0;
  /// Keep each substep's first-pass collisions and candidate faces in StepRecord::contact
  /// (for the per-frame contact files; sets DetectionConfig::keep_candidate_pairs).
  bool record_contacts = false;
};

/// Everything about one substep.
struct StepRecord {
  int frame = 0;                   ///< frame this substep belongs to (1-based)
  int substep = 0;                 ///< 0-based within the frame
  double time = 0;                 ///< simulated time at the end of the substep (s)
  ClothStepInfo cloth;             ///< the implicit solve
  std::int64_t arm_contacts = 0;   ///< vertices held on the implicit arm by contact springs
  std::int64_t arm_projected = 0;  ///< vertices moved out of the implicit arm afterwards
  StrainLimitStats strain_limit;   ///< the strain limiter (all its rounds)
  double max_strain = 0;           ///< largest edge strain at the end of the substep
  double strain_p99 = 0;           ///< 99th-percentile edge strain at the end of the substep
  ContactStats contact;  ///< the contact solver (self-collisions, impulses, zones, detection)
  bool checked = false;  ///< whether the static check ran
  std::int64_t self_intersections = 0;      ///< cloth-cloth (adjacent included), if checked
  std::int64_t obstacle_intersections = 0;  ///< cloth-arm, if checked
  double forces_solve_ms = 0;  ///< forces, assembly, linear solve, strain limit, arm projection
  double strain_ms = 0;        ///< strain limiting with the arm projection (inside forces_solve)
  double detection_ms = 0;     ///< self-collision detection inside the contact solver
  double response_ms = 0;      ///< contact response inside the contact solver
  double check_ms = 0;         ///< static intersection check
  double step_ms = 0;          ///< the whole substep
  /// All intersections the static check found.
  std::int64_t intersections() const { return self_intersections + obstacle_intersections; }
};

/// JSON object of one substep (one line of steps.jsonl).
void to_json(nlohmann::json& json, const StepRecord& record);

/// Sums and extremes over the substeps run so far.
struct SimulationTotals {
  int frames = 0;                        ///< frames completed
  std::int64_t steps = 0;                ///< substeps completed
  std::int64_t self_collisions = 0;      ///< cloth-cloth collisions the contact solver found
  std::int64_t obstacle_collisions = 0;  ///< cloth-arm collisions the contact solver found
  std::int64_t intersections = 0;        ///< found by the static check (must be 0)
  std::int64_t checked_steps = 0;        ///< substeps the static check ran after
  std::int64_t impulses = 0;             ///< CCD impulses applied
  std::int64_t impact_zones = 0;         ///< rigid impact zones formed
  std::int64_t last_resorts = 0;         ///< substeps the contact solver had to revert
  std::int64_t failed_solves = 0;        ///< implicit solves that failed (velocities kept)
  std::int64_t reverted_vertices = 0;    ///< summed over substeps (the last resort)
  std::int64_t unresolved = 0;           ///< collisions the last resort left (must be 0)
  double max_strain = 0;                 ///< largest edge strain after any substep
  double max_strain_p99 = 0;             ///< largest 99th-percentile strain after any substep
  ///@{
  /// Largest per-step number of candidate triangle pairs, and of VF and EE pairs sent to
  /// the exact CCD.
  std::int64_t max_ctps = 0, max_vf = 0, max_ee = 0;
  ///@}
  DetectionStats detection;  ///< summed over steps
  ///@{
  /// Summed times (ms) of the parts of a substep (see StepRecord).
  double forces_solve_ms = 0, detection_ms = 0, response_ms = 0, check_ms = 0, step_ms = 0;
  ///@}
  ///@{
  /// Parts of forces_solve_ms (ms, summed).
  double assemble_ms = 0, solve_ms = 0, strain_ms = 0;
  ///@}
  double wall_seconds = 0;  ///< wall time spent in step_frame()
};

/// Runs a Scene frame by frame.
class Simulation {
 public:
  /// Builds the scene, the cloth model (shoulder ring pinned) and the contact solver.
  /// Throws InputError (naming the resolution) for a sleeve too coarse for its faces to
  /// clear the arm: one whose arm_margin() would exceed the sleeve's slack.
  explicit Simulation(const SceneConfig& config, SimulationOptions options = {});
  ~Simulation();
  /// Moves the simulation; the moved-from one may only be destroyed or assigned to.
  Simulation(Simulation&&) noexcept;
  /// Move assignment (as the move constructor).
  Simulation& operator=(Simulation&&) noexcept;

  /// Advances one frame (config().substeps substeps); returns that frame's substeps.
  const std::vector<StepRecord>& step_frame();

  /// The built scene.
  const Scene& scene() const;
  /// The options it runs with.
  const SimulationOptions& options() const;
  /// Frames completed.
  int frame() const;
  /// Simulated time (s).
  double time() const;
  /// Cloth positions now.
  const Positions& cloth_positions() const;
  /// Cloth velocities now ((x1 - x0) / h of the last substep).
  const Positions& cloth_velocities() const;
  /// Skinned arm positions now.
  const Positions& arm_positions() const;
  /// The sleeve's connectivity.
  const TriangleMesh& cloth_mesh() const;
  /// The arm's connectivity.
  const TriangleMesh& arm_mesh() const;
  /// The cloth dynamics.
  const ClothModel& cloth_model() const;
  /// Energies of the current cloth state.
  ClothEnergy energy() const;
  /// Sums over the substeps run so far.
  const SimulationTotals& totals() const;
  /// How far outside the implicit arm cloth vertices are kept (m): 1.5 contact thicknesses,
  /// more for coarse sleeves so that their faces clear the arm too (face_clearance_margin).
  double arm_margin() const;
  /// Radial-view observer positions now, one per cluster (empty without radial view).
  std::vector<Vec3> observer_positions() const;
  /// Radial-view cluster id of every cloth face (empty without radial view).
  std::vector<Index> cluster_of_face() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

/// The summary of a run as JSON: frames, steps, self_collisions, intersections,
/// interrupted, ms per step split (forces_solve, detection, response, check, total),
/// frames per second, CTP/VF/EE means and maxima, and the scene.
nlohmann::json simulation_summary(const Simulation& simulation, bool interrupted);

}  // namespace tailor
