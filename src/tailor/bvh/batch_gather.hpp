#pragma once
/// @file
/// Filling a MovingTriangleBatch from vertex positions: the corners of up to kCapacity
/// triangles, transposed into the batch's structure-of-arrays rows.

#include <array>
#include <span>

#include "tailor/bvh/direction_mask.hpp"

namespace tailor {

/// Sets `batch` to the triangles `faces` (vertex ids; 1 to kCapacity of them) moving from
/// `x0` to `x1` (row-major, three doubles per vertex), padded as pad() pads: the result
/// is the batch that add() for each face and then pad() give, bit for bit.
void gather_batch(const double* x0, const double* x1, std::span<const std::array<Index, 3>> faces,
                  MovingTriangleBatch& batch);

/// Repeats lane 0 in the lanes from `count` up to a multiple of eight (the widest vector of
/// double lanes), for kernels that always run whole AVX-512 vectors.
void pad_to_eight_lanes(MovingTriangleBatch& batch);

namespace detail {
/// gather_batch one corner at a time (any processor) and four triangles at a time (AVX2:
/// call only when direction_mask_has_avx2()): a corner is one masked 4-double load
/// (the fourth lane is neither read nor used) and four corners are transposed in
/// registers, instead of three scalar loads and stores each. Exposed so that a test can
/// check they agree.
void gather_batch_one_by_one(const double* x0, const double* x1,
                             std::span<const std::array<Index, 3>> faces,
                             MovingTriangleBatch& batch);
void gather_batch_four_lanes(const double* x0, const double* x1,
                             std::span<const std::array<Index, 3>> faces,
                             MovingTriangleBatch& batch);
}  // namespace detail

}  // namespace tailor
