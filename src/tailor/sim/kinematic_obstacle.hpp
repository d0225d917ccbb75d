#pragma once
/// @file
/// A moving obstacle whose motion is prescribed (the arm), over one substep.

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// A kinematic obstacle: its mesh and its positions at the start and end of the substep.
struct KinematicObstacle {
  /// The obstacle mesh (not owned).
  const TriangleMesh* mesh = nullptr;
  ///@{
  /// Obstacle positions at the start and end of the substep.
  Positions x0, x1;
  ///@}
};

}  // namespace tailor
