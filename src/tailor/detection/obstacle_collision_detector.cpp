/// @file
/// Cloth against a moving obstacle: swept-box BVHs, then the exact CCD.

#include "tailor/detection/obstacle_collision_detector.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "tailor/bvh/feature_boxes.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

/// Swept boxes of every vertex, edge and face of `mesh` moving x0 -> x1.
struct SweptBoxes {
  std::vector<Aabb> vertices, edges, faces;
  SweptBoxes(const TriangleMesh& mesh, const Positions& x0, const Positions& x1)
      : vertices(static_cast<std::size_t>(mesh.num_vertices())),
        edges(static_cast<std::size_t>(mesh.num_edges())),
        faces(static_cast<std::size_t>(mesh.num_faces())) {
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
      vertices[v].extend(position(x0, v));
      vertices[v].extend(position(x1, v));
    }
    bound_edges_and_faces(mesh, vertices, edges, faces);
  }
};

/// Builds the three BVHs on `boxes` when `rebuild` (another mesh), else refits them.
void build_or_refit(bool rebuild, const SweptBoxes& boxes, Bvh& vertices, Bvh& edges, Bvh& faces) {
  if (rebuild) {
    vertices = Bvh(boxes.vertices);
    edges = Bvh(boxes.edges);
    faces = Bvh(boxes.faces);
  } else {
    vertices.refit(boxes.vertices);
    edges.refit(boxes.edges);
    faces.refit(boxes.faces);
  }
}

}  // namespace

ObstacleCollisionDetector::ObstacleCollisionDetector(const TriangleMesh& cloth,
                                                     std::vector<char> exempt)
    : m_cloth(cloth), m_exempt(std::move(exempt)) {
  if (!m_exempt.empty() && static_cast<Index>(m_exempt.size()) != cloth.num_vertices()) {
    throw InputError(fmt::format("obstacle detector: {} exempt flags for {} cloth vertices",
                                 m_exempt.size(), cloth.num_vertices()));
  }
  if (m_exempt.empty()) m_exempt.assign(static_cast<std::size_t>(cloth.num_vertices()), 0);
}

void ObstacleCollisionDetector::set_obstacle(const TriangleMesh& obstacle, const Positions& y0,
                                             const Positions& y1) {
  if (y0.rows() != obstacle.num_vertices() || y1.rows() != obstacle.num_vertices()) {
    throw InputError("obstacle detector: obstacle positions do not match its mesh");
  }
  const SweptBoxes boxes(obstacle, y0, y1);
  const bool other_mesh = m_obstacle != &obstacle ||
                          m_obstacle_vertices.num_primitives() != obstacle.num_vertices() ||
                          m_obstacle_faces.num_primitives() != obstacle.num_faces();
  build_or_refit(other_mesh, boxes, m_obstacle_vertices, m_obstacle_edges, m_obstacle_faces);
  m_obstacle = &obstacle;
  m_y0 = &y0;
  m_y1 = &y1;
}

std::vector<Index> ObstacleCollisionDetector::cloth_vertices(const ObstacleCollision& c) const {
  if (c.kind == ObstacleCollision::vertex_face) return {c.cloth};
  if (c.kind == ObstacleCollision::face_vertex) {
    return {m_cloth.faces()(c.cloth, 0), m_cloth.faces()(c.cloth, 1), m_cloth.faces()(c.cloth, 2)};
  }
  return {m_cloth.edges()(c.cloth, 0), m_cloth.edges()(c.cloth, 1)};
}

std::vector<ObstacleCollision> ObstacleCollisionDetector::detect(const Positions& x0,
                                                                 const Positions& x1) {
  if (m_obstacle == nullptr) throw InputError("obstacle detector: no obstacle set");
  if (x0.rows() != m_cloth.num_vertices() || x1.rows() != m_cloth.num_vertices()) {
    throw InputError("obstacle detector: cloth positions do not match the cloth mesh");
  }
  const TriangleMesh& m = *m_obstacle;
  const Positions& y0 = *m_y0;
  const Positions& y1 = *m_y1;
  const SweptBoxes boxes(m_cloth, x0, x1);
  build_or_refit(m_cloth_vertices.num_primitives() != m_cloth.num_vertices(), boxes,
                 m_cloth_vertices, m_cloth_edges, m_cloth_faces);
  const auto& F = m_cloth.faces();
  const auto& E = m_cloth.edges();
  std::vector<ObstacleCollision> candidates;
  m_cloth_vertices.for_each_overlapping_pair(m_obstacle_faces, [&](Index v, Index f) {
    if (!m_exempt[v]) candidates.push_back({ObstacleCollision::vertex_face, v, f, 1});
  });
  m_cloth_faces.for_each_overlapping_pair(m_obstacle_vertices, [&](Index f, Index v) {
    if (!m_exempt[F(f, 0)] && !m_exempt[F(f, 1)] && !m_exempt[F(f, 2)])
      candidates.push_back({ObstacleCollision::face_vertex, f, v, 1});
  });
  m_cloth_edges.for_each_overlapping_pair(m_obstacle_edges, [&](Index e, Index g) {
    if (!m_exempt[E(e, 0)] && !m_exempt[E(e, 1)])
      candidates.push_back({ObstacleCollision::edge_edge, e, g, 1});
  });
  std::vector<char> hit(candidates.size(), 0);
  tbb::parallel_for(std::size_t{0}, candidates.size(), [&](std::size_t i) {
    ObstacleCollision& c = candidates[i];
    CcdResult r;
    if (c.kind == ObstacleCollision::vertex_face) {
      const auto G = m.faces().row(c.obstacle);
      r = vertex_face_ccd(VertexFaceQuery{
          position(x0, c.cloth), position(y0, G(0)), position(y0, G(1)), position(y0, G(2)),
          position(x1, c.cloth), position(y1, G(0)), position(y1, G(1)), position(y1, G(2))});
    } else if (c.kind == ObstacleCollision::face_vertex) {
      r = vertex_face_ccd(VertexFaceQuery{
          position(y0, c.obstacle), position(x0, F(c.cloth, 0)), position(x0, F(c.cloth, 1)),
          position(x0, F(c.cloth, 2)), position(y1, c.obstacle), position(x1, F(c.cloth, 0)),
          position(x1, F(c.cloth, 1)), position(x1, F(c.cloth, 2))});
    } else {
      const auto G = m.edges().row(c.obstacle);
      r = edge_edge_ccd(EdgeEdgeQuery{position(x0, E(c.cloth, 0)), position(x0, E(c.cloth, 1)),
                                      position(y0, G(0)), position(y0, G(1)),
                                      position(x1, E(c.cloth, 0)), position(x1, E(c.cloth, 1)),
                                      position(y1, G(0)), position(y1, G(1))});
    }
    if (r.hit) {
      hit[i] = 1;
      c.toi = r.toi;
    }
  });
  std::vector<ObstacleCollision> out;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (hit[i]) out.push_back(candidates[i]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace tailor
