#pragma once
/// @file
/// Where each stage's own counts go in DetectionStats: the one place that turns the count
/// structs of the culling and candidate stages into a step's statistics (the detector calls
/// record_counts() once per stage and step).

#include "tailor/candidates/isolated_set.hpp"
#include "tailor/candidates/primitive_pair_generator.hpp"
#include "tailor/culling/bvh_traversal.hpp"
#include "tailor/culling/radial_view_culling.hpp"
#include "tailor/detection/collision.hpp"
#include "tailor/detection/detection_stats.hpp"

namespace tailor {

/// The traversal's node pairs, cone culls and contour tests, and the CTPs it emitted.
void record_counts(DetectionStats& stats, const TraversalCounts& counts,
                   std::int64_t candidate_triangle_pairs);
/// Radial view's classified clusters and triangles (the pairs it culled are counted where
/// they are removed).
void record_counts(DetectionStats& stats, const RadialViewCounts& counts);
/// The isolated set's VF and EE pairs.
void record_counts(DetectionStats& stats, const IsolatedSet& isolated);
/// The VF and EE pairs after each low-level stage; the last survivors are what the exact
/// CCD tested.
void record_counts(DetectionStats& stats, const LowLevelCounts& counts);
/// The collisions found.
void record_counts(DetectionStats& stats, const CollisionSet& collisions);

}  // namespace tailor
