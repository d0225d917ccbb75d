#pragma once
/// @file
/// The BVH of a deforming triangle mesh: swept face boxes (float, rounded outward) and
/// continuous normal cones, in flat arrays refitted in one pass.

#include <array>
#include <vector>

#include "tailor/bvh/bvh_layout.hpp"
#include "tailor/bvh/float_box.hpp"
#include "tailor/bvh/normal_cone.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// A BVH over a subset of the faces of a mesh (all of them by default), built once on
/// one frame (build_surface_layout: nodes are connected patches where possible, so that
/// normal cones can certify them) and refitted every step with swept boxes (box of x0
/// and x1) and continuous normal cones merged upward.
///
/// Layout (BvhLayout): pre-order, the left child of inner node i is i + 1. Each node is
/// one 32-byte record (box, right child or face, face count), 64 bytes per face, plus the
/// corners of each face in leaf order (12 bytes) so the refit reads them in sequence.
///
/// Cones: a subtree of fewer than kDirectConeFaces faces whose parent is larger gets one
/// cone computed directly from its faces' control normals; larger nodes merge their
/// children's cones; nodes inside such a small subtree get none (wide: never culled by
/// cones, their few pairs are left to adjacency culling and the low level). This keeps
/// square roots and divisions off the per-face path of the refit, and about one stored
/// cone (40 bytes) per 8 faces.
class MeshBvh {
 public:
  MeshBvh() = default;
  /// Builds over `faces` (mesh face ids), or over every face when `faces` is empty.
  MeshBvh(const TriangleMesh& mesh, const Positions& x_build, std::vector<Index> faces = {});

  /// Refits boxes (and cones when `with_cones`) to the step from `x0` to `x1` in one
  /// bottom-up pass (parallel over disjoint subtrees).
  void refit(const Positions& x0, const Positions& x1, bool with_cones);

  bool empty() const { return m_nodes.empty(); }
  Index num_nodes() const { return static_cast<Index>(m_nodes.size()); }
  bool is_leaf(Index node) const { return m_nodes[node].count == 1; }
  /// Children of an inner node.
  Index left(Index node) const { return node + 1; }
  Index right(Index node) const { return m_nodes[node].right_or_face; }
  /// Number of faces under a node.
  Index size(Index node) const { return m_nodes[node].count; }
  /// Mesh face id of a leaf.
  Index leaf_face(Index node) const { return m_nodes[node].right_or_face; }
  /// Swept box of a node (valid after refit).
  const FloatBox& box(Index node) const { return m_nodes[node].box; }
  /// Continuous normal cone of an inner node (valid after refit with cones); wide for the
  /// nodes below a subtree of fewer than kDirectConeFaces faces (see refit).
  const NormalCone& cone(Index node) const {
    return m_cone_slot[node] >= 0 ? m_cones[m_cone_slot[node]] : kWide;
  }
  /// Whether a node keeps a cone (the others report wide()), and its index among the
  /// num_cones() nodes that do.
  bool has_cone(Index node) const { return m_cone_slot[node] >= 0; }
  Index cone_index(Index node) const { return m_cone_slot[node]; }
  Index num_cones() const { return static_cast<Index>(m_cones.size()); }
  /// The faces the tree was built over, in the order given.
  const std::vector<Index>& faces() const { return m_faces; }

 private:
  static constexpr Index kDirectConeFaces = 16;
  static inline const NormalCone kWide = NormalCone::wide();

  struct Node {
    FloatBox box;
    Index right_or_face = -1;
    Index count = 0;
  };
  // Refits the nodes with ids in [begin, end) in decreasing order (children first): a
  // whole subtree, or one node above the task roots. `leaves_before` is the number of
  // leaves with ids below `begin`.
  void refit_range(Index begin, Index end, Index leaves_before, const Positions& x0,
                   const Positions& x1, bool with_cones);
  // The cone of the `count` faces of leaves first_leaf, first_leaf + 1, ... (leaf order).
  NormalCone direct_cone(Index first_leaf, Index count, const Positions& x0,
                         const Positions& x1) const;

  const TriangleMesh* m_mesh = nullptr;
  std::vector<Index> m_faces;
  std::vector<Node> m_nodes;
  std::vector<Index> m_cone_slot;  // inner node -> index into m_cones
  std::vector<NormalCone> m_cones;
  std::vector<std::array<Index, 3>> m_leaf_vertices;  // in leaf order, for a coherent refit
  struct TaskRoot {
    Index node, leaves_before;
  };
  std::vector<TaskRoot> m_task_roots;  // disjoint subtrees refitted in parallel
  std::vector<TaskRoot> m_top_nodes;   // the nodes above them, decreasing
};

}  // namespace tailor
