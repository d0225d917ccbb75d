/// @file
/// Intersection-free contact for one cloth substep: resolve() is a short sequence of named
/// stages (repel, apply_ccd_impulses, merge_impact_zones, last_resort, finish) over the
/// concepts kept in their own files: closest points (geometry/closest_point), cloth vs
/// moving obstacle CCD (detection/obstacle_collision_detector), contact impulses
/// (sim/contact_response), proximity repulsion (sim/proximity_repulsion) and rigid impact
/// zones (sim/impact_zones). The optional position filter (e.g. strain limiting) runs after
/// the repulsion and after every impulse pass, always before the detection that certifies
/// the next pass.
///
/// Order of work in resolve() (x0 fixed, x1 modified):
///  1. Proximity, cloth-arm: a cloth vertex closer than the thickness to the arm at the end
///     of the step is pushed out to the thickness (Coulomb friction on its motion relative
///     to the arm point).
///  2. Proximity, cloth-cloth (Bridson, Fedkiw & Anderson 2002, §7.2): VF and EE pairs
///     closer than the thickness at the end of the step get a repulsion that cancels
///     their approach (up to the overlap) plus a tenth of the overlap, with friction.
///  3. CCD impulses (Bridson et al. 2002, §7.1), iterated up to max_impulse_iterations:
///     cloth-arm collisions from the exact CCD (cloth vertex vs arm face, arm vertex vs
///     cloth face, cloth edge vs arm edge; the arm has infinite mass) and cloth-cloth
///     collisions from SelfCollisionDetector::detect(x0, x1). Each collision gets an
///     inelastic impulse along the contact normal at the time of impact, distributed by
///     the barycentric weights and inverse masses, so the linearised gap at the end is at
///     least half the thickness (the full thickness against the arm).
///  4. Rigid impact zones (Provot 1997; Harmon et al. 2008), up to max_zone_iterations:
///     the vertices of every remaining collision are merged into zones; a zone moves
///     rigidly from x0 with its mass-weighted mean linear and angular velocity. A zone
///     holding "kinematic" vertices (pinned ones, or ones that hit the arm, which are set
///     to follow the arm surface) instead moves with the rigid motion that best fits the
///     kinematic vertices' prescribed motion (Kabsch), so the pinned motion is kept.
///  5. Last resort, until nothing collides: the vertices of a zone still in a cloth-cloth
///     collision go back to x0 (reverted); a vertex in a collision with the arm, or in a
///     cloth-cloth collision with an arm-following or pinned vertex, follows the arm (its
///     closest arm point at t0, carried by the arm's motion, its offset rotated with the
///     face normal and lifted to the thickness). States only move forward
///     (free -> reverted -> arm-following), so the loop ends.
///
/// Guarantees. Given x0 free of intersections and contacts:
///  - When `ContactStats::unresolved == 0` (every case in the tests and the sleeve
///    runs measured), the returned x1 has no cloth-cloth VF/EE contact over the step
///    (the final detect() is empty) and no contact with the arm (the final exact arm CCD
///    is empty), hence x1 is intersection-free. This is checked, not assumed: the loop only
///    exits clean after a detect() and an arm CCD pass that both found nothing.
///  - Cloth-only scenes (no obstacle, any pinning that does not move): the last resort
///    always ends clean, since a fully reverted zone does not move and x0 is contact-free.
///  - With the moving arm it can get stuck (unresolved > 0, logged): an arm-following
///    vertex or edge can still be reached by another part of the arm where the arm
///    deforms non-rigidly (skin folding at the elbow) or where an edge spans a convex arm
///    region; pinned vertices on the arm surface can touch it. Cloth primitives incident to
///    a pinned vertex are excluded from cloth-arm contact (the sleeve is pinned onto the
///    arm surface, so they touch it by construction).

#include "tailor/sim/contact_solver.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/parallel_invoke.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "tailor/detection/obstacle_collision_detector.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/closest_point.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"
#include "tailor/sim/contact_response.hpp"
#include "tailor/sim/impact_zones.hpp"
#include "tailor/sim/proximity_repulsion.hpp"

