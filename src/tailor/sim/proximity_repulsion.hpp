#pragma once
/// @file
/// Proximity repulsion at the end of a substep (Bridson, Fedkiw & Anderson 2002, §7.2):
/// cloth closer than the thickness to the obstacle or to itself is pushed apart, with
/// Coulomb friction, before the CCD passes (which then see few collisions).

#include <cstdint>
#include <vector>

#include "tailor/bvh/bvh.hpp"
#include "tailor/detection/proximity_pairs.hpp"
#include "tailor/mesh/triangle_mesh.hpp"
#include "tailor/sim/contact_response.hpp"
#include "tailor/sim/kinematic_obstacle.hpp"

namespace tailor {

/// Repulsion passes of one cloth mesh (the obstacle search's trees built once, refitted per
/// call).
class ProximityRepulsion {
 public:
  /// `pinned[v]` (one per cloth vertex) marks vertices that never move. `cloth` must
  /// outlive this object.
  ProximityRepulsion(const TriangleMesh& cloth, const Positions& x_build, std::vector<char> pinned);

  /// Pushes every free cloth vertex closer than `thickness` to the obstacle's faces at
  /// the end of the step out to that distance (along the direction to the closest point,
  /// or the face normal from inside), reducing its motion relative to the obstacle point
  /// by at most `friction` times the push. Returns the vertices pushed.
  std::int64_t repel_obstacle(const Positions& x0, Positions& x1, const KinematicObstacle& obstacle,
                              double thickness, double friction);

  /// Vertex-face and edge-edge pairs of the cloth (sharing no vertex) closer than
  /// `thickness` at the end of the step, that were on the same side at the start, get a
  /// push that cancels their approach up to the overlap plus a tenth of the overlap.
  /// The pairs are the library's exact proximity pairs at the end positions
  /// (detection/proximity_pairs.hpp). Returns the pairs pushed.
  std::int64_t repel_cloth(const Positions& x0, Positions& x1, double thickness,
                           const ContactResponse& response);

 private:
  const TriangleMesh& m_cloth;
  std::vector<char> m_pinned;
  Bvh m_points, m_obstacle_faces;  // cloth vertices, the obstacle's faces
  ProximitySearch m_search;        // the cloth's own pairs
  const TriangleMesh* m_obstacle = nullptr;
};

}  // namespace tailor
