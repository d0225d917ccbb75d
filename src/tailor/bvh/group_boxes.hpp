#pragma once
/// @file
/// The boxes of every node of a small subtree (a group of the MeshBvh refit) from its
/// leaves' bounds, written into the node records in one pass.

#include <cstddef>
#include <cstdint>

#include "tailor/bvh/batch_bounds.hpp"
#include "tailor/bvh/diagonal_bounds.hpp"
#include "tailor/bvh/float_box.hpp"

namespace tailor {

/// Writes the boxes of a subtree of `2·count - 1` nodes in pre-order (node i's left child
/// is i + 1): bit i of `leaf_bits` says that node i is a leaf, the leaves in increasing
/// order take the boxes of lanes `first_lane` to first_lane + count - 1 of `bounds` (a
/// batch may hold several groups), and an inner node's box is
/// the union of its two children's. Node i's box is at `first` plus i·`stride` bytes, at
/// the start of a record of `stride` >= 32 bytes; the rest of each record keeps its value.
///
/// Nodes are visited in decreasing order, so both children of an inner node are done
/// before it (the right subtree, then the left child last): a stack of the pending
/// subtrees' boxes in registers gives them, and no box is read back from the records just
/// written (the join it replaces read the children's floats back one at a time, and was
/// slower). 1 <= count, first_lane + count <= MovingTriangleBatch::kCapacity.
void write_group_boxes(const BatchBounds& bounds, int first_lane, std::uint32_t leaf_bits,
                       int count, FloatBox* first, std::size_t stride);

/// write_group_boxes() for the nodes' diagonal bounds: the same subtree, leaves and
/// order, a DiagonalBox (32 bytes, written whole) at `first` plus i·`stride` bytes.
void write_group_diagonal_boxes(const DiagonalBatchBounds& bounds, int first_lane,
                                std::uint32_t leaf_bits, int count, DiagonalBox* first,
                                std::size_t stride);

namespace detail {
/// write_group_diagonal_boxes() with two SSE2 vectors per box and with one AVX2 vector per
/// box (call only when direction_mask_has_avx2()); exposed so that a test can check they
/// agree.
void write_group_diagonal_boxes_sse2(const DiagonalBatchBounds& bounds, int first_lane,
                                     std::uint32_t leaf_bits, int count, DiagonalBox* first,
                                     std::size_t stride);
void write_group_diagonal_boxes_avx2(const DiagonalBatchBounds& bounds, int first_lane,
                                     std::uint32_t leaf_bits, int count, DiagonalBox* first,
                                     std::size_t stride);
/// write_group_boxes() with two SSE2 vectors per box (any x86-64 processor), and with one
/// AVX2 vector per box (call only when direction_mask_has_avx2()), which rewrites
/// the eight bytes after each box with their own value. Exposed so that a test can check
/// they agree.
void write_group_boxes_sse2(const BatchBounds& bounds, int first_lane, std::uint32_t leaf_bits,
                            int count, FloatBox* first, std::size_t stride);
void write_group_boxes_avx2(const BatchBounds& bounds, int first_lane, std::uint32_t leaf_bits,
                            int count, FloatBox* first, std::size_t stride);
}  // namespace detail

}  // namespace tailor
