#pragma once
/// @file
/// The self-collision pipeline of one time step (docs/design.md §1): refit, high-level
/// culling, low-level culling, exact CCD.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tailor/culling/triangle_pair.hpp"
#include "tailor/detection/collision.hpp"
#include "tailor/detection/detection_config.hpp"
#include "tailor/detection/detection_stats.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Result of one step: the exact collisions and per-stage statistics.
struct DetectionResult {
  /// Every collision of the step (exact).
  CollisionSet collisions;
  /// Per-stage counts and times of the step.
  DetectionStats stats;
  /// The candidate triangle pairs of the step (only with DetectionConfig::keep_candidate_pairs).
  std::vector<TrianglePair> candidate_triangle_pairs;
};

/// Finds every self-collision of a deforming mesh over one linear step.
/// Built once per topology; `detect` may be called for any number of steps.
class SelfCollisionDetector {
 public:
  /// `x_build` positions the BVH is built on (usually the first frame). `mesh` must
  /// outlive the detector. `section_loops` (optional) are rings of vertices of a
  /// tube-like garment, one per observation point, for radial-view culling (used when
  /// `config.radial_view` is on).
  SelfCollisionDetector(const TriangleMesh& mesh, const Positions& x_build,
                        DetectionConfig config = DetectionConfig::preset("paper"),
                        std::vector<std::vector<Index>> section_loops = {});
  ~SelfCollisionDetector();
  /// Moves the detector; the moved-from one may only be destroyed or assigned to.
  SelfCollisionDetector(SelfCollisionDetector&&) noexcept;
  /// Move assignment (as the move constructor).
  SelfCollisionDetector& operator=(SelfCollisionDetector&&) noexcept;

  /// All VF and EE pairs that touch at some t in [0, 1] while vertices move from `x0`
  /// to `x1`. Throws InputError if the row counts differ from the mesh's or a coordinate
  /// is not finite.
  ///
  /// Steps may follow one another or not: the result never depends on earlier steps. Only
  /// the work does: after a step whose root the cone and contour test certified, the
  /// masks are refitted first, and the boxes only if the root fails this time
  /// (DetectionStats::boxes_refitted).
  DetectionResult detect(const Positions& x0, const Positions& x1);

  /// The settings the detector was built with.
  const DetectionConfig& config() const;
  /// The mesh given to the constructor.
  const TriangleMesh& mesh() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tailor
