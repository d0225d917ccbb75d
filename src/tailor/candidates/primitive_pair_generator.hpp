#pragma once
/// @file
/// Low-level culling: from candidate triangle pairs (and the isolated set) to the VF and
/// EE pairs that reach the exact CCD (the paper §3).

#include <cstdint>
#include <span>
#include <vector>

#include "tailor/bvh/aabb.hpp"
#include "tailor/candidates/feature_assignment.hpp"
#include "tailor/candidates/isolated_set.hpp"
#include "tailor/candidates/primitive_pair.hpp"
#include "tailor/culling/triangle_pair.hpp"

namespace tailor {

/// Which low-level stages run.
struct LowLevelOptions {
  bool feature_assignment = true;  ///< test each feature pair from one triangle pair only
  bool primitive_boxes = true;     ///< drop pairs whose swept boxes do not overlap
  bool coplanarity_filter = true;  ///< drop pairs that can never become coplanar
  bool adjacency_culling = true;   ///< the CTPs hold no adjacent pairs (see FeatureAssignment)
};

/// VF and EE pair counts after each low-level stage.
struct LowLevelCounts {
  std::int64_t vf_generated = 0, ee_generated = 0;
  std::int64_t vf_after_boxes = 0, ee_after_boxes = 0;
  std::int64_t vf_after_filter = 0, ee_after_filter = 0;
  LowLevelCounts& operator+=(const LowLevelCounts& other);
};

/// Generates the candidate primitive pairs of one step.
class PrimitivePairGenerator {
 public:
  PrimitivePairGenerator() = default;
  explicit PrimitivePairGenerator(const TriangleMesh& mesh);

  /// Fills `vertex_face` and `edge_edge` (cleared first) with the pairs of the CTPs and
  /// of `isolated` that survive the enabled stages. Parallel; the sets do not depend on
  /// the thread count.
  void generate(std::span<const TrianglePair> ctps, const IsolatedSet& isolated,
                const Positions& x0, const Positions& x1, const LowLevelOptions& options,
                std::vector<VertexFacePair>& vertex_face, std::vector<EdgeEdgePair>& edge_edge,
                LowLevelCounts& counts);

  const FeatureAssignment& assignment() const { return m_assignment; }

 private:
  const TriangleMesh* m_mesh = nullptr;
  FeatureAssignment m_assignment;
  std::vector<Aabb> m_edge_boxes, m_face_boxes;  // swept boxes of the current step
};

}  // namespace tailor
