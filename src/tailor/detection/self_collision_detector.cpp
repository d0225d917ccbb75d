#include "tailor/detection/self_collision_detector.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>

#include "tailor/bvh/aabb.hpp"
#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/candidates/isolated_set.hpp"
#include "tailor/candidates/primitive_pair_generator.hpp"
#include "tailor/candidates/thickness_pair_filter.hpp"
#include "tailor/culling/bvh_traversal.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/culling/radial_view_culling.hpp"
#include "tailor/detection/exact_pair_tests.hpp"
#include "tailor/detection/feature_box_pairs.hpp"
#include "tailor/detection/stage_counts.hpp"
#include "tailor/detection/stage_options.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/finite_positions.hpp"
#include "tailor/geometry/stopwatch.hpp"

namespace tailor {
namespace {

void check_positions(const TriangleMesh& mesh, const Positions& x, const char* name) {
  if (x.rows() != mesh.num_vertices()) {
    throw InputError(
        fmt::format("{} has {} vertices, the mesh has {}", name, x.rows(), mesh.num_vertices()));
  }
  if (const std::optional<Index> vertex = first_non_finite_vertex(x)) {
    throw InputError(fmt::format("{} has a non-finite coordinate at vertex {}", name, *vertex));
  }
}

/// The config, if its thickness is one the detector can use.
const DetectionConfig& checked(const DetectionConfig& config) {
  if (!(config.thickness >= 0) || !std::isfinite(config.thickness)) {
    throw InputError(
        fmt::format("detection: the thickness must be finite and >= 0, got {}", config.thickness));
  }
  return config;
}

}  // namespace

struct SelfCollisionDetector::Impl {
  // Candidate triangle pairs per round of low-level culling and exact CCD: bounds the
  // memory of the VF/EE pairs of a round (at most 15 per CTP) whatever the preset.
  static constexpr std::size_t kRoundTrianglePairs = std::size_t{1} << 17;

  const TriangleMesh& mesh;
  DetectionConfig config;
  tbb::task_arena arena;
  // One BVH over the whole mesh; radial view culls the pairs its traversal produces.
  MeshBvh bvh;
  NodeContours contours;
  RadialViewCulling radial;
  bool use_radial_view = false;
  IsolatedSet isolated;
  // Per-thread buffers reused from step to step.
  CandidateTraversal traversal;
  // This step's root was certified by its cone and contour: no two features of the mesh
  // can touch (CandidateTraversal::self), so the isolated set is not tested either.
  bool root_certified = false;
  PrimitivePairGenerator generator;
  ExactPairTester tester;
  // Collisions with a thickness: the trees over grown boxes at both ends of the step,
  // refitted each step.
  StepFeatureBoxTrees thickness_trees;

  Impl(const TriangleMesh& mesh_, const Positions& x_build, DetectionConfig config_,
       std::vector<std::vector<Index>> section_loops)
      : mesh(mesh_),
        config(checked(config_)),
        arena(config_.threads > 0 ? config_.threads : tbb::task_arena::automatic),
        traversal(mesh_) {
    use_radial_view = config.radial_view && !section_loops.empty();
    arena.execute([&] {
      check_positions(mesh, x_build, "the build frame");
      tester.set_thickness(config.thickness,
                           config.thickness_filter ? NormalTest::skip : NormalTest::run);
      if (config.thickness > 0) {
        // The trees of within_thickness(), built here on the build frame as the BVH is for
        // h = 0; each step refits them.
        thickness_trees.update(mesh, grown_vertex_boxes(x_build, x_build));
        return;
      }
      if (use_radial_view) radial = RadialViewCulling(mesh, x_build, std::move(section_loops));
      // The isolated set needs only the topology: it is built beside the tree and its
      // contours (the contours' recursion is sequential).
      tbb::parallel_invoke(
          [&] {
            bvh = MeshBvh(mesh, x_build);
            if (config.normal_cones && config.contour_test) contours = NodeContours(mesh, bvh);
          },
          [&] {
            if (config.adjacency_culling) isolated = IsolatedSet::build(mesh);
            generator = PrimitivePairGenerator(mesh);
          });
    });
  }