namespace tailor {
namespace {

/// Vertex states of the fail-safe; they only move forward.
enum class VertexState : unsigned char { free = 0, reverted = 1, arm_following = 2 };

std::vector<char> pinned_flags(const Eigen::VectorXd& masses) {
  std::vector<char> pinned(static_cast<std::size_t>(masses.size()), 0);
  for (Index i = 0; i < masses.size(); ++i) {
    if (!(masses[i] > 0)) {
      throw InputError(fmt::format("contact solver: vertex {} has mass {}", i, masses[i]));
    }
    pinned[static_cast<std::size_t>(i)] = std::isinf(masses[i]) ? 1 : 0;
  }
  return pinned;
}

Eigen::VectorXd inverse_masses(const Eigen::VectorXd& masses) {
  Eigen::VectorXd inverse(masses.size());
  for (Index i = 0; i < masses.size(); ++i)
    inverse[i] = std::isinf(masses[i]) ? 0.0 : 1.0 / masses[i];
  return inverse;
}

/// The collisions one pass finds: cloth-obstacle and cloth-cloth.
struct PassCollisions {
  std::vector<ObstacleCollision> obstacle;
  DetectionResult self;
  bool empty() const { return obstacle.empty() && self.collisions.size() == 0; }
};

}  // namespace

struct ContactSolver::Impl {
  const TriangleMesh& cloth;
  std::vector<char> pinned;
  ContactResponse response;
  SelfCollisionDetector detector;
  ObstacleCollisionDetector obstacle_detector;
  ProximityRepulsion repulsion;
  ContactParams params;
  PositionFilter filter;

  // State of one resolve() call.
  const Positions* x0 = nullptr;
  const KinematicObstacle* arm = nullptr;
  Positions pinned_x1;
  double detect_ms = 0;  // wall time of this call's detect() passes
  std::unordered_map<Index, Vec3> arm_targets;
  UnionFind zones;
  std::vector<char> follows, in_zone;

  Impl(const TriangleMesh& cloth_, const Positions& x_build, const Eigen::VectorXd& masses,
       DetectionConfig detection, ContactParams params_,
       std::vector<std::vector<Index>> section_loops)
      : cloth(cloth_),
        pinned(check_masses(cloth_, masses)),
        response(inverse_masses(masses), params_.friction),
        detector(cloth_, x_build, detection, std::move(section_loops)),
        obstacle_detector(cloth_, pinned),
        repulsion(cloth_, x_build, pinned),
        params(params_) {}

  static std::vector<char> check_masses(const TriangleMesh& cloth, const Eigen::VectorXd& masses) {
    if (masses.size() != cloth.num_vertices()) {
      throw InputError(fmt::format("contact solver: {} masses for {} cloth vertices", masses.size(),
                                   cloth.num_vertices()));
    }
    return pinned_flags(masses);
  }

  // ---- the stages of resolve() ---------------------------------------------------------

  ContactStats resolve(const Positions& X0, Positions& x1, const KinematicObstacle& obstacle,
                       double dt) {
    const auto start = SteadyClock::now();
    begin(X0, x1, obstacle, dt);
    ContactStats stats;
    stats.repulsions = repel(x1);
    bool clean = apply_ccd_impulses(x1, stats);
    if (!clean) clean = merge_impact_zones(x1, stats);
    if (!clean) last_resort(x1, stats);
    finish(x1, stats);
    stats.detection_ms = detect_ms;
    stats.response_ms = std::max(0.0, milliseconds_since(start) - stats.detection_ms);
    return stats;
  }

  /// Checks the input and sets the per-call state.
  void begin(const Positions& X0, const Positions& x1, const KinematicObstacle& obstacle,
             double dt) {
    if (X0.rows() != cloth.num_vertices() || x1.rows() != cloth.num_vertices()) {
      throw InputError("contact solver: positions do not match the cloth mesh");
    }
    if (!(dt > 0)) throw InputError("contact solver: the substep length must be positive");
    x0 = &X0;
    arm = obstacle.mesh != nullptr ? &obstacle : nullptr;
    if (arm != nullptr) obstacle_detector.set_obstacle(*obstacle.mesh, obstacle.x0, obstacle.x1);
    pinned_x1 = x1;
    detect_ms = 0;
    arm_targets.clear();
    const Index n = cloth.num_vertices();
    zones = UnionFind(n);
    follows.assign(static_cast<std::size_t>(n), 0);
    in_zone.assign(static_cast<std::size_t>(n), 0);
  }

  /// Every collision of the step x0 -> x1 (the certificate of a pass when empty).
  PassCollisions detect(const Positions& x1) {
    const auto start = SteadyClock::now();
    PassCollisions c;
    // The two detectors share nothing but the read-only positions, and neither fills two
    // cores on a sleeve-sized mesh: run side by side (default elbow: the arm's 0.9 ms and
    // the cloth's 0.5 ms per pass, one after the other before).
    tbb::parallel_invoke(
        [&] {
          if (arm != nullptr) c.obstacle = obstacle_detector.detect(*x0, x1);
        },
        [&] { c.self = detector.detect(*x0, x1); });
    detect_ms += milliseconds_since(start);
    return c;
  }

