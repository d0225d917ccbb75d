/// @file
/// The earliest time of impact among one detection's collisions.

#include "tailor/detection/collision_free_step.hpp"

#include "tailor/detection/self_collision_detector.hpp"

namespace tailor {

CollisionFreeStep collision_free_step(const TriangleMesh& mesh, const Positions& x0,
                                      const Positions& x1, double thickness,
                                      DetectionConfig config) {
  config.thickness = thickness;
  SelfCollisionDetector detector(mesh, x0, config);
  return first_contact(detector.detect(x0, x1).collisions);
}

CollisionFreeStep first_contact(const CollisionSet& collisions) {
  CollisionFreeStep step;
  for (const VertexFaceCollision& c : collisions.vertex_face) {
    if (c.toi < step.alpha || (!step.vertex_face && !step.edge_edge && c.toi == step.alpha)) {
      step.alpha = c.toi;
      step.vertex_face = c;
    }
  }
  for (const EdgeEdgeCollision& c : collisions.edge_edge) {
    if (c.toi < step.alpha || (!step.vertex_face && !step.edge_edge && c.toi == step.alpha)) {
      step.alpha = c.toi;
      step.vertex_face.reset();
      step.edge_edge = c;
    }
  }
  return step;
}

}  // namespace tailor
