/// @file
/// step_ccd_queries(): the low-level stages of the detector, with coordinates out.

#include "tailor/detection/ccd_query_export.hpp"

#include "tailor/candidates/isolated_set.hpp"
#include "tailor/candidates/primitive_pair_generator.hpp"
#include "tailor/detection/stage_options.hpp"

namespace tailor {

StepCcdQueries step_ccd_queries(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                                const DetectionConfig& config,
                                const std::vector<TrianglePair>& ctps) {
  const LowLevelOptions options = low_level_options(config);
  PrimitivePairGenerator generator(mesh);
  generator.begin_step();
  if (config.adjacency_culling) generator.add_isolated(IsolatedSet::build(mesh), x0, x1, options);
  generator.add_triangle_pairs(ctps, x0, x1, options);

  StepCcdQueries queries;
  const FaceArray& faces = mesh.faces();
  const EdgeArray& edges = mesh.edges();
  for (const auto block : generator.vertex_face_blocks()) {
    for (const auto& [v, f] : block) {
      const Index a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
      queries.vertex_face.push_back(
          {x0.row(v), x0.row(a), x0.row(b), x0.row(c), x1.row(v), x1.row(a), x1.row(b), x1.row(c)});
    }
  }
  for (const auto block : generator.edge_edge_blocks()) {
    for (const auto& [e1, e2] : block) {
      const Index a = edges(e1, 0), b = edges(e1, 1), c = edges(e2, 0), d = edges(e2, 1);
      queries.edge_edge.push_back(
          {x0.row(a), x0.row(b), x0.row(c), x0.row(d), x1.row(a), x1.row(b), x1.row(c), x1.row(d)});
    }
  }
  return queries;
}

}  // namespace tailor
