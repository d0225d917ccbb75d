#pragma once
/// @file
/// Candidate primitive pairs: the output of low-level culling and the input of the exact CCD.

#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A vertex-face candidate pair.
struct VertexFacePair {
  ///@{
  /// Vertex id and face id (-1 when unset).
  Index vertex = -1, face = -1;
  ///@}
};

/// An edge-edge candidate pair of edge ids, `edge_a < edge_b`.
struct EdgeEdgePair {
  ///@{
  /// Edge ids (-1 when unset).
  Index edge_a = -1, edge_b = -1;
  ///@}
};

/// Vertex-face and edge-edge pairs of one mesh.
struct FeaturePairs {
  std::vector<VertexFacePair> vertex_face;  ///< vertex-face pairs
  std::vector<EdgeEdgePair> edge_edge;      ///< edge-edge pairs
};

}  // namespace tailor
