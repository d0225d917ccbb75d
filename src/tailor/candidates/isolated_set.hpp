#pragma once
/// @file
/// The isolated (orphan) set of adjacency culling (Tang et al. 2009; the paper §2.3).

#include <utility>
#include <vector>

#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// First face around vertex `v` (ascending id) that shares no vertex with face `g`, or -1.
Index first_face_disjoint_from(const TriangleMesh& mesh, Index v, Index g);

/// First pair (f1 around edge `e1`, f2 around edge `e2`), lexicographic in ascending
/// face ids, of faces sharing no vertex; {-1, -1} if every pair shares a vertex.
std::pair<Index, Index> first_disjoint_face_pair(const TriangleMesh& mesh, Index e1, Index e2);

/// Feature pairs that adjacency culling would never test: a VF pair (v, g), v not in g,
/// whose every face around v shares a vertex with g, and an EE pair without a common
/// vertex whose every pair of incident faces shares a vertex. No triangle pair covering
/// them is ever emitted when adjacent pairs are culled, so they are tested directly.
struct IsolatedSet {
  /// The isolated vertex-face pairs.
  std::vector<VertexFacePair> vertex_face;
  /// The isolated edge-edge pairs.
  std::vector<EdgeEdgePair> edge_edge;

  /// Enumerates the set from topology alone (parallel, deterministic order). An edge whose
  /// ends are plain, whose apexes are not adjacent and whose ends share no other neighbour
  /// has no partner (the argument is in isolated_set.cpp): most edges of a regular mesh are
  /// settled by that test from per-vertex neighbour lists, without their link entries.
  static IsolatedSet build(const TriangleMesh& mesh);
};

}  // namespace tailor
