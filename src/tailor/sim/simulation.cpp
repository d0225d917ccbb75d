/// @file
/// The arm-sleeve simulation driver.

#include "tailor/sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "tailor/culling/radial_view.hpp"
#include "tailor/detection/intersection_check.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"
#include "tailor/sim/arm_collision.hpp"
#include "tailor/sim/pinned_vertices.hpp"
#include "tailor/sim/strain_limiter.hpp"

namespace tailor {
namespace {

/// Cloth faces are kept this many contact thicknesses outside the implicit arm (the
/// skinned mesh sticks out of it by up to about 1.3 mm, see Arm).
constexpr double kArmMarginFactor = 1.5;
/// Arm contact springs are this many times stiffer than a vertex's inertia (m / h²).
constexpr double kArmContactStiffness = 1e3;
/// Most Gauss-Seidel sweeps of the strain limiter (each followed by the arm projection);
/// it stops as soon as both hold. With one step per frame the 10× sleeve (66 edges from
/// its pins) needs a few hundred: capped at 100, its largest strain over the elbow, raise
/// and twist gestures was 16.7 / 11.7 / 216 %; at 400, 3.3 / 7.3 / 4.1 %.
constexpr int kStrainSweeps = 400;
/// Strain-limiting sweeps between two passes of the contact solver.
constexpr int kContactStrainSweeps = 20;

double longest_edge(const TriangleMesh& mesh, const Positions& x) {
  double longest = 0;
  for (Eigen::Index e = 0; e < mesh.edges().rows(); ++e) {
    longest = std::max(longest, (x.row(mesh.edges()(e, 0)) - x.row(mesh.edges()(e, 1))).norm());
  }
  return longest;
}

/// How far outside the implicit arm the cloth vertices are kept: enough for every point of
/// every face to clear it by kArmMarginFactor thicknesses (face_clearance_margin), so
/// coarse sleeves with long edges do not cut into the arm between their vertices. A sleeve
/// so coarse that this margin exceeds its slack (the room it has around the arm at rest)
/// is rejected: its rest shape does not provably clear the arm, and it would have to
/// inflate against the strain limit to keep the margin (2 × 3 is a triangular tube through
/// the arm; 3 × 4 has 26 cm edges that cannot bend round the elbow).
double arm_margin_for(const SceneConfig& config, const Sleeve& sleeve) {
  const ArmParams& a = config.arm;
  const double min_radius = std::min({a.shoulder_radius, a.elbow_radius, a.wrist_radius});
  const double longest = longest_edge(*sleeve.mesh, sleeve.rest);
  const double margin = face_clearance_margin(min_radius, longest, config.material.strain_limit,
                                              kArmMarginFactor * config.contact.thickness);
  if (margin > config.sleeve.slack) {
    throw InputError(fmt::format(
        "sleeve too coarse: {} rings × {} segments has edges up to {:.1f} cm, so the cloth must "
        "be kept {:.1f} cm off the arm for its faces to clear it, more than the sleeve's slack "
        "of {:.1f} cm; use more rings or segments",
        config.sleeve.rings, config.sleeve.segments, 100 * longest, 100 * margin,
        100 * config.sleeve.slack));
  }
  return margin;
}

}  // namespace

void to_json(nlohmann::json& j, const StepRecord& r) {
  const ContactStats& c = r.contact;
  j = nlohmann::json{{"frame", r.frame},
                     {"substep", r.substep},
                     {"time", r.time},
                     {"self_collisions", c.self_collisions},
                     {"obstacle_collisions", c.obstacle_collisions},
                     {"repulsions", c.repulsions},
                     {"impulses", c.impulses},
                     {"impulse_iterations", c.impulse_iterations},
                     {"impact_zones", c.impact_zones},
                     {"last_resort", c.last_resort},
                     {"arm_contacts", r.arm_contacts},
                     {"arm_projected", r.arm_projected},
                     {"max_strain", r.max_strain},
                     {"strain_p99", r.strain_p99},
                     {"strain_limit",
                      {{"sweeps", r.strain_limit.sweeps},
                       {"corrections", r.strain_limit.corrections},
                       {"max_strain_before", r.strain_limit.max_strain_before},
                       {"max_strain_after", r.strain_limit.max_strain_after}}},
                     {"reverted_vertices", c.reverted_vertices},
                     {"unresolved", c.unresolved},
                     {"solver",
                      {{"direct", r.cloth.direct},
                       {"iterations", r.cloth.iterations},
                       {"residual", r.cloth.residual},
                       {"ok", r.cloth.ok}}},
                     {"detection", c.detection},
                     {"ms",
                      {{"forces_solve", r.forces_solve_ms},
                       {"assemble", r.cloth.assemble_ms},
                       {"solve", r.cloth.solve_ms},
                       {"strain_limit", r.strain_ms},
                       {"detection", r.detection_ms},
                       {"response", r.response_ms},
                       {"check", r.check_ms},
                       {"step", r.step_ms}}}};
  if (r.checked) {
    j["intersections"] = {{"self", r.self_intersections}, {"obstacle", r.obstacle_intersections}};
  }
}

struct Simulation::Impl {
  Scene scene;
  SimulationOptions options;
  ClothModel cloth;
  std::unique_ptr<ContactSolver> contact;
  PinnedVertices pinned;              // the shoulder ring, in every form the parts read
  std::vector<char> released;         // arm contacts let go (their spring pulled last step)
  std::vector<double> normal_forces;  // arm contact normal force of the last step (N)
  StrainLimiter limiter;
  std::vector<Index> projected_ids;
  ArmClearanceCache arm_cache;  // per substep: the arm pose at its end
  double arm_margin = 0;        // cloth vertices are kept this far outside the implicit arm (m)
  Positions x, v, y;
  ArmSkeleton skeleton;
  int frame = 0;
  std::int64_t step_index = 0;
  std::vector<StepRecord> records;
  SimulationTotals totals;
  // The detector's radial-view clusters, rebuilt here (deterministically the same) for
  // the observer positions and cluster ids of the contact files.
  std::unique_ptr<RadialViewClusters> clusters;

