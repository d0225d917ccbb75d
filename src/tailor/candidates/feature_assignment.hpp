#pragma once
/// @file
/// Feature assignment (Curtis et al. 2008 representative triangles; the paper §3.1).

#include <array>
#include <cstdint>
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
///
/// For the hot loop of pair generation it also keeps, per face, which of its corners and
/// edges it owns, and per vertex (edge) the other corners of its owner, so "does the
/// owner share a vertex with g" needs no access to the owner's face.
class FeatureAssignment {
 public:
  /// Everything pair generation asks about one face, in one cache line: its corners and
  /// edges, which of them it owns, and for each the owner's other corners, so deciding
  /// which of a triangle pair's 15 feature pairs it owes reads two records and nothing
  /// indexed by vertex or edge.
  struct alignas(64) FaceFeatures {
    std::array<Index, 3> corners;  ///< faces(f, k)
    std::array<Index, 3> edges;    ///< face_edges(f)[k]: corners k and k+1
    /// owner_other_corners(corners[k])
    std::array<std::array<Index, 2>, 3> corner_owner_others;
    std::array<Index, 3> edge_owner_opposite;  ///< owner_opposite_corner(edges[k])
    std::uint32_t owned;                       ///< bits 0-2: corners, 3-5: edges
  };

  FeatureAssignment() = default;
  /// Assigns greedily in face order: each face takes the vertices and edges no earlier face
  /// took. Keeps a pointer to `mesh`, which must outlive it.
  explicit FeatureAssignment(const TriangleMesh& mesh);

  /// Triangle a vertex is assigned to (-1 for an unreferenced vertex).
  Index vertex_owner(Index v) const { return m_vertex_owner[v]; }
  /// Triangle an edge is assigned to.
  Index edge_owner(Index e) const { return m_edge_owner[e]; }
  /// Number of vertices assigned to face `f` (0-3).
  int vertices_assigned(Index f) const;
  /// Number of edges assigned to face `f` (0-3).
  int edges_assigned(Index f) const;
  /// Whether face `f` owns its corner `k` (faces(f, k)), k in 0-2.
  bool owns_corner(Index f, int k) const { return (m_owned[f] >> k) & 1; }
  /// Whether face `f` owns its edge `k` (face_edges(f)[k]), k in 0-2.
  bool owns_edge(Index f, int k) const { return (m_owned[f] >> (3 + k)) & 1; }
  /// The two corners of owner(v) other than v (-1 for an unreferenced vertex).
  const std::array<Index, 2>& owner_other_corners(Index v) const { return m_owner_others[v]; }
  /// The corner of owner(e) that is not on edge e.
  Index owner_opposite_corner(Index e) const { return m_owner_opposite[e]; }
  /// The record of face `f`.
  const FaceFeatures& face_features(Index f) const { return m_face_features[f]; }

  /// The face of the triangle pair that tests VF pair (v, g), v not in g; -1 if the pair
  /// is isolated (only possible with adjacency culling).
  Index vf_representative(Index v, Index g, bool adjacency_culling) const;
  /// The faces (around e1, around e2) of the triangle pair that tests EE pair (e1, e2);
  /// {-1, -1} if the pair is isolated (only possible with adjacency culling).
  std::pair<Index, Index> ee_representative(Index e1, Index e2, bool adjacency_culling) const;

 private:
  const TriangleMesh* m_mesh = nullptr;
  std::vector<Index> m_vertex_owner, m_edge_owner;
  std::vector<std::uint8_t> m_owned;  // bits 0-2: corners, 3-5: edges
  std::vector<std::array<Index, 2>> m_owner_others;
  std::vector<Index> m_owner_opposite;
  std::vector<FaceFeatures> m_face_features;
};

}  // namespace tailor
