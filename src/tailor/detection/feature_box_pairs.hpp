#pragma once
/// @file
/// Candidate pairs from vertex boxes: the vertex-face and edge-edge pairs whose boxes
/// overlap, through BVHs (the culling of proximity_pairs and of collisions with a
/// thickness).

#include <vector>

#include "tailor/bvh/aabb.hpp"
#include "tailor/bvh/bvh.hpp"
#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// The three trees (vertices, edges, faces) of overlapping_feature_pairs, kept for repeated
/// searches on one mesh: built on the first update, refitted on later ones. A refitted tree
/// finds the same pairs as a new one (every node's box is recomputed from its leaves); it
/// only gets slower when the mesh has moved far from the configuration it was built on.
/// `Box` is StepBox (StepFeatureBoxTrees: boxes at both ends of a step, whose pairs are
/// those that may meet; one instant is the same box at both ends).
template <class Box>
class BasicFeatureBoxTrees {
 public:
  /// Sets the box of every vertex of `mesh` (one per vertex); an edge's or a face's box is
  /// the union of its vertices' boxes. `mesh` must be the one of earlier updates.
  void update(const TriangleMesh& mesh, const std::vector<Box>& vertex_boxes);

  /// Every vertex-face pair (a face not holding the vertex) and edge-edge pair (edges
  /// without a common end, edge_a < edge_b) whose boxes overlap (closed boxes); the trees
  /// are walked in parallel. Unordered.
  FeaturePairs overlapping_pairs(const TriangleMesh& mesh) const;
  /// The same pairs, left in the parts the walk's threads collected (no joined copy: half
  /// the memory on a contact-heavy step).
  std::vector<FeaturePairs> overlapping_pair_parts(const TriangleMesh& mesh) const;

 private:
  BasicBvh<Box> m_vertices, m_edges, m_faces;
};

/// Trees over boxes at both ends of a step.
using StepFeatureBoxTrees = BasicFeatureBoxTrees<StepBox>;

/// Whether face `f` of `mesh` holds vertex `v`.
bool face_holds(const TriangleMesh& mesh, Index f, Index v);

/// Whether edges `e` and `g` of `mesh` share an end.
bool edges_share_an_end(const TriangleMesh& mesh, Index e, Index g);

}  // namespace tailor
