#pragma once
/// @file
/// The collisions one step of self-collision detection reports.

#include <tuple>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A vertex touching a face during the step.
struct VertexFaceCollision {
  Index vertex = -1;
  Index face = -1;
  double toi = 1.0;  ///< never later than the earliest contact
  friend bool operator<(const VertexFaceCollision& x, const VertexFaceCollision& y) {
    return std::tie(x.vertex, x.face) < std::tie(y.vertex, y.face);
  }
};

/// Two edges touching during the step; each edge as its two vertex ids, `a0 < a1`,
/// `b0 < b1`, and `(a0, a1) < (b0, b1)`.
struct EdgeEdgeCollision {
  Index a0 = -1, a1 = -1, b0 = -1, b1 = -1;
  Index edge_a = -1, edge_b = -1;  ///< edge ids in TriangleMesh::edges()
  double toi = 1.0;                ///< never later than the earliest contact
  friend bool operator<(const EdgeEdgeCollision& x, const EdgeEdgeCollision& y) {
    return std::tie(x.a0, x.a1, x.b0, x.b1) < std::tie(y.a0, y.a1, y.b0, y.b1);
  }
};

/// All collisions of one step, each list sorted and without duplicates.
struct CollisionSet {
  std::vector<VertexFaceCollision> vertex_face;
  std::vector<EdgeEdgeCollision> edge_edge;
  std::size_t size() const { return vertex_face.size() + edge_edge.size(); }
};

}  // namespace tailor