  // The refit and the traversal. After a step whose root was certified the masks come
  // first (temporal coherence: a cloth that stays free of folds keeps its root certified),
  // and when they and the contour certify the root again no box is read this step, so
  // none is refitted. Otherwise, or when the root fails, the boxes are refitted before the
  // traversal reads them (MeshBvh::boxes_current()): the guess changes the work, never the
  // pairs.
  void refit_and_traverse(const Positions& x0, const Positions& x1, DetectionStats& stats) {
    auto stage = SteadyClock::now();
    if (root_certified && config.normal_cones && config.contour_test) {
      bvh.refit_directions(x0, x1);
      stats.refit_ms = milliseconds_since(stage);
      stage = SteadyClock::now();
      traversal.clear();
      const bool certified =
          traversal.certify_root(bvh, contours, {x0, x1}, traversal_options(config));
      stats.traversal_ms = milliseconds_since(stage);
      if (certified) return;
      stage = SteadyClock::now();
      bvh.refit(x0, x1, false, config.diagonal_bounds);  // the masks are this step's
    } else {
      bvh.refit(x0, x1, config.normal_cones, config.diagonal_bounds);
    }
    stats.boxes_refitted = 1;
    stats.refit_ms += milliseconds_since(stage);
    stage = SteadyClock::now();
    traversal.clear();
    root_certified = traversal.self(bvh, contours, {x0, x1}, traversal_options(config));
    stats.traversal_ms += milliseconds_since(stage);
  }

  // Radial view only removes candidates: with none, it has nothing to do. Lazily: rule (5)
  // first, then only the clusters that can still cull a kept pair are classified.
  void radial_view_cull(const Positions& x0, const Positions& x1, DetectionStats& stats) {
    if (!use_radial_view || traversal.size() == 0) return;
    // Clean faces matter only where candidates may share a vertex (radial_view_culling.hpp).
    radial.begin_step(x0, x1, !config.adjacency_culling);
    stats.radial_pairs_culled = traversal.remove_if(
        [&](const TrianglePair& p) { return radial.edge_planes_separate(p.first, p.second); });
    const RadialViewCounts counts = radial.classify_wanted(config.classify_every_cluster);
    if (counts.clusters_used > 0) {
      stats.radial_pairs_culled += traversal.remove_if(
          [&](const TrianglePair& p) { return radial.classified_clean(p.first, p.second); });
    }
    record_counts(stats, counts);
  }

  void record_high_level(DetectionStats& stats) {
    record_counts(stats, traversal.counts(), traversal.size());
    record_counts(stats, isolated);
  }

  // One round: the pairs the generator holds through the exact CCD.
  void test_round(const Positions& x0, const Positions& x1, DetectionStats& stats) {
    const auto start = SteadyClock::now();
    tester.test(mesh, x0, x1, generator.vertex_face_blocks(), generator.edge_edge_blocks());
    stats.ccd_ms += milliseconds_since(start);
  }

  // Low-level culling and exact CCD, in rounds of at most kRoundTrianglePairs CTPs.
  void low_level_and_ccd(const Positions& x0, const Positions& x1, DetectionStats& stats) {
    const LowLevelOptions options = low_level_options(config);
    generator.begin_step();
    tester.begin_step();
    auto start = SteadyClock::now();
    if (!root_certified) generator.add_isolated(isolated, x0, x1, options);
    stats.pair_generation_ms += milliseconds_since(start);
    test_round(x0, x1, stats);
    traversal.consume([&](std::span<const TrianglePair> block) {
      for (std::size_t first = 0; first < block.size(); first += kRoundTrianglePairs) {
        start = SteadyClock::now();
        generator.clear_pairs();
        generator.add_triangle_pairs(
            block.subspan(first, std::min(kRoundTrianglePairs, block.size() - first)), x0, x1,
            options);
        stats.pair_generation_ms += milliseconds_since(start);
        test_round(x0, x1, stats);
      }
    });
    record_counts(stats, generator.counts());
    stats.ccd_exact_fallbacks = tester.exact_fallbacks();
  }

  // Each vertex's boxes at the step's start `x0` and end `x1`, grown by h / 2 (rounded
  // outwards).
  std::vector<StepBox> grown_vertex_boxes(const Positions& x0, const Positions& x1) const {
    std::vector<StepBox> boxes(static_cast<std::size_t>(mesh.num_vertices()));
    const double half = 0.5 * config.thickness;
    const auto at = [half](const Positions& x, Index v) {
      Aabb point;
      point.extend(x.row(v).transpose());
      return grown_outwards(point, half);
    };
    tbb::parallel_for(tbb::blocked_range<Index>(0, mesh.num_vertices(), 4096),
                      [&](const tbb::blocked_range<Index>& range) {
                        for (Index v = range.begin(); v != range.end(); ++v) {
                          boxes[static_cast<std::size_t>(v)] =
                              StepBox::holding(at(x0, v), at(x1, v));
                        }
                      });
    return boxes;
  }

