#pragma once
/// @file
/// The oracle: every feature pair through the exact CCD.

#include "tailor/detection/collision.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Every collision of the step by brute force: each vertex (used by some face) against
/// each face not incident to it, and each pair of edges without a common vertex, through
/// the exact CCD. The only pruning is a closed swept-box overlap test, which is exact
/// (a primitive moving linearly stays inside the box of its endpoints at t=0 and t=1),
/// applied by sorting boxes along x. Parallel; usable up to ~20K triangles. With a
/// `thickness` h > 0, the pairs that come within h (ccd/thickness_ccd.hpp), the boxes grown
/// by h / 2 each and rounded outwards (two primitives within h have boxes within h on every
/// axis).
CollisionSet brute_force_self_collisions(const TriangleMesh& mesh, const Positions& x0,
                                         const Positions& x1, double thickness = 0);

}  // namespace tailor