  /// 1–2. Proximity repulsion against the arm and within the cloth, then the filter.
  std::int64_t repel(Positions& x1) {
    std::int64_t count = 0;
    if (arm != nullptr && params.thickness > 0) {
      count += repulsion.repel_obstacle(*x0, x1, *arm, params.thickness, params.friction);
    }
    if (params.thickness > 0) count += repulsion.repel_cloth(*x0, x1, params.thickness, response);
    if (filter) filter(x1);
    return count;
  }

  /// 3. CCD impulses, iterated; true when a pass found nothing (certified clean).
  bool apply_ccd_impulses(Positions& x1, ContactStats& stats) {
    const int passes = std::max(1, params.max_impulse_iterations);
    for (int pass = 0; pass < passes; ++pass) {
      const PassCollisions found = detect(x1);
      if (pass == 0) record_first_pass(found, stats);
      if (found.empty()) return true;
      if (pass + 1 == passes) break;  // leave it to the impact zones
      ++stats.impulse_iterations;
      for (const ObstacleCollision& c : found.obstacle) {
        Contact contact = arm_contact(c, x1);
        if (orient_contact(contact) && response.apply(contact, params.thickness, x1))
          ++stats.impulses;
      }
      for (const auto& c : found.self.collisions.vertex_face) {
        Contact contact = self_vf_contact(c, x1);
        if (orient_contact(contact) && response.apply(contact, 0.5 * params.thickness, x1))
          ++stats.impulses;
      }
      for (const auto& c : found.self.collisions.edge_edge) {
        Contact contact = self_ee_contact(c, x1);
        if (orient_contact(contact) && response.apply(contact, 0.5 * params.thickness, x1))
          ++stats.impulses;
      }
      if (filter) filter(x1);
    }
    return false;
  }

  /// 4. Rigid impact zones; true when a pass found nothing.
  bool merge_impact_zones(Positions& x1, ContactStats& stats) {
    const Index n = cloth.num_vertices();
    for (int it = 0; it < params.max_zone_iterations; ++it) {
      const PassCollisions found = detect(x1);
      if (found.empty()) return true;
      ++stats.zone_iterations;
      const auto join = [&](std::initializer_list<Index> vs) {
        for (Index v : vs) {
          zones.unite(*vs.begin(), v);
          in_zone[v] = 1;
        }
      };
      for (const auto& c : found.self.collisions.vertex_face) {
        const auto F = cloth.faces().row(c.face);
        join({c.vertex, F(0), F(1), F(2)});
      }
      for (const auto& c : found.self.collisions.edge_edge) join({c.a0, c.a1, c.b0, c.b1});
      for (const ObstacleCollision& c : found.obstacle) {
        const std::vector<Index> vs = obstacle_detector.cloth_vertices(c);
        for (Index v : vs) {
          zones.unite(vs.front(), v);
          in_zone[v] = 1;
          if (!pinned[v]) follows[v] = 1;
        }
      }
      const std::vector<std::vector<Index>> groups = zone_groups(n);
      stats.impact_zones = static_cast<std::int64_t>(groups.size());
      for (const auto& g : groups) {
        move_zone_rigidly(
            g, *x0, response.inverse_mass(),
            {pinned, follows,
             [&](Index v) { return pinned[v] ? position(pinned_x1, v) : arm_target(v); }},
            x1);
      }
    }
    return false;
  }

  /// The vertices of each impact zone, zones in order of their smallest vertex.
  std::vector<std::vector<Index>> zone_groups(Index n) {
    std::vector<std::vector<Index>> groups;
    std::unordered_map<Index, std::size_t> group_of;
    for (Index v = 0; v < n; ++v) {
      if (!in_zone[v]) continue;
      auto [pos, added] = group_of.emplace(zones.find(v), groups.size());
      if (added) groups.emplace_back();
      groups[pos->second].push_back(v);
    }
    return groups;
  }

