/// @file
/// The contact-heavy procedural steps (folded and pleated cloth): size, topology, determinism, an
/// intersection-free start and a real crossing of the two layers during the step.

#include <gtest/gtest.h>

#include "tailor/detection/intersection_check.hpp"
#include "tailor/mesh/procedural_steps.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {
namespace {

TEST(FoldedClothOnSphere, HasAboutTheRequestedSizeAndOneManifoldSheet) {
  for (const std::int64_t target : {1'000, 5'000, 40'000}) {
    const ProceduralStep step = make_folded_cloth_on_sphere(target);
    const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
    EXPECT_NEAR(static_cast<double>(mesh.num_faces()), static_cast<double>(target), 0.1 * target);
    EXPECT_EQ(step.x1.rows(), step.x0.rows());
    EXPECT_TRUE(mesh.validation().is_manifold());
    EXPECT_EQ(mesh.num_components(), 1);
    EXPECT_EQ(mesh.num_boundary_loops(), 1);
  }
  EXPECT_THROW(make_folded_cloth_on_sphere(199), std::invalid_argument);
}

TEST(FoldedClothOnSphere, IsDeterministicAndSeeded) {
  const ProceduralStep a = make_folded_cloth_on_sphere(3'000, 7);
  const ProceduralStep b = make_folded_cloth_on_sphere(3'000, 7);
  const ProceduralStep c = make_folded_cloth_on_sphere(3'000, 8);
  EXPECT_EQ(a.x0, b.x0);
  EXPECT_EQ(a.x1, b.x1);
  EXPECT_NE(a.x0, c.x0);
}

TEST(FoldedClothOnSphere, StartsIntersectionFreeAndTheLayersCrossDuringTheStep) {
  const ProceduralStep step = make_folded_cloth_on_sphere(5'000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  EXPECT_TRUE(check_intersections(mesh, step.x0).intersection_free());
  // The top layer ends below the bottom one over part of the cloth.
  EXPECT_GT(check_intersections(mesh, step.x1).self_intersections, 100);
}

TEST(FoldedClothOnSphere, ThePlateauIsExactlyPlanarAtBothEnds) {
  const ProceduralStep step = make_folded_cloth_on_sphere(5'000);
  Index on_plateau = 0;
  for (Index v = 0; v < step.x0.rows(); ++v) {
    if (step.x0(v, 1) == 0.96) on_plateau += step.x1(v, 1) == 0.96 ? 1 : 0;
  }
  EXPECT_GT(on_plateau, 50);
}

TEST(PleatedCloth, HasAboutTheRequestedSizeAndOneManifoldSheet) {
  for (const std::int64_t target : {5'000, 20'000}) {
    const ProceduralStep step = make_pleated_cloth(target);
    const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
    EXPECT_NEAR(static_cast<double>(mesh.num_faces()), static_cast<double>(target), 0.1 * target);
    EXPECT_TRUE(mesh.validation().is_manifold());
    EXPECT_EQ(mesh.num_components(), 1);
    EXPECT_EQ(mesh.num_boundary_loops(), 1);
  }
  EXPECT_THROW(make_pleated_cloth(199), std::invalid_argument);
  EXPECT_THROW(make_pleated_cloth(1'000, 1), std::invalid_argument);
  EXPECT_EQ(make_pleated_cloth(3'000, 6, 4).x1, make_pleated_cloth(3'000, 6, 4).x1);
  EXPECT_NE(make_pleated_cloth(3'000, 6, 4).x0, make_pleated_cloth(3'000, 6, 5).x0);
}

TEST(PleatedCloth, StartsIntersectionFreeAndTheLayersCrossDuringTheStep) {
  const ProceduralStep step = make_pleated_cloth(5'000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  EXPECT_TRUE(check_intersections(mesh, step.x0).intersection_free());
  EXPECT_GT(check_intersections(mesh, step.x1).self_intersections, mesh.num_faces() / 10);
}

}  // namespace
}  // namespace tailor
