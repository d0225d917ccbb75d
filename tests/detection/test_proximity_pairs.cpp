/// @file
/// Proximity pairs at one instant against brute force (as sets) on a crumpled cloth and on
/// two parallel sheets exactly one thickness apart (where ungrown boxes would miss every
/// pair), and bad input.

#include <gtest/gtest.h>

#include <cmath>

#include "support/sanitized.hpp"
#include "tailor/detection/proximity_pairs.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/mesh/procedural_meshes.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

void expect_same_pairs(const ProximityPairs& a, const ProximityPairs& b) {
  ASSERT_EQ(a.vertex_face.size(), b.vertex_face.size());
  ASSERT_EQ(a.edge_edge.size(), b.edge_edge.size());
  for (std::size_t i = 0; i < a.vertex_face.size(); ++i) {
    EXPECT_EQ(a.vertex_face[i].vertex, b.vertex_face[i].vertex) << i;
    EXPECT_EQ(a.vertex_face[i].face, b.vertex_face[i].face) << i;
  }
  for (std::size_t i = 0; i < a.edge_edge.size(); ++i) {
    EXPECT_EQ(a.edge_edge[i].edge_a, b.edge_edge[i].edge_a) << i;
    EXPECT_EQ(a.edge_edge[i].edge_b, b.edge_edge[i].edge_b) << i;
  }
}

TEST(ProximityPairs, CrumpledClothMatchesBruteForceAtEveryThickness) {
  const ProceduralStep step = make_crumpling_cloth_step(testing::sanitized() ? 200 : 800);
  const TriangleMesh mesh(static_cast<Index>(step.x1.rows()), step.faces);
  const Vec3 diagonal = step.x1.colwise().maxCoeff() - step.x1.colwise().minCoeff();
  for (const double share : {0.0, 1e-3, 1e-2, 5e-2}) {
    const double h = share * diagonal.norm();
    const ProximityPairs fast = proximity_pairs(mesh, step.x1, h);
    expect_same_pairs(fast, proximity_pairs_brute_force(mesh, step.x1, h));
    if (share >= 5e-2) {  // the test means something: pairs were found (also on the
                          // sanitizers' smaller cloth)
      EXPECT_GT(fast.vertex_face.size(), 0u) << share;
      EXPECT_GT(fast.edge_edge.size(), 0u) << share;
    }
  }
}

TEST(ProximityPairs, OneSearchReusedAlongAStepMatchesBruteForceAtEveryCall) {
  // The search's trees are built on the first configuration and refitted on the later
  // ones, the last of which is moved far from it (mirrored and squashed: pairs appear whose
  // boxes were apart in the first configuration).
  const ProceduralStep step = make_crumpling_cloth_step(testing::sanitized() ? 200 : 800);
  const TriangleMesh mesh(static_cast<Index>(step.x1.rows()), step.faces);
  const Vec3 diagonal = step.x1.colwise().maxCoeff() - step.x1.colwise().minCoeff();
  const double h = 5e-2 * diagonal.norm();
  ProximitySearch search(mesh);
  std::size_t found = 0;
  for (const double t : {0.0, 0.5, 1.0, -1.0}) {
    Positions x = (1 - t) * step.x0 + t * step.x1;
    if (t < 0)
      x = (step.x1.array().rowwise() * Eigen::Array3d(-1.0, 0.2, 1.0).transpose()).matrix();
    const ProximityPairs pairs = search.pairs(x, h);
    expect_same_pairs(pairs, proximity_pairs_brute_force(mesh, x, h));
    found += pairs.vertex_face.size() + pairs.edge_edge.size();
  }
  EXPECT_GT(found, 0u);
}

TEST(ProximityPairs, SheetsOneThicknessApartAreFoundDespiteDisjointBoxes) {
  // Two flat 6 × 6 grids, the second 0.125 above the first: every vertex of one is exactly
  // the thickness from the other sheet (ungrown boxes are disjoint).
  const MeshData grid = make_grid(6, 6, 1.0, 1.0);
  const Index n = static_cast<Index>(grid.vertices.rows());
  FaceArray faces(2 * grid.faces.rows(), 3);
  faces << grid.faces, grid.faces.array() + n;
  Positions x(2 * n, 3);
  x << grid.vertices, grid.vertices;
  const int normal_axis = grid.vertices.col(2).isZero() ? 2 : 1;
  x.bottomRows(n).col(normal_axis).array() += 0.125;
  const TriangleMesh mesh(2 * n, faces);
  const ProximityPairs at = proximity_pairs(mesh, x, 0.125);
  expect_same_pairs(at, proximity_pairs_brute_force(mesh, x, 0.125));
  EXPECT_GE(at.vertex_face.size(), static_cast<std::size_t>(2 * n));
  const ProximityPairs short_of = proximity_pairs(mesh, x, std::nextafter(0.125, 0.0));
  expect_same_pairs(short_of, proximity_pairs_brute_force(mesh, x, std::nextafter(0.125, 0.0)));
  EXPECT_LT(short_of.vertex_face.size(), at.vertex_face.size());
}

TEST(ProximityPairs, BadInputIsAnInputError) {
  const MeshData grid = make_grid(2, 2, 1.0, 1.0);
  const TriangleMesh mesh(static_cast<Index>(grid.vertices.rows()), grid.faces);
  EXPECT_THROW(proximity_pairs(mesh, grid.vertices, -1), InputError);
  EXPECT_THROW(proximity_pairs(mesh, grid.vertices.topRows(2), 0.1), InputError);
  Positions nan = grid.vertices;
  nan(0, 0) = std::nan("");
  EXPECT_THROW(proximity_pairs(mesh, nan, 0.1), InputError);
}

}  // namespace
}  // namespace tailor
