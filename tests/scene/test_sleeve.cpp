/// @file
/// Sleeve topology and placement.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "tailor/geometry/error.hpp"
#include "tailor/scene/sleeve.hpp"

namespace tailor {
namespace {

TEST(Sleeve, DefaultIsThePapersSize) {
  const Arm arm;
  const Sleeve s = make_sleeve(arm, SleeveParams{});
  EXPECT_EQ(s.mesh->num_vertices(), 693);
  EXPECT_EQ(s.mesh->num_faces(), 1320);
  EXPECT_EQ(s.mesh->num_boundary_loops(), 2);
  EXPECT_EQ(s.mesh->num_components(), 1);
  EXPECT_TRUE(s.mesh->validation().is_manifold());
}

TEST(Sleeve, BoundaryLoopsAreTheEndRings) {
  const Arm arm;
  const Sleeve s = make_sleeve(arm, SleeveParams{});
  std::set<std::set<Index>> loops, ends;
  for (Index i = 0; i < s.mesh->num_boundary_loops(); ++i) {
    const auto loop = s.mesh->boundary_loop(i);
    loops.insert(std::set<Index>(loop.begin(), loop.end()));
  }
  for (const Index r : s.open_end_rings()) {
    const auto ring = s.ring(r);
    ends.insert(std::set<Index>(ring.begin(), ring.end()));
  }
  EXPECT_EQ(loops, ends);
  EXPECT_EQ(s.pinned_vertices(), s.ring(0));
}

TEST(Sleeve, RingsAreLoopsAroundTheArmWithSlack) {
  const Arm arm;
  SleeveParams params;
  const Sleeve s = make_sleeve(arm, params);
  const auto rings = s.rings();
  ASSERT_EQ(rings.size(), 21u);
  for (const auto& ring : rings) {
    ASSERT_EQ(ring.size(), 33u);
    const double x = s.rest(ring[0], 0);
    for (std::size_t j = 0; j < ring.size(); ++j) {
      // Consecutive ring vertices share an edge (the ring is a loop of the mesh).
      EXPECT_GE(s.mesh->find_edge(ring[j], ring[(j + 1) % ring.size()]), 0);
      EXPECT_DOUBLE_EQ(s.rest(ring[j], 0), x);
      const double r = s.rest.row(ring[j]).tail<2>().norm();
      EXPECT_NEAR(r - arm.radius_at(x), params.slack, 1e-9);
    }
  }
  EXPECT_NEAR(s.rest.col(0).minCoeff(), params.start, 1e-12);
  EXPECT_NEAR(s.rest.col(0).maxCoeff(), params.start + params.length, 1e-12);
}

TEST(Sleeve, FacesPointAwayFromTheArm) {
  const Arm arm;
  const Sleeve s = make_sleeve(arm, SleeveParams{});
  const FaceArray& f = s.mesh->faces();
  for (Eigen::Index t = 0; t < f.rows(); ++t) {
    const Vec3 a = s.rest.row(f(t, 0)), b = s.rest.row(f(t, 1)), c = s.rest.row(f(t, 2));
    const Vec3 n = (b - a).cross(c - a);
    const Vec3 centre = (a + b + c) / 3;
    EXPECT_GT(n.dot(Vec3(0, centre.y(), centre.z())), 0) << "face " << t;
  }
}

TEST(Sleeve, ScalesLinearly) {
  const Arm arm;
  SleeveParams params;
  params.rings = 301;
  params.segments = 500;
  const Sleeve s = make_sleeve(arm, params);
  EXPECT_EQ(s.mesh->num_vertices(), 301 * 500);
  EXPECT_EQ(s.mesh->num_faces(), 2 * 300 * 500);
  EXPECT_EQ(s.mesh->num_boundary_loops(), 2);
}

TEST(Sleeve, RejectsBadParameters) {
  const Arm arm;
  SleeveParams p;
  p.rings = 1;
  EXPECT_THROW(make_sleeve(arm, p), InputError);
  p = SleeveParams{};
  p.length = 1.0;  // longer than the arm
  EXPECT_THROW(make_sleeve(arm, p), InputError);
  p = SleeveParams{};
  p.slack = 0;
  EXPECT_THROW(make_sleeve(arm, p), InputError);
}

}  // namespace
}  // namespace tailor
