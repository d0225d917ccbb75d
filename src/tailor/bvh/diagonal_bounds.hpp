#pragma once
/// @file
/// Bounds of a moving triangle batch along three diagonal directions, d0 = (1, 1, 1),
/// d1 = (1, 1, -1) and d2 = (1, -1, 1): the slabs MeshBvh keeps beside each node's box.
///
/// Why they cull more. A node's axis-aligned box is loose around a sheet that lies oblique
/// to the axes, and two stacked layers of such a sheet (cloth lying on a ball, folded
/// cloth) keep overlapping boxes down to their leaves. The slabs along the diagonals are
/// tight where the axes are loosest: on cloth-ball's step they cut the node pairs a
/// self-traversal visits by about a quarter, and its candidate triangle pairs as much.
///
/// Why the culling stays sound. A node pair is kept apart when its slabs along one
/// direction are apart at both ends of the step in one order: the argument of
/// bvh/step_boxes.hpp holds for any fixed direction (a point at fixed barycentric
/// coordinates projects affinely in t), and these bounds hold every corner's projection.
/// The projection p = fl(fl(x ± y) ± z) is within γ2·S of the exact one (S = |x| + |y| +
/// |z|); the bounds are computed from p - e and p + e, e = 2^-50·S, which stay on their
/// side of the exact projection after their own roundings (e exceeds 7.9 u·S, the error
/// of p plus that of the subtraction is below 3.1 u·S), then rounded outward to float as
/// the boxes are (batch_bounds.hpp: beyond the float range, clamped).

#include "tailor/bvh/batch_bounds.hpp"

namespace tailor {

/// Per direction k and lane i, at each end of the step: the same contract as
/// batch_bounds(), for the projections of the corners on d0, d1 and d2 in place of their
/// coordinates. Lanes 0 to padded_count() of a padded batch.
void diagonal_batch_bounds(const MovingTriangleBatch& batch, BatchBounds& start, BatchBounds& end);

}  // namespace tailor
