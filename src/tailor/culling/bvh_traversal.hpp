#pragma once
/// @file
/// High-level culling: BVH self- and pair-traversal producing candidate triangle pairs.

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/culling/triangle_pair.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Which high-level stages the traversal applies.
struct TraversalOptions {
  bool normal_cones = true;       ///< skip a node whose normals are within 90° of a direction
                                  ///< of its mask (direction_mask.hpp) and whose contour passes
  bool contour_test = true;       ///< require the contour test before a cone skips a node
  bool adjacency_culling = true;  ///< never emit triangle pairs that share a vertex
};

/// Counts of one traversal.
struct TraversalCounts {
  std::int64_t node_pairs_visited = 0;  ///< node pairs whose boxes were compared
  /// Small subtrees (or pairs of them) compared leaf by leaf, lanes at a time; their leaf
  /// pairs are not counted as node pairs.
  std::int64_t leaf_buckets = 0;
  /// Nodes whose self-test a normal cone skipped (certified by the contour test when on).
  std::int64_t nodes_culled_by_cones = 0;
  std::int64_t contour_tests = 0;         ///< contour tests run (one per cone that held)
  std::int64_t contour_tests_failed = 0;  ///< contour tests that could not certify
  /// Adds `other` field by field (summing the per-thread counts).
  TraversalCounts& operator+=(const TraversalCounts& other);
};

/// The positions of one step, as the traversal sees them.
struct StepPositions {
  const Positions& x0;  ///< vertex positions at the start of the step (t=0)
  const Positions& x1;  ///< vertex positions at the end of the step (t=1)
};

/// Collects the candidate triangle pairs (CTPs) of a step from BVH self-traversals. The pairs stay
/// in per-thread lists of fixed-size blocks (no copy on growth, at most one partly filled block
/// per thread) that are read block by block, and either keep their memory for the next step
/// (clear()) or are freed as they are consumed (consume()).
class CandidateTraversal {
 public:
  /// A traversal of `mesh`'s BVHs (kept by pointer: `mesh` must outlive it).
  explicit CandidateTraversal(const TriangleMesh& mesh) : m_mesh(&mesh) {}

  /// Forgets the previous step's pairs and counts (keeping the memory).
  void clear();

  /// Adds every CTP inside one BVH: self(node) = self(left) + self(right) + pair(left,
  /// right), skipping nodes certified by normal cones and the contour test. `contours`
  /// must belong to `bvh` (used only when the contour test is on). Parallel; the set of
  /// pairs and the counts do not depend on the thread count, their order does.
  ///
  /// Returns true when the root itself was certified by its cone and the contour test.
  /// Then no two features of the whole mesh without a common vertex can touch during the
  /// step, adjacent triangles' included: every normal stays strictly on one side of the
  /// axis and the projected boundary stays simple, so at every t the projection along the
  /// axis is one to one on the surface (Volino & Magnenat-Thalmann 1994). A vertex
  /// touching a triangle, or two edges touching, would be two points of the surface with
  /// one projection. The caller may then skip the isolated set too.
  ///
  /// Reads the BVH's boxes: they must be current (MeshBvh::boxes_current(); throws
  /// std::logic_error otherwise).
  bool self(const MeshBvh& bvh, const NodeContours& contours, StepPositions step,
            const TraversalOptions& options);

  /// Only the first test of self(): whether the root is certified by its cone and the
  /// contour test (counted as self() counts it; no pair is added). Reads the root's mask
  /// and the positions, no box: valid after MeshBvh::refit_directions().
  bool certify_root(const MeshBvh& bvh, const NodeContours& contours, StepPositions step,
                    const TraversalOptions& options);

