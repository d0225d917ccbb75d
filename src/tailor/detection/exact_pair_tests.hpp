#pragma once
/// @file
/// The last stage: candidate VF/EE pairs through the exact CCD.

#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <vector>

#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/ccd/thickness_ccd.hpp"
#include "tailor/detection/collision.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Runs the exact CCD (vertex_face_ccd / edge_edge_ccd) on batches of candidate pairs in
/// parallel blocks and gathers the collisions of a step in per-thread block lists
/// (std::deque): they grow without the overshoot of a doubling vector, and the blocks are
/// freed as take_collisions() copies them out, so a contact-heavy step (about one
/// collision per triangle) holds its collisions about once, not up to four times.
class ExactPairTester {
 public:
  /// Starts a step: no collisions, no counts.
  void begin_step();
  /// From now on a pair counts when it comes within `thickness` (> 0) during the step, at
  /// the earliest such time (ccd/thickness_ccd.hpp); 0, the default, is touching (the
  /// exact CCD).
  /// `normal_test`: NormalTest::skip when every pair given has been through the same test
  /// along its own normal already (ccd/thickness_ccd.hpp).
  void set_thickness(double thickness, NormalTest normal_test = NormalTest::run) {
    m_thickness = thickness;
    m_normal_test = normal_test;
  }
  /// Tests every pair of one batch (parallel); may be called any number of times a step.
  void test(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
            std::span<const VertexFacePair> vertex_face, std::span<const EdgeEdgePair> edge_edge);
  /// Tests every pair of several batches (e.g. the per-thread blocks of a pair
  /// generator) as one parallel loop over chunks of kChunkPairs pairs.
  void test(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
            std::span<const std::span<const VertexFacePair>> vertex_face_blocks,
            std::span<const std::span<const EdgeEdgePair>> edge_edge_blocks);
  /// Pairs per parallel task: a query takes about a microsecond, so 64 amortise the
  /// scheduling, and a step with only a few hundred pairs (the bending tube of 100K
  /// triangles sends ~900) still splits into enough tasks for every thread; with the VF
  /// and EE pairs of each block in separate loops of 256-pair tasks, two threads ran
  /// that stage only 1.15× as fast as one.
  static constexpr std::size_t kChunkPairs = 64;
  /// Most pairs per task with a thickness: the chunk's advancements share vector lanes
  /// (ccd/advance_lanes.hpp), which stay full longer in a larger chunk; a call with few
  /// pairs still gets about eight chunks per thread (at least kChunkPairs pairs each).
  static constexpr std::size_t kThicknessChunkPairs = 256;
  /// Hands over the collisions since begin_step(), sorted and without duplicates, so the
  /// result does not depend on the batches, their order or the thread count. The
  /// per-thread blocks are released as they are copied into the result. `mesh` is the
  /// one the pairs were tested on.
  CollisionSet take_collisions(const TriangleMesh& mesh);
  /// Queries since begin_step() that the exact path decided.
  std::int64_t exact_fallbacks() const;

 private:
  // An edge-edge hit as found: the two edge ids (the vertex ids of EdgeEdgeCollision are
  // looked up when the collisions are handed over), half the size of the collision.
  struct EdgeEdgeHit {
    Index e1, e2;
    double toi;
  };
  struct ThreadOutput {
    std::deque<VertexFaceCollision> vertex_face;
    std::deque<EdgeEdgeHit> edge_edge;
    std::int64_t exact = 0;
    // A thickness chunk's queries and results, kept from chunk to chunk.
    std::vector<VertexFaceQuery> vertex_face_queries;
    std::vector<EdgeEdgeQuery> edge_edge_queries;
    std::vector<ThicknessResult> results;
  };
  // The pair's time of impact (touching; m_thickness is 0), if it has one; counts a query
  // the exact path decided in `exact`.
  template <class Query>
  std::optional<double> time_of_impact(const Query& query, std::int64_t& exact) const;
  // The pairs of one chunk, one by one (m_thickness is 0), or together against m_thickness.
  template <class Pair>
  void touching(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                std::span<const Pair> pairs, ThreadOutput& out) const;
  template <class Pair>
  void within_thickness(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                        std::span<const Pair> pairs, ThreadOutput& out) const;
  // A thread's query vector for a chunk of pairs of that kind, and where a hit goes.
  static std::vector<VertexFaceQuery>& queries_in(ThreadOutput& out,
                                                  std::span<const VertexFacePair>) {
    return out.vertex_face_queries;
  }
  static std::vector<EdgeEdgeQuery>& queries_in(ThreadOutput& out, std::span<const EdgeEdgePair>) {
    return out.edge_edge_queries;
  }
  static void record(ThreadOutput& out, const VertexFacePair& pair, double toi) {
    out.vertex_face.push_back({pair.vertex, pair.face, toi});
  }
  static void record(ThreadOutput& out, const EdgeEdgePair& pair, double toi) {
    out.edge_edge.push_back({pair.edge_a, pair.edge_b, toi});
  }

  tbb::enumerable_thread_specific<ThreadOutput> m_outputs;
  double m_thickness = 0;
  NormalTest m_normal_test = NormalTest::run;
};

/// The candidate pairs of one batch.
struct CandidateBatch {
  std::span<const VertexFacePair> vertex_face;  ///< vertex-face pairs
  std::span<const EdgeEdgePair> edge_edge;      ///< edge-edge pairs
};

/// One batch through ExactPairTester (with `thickness`, ExactPairTester::set_thickness): the
/// colliding pairs, sorted and without duplicates. `exact_fallbacks` receives how many
/// queries the exact path decided.
CollisionSet test_pairs_exactly(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                                CandidateBatch batch, double thickness = 0,
                                std::int64_t* exact_fallbacks = nullptr);

}  // namespace tailor
