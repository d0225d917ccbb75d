#pragma once
/// @file
/// Closest-point queries between a point and a triangle, and between two segments
/// (Ericson, Real-Time Collision Detection, 2005, §5.1.5 and §5.1.9). Floating point,
/// for contact response (normals, weights, distances) and for choosing a direction that a
/// certified test then checks (ccd/separating_axes), never for deciding collisions.

#include <utility>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Barycentric weights (w_a, w_b, w_c), non-negative and summing to 1, of the point of
/// triangle (a, b, c) closest to `p`. Inputs the region tests cannot classify (a
/// non-finite coordinate) give the centroid's weights.
Vec3 closest_point_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Parameters (s, u) in [0, 1]² of the closest points `p0 + s (p1 - p0)` and
/// `q0 + u (q1 - q0)` of two segments (the first pair found when they are parallel; a
/// segment of zero length counts as a point).
std::pair<double, double> closest_segment_parameters(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                                     const Vec3& q1);

}  // namespace tailor
