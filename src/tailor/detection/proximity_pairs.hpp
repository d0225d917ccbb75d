#pragma once
/// @file
/// Proximity at one instant: every vertex-face and edge-edge pair of a mesh closer than a
/// thickness in one configuration, for repulsion and barrier methods (a one-off function,
/// and brute force for tests).

#include <vector>

#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/detection/feature_box_pairs.hpp"
#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// The pairs of a mesh within a distance of each other at one instant: vertex_face sorted
/// by (vertex, face), edge_edge by (edge_a, edge_b), edge_a < edge_b.
using ProximityPairs = FeaturePairs;

/// Every vertex-face pair (a face not holding the vertex) and edge-edge pair (two edges
/// without a common end) of `mesh` whose distance in configuration `x` is at most
/// `thickness`, exactly (ccd/proximity_predicates.hpp). Culling: BVHs over the boxes of the
/// vertices, edges and faces, each grown by thickness / 2 and rounded outwards. It keeps
/// every pair within the thickness: the gap between two boxes along an axis is at most the
/// distance between any point of one and any point of the other, so two primitives within
/// h have boxes within h of each other on every axis, and grown by h / 2 each they overlap.
/// The exact tests run in parallel. Throws InputError when `x` does not hold one finite row
/// per vertex or `thickness` is negative or not finite.
ProximityPairs proximity_pairs(const TriangleMesh& mesh, const Positions& x, double thickness);

/// proximity_pairs for repeated calls on one mesh (a simulator's every step): the culling
/// trees are built on the first call and refitted on later ones (StepFeatureBoxTrees over
/// the boxes at the one instant); the pairs are those of proximity_pairs.
class ProximitySearch {
 public:
  /// A search over `mesh`, which must outlive it.
  explicit ProximitySearch(const TriangleMesh& mesh) : m_mesh(&mesh) {}

  /// The pairs of proximity_pairs(mesh, x, thickness), with the same checks.
  ProximityPairs pairs(const Positions& x, double thickness);

 private:
  const TriangleMesh* m_mesh;
  StepFeatureBoxTrees m_trees;
};

/// The same pairs from the exact test of every vertex-face and edge-edge pair (quadratic;
/// the oracle of the tests).
ProximityPairs proximity_pairs_brute_force(const TriangleMesh& mesh, const Positions& x,
                                           double thickness);

}  // namespace tailor
