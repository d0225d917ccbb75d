#pragma once
/// @file
/// The winding number of a closed oriented triangle surface around a point, exactly.

#include <array>
#include <optional>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A triangle given by its three corner positions, in the surface's orientation.
using TriangleCorners = std::array<Vec3, 3>;

/// Winding number of the closed surface `triangles` around `point`: the signed number of
/// times a ray from `point` crosses it, a crossing counting +1 when `point` lies behind
/// the triangle (on the side opposite to its right-hand normal). For a closed surface
/// (every edge used once in each direction) this does not depend on the ray, and it is
/// +1 for an outward-oriented sphere around the point.
///
/// Exact: the segment from `point` to a far point outside the surface's bounding box is
/// tested against every triangle with orient3d only. A segment through an edge, a vertex
/// or lying in a triangle's plane is retried with another far point; std::nullopt when
/// `point` lies on a triangle, when every retry was degenerate, or for an empty surface.
std::optional<int> winding_number(const std::vector<TriangleCorners>& triangles, const Vec3& point);

}  // namespace tailor
