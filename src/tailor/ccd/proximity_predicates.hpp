#pragma once
/// @file
/// Exact proximity predicates at one instant: is a vertex within a distance h of a closed
/// triangle, or a closed segment within h of another? The basis of collisions with a
/// thickness (repulsion and barrier methods need every pair within h).
///
/// The distance between two closed convex primitives is attained on a pair of features
/// where the connecting vector is orthogonal to both, so "distance ≤ h" is the union over
/// feature pairs of polynomial conditions (no division, no square root):
/// - point p, segment ab (u = b - a, w = p - a): |w|² ≤ h² at a, |p - b|² ≤ h² at b, or
///   between them u ≠ 0, 0 ≤ w·u ≤ |u|² and |w|²|u|² - (w·u)² ≤ h²|u|²;
/// - point p, triangle abc (n = (b-a)×(c-a)): one of its three edges, or p projects into the
///   triangle (n·((b-a)×(p-a)), n·((c-b)×(p-b)), n·((a-c)×(p-c)) all ≥ 0, n ≠ 0) and
///   ((p-a)·n)² ≤ h²|n|²;
/// - segments ab, cd: each endpoint against the other segment, or, with u = b-a, v = d-c,
///   w = c-a, n = u×v ≠ 0, the lines' closest points inside both segments
///   (0 ≤ (w×v)·n ≤ |n|², 0 ≤ (w×u)·n ≤ |n|²) and (w·n)² ≤ h²|n|². Parallel segments meet
///   their distance at an endpoint, which the first conditions cover.
/// Most pairs are settled before these conditions, in double, by two certified tests
/// (ccd/separating_axes.hpp): the closest points within h with their rounding bounded
/// (yes), or every corner difference beyond h along their direction (no). The rest, near h,
/// have each condition decided in rigorous ball arithmetic (ccd/ball.hpp) and, when a ball
/// cannot decide a sign, the whole predicate evaluated again in GMP rationals: exact on the
/// input doubles, whatever the scale of h.

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Whether vertex `points[0]` is within distance `h` (≥ 0) of the closed triangle
/// (`points[1]`, `points[2]`, `points[3]`): distance ≤ h, exactly. A degenerate triangle is
/// the union of its edges. Throws std::invalid_argument on a non-finite input or h < 0.
bool vertex_face_within(const FourPoints& points, double h);

/// Whether the closed segments (`points[0]`, `points[1]`) and (`points[2]`, `points[3]`)
/// come within distance `h` (≥ 0) of each other: distance ≤ h, exactly. Throws
/// std::invalid_argument on a non-finite input or h < 0.
bool edge_edge_within(const FourPoints& points, double h);

}  // namespace tailor