  /// Removes every pair found since clear() for which `culled(pair)` holds (a later stage
  /// of high-level culling, e.g. radial view); returns how many. Call it after the
  /// traversals of a step: blocks may be partly filled afterwards. `culled` is called
  /// from several threads at once.
  template <class Culled>
  std::int64_t remove_if(const Culled& culled) {
    // In chunks of kCullChunk pairs, not whole blocks: a step with few pairs has one
    // block per thread, often of very different sizes, and the test per pair is costly
    // (radial view's moving edge planes), so whole blocks left one thread doing most of
    // the work. Then each block is compacted by its flags.
    std::vector<std::vector<TrianglePair>*> used_blocks;
    for (ThreadOutput& out : m_outputs) {
      for (std::size_t b = 0; b < out.used; ++b) used_blocks.push_back(&out.blocks[b]);
    }
    std::vector<std::size_t> first_chunk(used_blocks.size() + 1, 0);  // per block
    std::vector<std::size_t> first_flag(used_blocks.size() + 1, 0);
    for (std::size_t b = 0; b < used_blocks.size(); ++b) {
      const std::size_t n = used_blocks[b]->size();
      first_chunk[b + 1] = first_chunk[b] + (n + kCullChunk - 1) / kCullChunk;
      first_flag[b + 1] = first_flag[b] + n;
    }
    m_culled_flags.assign(first_flag.back(), 0);
    tbb::parallel_for(std::size_t{0}, first_chunk.back(), [&](std::size_t chunk) {
      const auto b =
          static_cast<std::size_t>(std::upper_bound(first_chunk.begin(), first_chunk.end(), chunk) -
                                   first_chunk.begin() - 1);
      const std::vector<TrianglePair>& block = *used_blocks[b];
      const std::size_t begin = (chunk - first_chunk[b]) * kCullChunk;
      const std::size_t end = std::min(block.size(), begin + kCullChunk);
      for (std::size_t i = begin; i < end; ++i) {
        m_culled_flags[first_flag[b] + i] = culled(block[i]) ? 1 : 0;
      }
    });
    tbb::combinable<std::int64_t> removed([] { return std::int64_t{0}; });
    tbb::parallel_for(std::size_t{0}, used_blocks.size(), [&](std::size_t b) {
      std::vector<TrianglePair>& block = *used_blocks[b];
      const std::uint8_t* flag = m_culled_flags.data() + first_flag[b];
      std::size_t kept = 0;
      for (std::size_t i = 0; i < block.size(); ++i) {
        if (flag[i] == 0) block[kept++] = block[i];
      }
      removed.local() += static_cast<std::int64_t>(block.size() - kept);
      block.resize(kept);
    });
    return removed.combine(std::plus<>());
  }

  /// The pairs found since clear(), as blocks (each pair `first < second`).
  std::vector<std::span<const TrianglePair>> blocks() const;
  /// Hands each block of blocks() to `use` and then frees its memory, so that the stages
  /// that consume the pairs can grow while the pairs shrink (a contact-heavy step has
  /// about one collision per candidate pair: held together, the two were the step's
  /// memory peak). No pairs are left afterwards; the next step allocates its blocks again.
  template <class Use>
  void consume(const Use& use) {
    for (ThreadOutput& out : m_outputs) {
      for (std::size_t b = 0; b < out.used; ++b) {
        use(std::span<const TrianglePair>(out.blocks[b]));
        std::vector<TrianglePair>().swap(out.blocks[b]);
      }
      out.used = 0;
    }
  }
  /// Number of pairs found since clear().
  std::int64_t size() const;
  /// Counts since clear().
  TraversalCounts counts() const;

 private:
  // Pairs per block (256 KiB).
  static constexpr std::size_t kBlockPairs = std::size_t{1} << 15;
  // Pairs per task of remove_if().
  static constexpr std::size_t kCullChunk = 256;
  struct ThreadOutput {
    std::vector<std::vector<TrianglePair>> blocks;  // reserved to kBlockPairs each
    std::size_t used = 0;                           // blocks in use (the last may be partial)
    TraversalCounts counts;
    void push(TrianglePair pair) {
      if (used == 0 || blocks[used - 1].size() == kBlockPairs) {
        if (used == blocks.size()) blocks.emplace_back();
        blocks[used].reserve(kBlockPairs);  // released by consume()
        ++used;
      }
      blocks[used - 1].push_back(pair);
    }
  };
  class Walk;

  const TriangleMesh* m_mesh;
  tbb::enumerable_thread_specific<ThreadOutput> m_outputs;
  std::vector<std::uint8_t> m_culled_flags;  // remove_if(): one per pair, reused
};

}  // namespace tailor
