#pragma once
/// @file
/// Finding a non-finite coordinate among many positions, at memory speed.

#include <optional>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// The first vertex (lowest row) of `x` with a NaN or infinite coordinate, or nothing when
/// every coordinate is finite. Parallel (in the calling task arena), one pass over the
/// coordinates at about the speed of reading them, then a scan of the block that holds
/// the first bad row.
std::optional<Index> first_non_finite_vertex(const Positions& x);

}  // namespace tailor
