// Loads two frames of a cloth (same connectivity), finds every self-collision of the step
// between them, and prints them.
//   detect_step t0.ply t1.ply
#include <cstdio>

#include "tailor/tailor.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s MESH_T0 MESH_T1\n", argv[0]);
    return 2;
  }
  try {
    const tailor::MeshData t0 = tailor::read_mesh(argv[1]);
    const tailor::MeshData t1 = tailor::read_mesh(argv[2]);
    if (t0.faces.rows() != t1.faces.rows() || t0.faces != t1.faces) {
      std::fprintf(stderr, "%s and %s have different faces\n", argv[1], argv[2]);
      return 2;
    }
    const tailor::TriangleMesh mesh(static_cast<tailor::Index>(t0.vertices.rows()), t0.faces);
    // One step, the paper's preset (for many steps of one mesh: tailor::SelfCollisionDetector).
    const tailor::DetectionResult step =
        tailor::detect_self_collisions(mesh, t0.vertices, t1.vertices);

    for (const auto& c : step.collisions.vertex_face) {
      std::printf("vertex %d - face %d at t >= %.6f\n", c.vertex, c.face, c.toi);
    }
    for (const auto& c : step.collisions.edge_edge) {
      std::printf("edge (%d, %d) - edge (%d, %d) at t >= %.6f\n", c.a0, c.a1, c.b0, c.b1, c.toi);
    }
    std::printf("collisions: %zu vertex-face, %zu edge-edge (%.2f ms)\n",
                step.collisions.vertex_face.size(), step.collisions.edge_edge.size(),
                step.stats.total_ms);
    return 0;
  } catch (const tailor::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
