#pragma once
/// @file
/// The contour test of normal-cone culling (Volino & Magnenat-Thalmann 1994; Provot 1997;
/// continuous form of Tang et al. 2009): does a boundary loop, projected along an axis,
/// stay a simple closed curve during the whole step?

#include <span>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// True only when the loop `loop` (vertex ids, cyclic), with vertices moving linearly
/// from `x0` to `x1` and projected along `axis` (any nonzero length), is certainly a simple closed
/// polygon at every t in [0, 1]. Conservative: any doubt (touching edges, a zero-length projected
/// edge, a sign the certified error bound cannot settle) answers false.
bool contour_stays_simple(std::span<const Index> loop, const Positions& x0, const Positions& x1,
                          const Vec3& axis);

}  // namespace tailor
