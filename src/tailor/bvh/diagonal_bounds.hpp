#pragma once
/// @file
/// Bounds of a moving triangle batch along the four diagonal directions of the cube, d0 =
/// (1, 1, 1), d1 = (1, 1, -1), d2 = (1, -1, 1) and d3 = (-1, 1, 1): the slabs MeshBvh keeps
/// beside each node's box.
///
/// Why they cull more. A node's axis-aligned box is loose around a sheet that lies oblique
/// to the axes, and two stacked layers of such a sheet (cloth lying on a ball, folded
/// cloth) keep overlapping boxes down to their leaves. The slabs along the diagonals are
/// tight where the axes are loosest: on cloth-ball's step they cut the node pairs a
/// self-traversal visits by about a third, and its candidate triangle pairs as much.
///
/// Why the culling stays sound. A node pair is kept apart when its slabs along one
/// direction are apart at both ends of the step in one order: the argument of
/// bvh/step_boxes.hpp holds for any fixed direction (a point at fixed barycentric
/// coordinates projects affinely in t), and these bounds hold every corner's projection.
/// The projection p = fl(fl(±x ± y) ± z) is within γ2·S of the exact one (S = |x| + |y| +
/// |z|); the bounds are computed from p - e and p + e, e = 2^-50·S, which stay on their
/// side of the exact projection after their own roundings (e exceeds 7.9 u·S, the error
/// of p plus that of the subtraction is below 3.1 u·S), then rounded outward to float as
/// the boxes are (batch_bounds.hpp: beyond the float range, clamped).

#include <array>

#include "tailor/bvh/direction_mask.hpp"

namespace tailor {

/// Number of diagonal directions.
inline constexpr int kDiagonals = 4;

/// A set's bounds along the diagonals, in float: min[k] <= d_k·x <= max[k] for its points.
struct DiagonalBox {
  std::array<float, kDiagonals> min;  ///< lower bounds
  std::array<float, kDiagonals> max;  ///< upper bounds
};

/// Per direction k and lane i of a batch, at one end of the step: low[k][i] <= the
/// projection on d_k of every corner in that frame <= high[k][i], within a few float ulps
/// and the header's margin (beyond the float range clamped, as batch_bounds.hpp says).
struct DiagonalBatchBounds {
  /// Lower bounds: low[k][i] along direction k for lane i.
  alignas(16) float low[kDiagonals][MovingTriangleBatch::kCapacity];
  /// Upper bounds: high[k][i] along direction k for lane i.
  alignas(16) float high[kDiagonals][MovingTriangleBatch::kCapacity];
};

/// The bounds of lanes 0 to padded_count() of a padded batch (pad()): `start` of the
/// corners at t = 0, `end` of those at t = 1.
void diagonal_batch_bounds(const MovingTriangleBatch& batch, DiagonalBatchBounds& start,
                           DiagonalBatchBounds& end);

}  // namespace tailor