  Impl(const SceneConfig& config, SimulationOptions opts)
      : scene(config),
        options(opts),
        cloth([&]() -> ClothModel {
          const Positions warp = scene.sleeve().warp_directions();
          return ClothModel(*scene.sleeve().mesh, scene.sleeve().rest, config.material, &warp);
        }()),
        pinned(scene.sleeve().pinned_vertices(), scene.sleeve().rest),
        limiter(*scene.sleeve().mesh, scene.sleeve().rest,
                pinned.with_infinite_masses(cloth.masses()), config.material.strain_limit) {
    const Sleeve& sleeve = scene.sleeve();
    arm_margin = arm_margin_for(config, sleeve);
    cloth.set_pinned(pinned.ids());
    cloth.set_solver(options.solver, options.cg_tolerance);
    released.assign(pinned.flags().size(), 0);
    normal_forces.assign(pinned.flags().size(), 0.0);
    x = sleeve.rest;
    v = Positions::Zero(x.rows(), 3);
    const ArmPose pose0 = scene.gesture().pose_at(0.0);
    skeleton = scene.arm().skeleton(pose0);
    y = scene.arm().skin(pose0);
    // The pose at t = 0 may differ from the rest pose the sleeve was built in.
    if (!pinned.ids().empty()) {
      const Positions targets = scene.arm().skin_points(pinned.rest(), pose0);
      for (std::size_t i = 0; i < pinned.ids().size(); ++i)
        x.row(pinned.ids()[i]) = targets.row(static_cast<Eigen::Index>(i));
    }
    if (options.record_contacts) options.detection.keep_candidate_pairs = true;
    if (options.detection.radial_view) {
      clusters = std::make_unique<RadialViewClusters>(*sleeve.mesh, x, scene.observer_loops());
    }
    if (options.contact) {
      contact = std::make_unique<ContactSolver>(
          *sleeve.mesh, x, pinned.with_infinite_masses(cloth.masses()), options.detection,
          config.contact, scene.observer_loops());
    }
  }

