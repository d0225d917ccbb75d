#pragma once
/// @file
/// Candidate pairs passed between the pipeline's stages.

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A candidate triangle pair (CTP), `first < second`.
struct TrianglePair {
  Index first = -1, second = -1;
};

/// A vertex-face candidate pair.
struct VertexFacePair {
  Index vertex = -1, face = -1;
};

/// An edge-edge candidate pair of edge ids, `edge_a < edge_b`.
struct EdgeEdgePair {
  Index edge_a = -1, edge_b = -1;
};

}  // namespace tailor
