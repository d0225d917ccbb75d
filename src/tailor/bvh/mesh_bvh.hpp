#pragma once
/// @file
/// The BVH of a deforming triangle mesh: face boxes at both ends of a step (float, rounded
/// outward) and continuous normal bounds (direction masks), in flat arrays refitted in one
/// pass.

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include "tailor/bvh/batch_bounds.hpp"
#include "tailor/bvh/bvh_layout.hpp"
#include "tailor/bvh/diagonal_bounds.hpp"
#include "tailor/bvh/direction_mask.hpp"
#include "tailor/bvh/float_box.hpp"
#include "tailor/bvh/step_bound_columns.hpp"
#include "tailor/bvh/step_boxes.hpp"
#include "tailor/bvh/unwritten_allocator.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// A BVH over a subset of the faces of a mesh (all of them by default), built once on
/// one frame (build_surface_layout: nodes are connected patches where possible, so that
/// normal bounds can certify them) and refitted every step with two boxes per node (of its
/// faces at x0 and at x1: two nodes may meet only if may_meet_over_step(), step_boxes.hpp),
/// two sets of bounds along diagonals (the same test along them, diagonal_bounds.hpp) and
/// direction masks merged upward.
///
/// Layout (BvhLayout): pre-order, the left child of inner node i is i + 1. Each node is
/// one 128-byte record, two cache lines (box at t = 0, right child or face, face count, box
/// at t = 1; then the bounds along the four diagonals at t = 0 and t = 1, diagonal_bounds.hpp),
/// 256 bytes per face, plus the corners of each face in leaf order (12 bytes) so
/// the refit reads them in sequence. The leaves' bounds are also kept in columns, in leaf
/// order (StepBoundColumns, 112 bytes per face), so that a walk compares two small subtrees
/// leaf by leaf, sixteen leaves at a time, in place of visiting the node pairs between them.
///
/// Refit in two kinds of work. A *group* is a maximal subtree of fewer than kGroupFaces
/// faces: its faces' corners are read once into a MovingTriangleBatch (shared by
/// consecutive groups while their faces fit), from which its leaf boxes and its direction
/// mask are computed in vectorisable loops, then its inner boxes bottom-up. A *merge node*
/// (kGroupFaces faces or more) joins its children's boxes and masks (bitwise and: exact,
/// direction_mask.hpp). Masks are kept for groups and merge nodes only (one per about 8 faces);
/// nodes inside a group are never certified (their few pairs are left to adjacency culling and the
/// low level).
class MeshBvh {
 public:
  /// Subtrees of fewer faces are refitted as groups and keep at most one mask, at their
  /// root (see the class comment).
  static constexpr Index kGroupFaces = 16;

  MeshBvh() = default;
  /// Builds over `faces` (mesh face ids), or over every face when `faces` is empty.
  MeshBvh(const TriangleMesh& mesh, const Positions& x_build, std::vector<Index> faces = {});

  /// Refits boxes (with the diagonal bounds when `with_diagonals`, and the direction masks
  /// when `with_directions`) to the step from `x0` to `x1` in one bottom-up pass (parallel
  /// over disjoint subtrees). Without the diagonal bounds, may_meet() tests the boxes alone.
  void refit(const Positions& x0, const Positions& x1, bool with_directions,
             bool with_diagonals = true);
  /// Refits the direction masks only (the same pass without the boxes' bounds and
  /// writes). The boxes keep the step of the last refit(): boxes_current() is false
  /// until the next one. For a step whose root its mask certifies, no box is needed.
  void refit_directions(const Positions& x0, const Positions& x1);
  /// Whether the boxes belong to the last refit (false after refit_directions()).
  bool boxes_current() const { return m_boxes_current; }

