#pragma once
/// @file
/// The shape of a binary BVH, built once top-down; shared by Bvh and MeshBvh.

#include <span>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// A binary tree over n primitives with one primitive per leaf (2n - 1 nodes), numbered
/// in depth-first pre-order from the root 0: the left child of inner node i is i + 1, the
/// subtree of node i is the id range [i, i + 2·count[i] - 1), every child has a larger id
/// than its parent (so decreasing ids are bottom-up), and the leaves appear in the order
/// of the primitives they hold along the tree.
struct BvhLayout {
  /// Right child of an inner node; the primitive of a leaf.
  std::vector<Index> right;
  /// Primitives under each node (1 for a leaf).
  std::vector<Index> count;

  /// Number of nodes (2n - 1 for n primitives).
  Index num_nodes() const { return static_cast<Index>(count.size()); }
  /// Whether `node` is a leaf (count 1).
  bool is_leaf(Index node) const { return count[node] == 1; }
};

/// Builds top-down: each node splits its primitives at the median of their centres along
/// the widest axis of the centres' box (ties broken by primitive id, so the tree depends
/// only on the input). O(n log n), with memory O(n) besides the result; large subtrees are
/// split in parallel (the same tree on any number of threads).
BvhLayout build_median_split_layout(std::span<const Vec3> centers);

/// Builds top-down over the faces `faces` of `mesh` (primitive i is faces[i], with centre
/// centers[i]) so that nodes are connected patches of the surface wherever possible, as
/// normal-cone culling needs (a node is certified only if its faces form one patch with a
/// single boundary loop; a spatial split of a folded or curved sheet mixes pieces that
/// touch only at a vertex, or layers facing opposite ways). Each node's faces are split:
/// - into groups of whole edge-connected components, by the median of the components'
///   centres along the widest axis, when they are not connected;
/// - otherwise into the first half of a breadth-first order over edge-adjacent faces from
///   a peripheral face (the last face reached from any face) and the rest: a front that
///   sweeps the patch, leaving two patches of half the size. The first half is itself one
///   patch in breadth-first order from that peripheral face (a prefix of a breadth-first
///   order is one of its own patch), so it is halved along the same sweep with no new
///   search.
/// O(n log n); subtrees are split in parallel, and the tree does not depend on scheduling.
BvhLayout build_surface_layout(const TriangleMesh& mesh, std::span<const Index> faces,
                               std::span<const Vec3> centers);

}  // namespace tailor
