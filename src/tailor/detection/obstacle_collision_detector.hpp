#pragma once
/// @file
/// Continuous collision detection between a cloth and a moving kinematic obstacle (e.g.
/// the skinned arm) over one linear step: cloth vertex vs obstacle face, obstacle vertex vs
/// cloth face, cloth edge vs obstacle edge, each with the exact CCD.
///
/// Culling: swept boxes of cloth vertices, edges and faces against swept boxes of the
/// obstacle's faces, vertices and edges (one BVH each, refitted every call). A pair is
/// tested exactly only if its two swept boxes overlap, and two primitives moving linearly
/// stay inside their swept boxes, so no collision is dropped (checked against brute force
/// in tests/detection). Cloth primitives touching an `exempt` vertex (e.g. one pinned onto
/// the obstacle's surface) are not tested.

#include <cstdint>
#include <tuple>
#include <vector>

#include "tailor/bvh/bvh.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// One cloth-obstacle collision.
struct ObstacleCollision {
  /// Which primitives of the cloth and the obstacle touch.
  enum Kind : int {
    vertex_face = 0,  ///< cloth vertex `cloth` vs obstacle face `obstacle`
    face_vertex = 1,  ///< cloth face `cloth` vs obstacle vertex `obstacle`
    edge_edge = 2,    ///< cloth edge `cloth` vs obstacle edge `obstacle`
  };
  /// The kind of pair; it says what `cloth` and `obstacle` are.
  Kind kind = vertex_face;
  ///@{
  /// Vertex, face or edge id on the cloth and on the obstacle mesh (see Kind).
  Index cloth = -1, obstacle = -1;
  ///@}
  double toi = 1;  ///< never later than the earliest contact (the exact CCD's)
  /// Orders by (kind, cloth, obstacle).
  friend bool operator<(const ObstacleCollision& x, const ObstacleCollision& y) {
    return std::tie(x.kind, x.cloth, x.obstacle) < std::tie(y.kind, y.cloth, y.obstacle);
  }
  /// Same kind and primitives (toi is not compared).
  friend bool operator==(const ObstacleCollision& x, const ObstacleCollision& y) {
    return x.kind == y.kind && x.cloth == y.cloth && x.obstacle == y.obstacle;
  }
};

/// Cloth vs one moving obstacle; built once per cloth topology.
class ObstacleCollisionDetector {
 public:
  /// `exempt[v]` (size = cloth vertices, or empty) marks cloth vertices whose primitives
  /// are skipped. `cloth` must outlive the detector.
  ObstacleCollisionDetector(const TriangleMesh& cloth, std::vector<char> exempt = {});

  /// Sets the obstacle's step: its mesh and positions at t=0 and t=1 (all three must
  /// outlive the detect() calls of this step). Rebuilds the obstacle's trees when the mesh
  /// changes, else refits them. Throws
  /// InputError if the row counts do not match the mesh.
  void set_obstacle(const TriangleMesh& obstacle, const Positions& y0, const Positions& y1);

  /// Every collision between cloth moving x0 -> x1 and the obstacle, sorted. Throws
  /// InputError if the row counts do not match the cloth or no obstacle was set.
  std::vector<ObstacleCollision> detect(const Positions& x0, const Positions& x1);

  /// Cloth vertices of a collision's cloth primitive.
  std::vector<Index> cloth_vertices(const ObstacleCollision& c) const;

 private:
  const TriangleMesh& m_cloth;
  std::vector<char> m_exempt;
  const TriangleMesh* m_obstacle = nullptr;
  const Positions* m_y0 = nullptr;
  const Positions* m_y1 = nullptr;
  Bvh m_cloth_vertices, m_cloth_edges, m_cloth_faces;
  Bvh m_obstacle_vertices, m_obstacle_edges, m_obstacle_faces;
};

}  // namespace tailor
