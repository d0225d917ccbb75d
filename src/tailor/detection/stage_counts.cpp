#include "tailor/detection/stage_counts.hpp"

namespace tailor {

void record_counts(DetectionStats& stats, const TraversalCounts& counts,
                   std::int64_t candidate_triangle_pairs) {
  stats.node_pairs_visited = counts.node_pairs_visited;
  stats.leaf_buckets = counts.leaf_buckets;
  stats.nodes_culled_by_cones = counts.nodes_culled_by_cones;
  stats.contour_tests = counts.contour_tests;
  stats.contour_tests_failed = counts.contour_tests_failed;
  stats.candidate_triangle_pairs = candidate_triangle_pairs;
}

void record_counts(DetectionStats& stats, const RadialViewCounts& counts) {
  stats.clusters_classified = counts.clusters_classified;
  stats.clusters_certified = counts.clusters_certified;
  stats.radial_positive = counts.triangles_positive;
  stats.radial_negative = counts.triangles_negative;
  stats.radial_undetermined = counts.triangles_undetermined;
}

void record_counts(DetectionStats& stats, const IsolatedSet& isolated) {
  stats.isolated_vf_pairs = static_cast<std::int64_t>(isolated.vertex_face.size());
  stats.isolated_ee_pairs = static_cast<std::int64_t>(isolated.edge_edge.size());
}

void record_counts(DetectionStats& stats, const LowLevelCounts& counts) {
  stats.triangle_pairs_separated = counts.triangle_pairs_separated;
  stats.triangle_pairs_apart = counts.triangle_pairs_apart;
  stats.vf_generated = counts.vf_generated;
  stats.ee_generated = counts.ee_generated;
  stats.vf_after_boxes = counts.vf_after_boxes;
  stats.ee_after_boxes = counts.ee_after_boxes;
  stats.vf_after_filter = counts.vf_after_filter;
  stats.ee_after_filter = counts.ee_after_filter;
  stats.vf_after_projection = counts.vf_after_projection;
  stats.ee_after_projection = counts.ee_after_projection;
  stats.vf_tested = counts.vf_after_projection;
  stats.ee_tested = counts.ee_after_projection;
}

void record_counts(DetectionStats& stats, const CollisionSet& collisions) {
  stats.vf_colliding = static_cast<std::int64_t>(collisions.vertex_face.size());
  stats.ee_colliding = static_cast<std::int64_t>(collisions.edge_edge.size());
}

}  // namespace tailor
