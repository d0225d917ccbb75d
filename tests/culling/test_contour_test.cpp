// The contour test and why normal-cone culling needs it.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/culling/contour_test.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

// A strip winding 1.25 turns around the z axis with a small pitch: flat enough for a
// tiny normal cone, but its ends overlap in projection. The pitch flips sign over the
// step, so the overlapping ends pass through each other.
struct Ribbon {
  MeshData mesh;
  Positions x1;
};

Ribbon make_ribbon(int segments, double pitch0, double pitch1) {
  const double turns = 1.25, inner = 1.0, outer = 1.3;
  Ribbon ribbon;
  ribbon.mesh = make_grid(segments, 2, 1.0, 1.0);
  ribbon.x1 = ribbon.mesh.vertices;
  for (Eigen::Index i = 0; i < ribbon.mesh.vertices.rows(); ++i) {
    const double s = ribbon.mesh.vertices(i, 0), w = ribbon.mesh.vertices(i, 1);
    const double angle = 2 * std::numbers::pi * turns * s, radius = inner + (outer - inner) * w;
    for (auto [x, pitch] : {std::pair{&ribbon.mesh.vertices, pitch0}, {&ribbon.x1, pitch1}}) {
      x->row(i) << radius * std::cos(angle), radius * std::sin(angle), pitch * s;
    }
  }
  return ribbon;
}

// A mesh with its BVH and the BVH's contours (built in place: each points to the former).
struct Contoured {
  TriangleMesh mesh;
  MeshBvh bvh;
  NodeContours contours;
  explicit Contoured(const MeshData& data)
      : mesh(static_cast<Index>(data.vertices.rows()), data.faces),
        bvh(mesh, data.vertices),
        contours(mesh, bvh) {}
  Contoured(const Contoured&) = delete;
};

TEST(ContourTest, RigidlyMovingFlatPatchStaysSimple) {
  const MeshData grid = make_grid(6, 4, 1.0, 0.7);
  const Contoured tree(grid);
  const NodeContours& contours = tree.contours;
  ASSERT_TRUE(contours.has_single_loop(0));
  EXPECT_EQ(contours.loop(0).size(), 2u * (6 + 4));
  Positions x1 = grid.vertices;
  x1.col(2).array() += 0.3;
  x1.col(0).array() += 0.1;
  EXPECT_TRUE(contour_stays_simple(contours.loop(0), grid.vertices, x1, Vec3::UnitZ()));
  // Seen edge-on the same contour is degenerate: the test must refuse.
  EXPECT_FALSE(contour_stays_simple(contours.loop(0), grid.vertices, x1, Vec3::UnitX()));
}

TEST(ContourTest, TubeHasNoSingleLoop) {
  const Contoured tube(make_tube(5, 8, 0.3, 1.0));
  EXPECT_FALSE(tube.contours.has_single_loop(0));  // an annulus: two loops
}

TEST(ContourTest, OverlappingRibbonIsNotSimple) {
  const Ribbon ribbon = make_ribbon(60, 0.02, -0.02);
  const Contoured tree(ribbon.mesh);
  ASSERT_TRUE(tree.contours.has_single_loop(0));
  EXPECT_FALSE(
      contour_stays_simple(tree.contours.loop(0), ribbon.mesh.vertices, ribbon.x1, Vec3::UnitZ()));
}

TEST(ContourTest, TouchingContourIsNotSimple) {
  // A square loop whose far corner moves onto the opposite edge at t=1 (in projection).
  Positions x0(4, 3), x1(4, 3);
  x0 << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  x1 = x0;
  x1.row(2) << 0.5, 0.0, 0.0;  // lands on edge (0, 1)
  const std::vector<Index> loop{0, 1, 2, 3};
  EXPECT_FALSE(contour_stays_simple(loop, x0, x1, Vec3::UnitZ()));
  x1.row(2) << 0.5, std::ldexp(1.0, -40), 0.0;  // stays strictly off it
  EXPECT_TRUE(contour_stays_simple(loop, x0, x1, Vec3::UnitZ()));
}

