#include "tailor/candidates/feature_assignment.hpp"

#include "tailor/candidates/isolated_set.hpp"

namespace tailor {

FeatureAssignment::FeatureAssignment(const TriangleMesh& mesh)
    : m_mesh(&mesh),
      m_vertex_owner(static_cast<std::size_t>(mesh.num_vertices()), -1),
      m_edge_owner(static_cast<std::size_t>(mesh.num_edges()), -1),
      m_vertex_count(static_cast<std::size_t>(mesh.num_faces()), 0),
      m_edge_count(static_cast<std::size_t>(mesh.num_faces()), 0) {
  // Greedy in face order: each face takes its features that no earlier face took.
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto edges = mesh.face_edges(f);
    for (int k = 0; k < 3; ++k) {
      Index& vertex_owner = m_vertex_owner[mesh.faces()(f, k)];
      if (vertex_owner < 0) vertex_owner = f, ++m_vertex_count[f];
      Index& edge_owner = m_edge_owner[edges[k]];
      if (edge_owner < 0) edge_owner = f, ++m_edge_count[f];
    }
  }
}

Index FeatureAssignment::vf_representative(Index v, Index g, bool adjacency_culling) const {
  const Index owner = m_vertex_owner[v];
  if (!adjacency_culling || !m_mesh->faces_share_vertex(owner, g)) return owner;
  return first_face_disjoint_from(*m_mesh, v, g);
}

std::pair<Index, Index> FeatureAssignment::ee_representative(Index e1, Index e2,
                                                             bool adjacency_culling) const {
  const Index owner1 = m_edge_owner[e1], owner2 = m_edge_owner[e2];
  if (!adjacency_culling || !m_mesh->faces_share_vertex(owner1, owner2)) return {owner1, owner2};
  return first_disjoint_face_pair(*m_mesh, e1, e2);
}

}  // namespace tailor
