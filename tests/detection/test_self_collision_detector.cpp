// The detector refuses positions it cannot use, naming the frame and the vertex.

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

std::string error_of(SelfCollisionDetector& detector, const Positions& x0, const Positions& x1) {
  try {
    detector.detect(x0, x1);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SelfCollisionDetector, RefusesNonFiniteAndMismatchedPositions) {
  const MeshData grid = make_grid(20, 20, 1.0, 1.0);
  const TriangleMesh mesh(static_cast<Index>(grid.vertices.rows()), grid.faces);
  for (const int threads : {1, 2}) {
    DetectionConfig config = DetectionConfig::preset("paper");
    config.threads = threads;
    SelfCollisionDetector detector(mesh, grid.vertices, config);
    Positions bad = grid.vertices;
    bad(300, 1) = std::numeric_limits<double>::quiet_NaN();
    bad(400, 2) = std::numeric_limits<double>::infinity();
    EXPECT_EQ(error_of(detector, bad, grid.vertices),
              "x0 has a non-finite coordinate at vertex 300");
    EXPECT_EQ(error_of(detector, grid.vertices, bad),
              "x1 has a non-finite coordinate at vertex 300");
    Positions worse = grid.vertices;
    worse(7, 0) = -std::numeric_limits<double>::infinity();
    EXPECT_EQ(error_of(detector, bad, worse), "x0 has a non-finite coordinate at vertex 300");
    EXPECT_EQ(error_of(detector, grid.vertices, grid.vertices.topRows(10)),
              "x1 has 10 vertices, the mesh has 441");
    EXPECT_THROW(SelfCollisionDetector(mesh, bad, config), InputError);
    // The detector still works after refusing a step.
    EXPECT_EQ(error_of(detector, grid.vertices, grid.vertices), "no error");
  }
}

}  // namespace
}  // namespace tailor