  /// 5. Last resort: revert zones to x0 or make vertices follow the arm, until clean.
  void last_resort(Positions& x1, ContactStats& stats) {
    const Index n = cloth.num_vertices();
    std::vector<VertexState> state(static_cast<std::size_t>(n), VertexState::free);
    std::unordered_map<Index, std::vector<Index>> zone_members;
    for (Index v = 0; v < n; ++v) {
      if (follows[v]) state[v] = VertexState::arm_following;
      if (in_zone[v]) zone_members[zones.find(v)].push_back(v);
    }
    for (std::int64_t guard = 0; guard < 2 * static_cast<std::int64_t>(n) + 4; ++guard) {
      const PassCollisions found = detect(x1);
      if (found.empty()) break;
      stats.last_resort = true;
      bool changed = false;
      const auto follow = [&](Index v) {
        if (pinned[v] || arm == nullptr || state[v] == VertexState::arm_following) return;
        state[v] = VertexState::arm_following;
        x1.row(v) = arm_target(v).transpose();
        changed = true;
      };
      const auto revert_zone = [&](Index v) {
        const auto it = in_zone[v] ? zone_members.find(zones.find(v)) : zone_members.end();
        const std::vector<Index> single{v};
        for (Index u : it != zone_members.end() ? it->second : single) {
          if (pinned[u] || state[u] != VertexState::free) continue;
          state[u] = VertexState::reverted;
          x1.row(u) = x0->row(u);
          changed = true;
        }
      };
      for (const ObstacleCollision& c : found.obstacle) {
        for (Index v : obstacle_detector.cloth_vertices(c)) follow(v);
      }
      const auto handle = [&](std::initializer_list<Index> vs) {
        bool anchored = false;  // the pair holds a vertex that moves on its own
        for (Index v : vs)
          anchored = anchored || pinned[v] || state[v] == VertexState::arm_following;
        for (Index v : vs) {
          if (anchored && arm != nullptr) {
            follow(v);
          } else {
            revert_zone(v);
          }
        }
      };
      for (const auto& c : found.self.collisions.vertex_face) {
        const auto F = cloth.faces().row(c.face);
        handle({c.vertex, F(0), F(1), F(2)});
      }
      for (const auto& c : found.self.collisions.edge_edge) handle({c.a0, c.a1, c.b0, c.b1});
      if (!changed) {
        stats.unresolved =
            static_cast<std::int64_t>(found.obstacle.size() + found.self.collisions.size());
        spdlog::warn("contact: {} collisions left that the last resort cannot undo",
                     stats.unresolved);
        break;
      }
    }
    for (Index v = 0; v < n; ++v) {
      stats.reverted_vertices += state[v] == VertexState::reverted ? 1 : 0;
      stats.arm_following_vertices += state[v] == VertexState::arm_following ? 1 : 0;
    }
  }

  /// Pinned vertices end exactly where they were prescribed (guards rounding in zones).
  void finish(Positions& x1, ContactStats&) {
    for (Index v = 0; v < cloth.num_vertices(); ++v) {
      if (pinned[v]) x1.row(v) = pinned_x1.row(v);
    }
  }

  // ---- helpers -------------------------------------------------------------------------

