#pragma once
/// @file
/// A bounding volume hierarchy over primitives given by their boxes; flat arrays.

#include <tbb/parallel_invoke.h>

#include <bit>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "tailor/bvh/aabb.hpp"
#include "tailor/bvh/step_bound_columns.hpp"
#include "tailor/bvh/step_boxes.hpp"

namespace tailor {

/// Binary BVH with one primitive per leaf, stored in flat arrays. Nodes are numbered in
/// depth-first pre-order from the root 0, so every child has a larger id than its parent
/// and refitting in decreasing id order is bottom-up. The topology is built once; boxes
/// are refitted as primitives move. `Box` is Aabb (Bvh) or StepBox (boxes at both ends of a
/// step, whose overlaps() is "may meet"); it has extend(), overlaps() and center().
template <class Box>
class BasicBvh {
 public:
  BasicBvh() = default;
  /// Builds the tree top-down (build_median_split_layout on the box centres).
  explicit BasicBvh(std::span<const Box> primitive_boxes);

  /// Number of nodes (2n - 1 for n primitives; 0 when empty).
  Index num_nodes() const { return static_cast<Index>(m_left.size()); }
  /// Number of primitives (leaves).
  Index num_primitives() const { return static_cast<Index>(m_leaf_of_primitive.size()); }
  /// True for a tree over no primitives.
  bool empty() const { return m_left.empty(); }
  /// Whether `node` is a leaf (holds one primitive, no children).
  bool is_leaf(Index node) const { return m_left[node] < 0; }
  /// Left child of an inner node.
  Index left(Index node) const { return m_left[node]; }
  /// Right child of an inner node.
  Index right(Index node) const { return m_right[node]; }
  /// Primitive of a leaf.
  Index primitive(Index node) const { return m_right[node]; }
  /// Leaf node holding primitive `p`.
  Index leaf_of(Index p) const { return m_leaf_of_primitive[p]; }
  /// Parent of a node (-1 for the root).
  Index parent(Index node) const { return m_parent[node]; }
  /// Primitives under a node: a contiguous range of primitive_order().
  std::span<const Index> primitives_under(Index node) const {
    return {m_primitive_order.data() + m_first[node], static_cast<std::size_t>(m_count[node])};
  }
  /// Primitive ids in leaf order.
  const std::vector<Index>& primitive_order() const { return m_primitive_order; }

  /// Box of a node: its primitive's box for a leaf, the union of its children's otherwise.
  const Box& box(Index node) const { return m_boxes[node]; }
  /// Sets every leaf box from `primitive_boxes` and refits inner nodes bottom-up (parallel).
  void refit(std::span<const Box> primitive_boxes);

  /// Calls `update(node)` for every node after both its children (bottom-up); disjoint
  /// subtrees run in parallel, so `update` may only write data of `node` itself.
  template <class Update>
  void for_each_node_bottom_up(Update&& update) const {
    if (!empty()) bottom_up_recursive(0, update);
  }

  /// Calls `visit(p, q)` for every pair of primitives `p` of this tree and `q` of `other`
  /// whose boxes overlap (sequential, deterministic order).
  template <class Visit>
  void for_each_overlapping_pair(const BasicBvh& other, Visit&& visit) const;
  /// Calls `visit(p, q)`, p != q, once per unordered pair of overlapping primitives.
  template <class Visit>
  void for_each_self_overlapping_pair(Visit&& visit) const;

  /// The pairs of for_each_overlapping_pair, with large subtree pairs walked in parallel as
  /// tasks: each task calls `local()` once for its sink (a per-thread buffer, say), then
  /// `visit(sink, p, q)` for its pairs. Tasks run on several threads at once, in no fixed
  /// order.
  template <class Local, class Visit>
  void parallel_for_each_overlapping_pair(const BasicBvh& other, Local&& local,
                                          Visit&& visit) const {
    if (!empty() && !other.empty()) parallel_pair(0, other, 0, local, visit);
  }
  /// The pairs of for_each_self_overlapping_pair, walked in parallel as above.
  template <class Local, class Visit>
  void parallel_for_each_self_overlapping_pair(Local&& local, Visit&& visit) const {
    if (!empty()) parallel_self(0, local, visit);
  }

 private:
  // Subtrees with fewer primitives than this are handled by one task.
  static constexpr Index kParallelGrain = 2048;
  // Two subtrees of at most this many primitives each are compared primitive by primitive
  // (their boxes lie side by side in leaf order): for StepBoxes, compared sixteen or eight at
  // once (StepBoundColumns::lanes()), visiting the nodes between them costs more than the
  // comparisons they spare.
  static constexpr bool kColumns = std::is_same_v<Box, StepBox>;
  static Index bucket_size() { return kColumns ? StepBoundColumns::lanes() : 1; }
  struct NoColumns {};

  template <class Update>
  void bottom_up_recursive(Index node, Update& update) const {
    if (!is_leaf(node)) {
      if (m_count[node] > kParallelGrain) {
        tbb::parallel_invoke([&] { bottom_up_recursive(m_left[node], update); },
                             [&] { bottom_up_recursive(m_right[node], update); });
      } else {
        bottom_up_recursive(m_left[node], update);
        bottom_up_recursive(m_right[node], update);
      }
    }
    update(node);
  }
  template <class Visit>
  void pair_recursive(Index a, const BasicBvh& other, Index b, Visit& visit) const;
  template <class Visit>
  void self_recursive(Index a, Visit& visit) const;
  template <class Visit>
  void bucket_pairs(Index a, const BasicBvh& other, Index b, Visit& visit) const;
  template <class Visit>
  void bucket_self_pairs(Index a, Visit& visit) const;
  template <class Local, class Visit>
  void parallel_pair(Index a, const BasicBvh& other, Index b, Local& local, Visit& visit) const;
  template <class Local, class Visit>
  void parallel_self(Index a, Local& local, Visit& visit) const;

