#pragma once
/// @file
/// Low-level culling: from candidate triangle pairs (and the isolated set) to the VF and
/// EE pairs that reach the exact CCD (the paper §3).

#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <span>
#include <vector>

#include "tailor/candidates/batch_pair_filters.hpp"
#include "tailor/candidates/feature_assignment.hpp"
#include "tailor/candidates/isolated_set.hpp"
#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/culling/triangle_pair.hpp"

namespace tailor {

/// Which low-level stages run.
struct LowLevelOptions {
  bool triangle_filter =
      true;  ///< drop CTPs (and pairs) by their planes (triangle_plane_sides.hpp)
  bool direction_filter =
      true;  ///< drop CTPs a fixed direction keeps apart (step_separating_direction.hpp)
  bool feature_assignment = true;  ///< test each feature pair from one triangle pair only
  bool primitive_boxes = true;  ///< drop pairs kept apart by their boxes at both ends of the step
  bool coplanarity_filter = true;  ///< drop pairs that can never become coplanar
  bool projection_filter =
      true;  ///< drop pairs whose projection never touches (projection_filter.hpp)
  bool adjacency_culling = true;  ///< the CTPs hold no adjacent pairs (see FeatureAssignment)
};

/// VF and EE pair counts after each low-level stage.
struct LowLevelCounts {
  std::int64_t triangle_pairs_separated = 0;  ///< CTPs the triangle filter dropped whole
  std::int64_t triangle_pairs_apart = 0;      ///< CTPs the separating-direction filter dropped
  ///@{
  /// Pairs the feature assignment owed to the candidate triangle pairs (and the isolated set).
  std::int64_t vf_generated = 0, ee_generated = 0;
  ///@}
  ///@{
  /// Pairs whose boxes may meet (bvh/step_boxes.hpp; all of them when that stage is off).
  std::int64_t vf_after_boxes = 0, ee_after_boxes = 0;
  ///@}
  ///@{
  /// Pairs left after the triangle filter and the non-coplanarity (DNF) filter.
  std::int64_t vf_after_filter = 0, ee_after_filter = 0;
  ///@}
  ///@{
  /// Pairs left after the projection filter: the candidates for the exact CCD.
  std::int64_t vf_after_projection = 0, ee_after_projection = 0;
  ///@}
  /// Adds `other` field by field (summing the per-thread counts).
  LowLevelCounts& operator+=(const LowLevelCounts& other);
};

/// Generates the candidate primitive pairs of a step, in rounds: clear_pairs(), add
/// triangle pairs (and the isolated set), read the surviving pairs by blocks. The blocks
/// are per-thread buffers that keep their memory between rounds and steps, so a warm
/// generator does not allocate; the counts add up over a step (until begin_step()).
class PrimitivePairGenerator {
 public:
  PrimitivePairGenerator() = default;
  /// A generator for `mesh` (kept by pointer: it must outlive the generator), with its
  /// FeatureAssignment built.
  explicit PrimitivePairGenerator(const TriangleMesh& mesh);

  /// Starts a step: no pairs, zero counts.
  void begin_step();
  /// Starts a round: no pairs (the counts go on).
  void clear_pairs();
  /// Adds the pairs owed by `ctps` that survive the enabled stages (parallel).
  void add_triangle_pairs(std::span<const TrianglePair> ctps, const Positions& x0,
                          const Positions& x1, const LowLevelOptions& options);
  /// Adds the pairs of `isolated` that survive the enabled stages (parallel).
  void add_isolated(const IsolatedSet& isolated, const Positions& x0, const Positions& x1,
                    const LowLevelOptions& options);

  /// The surviving vertex-face pairs since clear_pairs(), by blocks (one per thread that
  /// has some); the set does not depend on the thread count (the order does).
  std::vector<std::span<const VertexFacePair>> vertex_face_blocks() const;
  /// The surviving edge-edge pairs since clear_pairs(), by blocks (as vertex_face_blocks()).
  std::vector<std::span<const EdgeEdgePair>> edge_edge_blocks() const;
  /// Counts since begin_step().
  LowLevelCounts counts() const;

  /// The feature assignment that decides which triangle pair tests each feature pair.
  const FeatureAssignment& assignment() const { return m_assignment; }

  /// What one thread generates: the surviving pairs, its counts, and the pairs waiting
  /// for the filters (batch_pair_filters.hpp).
  struct ThreadOutput {
    /// Surviving vertex-face pairs.
    std::vector<VertexFacePair> vertex_face;
    /// Surviving edge-edge pairs.
    std::vector<EdgeEdgePair> edge_edge;
    /// This thread's counts.
    LowLevelCounts counts;
    ///@{
    /// Pairs waiting for the filters, one batch per kind.
    PairBatch vertex_face_batch, edge_edge_batch;
    ///@}
  };

 private:
  // CTPs filtered and expanded together (the triangle filter's batch).
  static constexpr std::size_t kChunk = 64;

  // Prefetches the feature records that expanding the chunk at ctps[first] reads.
  void prefetch_ahead(std::span<const TrianglePair> ctps, std::size_t first, std::size_t end) const;
  // Runs the filters on every thread's waiting pairs.
  void flush_batches(const LowLevelOptions& options);

  const TriangleMesh* m_mesh = nullptr;
  FeatureAssignment m_assignment;
  tbb::enumerable_thread_specific<ThreadOutput> m_outputs;
};

}  // namespace tailor
