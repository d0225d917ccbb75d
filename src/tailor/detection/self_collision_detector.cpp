#include "tailor/detection/self_collision_detector.hpp"

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <chrono>

#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/candidates/primitive_pair_generator.hpp"
#include "tailor/culling/bvh_traversal.hpp"
#include "tailor/candidates/isolated_set.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/culling/radial_view_culling.hpp"
#include "tailor/detection/exact_pair_tests.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

void check_positions(const TriangleMesh& mesh, const Positions& x, const char* name) {
  if (x.rows() != mesh.num_vertices()) {
    throw InputError(
        fmt::format("{} has {} vertices, the mesh has {}", name, x.rows(), mesh.num_vertices()));
  }
  if (!x.allFinite()) throw InputError(fmt::format("{} has a non-finite coordinate", name));
}

}  // namespace

struct SelfCollisionDetector::Impl {
  const TriangleMesh& mesh;
  DetectionConfig config;
  tbb::task_arena arena;
  // One BVH over the whole mesh; radial view culls the pairs its traversal produces.
  std::vector<MeshBvh> bvhs;
  std::vector<NodeContours> contours;
  RadialViewCulling radial;
  bool use_radial_view = false;
  IsolatedSet isolated;
  PrimitivePairGenerator generator;
  std::vector<TrianglePair> ctps;
  std::vector<VertexFacePair> vf_pairs;
  std::vector<EdgeEdgePair> ee_pairs;

  Impl(const TriangleMesh& mesh_, const Positions& x_build, DetectionConfig config_,
       std::vector<std::vector<Index>> section_loops)
      : mesh(mesh_),
        config(config_),
        arena(config_.threads > 0 ? config_.threads : tbb::task_arena::automatic) {
    check_positions(mesh, x_build, "the build frame");
    use_radial_view = config.radial_view && !section_loops.empty();
    arena.execute([&] {
      if (use_radial_view) radial = RadialViewCulling(mesh, x_build, std::move(section_loops));
      bvhs.emplace_back(mesh, x_build);
      contours.resize(bvhs.size());
      if (config.normal_cones && config.contour_test) {
        for (std::size_t c = 0; c < bvhs.size(); ++c) contours[c] = NodeContours(mesh, bvhs[c]);
      }
      if (config.adjacency_culling) isolated = IsolatedSet::build(mesh);
      generator = PrimitivePairGenerator(mesh);
    });
  }

  DetectionResult detect(const Positions& x0, const Positions& x1) {
    check_positions(mesh, x0, "x0");
    check_positions(mesh, x1, "x1");
    DetectionResult result;
    DetectionStats& stats = result.stats;
    arena.execute([&] {
      const auto start = Clock::now();
      for (MeshBvh& bvh : bvhs) bvh.refit(x0, x1, config.normal_cones);
      stats.refit_ms = elapsed_ms(start);

      auto stage = Clock::now();
      ctps.clear();
      TraversalCounts traversal;
      const TraversalOptions options{config.normal_cones, config.contour_test,
                                     config.adjacency_culling};
      for (std::size_t c = 0; c < bvhs.size(); ++c) {
        self_traversal(mesh, bvhs[c], contours[c], {x0, x1}, options, ctps, traversal);
      }
      if (use_radial_view) {
        const RadialViewCounts counts =
            radial.classify_and_cull(x0, x1, ctps, !config.adjacency_culling);
        stats.clusters_certified = counts.clusters_certified;
        stats.radial_positive = counts.triangles_positive;
        stats.radial_negative = counts.triangles_negative;
        stats.radial_undetermined = counts.triangles_undetermined;
      }
      stats.traversal_ms = elapsed_ms(stage);
      stats.node_pairs_visited = traversal.node_pairs_visited;
      stats.nodes_culled_by_cones = traversal.nodes_culled_by_cones;
      stats.contour_tests = traversal.contour_tests;
      stats.contour_tests_failed = traversal.contour_tests_failed;
      stats.candidate_triangle_pairs = static_cast<std::int64_t>(ctps.size());
      if (config.keep_candidate_pairs) result.candidate_triangle_pairs = ctps;
      stats.isolated_vf_pairs = static_cast<std::int64_t>(isolated.vertex_face.size());
      stats.isolated_ee_pairs = static_cast<std::int64_t>(isolated.edge_edge.size());

      stage = Clock::now();
      LowLevelCounts low;
      const LowLevelOptions low_options{config.feature_assignment, config.primitive_boxes,
                                        config.coplanarity_filter, config.adjacency_culling};
      generator.generate(ctps, isolated, x0, x1, low_options, vf_pairs, ee_pairs, low);
      stats.pair_generation_ms = elapsed_ms(stage);
      stats.vf_generated = low.vf_generated;
      stats.ee_generated = low.ee_generated;
      stats.vf_after_boxes = low.vf_after_boxes;
      stats.ee_after_boxes = low.ee_after_boxes;
      stats.vf_after_filter = low.vf_after_filter;
      stats.ee_after_filter = low.ee_after_filter;
      stats.vf_tested = static_cast<std::int64_t>(vf_pairs.size());
      stats.ee_tested = static_cast<std::int64_t>(ee_pairs.size());

      stage = Clock::now();
      result.collisions =
          test_pairs_exactly(mesh, x0, x1, vf_pairs, ee_pairs, &stats.ccd_exact_fallbacks);
      stats.ccd_ms = elapsed_ms(stage);
      stats.vf_colliding = static_cast<std::int64_t>(result.collisions.vertex_face.size());
      stats.ee_colliding = static_cast<std::int64_t>(result.collisions.edge_edge.size());
      stats.total_ms = elapsed_ms(start);
    });
    return result;
  }
};

SelfCollisionDetector::SelfCollisionDetector(const TriangleMesh& mesh, const Positions& x_build,
                                             DetectionConfig config,
                                             std::vector<std::vector<Index>> section_loops)
    : m_impl(std::make_unique<Impl>(mesh, x_build, config, std::move(section_loops))) {}
SelfCollisionDetector::~SelfCollisionDetector() = default;
SelfCollisionDetector::SelfCollisionDetector(SelfCollisionDetector&&) noexcept = default;
SelfCollisionDetector& SelfCollisionDetector::operator=(SelfCollisionDetector&&) noexcept = default;

DetectionResult SelfCollisionDetector::detect(const Positions& x0, const Positions& x1) {
  return m_impl->detect(x0, x1);
}
const DetectionConfig& SelfCollisionDetector::config() const {
  return m_impl->config;
}
const TriangleMesh& SelfCollisionDetector::mesh() const {
  return m_impl->mesh;
}

}  // namespace tailor
