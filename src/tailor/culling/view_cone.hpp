#pragma once
/// @file
/// The view cone of a moving triangle seen from a moving observer over one step: a
/// circular cone around the observer that holds every direction from the observer to a
/// point of the triangle at any time of the step (radial-view culling, Wong et al. 2013).
///
/// Why it holds. Vertices and observer move linearly, so a point of the triangle at time
/// t, minus the observer, is x(t) - o(t) = Σ λ_k ((1-t)(v_k0 - o0) + t (v_k1 - o1)) with
/// barycentric λ_k ≥ 0: a nonnegative combination of the six vectors d_ke = v_ke - o_e.
/// A circular cone of half-angle under 90° is convex, so if it holds the six vectors it
/// holds every such combination.
///
/// Rounding. d_ke is one correctly rounded subtraction per component (relative error ≤ u
/// = 2^-53, no cancellation issue since v and o are the given doubles), which turns its
/// direction by at most √3·u. The cosines to the axis are evaluated with an absolute error
/// of a few u; the stored cosine of the half-angle is the smallest of them minus 2^-40,
/// so it is a certified lower bound, and the stored sine is rounded up by a relative
/// 2^-40. The disjointness test compares cosines with the same 2^-40 slack on each side,
/// so rounding can only make it answer "may overlap".

#include <array>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A circular cone of directions around an axis, or every direction (`everything`).
struct ViewCone {
  Vec3 axis = Vec3::UnitX();  ///< unit axis (as rounded; the bounds are relative to it)
  double cos_half = -1;       ///< lower bound on the cosine of the half-angle (> 0)
  double sin_half = 1;        ///< upper bound on the sine of the half-angle
  bool everything = true;     ///< no cone under 90° was found: every direction
};

/// The view cone of a triangle whose corners move from `triangle_t0` to `triangle_t1`, seen
/// from an observer moving from `observer_t0` to `observer_t1`. Every direction when a
/// vertex can meet the observer, the cone would reach 90° or an input is not finite.
ViewCone swept_view_cone(const std::array<Vec3, 3>& triangle_t0,
                         const std::array<Vec3, 3>& triangle_t1, const Vec3& observer_t0,
                         const Vec3& observer_t1);

/// The view cone holding six unit directions (as rounded from the observer to the three
/// vertices at t = 0 and t = 1, each vector divided by its norm): same rules as above.
ViewCone view_cone_of_directions(const Vec3 (&unit)[6]);

/// Unit direction from `observer` to `point`, or false when it cannot be trusted (the
/// points (nearly) coincide, or the difference is not finite).
bool unit_direction(const Vec3& observer, const Vec3& point, Vec3& unit);

/// A cone holding every cone of `cones` (`count` of them): its axis is the normalised sum
/// of theirs, and its half-angle bounds the angle β from that axis to each member's axis
/// plus the member's half-angle α (triangle inequality on the sphere), in cosines:
/// cos(β + α) ≥ cos β cos α - sin β sin α evaluated with lower bounds of the cosines
/// and upper bounds of the sines, each widened by the 2^-40 slack. Every direction when
/// a member is, or when the bound reaches 90°.
ViewCone bounding_view_cone(const ViewCone* cones, int count);

/// True only when no direction lies in both cones (certified: see the file comment).
bool view_cones_disjoint(const ViewCone& p, const ViewCone& q);

}  // namespace tailor