  void substep(int substep_index) {
    const SceneConfig& config = scene.config();
    const Arm& arm = scene.arm();
    const double h = config.time_step / config.substeps;
    StepRecord record;
    record.frame = frame + 1;
    record.substep = substep_index;
    // Times from the step count, so long runs do not accumulate rounding.
    const double t1 = static_cast<double>(step_index + 1) * h;
    record.time = t1;
    const auto step_start = SteadyClock::now();

    const ArmPose pose1 = scene.gesture().pose_at(t1);
    const ArmSkeleton skeleton1 = arm.skeleton(pose1);
    Positions y1 = arm.skin(pose1);
    const Positions targets = arm.skin_points(pinned.rest(), pose1);

    // Cloth on the arm: contact springs and friction in the solve, then strain limiting
    // and a safety projection out of the implicit arm, alternately.
    const double margin = arm_margin;
    const double arm_friction =
        options.arm_friction >= 0 ? options.arm_friction : config.contact.friction;
    const ArmContactSettings arm_settings{margin, 0.5 * margin, kArmContactStiffness, arm_friction};
    const ArmMotion arm_motion{arm, skeleton, skeleton1};
    const std::vector<ContactPlane> planes =
        arm_contact_planes(arm_motion, {x, v, cloth.masses()}, h, arm_settings,
                           {normal_forces, pinned.flags(), released});
    Positions x1, v1;
    record.cloth = cloth.step(x, v, {h, config.gravity, &targets, planes}, x1, v1);
    record.arm_contacts = finish_arm_contacts(planes, x1, released, normal_forces);
    // Strain limit and the implicit arm together (alternating projections); the
    // projection carries no friction here: friction acted in the solve.
    const auto strain_start = SteadyClock::now();
    arm_cache.reset(x1.rows());
    record.strain_limit = limiter.apply(x1, kStrainSweeps, [&](Positions& x_end) {
      const ArmCollisionStats arm_stats = project_out_of_arm(arm_motion, x, x_end,
                                                             {.margin = margin,
                                                              .friction = 0.0,
                                                              .fixed = &pinned.flags(),
                                                              .projected_ids = &projected_ids,
                                                              .cache = &arm_cache});
      for (Index i : projected_ids) released[static_cast<std::size_t>(i)] = 0;
      record.arm_projected += arm_stats.projected;
      return arm_stats.projected;
    });
    record.strain_ms = milliseconds_since(strain_start);
    record.forces_solve_ms = milliseconds_since(step_start);

    if (contact) resolve_contacts(x1, y1, h, record);
    v = (x1 - x) / h;
    x = std::move(x1);
    const StrainSummary strain = strain_summary(*scene.sleeve().mesh, scene.sleeve().rest, x);
    record.max_strain = strain.max;
    record.strain_p99 = strain.p99;
    y = std::move(y1);
    skeleton = skeleton1;

    if (options.check_intersections ||
        (options.check_frames && substep_index + 1 == config.substeps)) {
      check_step(record);
    }
    record.step_ms = milliseconds_since(step_start);
    ++step_index;
    accumulate(record);
    records.push_back(std::move(record));
  }

