#pragma once
/// @file
/// The last stage: candidate VF/EE pairs through the exact CCD.

#include <cstdint>
#include <span>

#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/detection/collision.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Runs the exact CCD on every pair (parallel) and returns the colliding ones, sorted and
/// without duplicates, so the result does not depend on the order of the pairs or on
/// the thread count. `exact_fallbacks` receives how many queries the exact path decided.
CollisionSet test_pairs_exactly(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                                std::span<const VertexFacePair> vertex_face,
                                std::span<const EdgeEdgePair> edge_edge,
                                std::int64_t* exact_fallbacks = nullptr);

}  // namespace tailor