  std::vector<Index> m_left, m_right, m_parent;  // leaf: left = -1, right = primitive
  std::vector<Index> m_first, m_count;           // range in m_primitive_order
  std::vector<Index> m_primitive_order, m_leaf_of_primitive;
  std::vector<Box> m_boxes;
  // StepBoxes: the box of primitive_order()[i] at i, for the buckets.
  [[no_unique_address]] std::conditional_t<kColumns, StepBoundColumns, NoColumns> m_columns;
};

/// A BVH over static boxes (or swept ones).
using Bvh = BasicBvh<Aabb>;

template <class Box>
template <class Visit>
void BasicBvh<Box>::for_each_overlapping_pair(const BasicBvh& other, Visit&& visit) const {
  if (empty() || other.empty()) return;
  pair_recursive(0, other, 0, visit);
}

template <class Box>
template <class Visit>
void BasicBvh<Box>::for_each_self_overlapping_pair(Visit&& visit) const {
  if (!empty()) self_recursive(0, visit);
}

template <class Box>
template <class Visit>
void BasicBvh<Box>::pair_recursive(Index a, const BasicBvh& other, Index b, Visit& visit) const {
  if (!m_boxes[a].overlaps(other.m_boxes[b])) return;
  const bool a_leaf = is_leaf(a), b_leaf = other.is_leaf(b);
  if (m_count[a] <= bucket_size() && other.m_count[b] <= bucket_size()) {
    if constexpr (kColumns) {
      bucket_pairs(a, other, b, visit);
    } else {
      visit(primitive(a), other.primitive(b));  // two leaves
    }
  } else if (b_leaf || (!a_leaf && m_count[a] >= other.m_count[b])) {
    pair_recursive(m_left[a], other, b, visit);
    pair_recursive(m_right[a], other, b, visit);
  } else {
    pair_recursive(a, other, other.m_left[b], visit);
    pair_recursive(a, other, other.m_right[b], visit);
  }
}

template <class Box>
template <class Visit>
void BasicBvh<Box>::self_recursive(Index a, Visit& visit) const {
  if (m_count[a] <= bucket_size()) {
    if constexpr (kColumns) bucket_self_pairs(a, visit);
    return;
  }
  self_recursive(m_left[a], visit);
  self_recursive(m_right[a], visit);
  pair_recursive(m_left[a], *this, m_right[a], visit);
}

template <class Box>
template <class Visit>
void BasicBvh<Box>::bucket_pairs(Index a, const BasicBvh& other, Index b, Visit& visit) const {
  const Index first_a = m_first[a], first_b = other.m_first[b];
  std::uint32_t masks[StepBoundColumns::kLanes];
  other.m_columns.may_meet_masks(m_columns, {first_a, static_cast<int>(m_count[a])},
                                 {first_b, static_cast<int>(other.m_count[b])}, 3, masks);
  for (Index r = 0; r < m_count[a]; ++r) {
    for (std::uint32_t mask = masks[r]; mask != 0; mask &= mask - 1) {
      visit(m_primitive_order[first_a + r],
            other.m_primitive_order[first_b + std::countr_zero(mask)]);
    }
  }
}

template <class Box>
template <class Visit>
void BasicBvh<Box>::bucket_self_pairs(Index a, Visit& visit) const {
  const Index first = m_first[a];
  std::uint32_t masks[StepBoundColumns::kLanes];
  m_columns.may_meet_masks_within({first, static_cast<int>(m_count[a])}, 3, masks);
  for (Index r = 0; r < m_count[a]; ++r) {
    for (std::uint32_t mask = masks[r]; mask != 0; mask &= mask - 1) {
      visit(m_primitive_order[first + r], m_primitive_order[first + std::countr_zero(mask)]);
    }
  }
}

// The walk of pair_recursive, splitting the same node, with both halves as tasks while the
// pair holds more than kParallelGrain primitives; below, one task walks it sequentially.
template <class Box>
template <class Local, class Visit>
void BasicBvh<Box>::parallel_pair(Index a, const BasicBvh& other, Index b, Local& local,
                                  Visit& visit) const {
  if (m_count[a] + other.m_count[b] <= kParallelGrain) {
    auto& sink = local();
    auto to_sink = [&](Index p, Index q) { visit(sink, p, q); };
    return pair_recursive(a, other, b, to_sink);
  }
  if (!m_boxes[a].overlaps(other.m_boxes[b])) return;
  if (other.is_leaf(b) || (!is_leaf(a) && m_count[a] >= other.m_count[b])) {
    tbb::parallel_invoke([&] { parallel_pair(m_left[a], other, b, local, visit); },
                         [&] { parallel_pair(m_right[a], other, b, local, visit); });
  } else {
    tbb::parallel_invoke([&] { parallel_pair(a, other, other.m_left[b], local, visit); },
                         [&] { parallel_pair(a, other, other.m_right[b], local, visit); });
  }
}

template <class Box>
template <class Local, class Visit>
void BasicBvh<Box>::parallel_self(Index a, Local& local, Visit& visit) const {
  if (m_count[a] <= kParallelGrain) {
    auto& sink = local();
    auto to_sink = [&](Index p, Index q) { visit(sink, p, q); };
    return self_recursive(a, to_sink);
  }
  tbb::parallel_invoke([&] { parallel_self(m_left[a], local, visit); },
                       [&] { parallel_self(m_right[a], local, visit); },
                       [&] { parallel_pair(m_left[a], *this, m_right[a], local, visit); });
}

}  // namespace tailor
