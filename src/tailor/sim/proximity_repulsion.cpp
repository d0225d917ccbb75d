/// @file
/// Proximity repulsion against an obstacle and within the cloth.

#include "tailor/sim/proximity_repulsion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tailor/bvh/feature_boxes.hpp"
#include "tailor/geometry/closest_point.hpp"

namespace tailor {
namespace {

Aabb point_box(const Vec3& p, double inflate) {
  Aabb box;
  box.extend(p);
  box.min -= inflate;
  box.max += inflate;
  return box;
}

/// Boxes of the end positions of every vertex, edge and face, grown by `inflate`.
struct EndBoxes {
  std::vector<Aabb> vertices, edges, faces;
  EndBoxes(const TriangleMesh& mesh, const Positions& x, double inflate)
      : vertices(static_cast<std::size_t>(mesh.num_vertices())),
        edges(static_cast<std::size_t>(mesh.num_edges())),
        faces(static_cast<std::size_t>(mesh.num_faces())) {
    for (Index v = 0; v < mesh.num_vertices(); ++v)
      vertices[v] = point_box(position(x, v), inflate);
    bound_edges_and_faces(mesh, vertices, edges, faces);
  }
};

}  // namespace

ProximityRepulsion::ProximityRepulsion(const TriangleMesh& cloth, const Positions& x_build,
                                       std::vector<char> pinned)
    : m_cloth(cloth), m_pinned(std::move(pinned)), m_search(cloth) {
  m_points = Bvh(EndBoxes(cloth, x_build, 0).vertices);
}

std::int64_t ProximityRepulsion::repel_obstacle(const Positions& x0, Positions& x1,
                                                const KinematicObstacle& obstacle, double h,
                                                double friction) {
  const TriangleMesh& m = *obstacle.mesh;
  const Positions& y0 = obstacle.x0;
  const Positions& y1 = obstacle.x1;
  const EndBoxes obstacle_boxes(m, y1, h);
  if (m_obstacle != &m || m_obstacle_faces.num_primitives() != m.num_faces()) {
    m_obstacle_faces = Bvh(obstacle_boxes.faces);
    m_obstacle = &m;
  } else {
    m_obstacle_faces.refit(obstacle_boxes.faces);
  }
  m_points.refit(EndBoxes(m_cloth, x1, 0).vertices);
  std::vector<std::pair<Index, Index>> pairs;
  m_points.for_each_overlapping_pair(m_obstacle_faces, [&](Index v, Index f) {
    if (!m_pinned[v]) pairs.emplace_back(v, f);
  });
  std::sort(pairs.begin(), pairs.end());
  std::int64_t count = 0;
  for (std::size_t i = 0; i < pairs.size();) {
    const Index v = pairs[i].first;
    const Vec3 p = position(x1, v);
    double best = std::numeric_limits<double>::infinity();
    Index best_face = -1;
    Vec3 best_bary = Vec3::Zero();
    for (; i < pairs.size() && pairs[i].first == v; ++i) {
      const auto F = m.faces().row(pairs[i].second);
      const Vec3 a = position(y1, F(0)), b = position(y1, F(1)), c = position(y1, F(2));
      const Vec3 bary = closest_point_barycentric(p, a, b, c);
      const double d = (p - (bary[0] * a + bary[1] * b + bary[2] * c)).norm();
      if (d < best) {
        best = d;
        best_face = pairs[i].second;
        best_bary = bary;
      }
    }
    if (best_face < 0 || !(best < h)) continue;
    const auto F = m.faces().row(best_face);
    const Vec3 a1 = position(y1, F(0)), b1 = position(y1, F(1)), c1 = position(y1, F(2));
    const Vec3 q1 = best_bary[0] * a1 + best_bary[1] * b1 + best_bary[2] * c1;
    const Vec3 q0 = best_bary[0] * position(y0, F(0)) + best_bary[1] * position(y0, F(1)) +
                    best_bary[2] * position(y0, F(2));
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
    const Vec3 rel = (x - position(x0, v)) - (q1 - q0);
    const Vec3 tangential = rel - rel.dot(dir) * dir;
    const double tl = tangential.norm();
    if (tl > 0 && friction > 0) x -= std::min(1.0, friction * dn / tl) * tangential;
    x1.row(v) = x.transpose();
    ++count;
  }
  return count;
}

std::int64_t ProximityRepulsion::repel_cloth(const Positions& x0, Positions& x1, double h,
                                             const ContactResponse& response) {
  // The library's exact proximity pairs at the end positions (detection/proximity_pairs).
  const ProximityPairs pairs = m_search.pairs(x1, h);
  const auto& F = m_cloth.faces();
  const auto& E = m_cloth.edges();
  std::int64_t count = 0;
  const auto repel = [&](Contact& c) {
    // Distance and direction at t1 (from the current x1).
    Vec3 rel1 = Vec3::Zero(), rel0 = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      rel1 += c.points[k].w * c.points[k].p1;
      rel0 += c.points[k].w * c.points[k].p0;
    }
    const double d = rel1.norm();
    if (!(d < h) || !(d > 0)) return;
    const Vec3 n = rel1 / d;
    // Keep the side the pair started on: if the closest direction flipped during the
    // step, the CCD passes handle it.
    if (n.dot(rel0) < 0) return;
    c.normal = n;
    // The current distance is the gap: cancel the approach up to the overlap, plus a
    // tenth of the overlap (Bridson et al. 2002, §7.2, in displacement form).
    double rn = 0;
    for (int k = 0; k < 4; ++k) rn += c.points[k].w * n.dot(c.points[k].p1 - c.points[k].p0);
    const double overlap = h - d;
    const double push = std::min(overlap, std::max(0.0, -rn)) + 0.1 * overlap;
    if (response.push_apart(c, push, x1)) ++count;
  };
  for (const auto& [v, f] : pairs.vertex_face) {
    Contact c;
    c.points = {response.cloth_point(v, x0, x1), response.cloth_point(F(f, 0), x0, x1),
                response.cloth_point(F(f, 1), x0, x1), response.cloth_point(F(f, 2), x0, x1)};
    set_vertex_face_weights(c, 1.0);
    repel(c);
  }
  for (const auto& [e, d] : pairs.edge_edge) {
    Contact c;
    c.points = {response.cloth_point(E(e, 0), x0, x1), response.cloth_point(E(e, 1), x0, x1),
                response.cloth_point(E(d, 0), x0, x1), response.cloth_point(E(d, 1), x0, x1)};
    set_edge_edge_weights(c, 1.0);
    repel(c);
  }
  return count;
}

}  // namespace tailor
