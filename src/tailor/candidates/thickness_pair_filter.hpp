#pragma once
/// @file
/// The first test of a candidate pair of collisions with a thickness h > 0, over batches of
/// pairs in vector lanes: a vertex-face or edge-edge pair that its own normal, or the
/// direction from one primitive to the other, keeps more than h apart for the whole step is
/// dropped before the minimum-separation CCD
/// (ccd/thickness_ccd.hpp), whose scalar setup costs far more per pair.
///
/// Why it holds. Let d be a fixed direction. Each point of either primitive at fixed
/// barycentric coordinates moves linearly over the step, so its projection on d is affine in
/// t. If every corner of the second primitive projects beyond every corner of the first by
/// more than h |d| at t = 0 and again at t = 1, then for a point p of the first and q of the
/// second, d · (q(t) - p(t)) is affine in t and above h |d| at both ends, so above it on [0,
/// 1]: |q(t) - p(t)| > h at every t. The same in the other order. Any direction will do, so
/// d is whatever the arithmetic gives. Directions tried: the face's normal (vertex-face) or
/// the two edges' cross product (edge-edge), at t = 0 and at t = 1 — the directions along
/// which layered cloth is apart — and the sum over both ends and the three corners of the
/// second primitive's corners minus the first's (from one primitive's middle to the
/// other's: primitives side by side). On the funnel's thickness step the normals drop about
/// 70 % of the candidates not within h (cloth-ball: about half), and the third direction
/// 63 % of the rest (cloth-ball: 33 %).
///
/// Certified comparisons (as step_separating_direction.hpp, with a margin): each projection
/// is within E = 2^-50·|d|₁·M + 2^-1000 of the exact one (M: the largest |coordinate| of the
/// pair's corners), so a computed gap g between the two primitives' extents is within 2E of
/// the exact gap, up to one rounding. The pair is dropped when g > (4E + hd)(1 + 2^-45),
/// where hd = h · fl(√(d·d)) · (1 + 2^-46) bounds h |d| from above (the norm and the
/// products round a few times, each within 2^-53); then the exact gap exceeds h |d|. A lane
/// whose |d|₁·M exceeds 2^900, or whose corners hold an infinity or a NaN, is never dropped.

#include <vector>

#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Removes from `pairs` the vertex-face and edge-edge pairs of `mesh`, moving from `x0` to
/// `x1`, that their own normal, or the direction between them, keeps more than `h` (> 0)
/// apart for the whole step (the header's test); keeps the others in their order. Runs in parallel
/// over blocks of pairs; the result does not depend on the processor's vector width. Returns the
/// number removed.
std::size_t drop_pairs_kept_apart(const TriangleMesh& mesh, const Positions& x0,
                                  const Positions& x1, double h, FeaturePairs& pairs);

namespace detail {
/// drop_pairs_kept_apart with two lanes per vector (SSE2, any x86-64 processor); exposed so
/// that a test can check that every build agrees.
std::size_t drop_pairs_kept_apart_two_lanes(const TriangleMesh& mesh, const Positions& x0,
                                            const Positions& x1, double h, FeaturePairs& pairs);
}  // namespace detail

}  // namespace tailor
