#pragma once
/// @file
/// The largest fraction of a step that keeps a mesh at least a thickness apart (as
/// ipc-toolkit's compute_collision_free_stepsize): the line search of a simulator that must
/// never let cloth come closer than its thickness.

#include <optional>

#include "tailor/detection/collision.hpp"
#include "tailor/detection/detection_config.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// What collision_free_step found.
struct CollisionFreeStep {
  /// The fraction α in [0, 1] of the step: on [0, α) every pair sharing no vertex stays
  /// farther apart than the thickness (with thickness 0: never touches). A certified lower
  /// bound of the largest such fraction (1 when nothing comes that close): within 1e-6 of it
  /// at thickness 0; above 0, within 1e-6 of a time at which the limiting pair is within
  /// (1 + 1e-6) times the thickness (ccd/thickness_ccd.hpp: a pair that grazes the
  /// thickness can get a fraction more than 1e-6 short).
  double alpha = 1.0;
  /// The vertex-face pair that limits α, when one does (its toi is α).
  std::optional<VertexFaceCollision> vertex_face;
  /// The edge-edge pair that limits α, when no vertex-face pair does at the same time.
  std::optional<EdgeEdgeCollision> edge_edge;
};

/// The earliest time of impact among `collisions` and the pair that has it (a vertex-face
/// pair before an edge-edge pair at the same time); α = 1 and no pair when there are none.
CollisionFreeStep first_contact(const CollisionSet& collisions);

/// The largest fraction of the linear step from `x0` to `x1` that keeps every vertex-face
/// and edge-edge pair of `mesh` (sharing no vertex) more than `thickness` apart, and the
/// pair that limits it: the earliest time of impact of detect_self_collisions with
/// `config.thickness = thickness` (0 is the exact CCD; above 0, ccd/thickness_ccd.hpp). Each
/// time of impact is a lower bound of the true one, so α is too. Throws InputError on
/// positions that do not match the mesh or are not finite, and on a negative or infinite
/// thickness.
CollisionFreeStep collision_free_step(const TriangleMesh& mesh, const Positions& x0,
                                      const Positions& x1, double thickness,
                                      DetectionConfig config = {});

}  // namespace tailor