  /// Keeps the first pass's counts, and its collisions and candidate faces for the
  /// per-frame contact files when the detector keeps candidate pairs.
  void record_first_pass(const PassCollisions& found, ContactStats& stats) const {
    stats.self_collisions = static_cast<std::int64_t>(found.self.collisions.size());
    stats.obstacle_collisions = static_cast<std::int64_t>(found.obstacle.size());
    stats.detection = found.self.stats;
    if (!detector.config().keep_candidate_pairs) return;
    stats.first_pass_collisions = found.self.collisions;
    std::vector<Index>& faces = stats.candidate_faces;
    faces.clear();
    faces.reserve(2 * found.self.candidate_triangle_pairs.size());
    for (const TrianglePair& p : found.self.candidate_triangle_pairs) {
      faces.push_back(p.first);
      faces.push_back(p.second);
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  }

  ContactPoint arm_point(Index v) const {
    return {-1, position(arm->x0, v), position(arm->x1, v), 0};
  }

  Contact self_vf_contact(const VertexFaceCollision& col, const Positions& x1) const {
    Contact c;
    const auto F = cloth.faces().row(col.face);
    c.points = {response.cloth_point(col.vertex, *x0, x1), response.cloth_point(F(0), *x0, x1),
                response.cloth_point(F(1), *x0, x1), response.cloth_point(F(2), *x0, x1)};
    set_vertex_face_weights(c, col.toi);
    return c;
  }
  Contact self_ee_contact(const EdgeEdgeCollision& col, const Positions& x1) const {
    Contact c;
    c.points = {response.cloth_point(col.a0, *x0, x1), response.cloth_point(col.a1, *x0, x1),
                response.cloth_point(col.b0, *x0, x1), response.cloth_point(col.b1, *x0, x1)};
    set_edge_edge_weights(c, col.toi);
    return c;
  }
  Contact arm_contact(const ObstacleCollision& col, const Positions& x1) const {
    Contact c;
    const TriangleMesh& m = *arm->mesh;
    if (col.kind == ObstacleCollision::vertex_face) {
      const auto G = m.faces().row(col.obstacle);
      c.points = {response.cloth_point(col.cloth, *x0, x1), arm_point(G(0)), arm_point(G(1)),
                  arm_point(G(2))};
      set_vertex_face_weights(c, col.toi);
    } else if (col.kind == ObstacleCollision::face_vertex) {
      const auto F = cloth.faces().row(col.cloth);
      c.points = {arm_point(col.obstacle), response.cloth_point(F(0), *x0, x1),
                  response.cloth_point(F(1), *x0, x1), response.cloth_point(F(2), *x0, x1)};
      set_vertex_face_weights(c, col.toi);
    } else {
      const auto E = cloth.edges().row(col.cloth);
      const auto G = m.edges().row(col.obstacle);
      c.points = {response.cloth_point(E(0), *x0, x1), response.cloth_point(E(1), *x0, x1),
                  arm_point(G(0)), arm_point(G(1))};
      set_edge_edge_weights(c, col.toi);
    }
    return c;
  }

  /// Where an arm-following vertex goes: its closest arm point at t0 carried to t1, with
  /// the offset rotated like the face normal and at least the thickness along it.
  Vec3 arm_target(Index v) {
    if (auto it = arm_targets.find(v); it != arm_targets.end()) return it->second;
    const TriangleMesh& m = *arm->mesh;
    const Vec3 p = position(*x0, v);
    double best = std::numeric_limits<double>::infinity();
    Index best_face = -1;
    Vec3 best_bary = Vec3::Zero();
    for (Index f = 0; f < m.num_faces(); ++f) {
      const auto F = m.faces().row(f);
      const Vec3 a = position(arm->x0, F(0)), b = position(arm->x0, F(1)),
                 c = position(arm->x0, F(2));
      const Vec3 bary = closest_point_barycentric(p, a, b, c);
      const double d = (p - (bary[0] * a + bary[1] * b + bary[2] * c)).squaredNorm();
      if (d < best) {
        best = d;
        best_face = f;
        best_bary = bary;
      }
    }
    Vec3 target = p;
    if (best_face >= 0) {
      const auto F = m.faces().row(best_face);
      const auto point = [&](const Positions& y) {
        return Vec3(best_bary[0] * position(y, F(0)) + best_bary[1] * position(y, F(1)) +
                    best_bary[2] * position(y, F(2)));
      };
      const auto normal = [&](const Positions& y) {
        Vec3 n =
            (position(y, F(1)) - position(y, F(0))).cross(position(y, F(2)) - position(y, F(0)));
        return n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
      };
      const Vec3 q0 = point(arm->x0), q1 = point(arm->x1), n0 = normal(arm->x0),
                 n1 = normal(arm->x1);
      Vec3 offset = p - q0;
      if (n0.norm() > 0 && n1.norm() > 0) {
        offset = Eigen::Quaterniond::FromTwoVectors(n0, n1) * offset;
        const double along = offset.dot(n1);
        if (along < params.thickness) offset += (params.thickness - along) * n1;
      }
      target = q1 + offset;
    }
    arm_targets.emplace(v, target);
    return target;
  }
};

ContactSolver::ContactSolver(const TriangleMesh& cloth, const Positions& x_build,
                             Eigen::VectorXd masses, DetectionConfig detection,
                             ContactParams params, std::vector<std::vector<Index>> section_loops)
    : m_impl(std::make_unique<Impl>(cloth, x_build, masses, detection, params,
                                    std::move(section_loops))) {}
ContactSolver::~ContactSolver() = default;
ContactSolver::ContactSolver(ContactSolver&&) noexcept = default;
ContactSolver& ContactSolver::operator=(ContactSolver&&) noexcept = default;

void ContactSolver::set_position_filter(PositionFilter filter) {
  m_impl->filter = std::move(filter);
}

ContactStats ContactSolver::resolve(const Positions& x0, Positions& x1,
                                    const KinematicObstacle& obstacle, double dt) {
  return m_impl->resolve(x0, x1, obstacle, dt);
}

}  // namespace tailor