  /// True for a tree over no faces.
  bool empty() const { return m_nodes.empty(); }
  /// Number of nodes (2n - 1 for n faces).
  Index num_nodes() const { return static_cast<Index>(m_nodes.size()); }
  /// Whether `node` is a leaf (holds one face).
  bool is_leaf(Index node) const { return m_nodes[node].count == 1; }
  /// Left child of an inner node (node + 1: pre-order numbering).
  Index left(Index node) const { return node + 1; }
  /// Right child of an inner node.
  Index right(Index node) const { return m_nodes[node].right_or_face; }
  /// Number of faces under a node.
  Index size(Index node) const { return m_nodes[node].count; }
  /// Mesh face id of a leaf.
  Index leaf_face(Index node) const { return m_nodes[node].right_or_face; }
  /// Box of a node's faces at the step's start, x0 (valid after refit).
  const FloatBox& start_box(Index node) const { return m_nodes[node].start; }
  /// Box of a node's faces at the step's end, x1 (valid after refit).
  const FloatBox& end_box(Index node) const { return m_nodes[node].end; }
  /// Bounds of a node's corners at x0 along the diagonals of diagonal_bounds.hpp: min[k] and
  /// max[k] along d_k (valid after refit).
  const DiagonalBox& diagonal_start_box(Index node) const { return m_nodes[node].diagonal_start; }
  /// The same at x1.
  const DiagonalBox& diagonal_end_box(Index node) const { return m_nodes[node].diagonal_end; }
  /// Leaf order: the leaves by increasing node id. The leaves under `node` are the
  /// size(node) leaves from first_leaf(node) on.
  Index first_leaf(Index node) const { return m_nodes[node].first_leaf; }
  /// Mesh face id of the leaf at `leaf` in leaf order.
  Index face_at_leaf(Index leaf) const { return m_leaf_faces[leaf]; }
  /// Corners of the face at `leaf` in leaf order.
  const std::array<Index, 3>& corners_at_leaf(Index leaf) const { return m_leaf_vertices[leaf]; }
  /// The leaves' bounds in leaf order (valid after refit): along the axes, then the four
  /// diagonals of diagonal_bounds.hpp when the refit computed them.
  const StepBoundColumns& leaf_bounds() const { return m_leaf_bounds; }
  /// Directions of leaf_bounds() that may_meet() tests: 3, or 7 with the diagonals.
  int bound_directions() const {
    return m_diagonals_current ? StepBoundColumns::kMaxDirections : 3;
  }
  /// Whether faces of `node` and faces of `other`'s node `other_node` may meet during the
  /// refitted step: may_meet_over_step() of their boxes, then of their diagonal bounds
  /// (diagonal_bounds.hpp) when both trees were refitted with them.
  bool may_meet(Index node, const MeshBvh& other, Index other_node) const {
    const Node& a = m_nodes[node];
    const Node& b = other.m_nodes[other_node];
    if (!may_meet_over_step(a.start, a.end, b.start, b.end)) return false;
    if (!m_diagonals_current || !other.m_diagonals_current) return true;
    return may_meet_over_step(a.diagonal_start, a.diagonal_end, b.diagonal_start, b.diagonal_end);
  }
  /// Directions within 90° of every normal below the node over the step (valid after a
  /// refit with directions); 0 for the nodes inside a group, which keep no mask.
  DirectionMask direction_mask(Index node) const {
    return has_mask(node) ? m_masks[mask_index(node)] : 0;
  }
  /// An axis (not normalised) within 90° of every normal below the node over the whole
  /// step (mask_axis() of its mask), or nothing.
  std::optional<Vec3> acute_axis(Index node) const {
    const DirectionMask mask = direction_mask(node);
    if (mask == 0) return std::nullopt;
    return mask_axis(mask);
  }
  /// Whether a node keeps a mask (groups and merge nodes), and its index among the
  /// num_masks() nodes that do.
  bool has_mask(Index node) const {
    return (m_mask_bits[static_cast<std::size_t>(node) >> 6] >> (node & 63)) & 1;
  }
  /// (Only for a node that has_mask().)
  Index mask_index(Index node) const {
    // Masks are stored in increasing node order: the index is the number of nodes with a
    // mask before this one (a rank over the bit set, 2 bits and half a byte per face in
    // place of a 4-byte index per node).
    const std::size_t word = static_cast<std::size_t>(node) >> 6;
    const std::uint64_t below = (std::uint64_t{1} << (node & 63)) - 1;
    return m_masks_before_word[word] + std::popcount(m_mask_bits[word] & below);
  }
  /// Number of nodes that keep a direction mask (see has_mask()).
  Index num_masks() const { return static_cast<Index>(m_masks.size()); }

