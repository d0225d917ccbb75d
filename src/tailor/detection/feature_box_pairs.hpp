#pragma once
/// @file
/// Candidate pairs from vertex boxes: the vertex-face and edge-edge pairs whose boxes
/// overlap, through BVHs (the culling of proximity_pairs and of collisions with a
/// thickness).

#include <vector>

#include "tailor/bvh/aabb.hpp"
#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Every vertex-face pair (a face not holding the vertex) and edge-edge pair (edges without
/// a common end, edge_a < edge_b) of `mesh` whose boxes overlap (closed boxes), the box of
/// an edge or a face being the union of its vertices' boxes `vertex_boxes` (one per
/// vertex). Unordered.
FeaturePairs overlapping_feature_pairs(const TriangleMesh& mesh,
                                       const std::vector<Aabb>& vertex_boxes);

/// Whether face `f` of `mesh` holds vertex `v`.
bool face_holds(const TriangleMesh& mesh, Index f, Index v);

/// Whether edges `e` and `g` of `mesh` share an end.
bool edges_share_an_end(const TriangleMesh& mesh, Index e, Index g);

}  // namespace tailor
