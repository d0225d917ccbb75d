#pragma once
/// @file
/// The exact-CCD queries of one detection step, as coordinates: what the detector sends to
/// the exact CCD, for benchmarks (bench_ccd) and query files (`tailor detect --dump-queries`).

#include <vector>

#include "tailor/ccd/ccd.hpp"
#include "tailor/culling/triangle_pair.hpp"
#include "tailor/detection/detection_config.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// The VF and EE queries of one step.
struct StepCcdQueries {
  /// The vertex-face queries.
  std::vector<VertexFaceQuery> vertex_face;
  /// The edge-edge queries.
  std::vector<EdgeEdgeQuery> edge_edge;
};

/// Regenerates the queries that a detector with `config` sends to the exact CCD from its
/// candidate triangle pairs `ctps` (DetectionResult::candidate_triangle_pairs with
/// `keep_candidate_pairs`) and, with adjacency culling, the mesh's isolated set: the same
/// low-level stages, so the same set of queries (in a thread-dependent order).
StepCcdQueries step_ccd_queries(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                                const DetectionConfig& config,
                                const std::vector<TrianglePair>& ctps);

}  // namespace tailor
