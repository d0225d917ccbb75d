#pragma once
/// @file
/// The separating-direction filter of a candidate triangle pair: two triangles that one
/// fixed direction keeps apart at both ends of the step, in the same order, never touch
/// during it. It runs after the plane-side filter (triangle_plane_sides.hpp), on the pairs
/// that filter keeps, and drops a pair whole.
///
/// Why it holds. A point of a triangle at fixed barycentric coordinates moves linearly over
/// the step, so its projection on a fixed direction d is affine in t (the argument of
/// bvh/step_boxes.hpp, there for the three coordinate axes). If every corner of B projects
/// beyond every corner of A at t = 0 and again at t = 1 (min over B of d·x > max over A of
/// d·x at both ends), then for a point p of A and a point q of B, d·(q(t) - p(t)) is an
/// affine function of t that is positive at both ends: positive on [0, 1], so q(t) ≠ p(t).
/// No point of A ever meets a point of B, and no vertex-face or edge-edge pair of the two
/// triangles can collide. Any direction will do, so d is whatever the arithmetic gives: it
/// need not be exact, only the comparisons must be.
///
/// Directions tried: the nine cross products of an edge of A with an edge of B at t = 1 (the
/// axes of the static separating-axis test of two triangles beyond their normals, which the
/// plane filter has tried already as moving planes). On cloth-ball's step they drop 296,875
/// of the 705,033 CTPs the planes keep, on the pleated 100K 525,857 of 1,453,111; the same
/// crosses at t = 0 would add 61 K and 2 K for as much time as they save.
///
/// Certified comparisons. Each projection p = fl(d·x) of an input corner x (three products,
/// two sums, in any order, with or without fused multiply-adds) is within
/// γ3·|d|₁·M + 2^-1072 of d·x (M: the largest |coordinate| of the pair's twelve corner
/// positions; the second term covers underflow), below E = 2^-50·|d|₁·M + 2^-1000 even after
/// the roundings of |d|₁·M itself. A pair is apart along d when the computed gap
/// fl(min_B - max_A) exceeds 4E at both ends (the true gap is then above 4E/(1 + u) - 2E > 0);
/// a lane whose |d|₁·M exceeds 2^900 (no product can overflow below that) or whose corners
/// hold an infinity or a NaN (then M is one) is never certified.

#include <span>

#include "tailor/candidates/triangle_plane_sides.hpp"

namespace tailor {

/// Sets `sides[i].apart` for each pair of `pairs` (faces of `faces`, vertices moving from
/// `x0` to `x1`) that `sides[i]` does not already separate and that a fixed direction keeps
/// apart over the whole step (the header's test); clears it for the others. Sequential
/// (call it from parallel tasks on parts of a list); the result does not depend on the
/// processor's vector width.
void mark_pairs_apart(const FaceArray& faces, const Positions& x0, const Positions& x1,
                      std::span<const TrianglePair> pairs, std::span<TrianglePairSides> sides);

namespace detail {
/// mark_pairs_apart with two lanes per vector (SSE2, any x86-64 processor); exposed so that
/// a test can check that every build agrees.
void mark_pairs_apart_two_lanes(const FaceArray& faces, const Positions& x0, const Positions& x1,
                                std::span<const TrianglePair> pairs,
                                std::span<TrianglePairSides> sides);
}  // namespace detail

}  // namespace tailor
