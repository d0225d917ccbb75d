#include "tailor/candidates/feature_assignment.hpp"

#include <tbb/parallel_for.h>

#include <bit>

#include "tailor/candidates/isolated_set.hpp"

namespace tailor {

FeatureAssignment::FeatureAssignment(const TriangleMesh& mesh)
    : m_mesh(&mesh),
      m_vertex_owner(static_cast<std::size_t>(mesh.num_vertices()), -1),
      m_edge_owner(static_cast<std::size_t>(mesh.num_edges()), -1),
      m_owned(static_cast<std::size_t>(mesh.num_faces()), 0),
      m_owner_others(static_cast<std::size_t>(mesh.num_vertices()), {-1, -1}),
      m_owner_opposite(static_cast<std::size_t>(mesh.num_edges()), -1) {
  // Greedy in face order: each face takes its features that no earlier face took.
  const FaceArray& faces = mesh.faces();
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto edges = mesh.face_edges(f);
    for (int k = 0; k < 3; ++k) {
      const Index v = faces(f, k);
      if (m_vertex_owner[v] < 0) {
        m_vertex_owner[v] = f;
        m_owned[f] |= static_cast<std::uint8_t>(1u << k);
        m_owner_others[v] = {faces(f, (k + 1) % 3), faces(f, (k + 2) % 3)};
      }
      // Edge k joins corners k and k+1; the opposite corner is k+2.
      if (m_edge_owner[edges[k]] < 0) {
        m_edge_owner[edges[k]] = f;
        m_owned[f] |= static_cast<std::uint8_t>(1u << (3 + k));
        m_owner_opposite[edges[k]] = faces(f, (k + 2) % 3);
      }
    }
  }
  m_face_features.resize(static_cast<std::size_t>(mesh.num_faces()));
  tbb::parallel_for(Index{0}, mesh.num_faces(), [&](Index f) {
    FaceFeatures& record = m_face_features[f];
    record.edges = mesh.face_edges(f);
    for (int k = 0; k < 3; ++k) {
      record.corners[k] = faces(f, k);
      record.corner_owner_others[k] = m_owner_others[faces(f, k)];
      record.edge_owner_opposite[k] = m_owner_opposite[record.edges[k]];
    }
    record.owned = m_owned[f];
  });
}

int FeatureAssignment::vertices_assigned(Index f) const {
  return std::popcount(static_cast<unsigned>(m_owned[f] & 7u));
}

int FeatureAssignment::edges_assigned(Index f) const {
  return std::popcount(static_cast<unsigned>(m_owned[f] >> 3));
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