  // Self and arm contacts of the step from x to x1 (the arm from y to y1), with strain
  // limiting interleaved with the contact passes (see ContactSolver).
  void resolve_contacts(Positions& x1, const Positions& y1, double h, StepRecord& record) {
    contact->set_position_filter([&](Positions& x_end) {
      const StrainLimitStats again = limiter.apply(x_end, kContactStrainSweeps);
      record.strain_limit.sweeps += again.sweeps;
      record.strain_limit.corrections += again.corrections;
      record.strain_limit.max_strain_after = again.max_strain_after;
    });
    KinematicObstacle obstacle;
    obstacle.mesh = &scene.arm().mesh();
    obstacle.x0 = std::move(y);
    obstacle.x1 = y1;
    record.contact = contact->resolve(x, x1, obstacle, h);
    record.detection_ms = record.contact.detection_ms;
    record.response_ms = record.contact.response_ms;
  }

  // The exact static intersection check of the cloth (and against the arm) at the end of
  // the step.
  void check_step(StepRecord& record) const {
    const auto check_start = SteadyClock::now();
    const IntersectionReport report =
        check_intersections(*scene.sleeve().mesh, x, &scene.arm().mesh(), &y);
    record.checked = true;
    record.self_intersections = report.self_intersections + report.adjacent_intersections;
    record.obstacle_intersections = report.obstacle_intersections;
    record.check_ms = milliseconds_since(check_start);
  }

