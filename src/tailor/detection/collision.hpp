#pragma once
/// @file
/// The collisions one step of self-collision detection reports.

#include <tuple>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A vertex touching a face during the step.
struct VertexFaceCollision {
  /// Vertex id.
  Index vertex = -1;
  /// Face id (the face does not contain the vertex).
  Index face = -1;
  double toi = 1.0;  ///< never later than the earliest contact
  /// Orders by (vertex, face), the order of CollisionSet::vertex_face.
  friend bool operator<(const VertexFaceCollision& x, const VertexFaceCollision& y) {
    return std::tie(x.vertex, x.face) < std::tie(y.vertex, y.face);
  }
};

/// Two edges touching during the step; each edge as its two vertex ids, `a0 < a1`,
/// `b0 < b1`, and `(a0, a1) < (b0, b1)`.
struct EdgeEdgeCollision {
  ///@{
  /// Vertex ids of edge a (a0, a1) and edge b (b0, b1).
  Index a0 = -1, a1 = -1, b0 = -1, b1 = -1;
  ///@}
  ///@{
  /// Edge ids in TriangleMesh::edges() of edge a and edge b.
  Index edge_a = -1, edge_b = -1;
  ///@}
  double toi = 1.0;  ///< never later than the earliest contact
  /// Orders by (a0, a1, b0, b1), the order of CollisionSet::edge_edge.
  friend bool operator<(const EdgeEdgeCollision& x, const EdgeEdgeCollision& y) {
    return std::tie(x.a0, x.a1, x.b0, x.b1) < std::tie(y.a0, y.a1, y.b0, y.b1);
  }
};

/// All collisions of one step, each list sorted and without duplicates.
struct CollisionSet {
  /// Vertex-face collisions, sorted by (vertex, face).
  std::vector<VertexFaceCollision> vertex_face;
  /// Edge-edge collisions, sorted by (a0, a1, b0, b1).
  std::vector<EdgeEdgeCollision> edge_edge;
  /// Number of collisions of both kinds.
  std::size_t size() const { return vertex_face.size() + edge_edge.size(); }
};

}  // namespace tailor
