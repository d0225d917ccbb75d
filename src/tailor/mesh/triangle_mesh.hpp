#pragma once
/// @file
/// Connectivity of a triangle mesh: edges, adjacency (flat CSR arrays), boundary, components.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// What validation found in a mesh's connectivity. Errors make the constructor throw;
/// the rest are warnings (real garments are often non-manifold).
struct MeshValidation {
  std::vector<Index> non_manifold_edges;     ///< edges with more than two incident faces
  std::vector<Index> unreferenced_vertices;  ///< vertices used by no face
  /// True when every edge has one or two faces and every vertex is used.
  bool is_manifold() const { return non_manifold_edges.empty(); }
};

/// Fixed connectivity of a triangle mesh, built once from its faces.
///
/// Edges are the unique undirected edges `(a, b)` with `a < b`, ordered by `b`, then by
/// `a` (the order of the reference data in ../shared/data). All adjacency is stored as
/// flat CSR arrays.
class TriangleMesh {
 public:
  /// Builds the connectivity. Throws InputError on an out-of-range index or a face that
  /// repeats a vertex; non-manifold edges and unreferenced vertices are only reported
  /// in validation().
  TriangleMesh(Index num_vertices, FaceArray faces);

  /// Number of vertices (including unreferenced ones).
  Index num_vertices() const { return m_num_vertices; }
  /// Number of triangles.
  Index num_faces() const { return static_cast<Index>(m_faces.rows()); }
  /// Number of unique undirected edges.
  Index num_edges() const { return static_cast<Index>(m_edges.rows()); }

  /// Faces as given, one row of three vertex ids per face.
  const FaceArray& faces() const { return m_faces; }
  /// Unique edges `(a, b)`, `a < b`, sorted by `(b, a)`.
  const EdgeArray& edges() const { return m_edges; }

  /// The three edges of face `f`: entry `i` joins `faces(f, i)` and `faces(f, (i+1)%3)`.
  std::array<Index, 3> face_edges(Index f) const {
    return {m_face_edges[3 * f], m_face_edges[3 * f + 1], m_face_edges[3 * f + 2]};
  }
  /// Faces incident to edge `e` (one for a boundary edge, two inside, more if non-manifold).
  std::span<const Index> edge_faces(Index e) const;
  /// Faces incident to vertex `v`, in increasing order.
  std::span<const Index> vertex_faces(Index v) const;
  /// Edges incident to vertex `v`, in increasing order (assembled on each call from the
  /// edge order and vertex_faces(): no table of them is kept).
  std::vector<Index> vertex_edges(Index v) const;

  /// Id of edge `(a, b)` (either order), or -1 if there is none.
  Index find_edge(Index a, Index b) const;

  /// True when edge `e` has exactly one incident face.
  bool is_boundary_edge(Index e) const { return edge_faces(e).size() == 1; }
  /// Number of boundary loops.
  Index num_boundary_loops() const { return static_cast<Index>(m_loop_offsets.size()) - 1; }
  /// Vertices of boundary loop `i`, in walking order (first vertex not repeated). Loops
  /// follow the orientation of their faces where it is consistent, and use every boundary
  /// edge exactly once. On a non-manifold or inconsistently oriented boundary a "loop" can
  /// be an open chain (its last and first vertices are then not joined by a boundary edge).
  std::span<const Index> boundary_loop(Index i) const;

  /// Number of connected components (by shared vertices; isolated vertices not counted).
  Index num_components() const { return m_num_components; }
  /// Component id of each face.
  const std::vector<Index>& face_components() const { return m_face_component; }

  /// True when faces `f` and `g` share at least one vertex (`f == g` included).
  bool faces_share_vertex(Index f, Index g) const;
  /// True when edges `e1` and `e2` share an endpoint (`e1 == e2` included).
  bool edges_share_vertex(Index e1, Index e2) const {
    const auto a = m_edges.row(e1), b = m_edges.row(e2);
    return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
  }

  /// Warnings found while building.
  const MeshValidation& validation() const { return m_validation; }

 private:
  // The 3F face sides bucketed by their larger vertex, each bucket sorted by the smaller
  // vertex: keys (smaller vertex << 32 | 3f + i) and the buckets' offsets.
  struct SortedSides {
    std::vector<Index> bucket_offsets;
    std::vector<std::uint64_t> keys;
  };
  // Boundary edges: each with its face's direction (from, to; -1 inside), and the
  // boundary edges of every vertex (CSR).
  struct BoundaryEdges {
    std::vector<Index> from, to;
    std::vector<Index> vertex_offsets, vertex_edges;
  };
  // The construction, in order (each step reads what the ones before it built).
  void validate_faces() const;
  SortedSides sorted_sides() const;
  void build_edges(const SortedSides& sides);
  void build_vertex_faces();
  void build_edge_ends();
  void record_warnings();
  BoundaryEdges boundary_edges() const;
  void build_boundary_loops();
  void label_components();

  Index m_num_vertices = 0;
  FaceArray m_faces;
  EdgeArray m_edges;
  std::vector<Index> m_face_edges;  // 3 per face
  std::vector<Index> m_edge_face_offsets, m_edge_face_ids;
  std::vector<Index> m_vertex_face_offsets, m_vertex_face_ids;
  std::vector<Index> m_edge_end_offsets;  // edges (a, b) of each b: a contiguous range
  std::vector<Index> m_loop_offsets{0}, m_loop_vertices;
  std::vector<Index> m_face_component;
  Index m_num_components = 0;
  MeshValidation m_validation;
};

}  // namespace tailor