  void accumulate(const StepRecord& r) {
    SimulationTotals& t = totals;
    ++t.steps;
    t.self_collisions += r.contact.self_collisions;
    t.obstacle_collisions += r.contact.obstacle_collisions;
    t.intersections += r.intersections();
    t.checked_steps += r.checked ? 1 : 0;
    t.impulses += r.contact.impulses;
    t.impact_zones += r.contact.impact_zones;
    t.last_resorts += r.contact.last_resort ? 1 : 0;
    t.failed_solves += r.cloth.ok ? 0 : 1;
    t.reverted_vertices += r.contact.reverted_vertices;
    t.unresolved += r.contact.unresolved;
    t.max_strain = std::max(t.max_strain, r.max_strain);
    t.max_strain_p99 = std::max(t.max_strain_p99, r.strain_p99);
    t.max_ctps = std::max(t.max_ctps, r.contact.detection.candidate_triangle_pairs);
    t.max_vf = std::max(t.max_vf, r.contact.detection.vf_tested);
    t.max_ee = std::max(t.max_ee, r.contact.detection.ee_tested);
    t.detection += r.contact.detection;
    t.forces_solve_ms += r.forces_solve_ms;
    t.assemble_ms += r.cloth.assemble_ms;
    t.solve_ms += r.cloth.solve_ms;
    t.strain_ms += r.strain_ms;
    t.detection_ms += r.detection_ms;
    t.response_ms += r.response_ms;
    t.check_ms += r.check_ms;
    t.step_ms += r.step_ms;
  }
};

Simulation::Simulation(const SceneConfig& config, SimulationOptions options)
    : m_impl(std::make_unique<Impl>(config, options)) {}
Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

const std::vector<StepRecord>& Simulation::step_frame() {
  Impl& m = *m_impl;
  const auto start = SteadyClock::now();
  m.records.clear();
  for (int s = 0; s < m.scene.config().substeps; ++s) m.substep(s);
  ++m.frame;
  m.totals.frames = m.frame;
  m.totals.wall_seconds += milliseconds_since(start) / 1000.0;
  return m.records;
}

const Scene& Simulation::scene() const {
  return m_impl->scene;
}
const SimulationOptions& Simulation::options() const {
  return m_impl->options;
}
int Simulation::frame() const {
  return m_impl->frame;
}
double Simulation::time() const {
  return static_cast<double>(m_impl->step_index) * m_impl->scene.config().time_step /
         m_impl->scene.config().substeps;
}
const Positions& Simulation::cloth_positions() const {
  return m_impl->x;
}
const Positions& Simulation::cloth_velocities() const {
  return m_impl->v;
}
const Positions& Simulation::arm_positions() const {
  return m_impl->y;
}
const TriangleMesh& Simulation::cloth_mesh() const {
  return *m_impl->scene.sleeve().mesh;
}
const TriangleMesh& Simulation::arm_mesh() const {
  return m_impl->scene.arm().mesh();
}
const ClothModel& Simulation::cloth_model() const {
  return m_impl->cloth;
}
ClothEnergy Simulation::energy() const {
  return m_impl->cloth.energy(m_impl->x, m_impl->v, m_impl->scene.config().gravity);
}
const SimulationTotals& Simulation::totals() const {
  return m_impl->totals;
}
double Simulation::arm_margin() const {
  return m_impl->arm_margin;
}

std::vector<Vec3> Simulation::observer_positions() const {
  std::vector<Vec3> out;
  const Impl& m = *m_impl;
  if (!m.clusters) return out;
  for (Index c = 0; c < m.clusters->num_clusters(); ++c)
    out.push_back(m.clusters->observer(c, m.x));
  return out;
}

std::vector<Index> Simulation::cluster_of_face() const {
  const Impl& m = *m_impl;
  if (!m.clusters) return {};
  std::vector<Index> out(static_cast<std::size_t>(cloth_mesh().num_faces()), -1);
  for (Index c = 0; c < m.clusters->num_clusters(); ++c) {
    for (Index f : m.clusters->faces(c)) out[static_cast<std::size_t>(f)] = c;
  }
  return out;
}

nlohmann::json simulation_summary(const Simulation& simulation, bool interrupted) {
  const SimulationTotals& t = simulation.totals();
  const double steps = t.steps > 0 ? static_cast<double>(t.steps) : 1.0;
  const DetectionConfig& d = simulation.options().detection;
  nlohmann::json j;
  j["frames"] = t.frames;
  j["steps"] = t.steps;
  j["self_collisions"] = t.self_collisions;
  j["obstacle_collisions"] = t.obstacle_collisions;
  j["intersections"] = t.intersections;
  j["checked_steps"] = t.checked_steps;
  j["interrupted"] = interrupted;
  j["impulses"] = t.impulses;
  j["impact_zones"] = t.impact_zones;
  j["last_resorts"] = t.last_resorts;
  j["failed_solves"] = t.failed_solves;
  j["reverted_vertices"] = t.reverted_vertices;
  j["unresolved"] = t.unresolved;
  j["strain"] = {{"max", t.max_strain}, {"p99_max", t.max_strain_p99}};
  j["ms_per_step"] = {{"forces_solve", t.forces_solve_ms / steps},
                      {"assemble", t.assemble_ms / steps},
                      {"solve", t.solve_ms / steps},
                      {"strain_limit", t.strain_ms / steps},
                      {"detection", t.detection_ms / steps},
                      {"response", t.response_ms / steps},
                      {"check", t.check_ms / steps},
                      {"total", t.step_ms / steps}};
  j["frames_per_second"] = t.wall_seconds > 0 ? t.frames / t.wall_seconds : 0.0;
  j["wall_seconds"] = t.wall_seconds;
  j["candidate_triangle_pairs"] = {
      {"mean", static_cast<double>(t.detection.candidate_triangle_pairs) / steps},
      {"max", t.max_ctps}};
  j["vf_tested"] = {{"mean", static_cast<double>(t.detection.vf_tested) / steps},
                    {"max", t.max_vf}};
  j["ee_tested"] = {{"mean", static_cast<double>(t.detection.ee_tested) / steps},
                    {"max", t.max_ee}};
  j["detection_totals"] = t.detection;
  j["detection_config"] = d;  // every setting (docs/settings.md)
  j["cloth"] = {{"vertices", simulation.cloth_mesh().num_vertices()},
                {"faces", simulation.cloth_mesh().num_faces()}};
  j["arm"] = {{"vertices", simulation.arm_mesh().num_vertices()},
              {"faces", simulation.arm_mesh().num_faces()}};
  j["arm_margin"] = simulation.arm_margin();
  j["scene"] = scene_config_to_json(simulation.scene().config());
  return j;
}

}  // namespace tailor
