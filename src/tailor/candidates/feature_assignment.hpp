#pragma once
/// @file
/// Feature assignment (Curtis et al. 2008 representative triangles; the paper §3.1).

#include <utility>
#include <vector>

#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Assigns every vertex and every edge to exactly one incident triangle, greedily in
/// face order (the paper's "characteristic distribution": a face takes the features it
/// has that no earlier face took), and picks for every VF and EE feature pair the one
/// triangle pair it is tested from.
///
/// Why nothing is lost together with adjacency culling (docs/design.md §2, third trap): the
/// pair (v, g) is tested from (owner(v), g). When adjacency culling is on and owner(v)
/// shares a vertex with g, that triangle pair is never emitted, so the representative
/// falls back to the first face around v that shares no vertex with g (Tang's per-pair
/// rule); when there is none, (v, g) is in the isolated set. Every pair therefore has
/// exactly one representative triangle pair or is isolated. The same holds for EE pairs
/// with (owner(e1), owner(e2)) and the first vertex-disjoint pair of their faces.
class FeatureAssignment {
 public:
  FeatureAssignment() = default;
  explicit FeatureAssignment(const TriangleMesh& mesh);

  /// Triangle a vertex is assigned to (-1 for an unreferenced vertex).
  Index vertex_owner(Index v) const { return m_vertex_owner[v]; }
  /// Triangle an edge is assigned to.
  Index edge_owner(Index e) const { return m_edge_owner[e]; }
  /// Number of vertices / edges assigned to face `f`.
  int vertices_assigned(Index f) const { return m_vertex_count[f]; }
  int edges_assigned(Index f) const { return m_edge_count[f]; }

  /// The face of the triangle pair that tests VF pair (v, g), v not in g; -1 if the pair
  /// is isolated (only possible with adjacency culling).
  Index vf_representative(Index v, Index g, bool adjacency_culling) const;
  /// The faces (around e1, around e2) of the triangle pair that tests EE pair (e1, e2);
  /// {-1, -1} if the pair is isolated (only possible with adjacency culling).
  std::pair<Index, Index> ee_representative(Index e1, Index e2, bool adjacency_culling) const;

 private:
  const TriangleMesh* m_mesh = nullptr;
  std::vector<Index> m_vertex_owner, m_edge_owner;
  std::vector<std::uint8_t> m_vertex_count, m_edge_count;
};

}  // namespace tailor