TEST(ContourTest, CollinearEdgesAreSeparatedAlongTheirLine) {
  // A rectangle with a notch: edges AB and EF lie on one line (y = 0). Moved rigidly by
  // more than the gap between them, their swept boxes overlap while they stay disjoint at
  // every t: only separation along the line can certify them (no side test can: each
  // lies on the other's line).
  Positions x0(8, 3);
  x0 << 0, 0, 0, 1, 0, 0, 1, -1, 0, 2, -1, 0, 2, 0, 0, 3, 0, 0, 3, 1, 0, 0, 1, 0;
  const std::vector<Index> loop{0, 1, 2, 3, 4, 5, 6, 7};
  Positions x1 = x0;
  x1.col(0).array() += 2.0;
  EXPECT_TRUE(contour_stays_simple(loop, x0, x1, Vec3::UnitZ()));
  // E slides left along the line past B during the step: EF overlaps AB at the end.
  x1 = x0;
  x1.row(4) << 0.5, 0, 0;
  EXPECT_FALSE(contour_stays_simple(loop, x0, x1, Vec3::UnitZ()));
  // ... and until E reaches B's x exactly: the edges touch at t = 1.
  x1.row(4) << 1, 0, 0;
  EXPECT_FALSE(contour_stays_simple(loop, x0, x1, Vec3::UnitZ()));
}

// Loops of 512 edges and more are tested in parallel: the same answers.
TEST(ContourTest, LongLoopsGiveTheSameAnswers) {
  // A rigidly moving strip of 300 x 3 cells: long straight sides along the x axis, whose
  // boxes all overlap in y.
  const MeshData strip = make_grid(300, 3, 3.0, 0.03);
  const Contoured tree(strip);
  const NodeContours& contours = tree.contours;
  ASSERT_TRUE(contours.has_single_loop(0));
  ASSERT_EQ(contours.loop(0).size(), 606u);
  Positions x1 = strip.vertices;
  x1.col(0).array() += 0.2;
  x1.col(2).array() += 0.1;
  EXPECT_TRUE(contour_stays_simple(contours.loop(0), strip.vertices, x1, Vec3::UnitZ()));
  // The far side, apart from its ends, sinks through the near one: every corner stays
  // simple, only the sweep over non-adjacent edges can see it.
  Positions sunk = x1;
  for (Index v = 0; v < sunk.rows(); ++v) {
    const double x = strip.vertices(v, 0);
    if (strip.vertices(v, 1) > 0.029 && x > 0.5 && x < 2.5) sunk(v, 1) = -0.02;
  }
  EXPECT_FALSE(contour_stays_simple(contours.loop(0), strip.vertices, sunk, Vec3::UnitZ()));
  // One vertex of a long side slides back past its neighbour: a corner folds back.
  for (const Index along : {7, 150, 290}) {
    Positions folded = x1;
    for (Index v = 0; v < folded.rows(); ++v) {
      if (strip.vertices(v, 1) == 0 && std::abs(strip.vertices(v, 0) - 0.01 * along) < 1e-9) {
        folded(v, 0) -= 0.015;
      }
    }
    EXPECT_FALSE(contour_stays_simple(contours.loop(0), strip.vertices, folded, Vec3::UnitZ()))
        << along;
  }
  // The ribbon's ends overlap in projection whichever way the pitch goes.
  const Ribbon ribbon = make_ribbon(400, 0.02, 0.03);
  const Contoured ribbon_tree(ribbon.mesh);
  ASSERT_TRUE(ribbon_tree.contours.has_single_loop(0));
  ASSERT_GE(ribbon_tree.contours.loop(0).size(), 512u);
  EXPECT_FALSE(contour_stays_simple(ribbon_tree.contours.loop(0), ribbon.mesh.vertices, ribbon.x1,
                                    Vec3::UnitZ()));
}

TEST(NormalConeCulling, ContourTestIsWhatKeepsTheRibbonCollisions) {
  const Ribbon ribbon = make_ribbon(80, 0.02, -0.02);
  const TriangleMesh mesh(static_cast<Index>(ribbon.mesh.vertices.rows()), ribbon.mesh.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, ribbon.mesh.vertices, ribbon.x1);
  ASSERT_GT(truth.size(), 0u);

  SelfCollisionDetector with_contour(mesh, ribbon.mesh.vertices, DetectionConfig::preset("tang"));
  const DetectionResult sound = with_contour.detect(ribbon.mesh.vertices, ribbon.x1);
  EXPECT_EQ(sound.collisions.size(), truth.size());
  EXPECT_GT(sound.stats.contour_tests_failed, 0);

  // The cone alone (under 90 degrees at the root) would skip the whole ribbon.
  DetectionConfig unsound = DetectionConfig::preset("tang");
  unsound.contour_test = false;
  SelfCollisionDetector without_contour(mesh, ribbon.mesh.vertices, unsound);
  const DetectionResult culled = without_contour.detect(ribbon.mesh.vertices, ribbon.x1);
  EXPECT_EQ(culled.stats.candidate_triangle_pairs, 0);
  EXPECT_LT(culled.collisions.size(), truth.size());
}

}  // namespace
}  // namespace tailor