 private:
  static_assert(kGroupFaces <= MovingTriangleBatch::kCapacity + 1);
  static_assert(2 * kGroupFaces - 3 <= 32);

  // Which nodes root a group (refitted from its faces) and which a parallel task.
  struct Roles {
    std::vector<char> group_root, task_root;
  };
  // The construction, in order: the node records from the surface layout; the roles; the
  // mask slots, groups, merge nodes and leaf corners; the tasks' ranges of groups and
  // merge nodes.
  void build_nodes(const TriangleMesh& mesh, const Positions& x_build, std::vector<Index> faces);
  Roles mark_roles();
  void assign_slots(const TriangleMesh& mesh, const Roles& roles);
  void index_tasks(const Roles& roles);

  // Aligned to its size, so that no record straddles two cache lines (malloc aligns large
  // arrays to 16 bytes only). Each box is followed by eight bytes that write_group_boxes()
  // may rewrite with their own value.
  struct alignas(128) Node {
    FloatBox start;
    Index right_or_face = -1;
    Index count = 0;
    FloatBox end;
    Index first_leaf = 0;  // first_leaf()
    Index unused = 0;
    // Bounds along the diagonals (diagonal_bounds.hpp): the record's second cache line.
    DiagonalBox diagonal_start;
    DiagonalBox diagonal_end;
  };
  struct Group {
    Index root, first_leaf;  // its leaves are first_leaf, first_leaf + 1, ... (leaf order)
    Index mask_slot;         // mask_index(root), so that the refit counts no bits
    // Bit i: node root + i is a leaf (a group has at most 2·kGroupFaces - 3 nodes), so
    // that the refit visits leaves and inner nodes without a branch per node.
    std::uint32_t leaf_bits;
  };
  // A merge node with the mask slots of itself and its two children.
  struct Merge {
    Index node, slot, left_slot, right_slot;
  };
  // The work of one parallel task: a range of groups, then a range of merge nodes
  // (visited in decreasing id order, children first).
  struct Task {
    Index groups_begin, groups_end, merges_begin, merges_end;
  };
  // The faces of group g (from the first leaves of g and g + 1: no node record is read).
  Index group_faces(Index g) const;
  // What one refit pass computes.
  struct RefitParts {
    bool boxes, diagonals, directions;
  };
  void refit_parts(const Positions& x0, const Positions& x1, RefitParts parts);
  // Refits groups [first, end), of `faces` faces in all (at most a batch), from one batch.
  void refit_groups(Index first, Index end, Index faces, const Positions& x0, const Positions& x1,
                    RefitParts parts);
  // The leaf bounds of a batch's `faces` lanes, from leaf `first_leaf` on.
  void write_leaf_bounds(Index first_leaf, Index faces, const BatchBounds& start,
                         const BatchBounds& end);
  void write_leaf_diagonal_bounds(Index first_leaf, Index faces, const DiagonalBatchBounds& start,
                                  const DiagonalBatchBounds& end);
  void merge(const Merge& merge, RefitParts parts);
  // Sets an inner node's boxes to the unions of its children's.
  void join_children(Index node, bool diagonals);

  // Built in place, in parallel (build_nodes()): 256 bytes per face, zeroed on one thread
  // they cost cloth-ball's build about a fifth more.
  std::vector<Node, UnwrittenAllocator<Node>> m_nodes;
  std::vector<std::uint64_t> m_mask_bits;  // bit `node`: the node keeps a mask
  std::vector<Index> m_masks_before_word;  // masks of the nodes below 64 · word
  std::vector<DirectionMask> m_masks;
  std::vector<std::array<Index, 3>> m_leaf_vertices;  // in leaf order, for a coherent refit
  std::vector<Index> m_leaf_faces;                    // in leaf order
  StepBoundColumns m_leaf_bounds;                     // in leaf order
  std::vector<Group> m_groups;                        // increasing root id
  std::vector<Merge> m_merges;                        // increasing node id
  std::vector<Task> m_tasks;                          // disjoint subtrees
  std::vector<Index> m_top_merges;  // positions in m_merges of those above the tasks, decreasing
  bool m_boxes_current = false;
  bool m_diagonals_current = false;
};

}  // namespace tailor
