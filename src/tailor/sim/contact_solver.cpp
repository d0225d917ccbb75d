/// @file
/// Intersection-free contact for one cloth substep.
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
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "tailor/bvh/bvh.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

Vec3 row(const Positions& x, Index i) {
  return x.row(i).transpose();
}

/// Closest point of triangle (a, b, c) to p, as barycentric weights (Ericson 2005, 5.1.5).
Vec3 closest_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = (d1 - d3) != 0 ? d1 / (d1 - d3) : 0.0;
    return {1 - v, v, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = (d2 - d6) != 0 ? d2 / (d2 - d6) : 0.0;
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double den = (d4 - d3) + (d5 - d6);
    const double w = den != 0 ? (d4 - d3) / den : 0.0;
    return {0, 1 - w, w};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0) || !std::isfinite(sum)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  const double v = vb / sum, w = vc / sum;
  return {1 - v - w, v, w};
}

/// Parameters (s, u) of the closest points of segments p0p1 and q0q1 (Ericson 5.1.9).
std::pair<double, double> closest_segment_params(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                                 const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double tiny = 1e-300;
  if (a <= tiny && e <= tiny) return {0, 0};
  double s = 0, t = 0;
  if (a <= tiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= tiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {s, t};
}

/// One point of a contact pair: a cloth vertex (cloth >= 0) or an arm point, with its
/// positions at the start and end of the step and its weight in the relative position
/// (positive on one side, negative on the other; each side's weights sum to 1).
struct Slot {
  Index cloth = -1;
  Vec3 p0, p1;
  double w = 0;
};

/// A contact between two features: up to four slots.
struct Contact {
  std::array<Slot, 4> slots;
  int n = 0;
  Vec3 normal = Vec3::Zero();  ///< from side "negative" to side "positive"
  double gap0 = 0;             ///< gap along the normal at t = 0
};

/// What kind of arm collision: cloth vertex vs arm face, arm vertex vs cloth face, or
/// cloth edge vs arm edge; a, b, c, d are the ids in that order (cloth ids, arm ids).
struct ArmCollision {
  enum Kind : int { vertex_face = 0, face_vertex = 1, edge_edge = 2 } kind;
  Index a = -1, b = -1;  ///< the cloth primitive, the arm primitive
  double toi = 1;
  friend bool operator<(const ArmCollision& x, const ArmCollision& y) {
    return std::tie(x.kind, x.a, x.b) < std::tie(y.kind, y.a, y.b);
  }
};

Aabb point_box(const Vec3& p0, const Vec3& p1, double inflate = 0) {
  Aabb box;
  box.extend(p0);
  box.extend(p1);
  box.min -= inflate;
  box.max += inflate;
  return box;
}

/// Vertex states of the fail-safe; they only move forward.
enum class VertexState : unsigned char { free = 0, reverted = 1, arm_following = 2 };

/// Union-find over cloth vertices.
struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(Index n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  Index find(Index v) {
    while (parent[v] != v) {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // deterministic roots
  }
};

}  // namespace

struct ContactSolver::Impl {
  const TriangleMesh& cloth;
  Eigen::VectorXd inv_mass;
  std::vector<char> pinned;
  SelfCollisionDetector detector;
  ContactParams params;

  // Cloth-arm broad phase (cloth trees refitted every pass, arm trees per resolve).
  Bvh cloth_vertex_bvh, cloth_edge_bvh, cloth_face_bvh;
  Bvh arm_vertex_bvh, arm_edge_bvh, arm_face_bvh;
  // Proximity trees on end-of-step boxes (refitted, built once per topology).
  Bvh cloth_point_bvh, cloth_near_face_bvh, arm_near_face_bvh;
  const TriangleMesh* arm_mesh = nullptr;
  bool arm_mesh_changed = false;  // the arm trees were rebuilt in this resolve
  // Per-resolve state.
  const Positions* x0 = nullptr;
  const KinematicObstacle* arm = nullptr;
  double arm_seconds = 0;  // time spent in arm CCD
  std::unordered_map<Index, Vec3> arm_targets;
  PositionFilter filter;

  Impl(const TriangleMesh& cloth_, const Positions& x_build, Eigen::VectorXd masses,
       DetectionConfig detection, ContactParams params_,
       std::vector<std::vector<Index>> section_loops)
      : cloth(cloth_),
        detector(cloth_, x_build, detection, std::move(section_loops)),
        params(params_) {
    if (masses.size() != cloth.num_vertices()) {
      throw InputError(fmt::format("contact solver: {} masses for {} cloth vertices", masses.size(),
                                   cloth.num_vertices()));
    }
    inv_mass.resize(masses.size());
    pinned.assign(static_cast<std::size_t>(masses.size()), 0);
    for (Index i = 0; i < masses.size(); ++i) {
      if (!(masses[i] > 0)) {
        throw InputError(fmt::format("contact solver: vertex {} has mass {}", i, masses[i]));
      }
      pinned[i] = std::isinf(masses[i]) ? 1 : 0;
      inv_mass[i] = pinned[i] ? 0.0 : 1.0 / masses[i];
    }
    cloth_vertex_bvh = Bvh(cloth_vertex_boxes(x_build, x_build));
    cloth_edge_bvh = Bvh(cloth_edge_boxes(x_build, x_build));
    cloth_face_bvh = Bvh(cloth_face_boxes(x_build, x_build, 0));
    cloth_point_bvh = Bvh(cloth_vertex_boxes(x_build, x_build));
    cloth_near_face_bvh = Bvh(cloth_face_boxes(x_build, x_build, 0));
  }

  // ---- boxes ---------------------------------------------------------------------------

  std::vector<Aabb> cloth_vertex_boxes(const Positions& a, const Positions& b) const {
    std::vector<Aabb> boxes(static_cast<std::size_t>(cloth.num_vertices()));
    for (Index v = 0; v < cloth.num_vertices(); ++v) boxes[v] = point_box(row(a, v), row(b, v));
    return boxes;
  }
  std::vector<Aabb> cloth_edge_boxes(const Positions& a, const Positions& b) const {
    std::vector<Aabb> boxes(static_cast<std::size_t>(cloth.num_edges()));
    for (Index e = 0; e < cloth.num_edges(); ++e) {
      for (int k = 0; k < 2; ++k)
        boxes[e].extend(point_box(row(a, cloth.edges()(e, k)), row(b, cloth.edges()(e, k))));
    }
    return boxes;
  }
  std::vector<Aabb> cloth_face_boxes(const Positions& a, const Positions& b, double inflate) const {
    std::vector<Aabb> boxes(static_cast<std::size_t>(cloth.num_faces()));
    for (Index f = 0; f < cloth.num_faces(); ++f) {
      for (int k = 0; k < 3; ++k) {
        boxes[f].extend(
            point_box(row(a, cloth.faces()(f, k)), row(b, cloth.faces()(f, k)), inflate));
      }
    }
    return boxes;
  }

  void prepare_arm(const KinematicObstacle& obstacle) {
    const TriangleMesh& m = *obstacle.mesh;
    if (obstacle.x0.rows() != m.num_vertices() || obstacle.x1.rows() != m.num_vertices()) {
      throw InputError("contact solver: obstacle positions do not match its mesh");
    }
    std::vector<Aabb> vb(static_cast<std::size_t>(m.num_vertices())),
        eb(static_cast<std::size_t>(m.num_edges())), fb(static_cast<std::size_t>(m.num_faces()));
    for (Index v = 0; v < m.num_vertices(); ++v)
      vb[v] = point_box(row(obstacle.x0, v), row(obstacle.x1, v));
    for (Index e = 0; e < m.num_edges(); ++e) {
      eb[e].extend(vb[m.edges()(e, 0)]);
      eb[e].extend(vb[m.edges()(e, 1)]);
    }
    for (Index f = 0; f < m.num_faces(); ++f) {
      for (int k = 0; k < 3; ++k) fb[f].extend(vb[m.faces()(f, k)]);
    }
    arm_mesh_changed = false;
    if (arm_mesh != &m || arm_vertex_bvh.num_primitives() != m.num_vertices() ||
        arm_face_bvh.num_primitives() != m.num_faces()) {
      arm_vertex_bvh = Bvh(vb);
      arm_edge_bvh = Bvh(eb);
      arm_face_bvh = Bvh(fb);
      arm_mesh = &m;
      arm_mesh_changed = true;
    } else {
      arm_vertex_bvh.refit(vb);
      arm_edge_bvh.refit(eb);
      arm_face_bvh.refit(fb);
    }
  }

  bool touches_pinned_face(Index f) const {
    const auto& F = cloth.faces();
    return pinned[F(f, 0)] || pinned[F(f, 1)] || pinned[F(f, 2)];
  }
  bool touches_pinned_edge(Index e) const {
    return pinned[cloth.edges()(e, 0)] || pinned[cloth.edges()(e, 1)];
  }

  // ---- cloth-arm exact CCD -------------------------------------------------------------

  /// Every cloth-arm collision over x0 -> x1 (sorted).
  std::vector<ArmCollision> arm_collisions(const Positions& x1) {
    std::vector<ArmCollision> out;
    if (arm == nullptr) return out;
    const auto start = Clock::now();
    const Positions& X0 = *x0;
    const Positions& Y0 = arm->x0;
    const Positions& Y1 = arm->x1;
    const TriangleMesh& m = *arm_mesh;
    cloth_vertex_bvh.refit(cloth_vertex_boxes(X0, x1));
    cloth_edge_bvh.refit(cloth_edge_boxes(X0, x1));
    cloth_face_bvh.refit(cloth_face_boxes(X0, x1, 0));
    std::vector<ArmCollision> candidates;
    cloth_vertex_bvh.for_each_overlapping_pair(arm_face_bvh, [&](Index v, Index f) {
      if (!pinned[v]) candidates.push_back({ArmCollision::vertex_face, v, f, 1});
    });
    cloth_face_bvh.for_each_overlapping_pair(arm_vertex_bvh, [&](Index f, Index v) {
      if (!touches_pinned_face(f)) candidates.push_back({ArmCollision::face_vertex, f, v, 1});
    });
    cloth_edge_bvh.for_each_overlapping_pair(arm_edge_bvh, [&](Index e, Index g) {
      if (!touches_pinned_edge(e)) candidates.push_back({ArmCollision::edge_edge, e, g, 1});
    });
    std::vector<char> hit(candidates.size(), 0);
    tbb::parallel_for(std::size_t{0}, candidates.size(), [&](std::size_t i) {
      ArmCollision& c = candidates[i];
      CcdResult r;
      if (c.kind == ArmCollision::vertex_face) {
        const auto F = m.faces().row(c.b);
        r = vertex_face_ccd(VertexFaceQuery{row(X0, c.a), row(Y0, F(0)), row(Y0, F(1)),
                                            row(Y0, F(2)), row(x1, c.a), row(Y1, F(0)),
                                            row(Y1, F(1)), row(Y1, F(2))});
      } else if (c.kind == ArmCollision::face_vertex) {
        const auto F = cloth.faces().row(c.a);
        r = vertex_face_ccd(VertexFaceQuery{row(Y0, c.b), row(X0, F(0)), row(X0, F(1)),
                                            row(X0, F(2)), row(Y1, c.b), row(x1, F(0)),
                                            row(x1, F(1)), row(x1, F(2))});
      } else {
        const auto E = cloth.edges().row(c.a);
        const auto G = m.edges().row(c.b);
        r = edge_edge_ccd(EdgeEdgeQuery{row(X0, E(0)), row(X0, E(1)), row(Y0, G(0)), row(Y0, G(1)),
                                        row(x1, E(0)), row(x1, E(1)), row(Y1, G(0)),
                                        row(Y1, G(1))});
      }
      if (r.hit) {
        hit[i] = 1;
        c.toi = r.toi;
      }
    });
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (hit[i]) out.push_back(candidates[i]);
    }
    std::sort(out.begin(), out.end());
    arm_seconds += ms_since(start);
    return out;
  }

  /// The cloth vertices an arm collision involves.
  std::vector<Index> cloth_vertices_of(const ArmCollision& c) const {
    if (c.kind == ArmCollision::vertex_face) return {c.a};
    if (c.kind == ArmCollision::face_vertex) {
      return {cloth.faces()(c.a, 0), cloth.faces()(c.a, 1), cloth.faces()(c.a, 2)};
    }
    return {cloth.edges()(c.a, 0), cloth.edges()(c.a, 1)};
  }

  // ---- contacts and impulses -----------------------------------------------------------

  Slot cloth_slot(Index v, const Positions& x1, double w) const {
    return {v, row(*x0, v), row(x1, v), w};
  }
  Slot arm_slot(Index v, double w) const { return {-1, row(arm->x0, v), row(arm->x1, v), w}; }

  /// Sets weights and the normal of a VF contact (slot 0 the point, 1..3 the triangle) at
  /// time t, and orients the normal so that the start gap is positive.
  static void finish_vertex_face(Contact& c, double t) {
    const auto at = [&](int k) -> Vec3 { return (1 - t) * c.slots[k].p0 + t * c.slots[k].p1; };
    const Vec3 p = at(0), a = at(1), b = at(2), cc = at(3);
    const Vec3 bary = closest_barycentric(p, a, b, cc);
    c.slots[0].w = 1;
    for (int k = 0; k < 3; ++k) c.slots[k + 1].w = -bary[k];
    Vec3 n = (b - a).cross(cc - a);
    if (!(n.norm() > 0)) n = p - (bary[0] * a + bary[1] * b + bary[2] * cc);
    c.normal = n;
    c.n = 4;
  }

  static void finish_edge_edge(Contact& c, double t) {
    const auto at = [&](int k) -> Vec3 { return (1 - t) * c.slots[k].p0 + t * c.slots[k].p1; };
    const Vec3 a0 = at(0), a1 = at(1), b0 = at(2), b1 = at(3);
    const auto [s, u] = closest_segment_params(a0, a1, b0, b1);
    c.slots[0].w = 1 - s;
    c.slots[1].w = s;
    c.slots[2].w = -(1 - u);
    c.slots[3].w = -u;
    Vec3 n = (a1 - a0).cross(b1 - b0);
    const double scale = (a1 - a0).norm() * (b1 - b0).norm();
    if (!(n.norm() > 1e-6 * scale)) n = ((1 - s) * a0 + s * a1) - ((1 - u) * b0 + u * b1);
    c.normal = n;
    c.n = 4;
  }

  /// Normalises and orients the normal (positive gap at t0; else against the approach).
  static bool orient(Contact& c) {
    Vec3 rel0 = Vec3::Zero(), disp = Vec3::Zero();
    for (int k = 0; k < c.n; ++k) {
      rel0 += c.slots[k].w * c.slots[k].p0;
      disp += c.slots[k].w * (c.slots[k].p1 - c.slots[k].p0);
    }
    if (!(c.normal.norm() > 0)) c.normal = -disp;
    if (!(c.normal.norm() > 0)) c.normal = rel0;
    const double len = c.normal.norm();
    if (!(len > 0) || !std::isfinite(len)) return false;
    c.normal /= len;
    double g = c.normal.dot(rel0);
    if (g < 0 || (g == 0 && c.normal.dot(disp) > 0)) {
      c.normal = -c.normal;
      g = -g;
    }
    c.gap0 = g;
    return true;
  }

  /// Relative displacement of the contact's two sides over the step (current x1).
  Vec3 relative_displacement(const Contact& c, const Positions& x1, double* denom) const {
    Vec3 disp = Vec3::Zero();
    *denom = 0;
    for (int k = 0; k < c.n; ++k) {
      const Slot& s = c.slots[k];
      const Vec3 p1 = s.cloth >= 0 ? row(x1, s.cloth) : s.p1;
      disp += s.w * (p1 - s.p0);
      if (s.cloth >= 0) *denom += s.w * s.w * inv_mass[s.cloth];
    }
    return disp;
  }

  /// Adds `dn` to the relative normal displacement of the contact, distributed over the
  /// cloth slots by weight and inverse mass, and takes off up to friction·dn of the
  /// relative tangential displacement (Coulomb, Bridson et al. 2002 §7.3).
  bool push_apart(const Contact& c, double dn, Positions& x1) const {
    double denom = 0;
    const Vec3 disp = relative_displacement(c, x1, &denom);
    if (!(denom > 0)) return false;
    if (!(dn > 0)) return true;
    Vec3 change = dn * c.normal;
    const Vec3 tangential = disp - c.normal.dot(disp) * c.normal;
    const double tl = tangential.norm();
    if (tl > 0 && params.friction > 0)
      change -= std::min(1.0, params.friction * dn / tl) * tangential;
    for (int k = 0; k < c.n; ++k) {
      const Slot& s = c.slots[k];
      if (s.cloth < 0 || inv_mass[s.cloth] == 0) continue;
      x1.row(s.cloth) += (s.w * inv_mass[s.cloth] / denom) * change.transpose();
    }
    return true;
  }

  /// The CCD impulse: makes the linearised gap at the end of the step at least
  /// `target_gap` (inelastic when the pair already ends that far apart along the normal).
  /// Returns false when no cloth slot can move (all pinned).
  bool apply(const Contact& c, double target_gap, Positions& x1) const {
    double denom = 0;
    const double rn = c.normal.dot(relative_displacement(c, x1, &denom));
    const double wanted = std::max({rn, 0.0, target_gap - c.gap0});
    return push_apart(c, wanted - rn, x1);
  }

  Contact self_vf_contact(const VertexFaceCollision& col, const Positions& x1) const {
    Contact c;
    const auto F = cloth.faces().row(col.face);
    c.slots = {cloth_slot(col.vertex, x1, 0), cloth_slot(F(0), x1, 0), cloth_slot(F(1), x1, 0),
               cloth_slot(F(2), x1, 0)};
    finish_vertex_face(c, col.toi);
    return c;
  }
  Contact self_ee_contact(const EdgeEdgeCollision& col, const Positions& x1) const {
    Contact c;
    c.slots = {cloth_slot(col.a0, x1, 0), cloth_slot(col.a1, x1, 0), cloth_slot(col.b0, x1, 0),
               cloth_slot(col.b1, x1, 0)};
    finish_edge_edge(c, col.toi);
    return c;
  }
  Contact arm_contact(const ArmCollision& col, const Positions& x1) const {
    Contact c;
    const TriangleMesh& m = *arm_mesh;
    if (col.kind == ArmCollision::vertex_face) {
      const auto F = m.faces().row(col.b);
      c.slots = {cloth_slot(col.a, x1, 0), arm_slot(F(0), 0), arm_slot(F(1), 0), arm_slot(F(2), 0)};
      finish_vertex_face(c, col.toi);
    } else if (col.kind == ArmCollision::face_vertex) {
      const auto F = cloth.faces().row(col.a);
      c.slots = {arm_slot(col.b, 0), cloth_slot(F(0), x1, 0), cloth_slot(F(1), x1, 0),
                 cloth_slot(F(2), x1, 0)};
      finish_vertex_face(c, col.toi);
    } else {
      const auto E = cloth.edges().row(col.a);
      const auto G = m.edges().row(col.b);
      c.slots = {cloth_slot(E(0), x1, 0), cloth_slot(E(1), x1, 0), arm_slot(G(0), 0),
                 arm_slot(G(1), 0)};
      finish_edge_edge(c, col.toi);
    }
    return c;
  }

  // ---- proximity -----------------------------------------------------------------------

  /// Pushes free cloth vertices closer than the thickness to the arm (at t1) out to it.
  std::int64_t arm_proximity(Positions& x1) {
    const TriangleMesh& m = *arm_mesh;
    const double h = params.thickness;
    std::vector<Aabb> arm_boxes(static_cast<std::size_t>(m.num_faces()));
    for (Index f = 0; f < m.num_faces(); ++f) {
      for (int k = 0; k < 3; ++k)
        arm_boxes[f].extend(
            point_box(row(arm->x1, m.faces()(f, k)), row(arm->x1, m.faces()(f, k)), h));
    }
    if (arm_near_face_bvh.num_primitives() != m.num_faces() || arm_mesh_changed) {
      arm_near_face_bvh = Bvh(arm_boxes);
    } else {
      arm_near_face_bvh.refit(arm_boxes);
    }
    const Bvh& arm_end = arm_near_face_bvh;
    cloth_point_bvh.refit(cloth_vertex_boxes(x1, x1));
    const Bvh& verts = cloth_point_bvh;
    std::vector<std::pair<Index, Index>> pairs;
    verts.for_each_overlapping_pair(arm_end, [&](Index v, Index f) {
      if (!pinned[v]) pairs.emplace_back(v, f);
    });
    std::sort(pairs.begin(), pairs.end());
    std::int64_t count = 0;
    for (std::size_t i = 0; i < pairs.size();) {
      const Index v = pairs[i].first;
      const Vec3 p = row(x1, v);
      double best = std::numeric_limits<double>::infinity();
      Index best_face = -1;
      Vec3 best_bary = Vec3::Zero();
      for (; i < pairs.size() && pairs[i].first == v; ++i) {
        const auto F = m.faces().row(pairs[i].second);
        const Vec3 a = row(arm->x1, F(0)), b = row(arm->x1, F(1)), c = row(arm->x1, F(2));
        const Vec3 bary = closest_barycentric(p, a, b, c);
        const double d = (p - (bary[0] * a + bary[1] * b + bary[2] * c)).norm();
        if (d < best) {
          best = d;
          best_face = pairs[i].second;
          best_bary = bary;
        }
      }
      if (best_face < 0 || !(best < h)) continue;
      const auto F = m.faces().row(best_face);
      const Vec3 a1 = row(arm->x1, F(0)), b1 = row(arm->x1, F(1)), c1 = row(arm->x1, F(2));
      const Vec3 q1 = best_bary[0] * a1 + best_bary[1] * b1 + best_bary[2] * c1;
      const Vec3 q0 = best_bary[0] * row(arm->x0, F(0)) + best_bary[1] * row(arm->x0, F(1)) +
                      best_bary[2] * row(arm->x0, F(2));
      Vec3 n = (b1 - a1).cross(c1 - a1);
      if (!(n.norm() > 0)) continue;
      n.normalize();
      const double side = n.dot(p - q1);
      // Outside: push along the direction to the closest point (the face normal when the
      // closest point is inside the face); inside: along the face normal.
      Vec3 dir = n;
      if (side > 0 && best > 0) dir = (p - q1) / best;
      const double dn = side > 0 ? h - best : h - side;
      Vec3 x = p + dn * dir;
      const Vec3 rel = (x - row(*x0, v)) - (q1 - q0);
      const Vec3 tangential = rel - rel.dot(dir) * dir;
      const double tl = tangential.norm();
      if (tl > 0 && params.friction > 0) x -= std::min(1.0, params.friction * dn / tl) * tangential;
      x1.row(v) = x.transpose();
      ++count;
    }
    return count;
  }

  /// Bridson-style repulsion of cloth VF and EE pairs closer than the thickness at t1.
  std::int64_t cloth_proximity(Positions& x1) {
    const double h = params.thickness;
    const std::vector<Aabb> face_boxes = cloth_face_boxes(x1, x1, 0.5 * h);
    cloth_near_face_bvh.refit(face_boxes);
    const Bvh& faces = cloth_near_face_bvh;
    std::vector<Aabb> edge_boxes(static_cast<std::size_t>(cloth.num_edges()));
    for (Index e = 0; e < cloth.num_edges(); ++e) {
      for (int k = 0; k < 2; ++k)
        edge_boxes[e].extend(
            point_box(row(x1, cloth.edges()(e, k)), row(x1, cloth.edges()(e, k)), 0.5 * h));
    }
    struct Pair {
      int kind;  // 0: VF (vertex, face), 1: EE (edge, edge)
      Index a, b;
      bool operator<(const Pair& o) const {
        return std::tie(kind, a, b) < std::tie(o.kind, o.a, o.b);
      }
      bool operator==(const Pair& o) const { return kind == o.kind && a == o.a && b == o.b; }
    };
    std::vector<Pair> pairs;
    const auto& F = cloth.faces();
    // Candidate feature pairs: their boxes, each grown by h/2, overlap (exact prefilter
    // for "closer than h").
    faces.for_each_self_overlapping_pair([&](Index f, Index g) {
      for (int pass = 0; pass < 2; ++pass) {
        const Index p = pass == 0 ? f : g, q = pass == 0 ? g : f;
        for (int k = 0; k < 3; ++k) {
          const Index v = F(p, k);
          if (v == F(q, 0) || v == F(q, 1) || v == F(q, 2)) continue;
          if (!face_boxes[q].overlaps(point_box(row(x1, v), row(x1, v), 0.5 * h))) continue;
          pairs.push_back({0, v, q});
        }
      }
      const auto ef = cloth.face_edges(f), eg = cloth.face_edges(g);
      for (Index e : ef) {
        for (Index d : eg) {
          const auto E = cloth.edges().row(e), D = cloth.edges().row(d);
          if (E(0) == D(0) || E(0) == D(1) || E(1) == D(0) || E(1) == D(1)) continue;
          if (!edge_boxes[e].overlaps(edge_boxes[d])) continue;
          pairs.push_back({1, std::min(e, d), std::max(e, d)});
        }
      }
    });
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::int64_t count = 0;
    for (const Pair& pr : pairs) {
      Contact c;
      if (pr.kind == 0) {
        c.slots = {cloth_slot(pr.a, x1, 0), cloth_slot(F(pr.b, 0), x1, 0),
                   cloth_slot(F(pr.b, 1), x1, 0), cloth_slot(F(pr.b, 2), x1, 0)};
        finish_vertex_face(c, 1.0);
      } else {
        const auto E = cloth.edges().row(pr.a), D = cloth.edges().row(pr.b);
        c.slots = {cloth_slot(E(0), x1, 0), cloth_slot(E(1), x1, 0), cloth_slot(D(0), x1, 0),
                   cloth_slot(D(1), x1, 0)};
        finish_edge_edge(c, 1.0);
      }
      // Distance and direction at t1 (from the current x1).
      Vec3 rel1 = Vec3::Zero(), rel0 = Vec3::Zero();
      for (int k = 0; k < 4; ++k) {
        rel1 += c.slots[k].w * c.slots[k].p1;
        rel0 += c.slots[k].w * c.slots[k].p0;
      }
      const double d = rel1.norm();
      if (!(d < h) || !(d > 0)) continue;
      Vec3 n = rel1 / d;
      // Keep the side the pair started on: if the closest direction flipped during the
      // step, the CCD stage handles it.
      if (n.dot(rel0) < 0) continue;
      c.normal = n;
      // Treat the current distance as the gap: cancel approach up to the overlap, plus a
      // tenth of the overlap (Bridson et al. 2002, §7.2, in displacement form).
      double rn = 0;
      for (int k = 0; k < 4; ++k) rn += c.slots[k].w * n.dot(c.slots[k].p1 - c.slots[k].p0);
      const double overlap = h - d;
      const double push = std::min(overlap, std::max(0.0, -rn)) + 0.1 * overlap;
      if (push_apart(c, push, x1)) ++count;
    }
    return count;
  }

  // ---- impact zones and the last resort -----------------------------------------------

  /// Where an arm-following vertex goes: its closest arm point at t0 carried to t1, with
  /// the offset rotated like the face normal and at least the thickness along it.
  Vec3 arm_target(Index v) {
    if (auto it = arm_targets.find(v); it != arm_targets.end()) return it->second;
    const TriangleMesh& m = *arm_mesh;
    const Vec3 p = row(*x0, v);
    double best = std::numeric_limits<double>::infinity();
    Index best_face = -1;
    Vec3 best_bary = Vec3::Zero();
    for (Index f = 0; f < m.num_faces(); ++f) {
      const auto F = m.faces().row(f);
      const Vec3 a = row(arm->x0, F(0)), b = row(arm->x0, F(1)), c = row(arm->x0, F(2));
      const Vec3 bary = closest_barycentric(p, a, b, c);
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
        return Vec3(best_bary[0] * row(y, F(0)) + best_bary[1] * row(y, F(1)) +
                    best_bary[2] * row(y, F(2)));
      };
      const auto normal = [&](const Positions& y) {
        Vec3 n = (row(y, F(1)) - row(y, F(0))).cross(row(y, F(2)) - row(y, F(0)));
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

  /// Moves the zone `members` rigidly from x0: with the best-fit motion of its kinematic
  /// members (pinned: their x1; arm-following: their arm target) when it has any, else
  /// with its mass-weighted mean linear and angular velocity.
  void move_zone_rigidly(const std::vector<Index>& members, const std::vector<char>& follows,
                         const Positions& pinned_x1, Positions& x1) {
    std::vector<Index> kinematic;
    for (Index v : members) {
      if (pinned[v] || follows[v]) kinematic.push_back(v);
    }
    const auto target_of = [&](Index v) -> Vec3 {
      return pinned[v] ? row(pinned_x1, v) : arm_target(v);
    };
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Vec3 c0 = Vec3::Zero(), c1 = Vec3::Zero();
    if (!kinematic.empty()) {
      for (Index v : kinematic) {
        c0 += row(*x0, v);
        c1 += target_of(v);
      }
      c0 /= static_cast<double>(kinematic.size());
      c1 /= static_cast<double>(kinematic.size());
      if (kinematic.size() >= 2) {
        Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
        for (Index v : kinematic) cov += (target_of(v) - c1) * (row(*x0, v) - c0).transpose();
        const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
        Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
        if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) d(2, 2) = -1;
        rotation = svd.matrixU() * d * svd.matrixV().transpose();
      }
      for (Index v : members) {
        if (pinned[v]) continue;
        const Vec3 moved = follows[v] ? target_of(v) : Vec3(c1 + rotation * (row(*x0, v) - c0));
        x1.row(v) = moved.transpose();
      }
      return;
    }
    double mass = 0;
    Vec3 displacement = Vec3::Zero();
    for (Index v : members) {
      const double mv = 1.0 / inv_mass[v];
      mass += mv;
      c0 += mv * row(*x0, v);
      displacement += mv * (row(x1, v) - row(*x0, v));
    }
    c0 /= mass;
    displacement /= mass;
    Vec3 angular = Vec3::Zero();  // angular momentum of the displacements
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (Index v : members) {
      const double mv = 1.0 / inv_mass[v];
      const Vec3 r = row(*x0, v) - c0;
      angular += mv * r.cross(row(x1, v) - row(*x0, v) - displacement);
      inertia += mv * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    // Pseudo-inverse: a collinear zone has no inertia about its axis.
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(inertia, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Vector3d sv = svd.singularValues();
    const double cut = 1e-12 * sv(0);
    for (int k = 0; k < 3; ++k) sv(k) = sv(k) > cut ? 1.0 / sv(k) : 0.0;
    const Vec3 omega = svd.matrixV() * sv.asDiagonal() * svd.matrixU().transpose() * angular;
    const double angle = omega.norm();
    if (angle > 0) rotation = Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
    for (Index v : members)
      x1.row(v) = (c0 + displacement + rotation * (row(*x0, v) - c0)).transpose();
  }

  /// Keeps the first pass's collisions and candidate faces for the per-frame contact files.
  static void record_first_pass(const DetectionResult& self, ContactStats& stats) {
    stats.first_pass_collisions = self.collisions;
    std::vector<Index>& faces = stats.candidate_faces;
    faces.clear();
    faces.reserve(2 * self.candidate_triangle_pairs.size());
    for (const TrianglePair& p : self.candidate_triangle_pairs) {
      faces.push_back(p.first);
      faces.push_back(p.second);
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  }

  // ---- the whole substep ---------------------------------------------------------------

  ContactStats resolve(const Positions& X0, Positions& x1, const KinematicObstacle& obstacle,
                       double dt) {
    const auto start = Clock::now();
    if (X0.rows() != cloth.num_vertices() || x1.rows() != cloth.num_vertices()) {
      throw InputError("contact solver: positions do not match the cloth mesh");
    }
    if (!(dt > 0)) throw InputError("contact solver: the substep length must be positive");
    ContactStats stats;
    x0 = &X0;
    arm = obstacle.mesh != nullptr ? &obstacle : nullptr;
    arm_seconds = 0;
    arm_targets.clear();
    double detect_ms = 0;
    const Positions pinned_x1 = x1;
    const Index n = cloth.num_vertices();
    const auto detect = [&](const Positions& x) {
      DetectionResult r = detector.detect(X0, x);
      detect_ms += r.stats.total_ms;
      return r;
    };

    if (arm != nullptr) {
      prepare_arm(obstacle);
      stats.repulsions += arm_proximity(x1);
    }
    if (params.thickness > 0) stats.repulsions += cloth_proximity(x1);
    if (filter) filter(x1);

    // CCD impulses.
    bool clean = false;
    for (int pass = 0; pass < std::max(1, params.max_impulse_iterations) && !clean; ++pass) {
      const auto arm_hits = arm_collisions(x1);
      DetectionResult self = detect(x1);
      if (pass == 0) {
        stats.self_collisions = static_cast<std::int64_t>(self.collisions.size());
        stats.obstacle_collisions = static_cast<std::int64_t>(arm_hits.size());
        stats.detection = self.stats;
        if (detector.config().keep_candidate_pairs) record_first_pass(self, stats);
      }
      if (arm_hits.empty() && self.collisions.size() == 0) {
        clean = true;
        break;
      }
      if (pass + 1 == std::max(1, params.max_impulse_iterations)) break;  // leave it to zones
      ++stats.impulse_iterations;
      for (const ArmCollision& c : arm_hits) {
        Contact contact = arm_contact(c, x1);
        if (orient(contact) && apply(contact, params.thickness, x1)) ++stats.impulses;
      }
      for (const auto& c : self.collisions.vertex_face) {
        Contact contact = self_vf_contact(c, x1);
        if (orient(contact) && apply(contact, 0.5 * params.thickness, x1)) ++stats.impulses;
      }
      for (const auto& c : self.collisions.edge_edge) {
        Contact contact = self_ee_contact(c, x1);
        if (orient(contact) && apply(contact, 0.5 * params.thickness, x1)) ++stats.impulses;
      }
      if (filter) filter(x1);
    }

    // Rigid impact zones.
    UnionFind zones(n);
    std::vector<char> follows(static_cast<std::size_t>(n), 0);
    std::vector<char> in_zone(static_cast<std::size_t>(n), 0);
    for (int it = 0; !clean && it < params.max_zone_iterations; ++it) {
      const auto arm_hits = arm_collisions(x1);
      const DetectionResult self = detect(x1);
      if (arm_hits.empty() && self.collisions.size() == 0) {
        clean = true;
        break;
      }
      ++stats.zone_iterations;
      const auto join = [&](std::initializer_list<Index> vs) {
        const Index first = *vs.begin();
        for (Index v : vs) {
          zones.unite(first, v);
          in_zone[v] = 1;
        }
      };
      for (const auto& c : self.collisions.vertex_face) {
        const auto F = cloth.faces().row(c.face);
        join({c.vertex, F(0), F(1), F(2)});
      }
      for (const auto& c : self.collisions.edge_edge) join({c.a0, c.a1, c.b0, c.b1});
      for (const ArmCollision& c : arm_hits) {
        const auto vs = cloth_vertices_of(c);
        for (Index v : vs) {
          zones.unite(vs.front(), v);
          in_zone[v] = 1;
          if (!pinned[v]) follows[v] = 1;
        }
      }
      std::vector<std::vector<Index>> groups;
      std::unordered_map<Index, std::size_t> group_of;
      for (Index v = 0; v < n; ++v) {
        if (!in_zone[v]) continue;
        const Index r = zones.find(v);
        auto [pos, added] = group_of.emplace(r, groups.size());
        if (added) groups.emplace_back();
        groups[pos->second].push_back(v);
      }
      stats.impact_zones = static_cast<std::int64_t>(groups.size());
      for (const auto& g : groups) move_zone_rigidly(g, follows, pinned_x1, x1);
    }

    // Last resort: revert zones to x0 or make vertices follow the arm, until clean.
    std::vector<VertexState> state(static_cast<std::size_t>(n), VertexState::free);
    std::unordered_map<Index, std::vector<Index>> zone_members;
    for (Index v = 0; v < n; ++v) {
      if (follows[v]) state[v] = VertexState::arm_following;
      if (in_zone[v]) zone_members[zones.find(v)].push_back(v);
    }
    for (std::int64_t guard = 0; !clean && guard < 2 * static_cast<std::int64_t>(n) + 4; ++guard) {
      const auto arm_hits = arm_collisions(x1);
      const DetectionResult self = detect(x1);
      if (arm_hits.empty() && self.collisions.size() == 0) {
        clean = true;
        break;
      }
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
          x1.row(u) = X0.row(u);
          changed = true;
        }
      };
      for (const ArmCollision& c : arm_hits) {
        for (Index v : cloth_vertices_of(c)) follow(v);
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
      for (const auto& c : self.collisions.vertex_face) {
        const auto F = cloth.faces().row(c.face);
        handle({c.vertex, F(0), F(1), F(2)});
      }
      for (const auto& c : self.collisions.edge_edge) handle({c.a0, c.a1, c.b0, c.b1});
      if (!changed) {
        stats.unresolved = static_cast<std::int64_t>(arm_hits.size() + self.collisions.size());
        spdlog::warn("contact: {} collisions left that the last resort cannot undo",
                     stats.unresolved);
        break;
      }
    }
    for (Index v = 0; v < n; ++v) {
      if (pinned[v]) x1.row(v) = pinned_x1.row(v);  // never moved (guards rounding in zones)
      stats.reverted_vertices += state[v] == VertexState::reverted ? 1 : 0;
      stats.arm_following_vertices += state[v] == VertexState::arm_following ? 1 : 0;
    }
    stats.detection_ms = detect_ms + arm_seconds;
    stats.response_ms = std::max(0.0, ms_since(start) - stats.detection_ms);
    return stats;
  }
};

ContactSolver::ContactSolver(const TriangleMesh& cloth, const Positions& x_build,
                             Eigen::VectorXd masses, DetectionConfig detection,
                             ContactParams params, std::vector<std::vector<Index>> section_loops)
    : m_impl(std::make_unique<Impl>(cloth, x_build, std::move(masses), detection, params,
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
