#pragma once
/// @file
/// Float boxes of the moving triangles of a MovingTriangleBatch at the two ends of a step
/// (rounded outward), computed a vector of lanes at a time.

#include "tailor/bvh/direction_mask.hpp"

namespace tailor {

/// Per coordinate k and lane i of a batch, at one end of the step: low[k][i] <= every
/// corner's coordinate k in that frame <= high[k][i], each within 3 float ulps of the extreme.
/// Beyond the float range the bound is clamped to the largest float (then it no longer holds the
/// corner, but overlaps of clamped boxes are kept, which is all the traversal asks of them).
struct BatchBounds {
  /// Lower bounds: low[k][i] for coordinate k of lane i.
  alignas(16) float low[3][MovingTriangleBatch::kCapacity];
  /// Upper bounds: high[k][i] for coordinate k of lane i.
  alignas(16) float high[3][MovingTriangleBatch::kCapacity];
};

/// The bounds of lanes 0 to padded_count() of a padded batch (pad()): `start` of the
/// corners at t = 0, `end` of those at t = 1.
void batch_bounds(const MovingTriangleBatch& batch, BatchBounds& start, BatchBounds& end);

namespace detail {
/// batch_bounds two lanes at a time (SSE2) and four at a time (AVX2: call only when
/// direction_mask_has_avx2()); exposed so that a test can check they agree.
void batch_bounds_two_lanes(const MovingTriangleBatch& batch, BatchBounds& start, BatchBounds& end);
void batch_bounds_four_lanes(const MovingTriangleBatch& batch, BatchBounds& start,
                             BatchBounds& end);
/// Eight at a time (AVX-512 F and DQ: call only when direction_mask_has_avx512()).
void batch_bounds_eight_lanes(const MovingTriangleBatch& batch, BatchBounds& start,
                              BatchBounds& end);
}  // namespace detail

}  // namespace tailor