  // Collisions with a thickness h > 0: each vertex's boxes at both ends of the step grown
  // by h / 2, the vertex-face and edge-edge pairs that may meet (two primitives kept more
  // than h apart along one axis at both ends, in one order, stay more than h apart for the
  // whole step: bvh/step_boxes.hpp), the pairs their own normal keeps more than h apart
  // dropped (candidates/thickness_pair_filter.hpp), and the minimum-separation CCD. The other
  // stages are off: their arguments hold for touching only (docs/thickness.md).
  CollisionSet within_thickness(const Positions& x0, const Positions& x1, DetectionStats& stats) {
    const auto refit = SteadyClock::now();
    thickness_trees.update(mesh, grown_vertex_boxes(x0, x1));
    stats.refit_ms = milliseconds_since(refit);
    const auto stage = SteadyClock::now();
    std::vector<FeaturePairs> parts = thickness_trees.overlapping_pair_parts(mesh);
    stats.traversal_ms = milliseconds_since(stage);
    // The walk's pairs count as those after the boxes; the normal filter's survivors as
    // those after the filter (candidates/thickness_pair_filter.hpp).
    const auto filter = SteadyClock::now();
    std::vector<std::span<const VertexFacePair>> vertex_face;
    std::vector<std::span<const EdgeEdgePair>> edge_edge;
    for (FeaturePairs& part : parts) {
      stats.vf_after_boxes += static_cast<std::int64_t>(part.vertex_face.size());
      stats.ee_after_boxes += static_cast<std::int64_t>(part.edge_edge.size());
      if (config.thickness_filter) {
        drop_pairs_kept_apart(mesh, x0, x1, config.thickness, part);
      }
      vertex_face.emplace_back(part.vertex_face);
      edge_edge.emplace_back(part.edge_edge);
      stats.vf_tested += static_cast<std::int64_t>(part.vertex_face.size());
      stats.ee_tested += static_cast<std::int64_t>(part.edge_edge.size());
    }
    stats.vf_generated = stats.vf_after_boxes, stats.ee_generated = stats.ee_after_boxes;
    stats.vf_after_filter = stats.vf_after_projection = stats.vf_tested;
    stats.ee_after_filter = stats.ee_after_projection = stats.ee_tested;
    stats.pair_generation_ms = milliseconds_since(filter);
    const auto ccd = SteadyClock::now();
    tester.begin_step();
    tester.test(mesh, x0, x1, vertex_face, edge_edge);
    CollisionSet collisions = tester.take_collisions(mesh);
    stats.ccd_ms = milliseconds_since(ccd);
    record_counts(stats, collisions);
    return collisions;
  }

  DetectionResult detect(const Positions& x0, const Positions& x1) {
    DetectionResult result;
    DetectionStats& stats = result.stats;
    arena.execute([&] {
      // The step's total includes reading every coordinate once for this check.
      const auto start = SteadyClock::now();
      check_positions(mesh, x0, "x0");
      check_positions(mesh, x1, "x1");
      if (config.thickness > 0) {
        result.collisions = within_thickness(x0, x1, stats);
        stats.total_ms = milliseconds_since(start);
        return;
      }
      refit_and_traverse(x0, x1, stats);
      auto stage = SteadyClock::now();
      radial_view_cull(x0, x1, stats);
      stats.radial_view_ms = milliseconds_since(stage);
      record_high_level(stats);
      if (config.keep_candidate_pairs) {
        for (std::span<const TrianglePair> block : traversal.blocks()) {
          result.candidate_triangle_pairs.insert(result.candidate_triangle_pairs.end(),
                                                 block.begin(), block.end());
        }
      }

      low_level_and_ccd(x0, x1, stats);
      const auto gather = SteadyClock::now();
      result.collisions = tester.take_collisions(mesh);
      stats.ccd_ms += milliseconds_since(gather);
      record_counts(stats, result.collisions);
      stats.total_ms = milliseconds_since(start);
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
