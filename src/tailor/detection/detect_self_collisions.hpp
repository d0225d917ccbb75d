#pragma once
/// @file
/// The one-off form of SelfCollisionDetector: one call for one step.

#include <vector>

#include "tailor/detection/detection_config.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Every vertex-face and edge-edge pair of `mesh` that touches at some t in [0, 1] while its
/// vertices move linearly from `x0` to `x1`, with per-stage statistics: builds a
/// SelfCollisionDetector on `x0` and runs one step. For many steps of one mesh keep a
/// SelfCollisionDetector instead (it builds the BVH, contours and isolated set once).
/// `section_loops`: radial-view observers, as for SelfCollisionDetector. Throws InputError
/// if the row counts differ from the mesh's or a coordinate is not finite.
DetectionResult detect_self_collisions(
    const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
    const DetectionConfig& config = DetectionConfig::preset("paper"),
    std::vector<std::vector<Index>> section_loops = {});

}  // namespace tailor
