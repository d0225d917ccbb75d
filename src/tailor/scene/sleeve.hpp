#pragma once
/// @file
/// The sleeve: an open tube around the arm, `rings × segments` vertices.

#include <array>
#include <memory>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"
#include "tailor/scene/arm.hpp"

namespace tailor {

/// Size and resolution of the sleeve.
struct SleeveParams {
  int rings = 21;        ///< vertex loops along the arm (≥ 2)
  int segments = 33;     ///< vertices around each ring (≥ 3)
  double slack = 0.03;   ///< radius beyond the arm's (m)
  double start = 0.02;   ///< rest-pose abscissa of the shoulder end (m from the shoulder joint)
  double length = 0.53;  ///< along the arm (m)
};

/// An open tube. Vertex `r * segments + j` is vertex `j` of ring `r`; ring 0 is the
/// shoulder end (pinned to the arm), ring `rings - 1` the wrist end. Faces are oriented
/// with outward normals.
struct Sleeve {
  /// The parameters it was built with.
  SleeveParams params;
  Positions rest;                      ///< rest (and initial) positions
  std::shared_ptr<TriangleMesh> mesh;  ///< fixed connectivity
  Index elbow_ring = 0;                ///< ring nearest to the elbow in the rest pose
  /// Section rings of the radial-view observers along the arm: the elbow ring and every
  /// kObserverSpacing metres from it toward both ends (ascending); on the default sleeve
  /// one in the upper-arm part, one at the elbow, one in the forearm part.
  std::vector<Index> observer_rings;
  /// Distance between consecutive observers along the sleeve (m). Measured on the three
  /// gestures (culling/radial_view.hpp): 0.18 m (three observers, each seeing the whole
  /// sleeve) leaves half the candidate pairs that 0.1 m (five, on shorter clusters) does.
  static constexpr double kObserverSpacing = 0.18;

  /// Rings along the arm.
  Index num_rings() const { return params.rings; }
  /// Vertices per ring.
  Index num_segments() const { return params.segments; }
  /// Vertex ids of ring `r`, in order around the arm.
  std::vector<Index> ring(Index r) const;
  /// Every ring's vertex ids (the section loops).
  std::vector<std::vector<Index>> rings() const;
  /// The two open ends: {shoulder ring, wrist ring}.
  std::array<Index, 2> open_end_rings() const { return {0, params.rings - 1}; }
  /// Vertex ids of the observer rings (section loops for radial-view culling).
  std::vector<std::vector<Index>> observer_loops() const {
    std::vector<std::vector<Index>> loops;
    for (Index r : observer_rings) loops.push_back(ring(r));
    return loops;
  }
  /// Vertices attached to the arm (the shoulder ring).
  std::vector<Index> pinned_vertices() const { return ring(0); }
  /// Per-face warp direction (along the arm) for the cloth model's anisotropic membrane.
  Positions warp_directions() const;
};

/// Memory the simulation needs for a sleeve of these parameters, in bytes: `rings ×
/// segments` vertices times 16 KiB. Measured (`tailor simulate`, 40K-160K vertices):
/// about 4 KiB per vertex to build the scene and 8 KiB after one frame; the factor 2 is
/// a margin for contact-heavy frames.
double sleeve_memory_estimate(const SleeveParams& params);

/// Generates the sleeve around `arm` in its rest pose, in time linear in the vertex count.
/// Throws InputError on a bad size or resolution, a sleeve that leaves the arm, or one
/// whose sleeve_memory_estimate() exceeds the memory budget (io/memory_budget.hpp).
Sleeve make_sleeve(const Arm& arm, const SleeveParams& params);

}  // namespace tailor
