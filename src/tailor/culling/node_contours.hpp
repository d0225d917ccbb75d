#pragma once
/// @file
/// Boundary contours of BVH nodes, precomputed once from topology for the contour test.

#include <span>
#include <vector>

#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// For every node of a MeshBvh that keeps a direction mask (the only ones the traversal
/// tests): whether its faces can be certified by the normal-cone
/// theorem at all (edge-manifold, consistently oriented, exactly one boundary loop), and
/// that loop. A patch whose normals all lie within 90° of an axis is immersed in the
/// plane by the projection along that axis; with one simple boundary loop the immersion
/// is injective, so the patch cannot touch itself. Several loops (an annulus, two
/// pieces) or none (a closed surface) never certify.
class NodeContours {
 public:
  NodeContours() = default;
  /// Built for `bvh`, which must outlive the contours (they use its mask indices).
  NodeContours(const TriangleMesh& mesh, const MeshBvh& bvh);

  /// True when the node keeps a mask and its faces have exactly one consistently oriented
  /// boundary loop.
  bool has_single_loop(Index node) const { return !loop(node).empty(); }
  /// Vertices of the node's boundary loop in walking order (empty if none).
  std::span<const Index> loop(Index node) const {
    if (m_bvh == nullptr || !m_bvh->has_mask(node)) return {};
    const Index slot = m_bvh->mask_index(node);
    return {m_loop_vertices.data() + m_loop_start[slot],
            static_cast<std::size_t>(m_loop_length[slot])};
  }
  /// Total number of stored loop vertices (memory use).
  std::size_t stored_vertices() const { return m_loop_vertices.size(); }

 private:
  const MeshBvh* m_bvh = nullptr;
  std::vector<std::int64_t> m_loop_start;  // per mask index
  std::vector<Index> m_loop_length;        // per mask index (0: no single loop)
  std::vector<Index> m_loop_vertices;
};

}  // namespace tailor
