#pragma once
// Checks of radial-view culling against brute force, shared by the tube tests and the
// sleeve-gesture tests.

#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <string>

#include "tailor/culling/radial_view_culling.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor::testing {

/// How many pairs of distinct faces (f on the first feature, g on the second) around the
/// collisions of `truth` `radial` culls: must be 0, whichever face the feature assignment
/// picks.
inline std::int64_t culled_colliding_pairs(const TriangleMesh& mesh, const CollisionSet& truth,
                                           const RadialViewCulling& radial) {
  std::int64_t wrong = 0;
  const auto check = [&](std::span<const Index> a, std::span<const Index> b) {
    for (Index f : a) {
      for (Index g : b) wrong += f != g && radial.pair_culled(f, g);
    }
  };
  for (const VertexFaceCollision& c : truth.vertex_face) {
    const Index face[] = {c.face};
    check(mesh.vertex_faces(c.vertex), face);
  }
  for (const EdgeEdgeCollision& c : truth.edge_edge) {
    check(mesh.edge_faces(c.edge_a), mesh.edge_faces(c.edge_b));
  }
  return wrong;
}

/// Expects `result` to hold the pairs of `truth`, in the same order (`what` names the
/// result in failures).
inline void expect_same_collisions(const CollisionSet& result, const CollisionSet& truth,
                                   const std::string& what) {
  ASSERT_EQ(result.vertex_face.size(), truth.vertex_face.size()) << what;
  ASSERT_EQ(result.edge_edge.size(), truth.edge_edge.size()) << what;
  for (std::size_t i = 0; i < truth.vertex_face.size(); ++i) {
    EXPECT_EQ(result.vertex_face[i].vertex, truth.vertex_face[i].vertex) << what;
    EXPECT_EQ(result.vertex_face[i].face, truth.vertex_face[i].face) << what;
  }
  for (std::size_t i = 0; i < truth.edge_edge.size(); ++i) {
    EXPECT_EQ(result.edge_edge[i].edge_a, truth.edge_edge[i].edge_a) << what;
    EXPECT_EQ(result.edge_edge[i].edge_b, truth.edge_edge[i].edge_b) << what;
  }
}

}  // namespace tailor::testing
