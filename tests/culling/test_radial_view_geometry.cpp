// The geometric pieces of radial-view culling, each against an independent oracle:
// the exact winding number, the batched plane-side test and the view cones.

#include <gtest/gtest.h>

#include <random>

#include "support/random_steps.hpp"
#include "support/sanitized.hpp"
#include "tailor/culling/moving_plane.hpp"
#include "tailor/culling/view_cone.hpp"
#include "tailor/culling/winding_number.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

using testing::sanitized;

std::vector<TriangleCorners> corners(const MeshData& mesh) {
  std::vector<TriangleCorners> out;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    out.push_back({mesh.vertices.row(mesh.faces(f, 0)), mesh.vertices.row(mesh.faces(f, 1)),
                   mesh.vertices.row(mesh.faces(f, 2))});
  }
  return out;
}

TEST(WindingNumber, SpheresInsideOutsideAndReversed) {
  const MeshData sphere = make_sphere(8, 12, 1.0);
  std::vector<TriangleCorners> surface = corners(sphere);
  EXPECT_EQ(winding_number(surface, Vec3(0, 0, 0)), 1);
  EXPECT_EQ(winding_number(surface, Vec3(0.3, -0.2, 0.5)), 1);
  EXPECT_EQ(winding_number(surface, Vec3(2, 0, 0)), 0);
  EXPECT_EQ(winding_number(surface, Vec3(0.1, 5, -3)), 0);
  // Two nested spheres wind twice around their common centre, once in the shell.
  const MeshData inner = make_sphere(6, 10, 0.5);
  const std::vector<TriangleCorners> inner_surface = corners(inner);
  std::vector<TriangleCorners> nested = surface;
  nested.insert(nested.end(), inner_surface.begin(), inner_surface.end());
  EXPECT_EQ(winding_number(nested, Vec3(0, 0, 0.01)), 2);
  EXPECT_EQ(winding_number(nested, Vec3(0, 0, 0.75)), 1);
  for (TriangleCorners& t : surface) std::swap(t[1], t[2]);
  EXPECT_EQ(winding_number(surface, Vec3(0, 0, 0)), -1);
  EXPECT_EQ(winding_number(surface, Vec3(3, 0, 0)), 0);
}

TEST(WindingNumber, RaysThroughVerticesAreRetried) {
  // An octahedron around the origin: every axis ray from the centre leaves through a
  // vertex, so the first six far points are degenerate and an oblique one decides.
  const Vec3 v[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<TriangleCorners> octahedron;
  for (int sx : {0, 1}) {
    for (int sy : {2, 3}) {
      for (int sz : {4, 5}) {
        TriangleCorners t{v[sx], v[sy], v[sz]};
        const Vec3 normal = (t[1] - t[0]).cross(t[2] - t[0]);
        if (normal.dot(t[0]) < 0) std::swap(t[1], t[2]);  // outward
        octahedron.push_back(t);
      }
    }
  }
  EXPECT_EQ(winding_number(octahedron, Vec3(0, 0, 0)), 1);
  EXPECT_EQ(winding_number(octahedron, Vec3(0.1, 0.1, 0.1)), 1);
  EXPECT_EQ(winding_number(octahedron, Vec3(0, 0, 2)), 0);
}

TEST(WindingNumber, PointOnTheSurfaceHasNone) {
  const std::vector<TriangleCorners> surface = corners(make_sphere(6, 8, 1.0));
  EXPECT_FALSE(winding_number(surface, surface[3][1]).has_value());  // a vertex
  const Vec3 inside_face = (surface[5][0] + surface[5][1] + surface[5][2]) / 3;
  // Rounded onto the face or just off it: never a wrong number.
  const std::optional<int> w = winding_number(surface, inside_face);
  EXPECT_TRUE(!w.has_value() || *w == 0 || *w == 1);
  EXPECT_FALSE(winding_number({}, Vec3(0, 0, 0)).has_value());
}

TEST(MovingPlane, SideIsCoplanaritySign) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const auto random_point = [&] { return Vec3(uniform(rng), uniform(rng), uniform(rng)); };
  const int runs = sanitized() ? 3000 : 30000;
  int decided = 0;
  for (int i = 0; i < runs; ++i) {
    Vec3 a0 = random_point(), q0 = random_point(), r0 = random_point();
    Vec3 a1 = a0 + 0.3 * random_point(), q1 = q0 + 0.3 * random_point();
    Vec3 r1 = r0 + 0.3 * random_point();
    Vec3 p0 = random_point(), p1 = p0 + 0.3 * random_point();
    switch (i % 5) {
      case 1:  // snapped to a coarse lattice: exact zeros and coplanarities
        for (Vec3* x : {&a0, &q0, &r0, &a1, &q1, &r1, &p0, &p1}) {
          *x = (*x * 4).array().round().matrix() / 4;
        }
        break;
      case 2:  // p on the plane at t = 0, or one of its points
        p0 = a0 + 0.5 * (q0 - a0) + 0.25 * (r0 - a0);
        if (i % 2) p1 = q1;
        break;
      case 3:  // tiny and huge scales
        for (Vec3* x : {&a0, &q0, &r0, &a1, &q1, &r1, &p0, &p1}) *x *= (i % 2) ? 1e-120 : 1e120;
        break;
      default:
        break;
    }
    const MovingPlane plane(a0, q0, r0, a1, q1, r1);
    const StepSign expected = coplanarity_sign({a0, p0, q0, r0}, {a1, p1, q1, r1});
    ASSERT_EQ(plane.side(p0, p1), expected) << i;
    decided += expected != StepSign::mixed;
  }
  EXPECT_GT(decided, runs / 4);
}

// Every direction from the observer to a sampled point of the moving triangle lies in
// the cone (its cosine to the axis is at least the cone's lower bound).
TEST(ViewCone, HoldsEverySampledDirection) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(0, 1);
  const auto point = [&](double spread) {
    return Vec3(spread * (uniform(rng) - 0.5), spread * (uniform(rng) - 0.5), 1 + uniform(rng));
  };
  const int runs = sanitized() ? 300 : 3000;
  int narrow = 0;
  for (int i = 0; i < runs; ++i) {
    const double spread = 0.1 + 2.0 * uniform(rng);
    const Vec3 a0 = point(spread), b0 = point(spread), c0 = point(spread);
    const Vec3 a1 = point(spread), b1 = point(spread), c1 = point(spread);
    const Vec3 o0(0.2 * uniform(rng), 0, 0), o1(0, 0.2 * uniform(rng), 0.1 * uniform(rng));
    const ViewCone cone = swept_view_cone({a0, b0, c0}, {a1, b1, c1}, o0, o1);
    if (cone.everything) continue;
    ++narrow;
    for (int s = 0; s < 50; ++s) {
      const double t = uniform(rng);
      double u = uniform(rng), v = uniform(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Vec3 a = (1 - t) * a0 + t * a1, b = (1 - t) * b0 + t * b1, c = (1 - t) * c0 + t * c1;
      const Vec3 x = a + u * (b - a) + v * (c - a);
      const Vec3 direction = (x - ((1 - t) * o0 + t * o1)).normalized();
      ASSERT_GE(direction.dot(cone.axis), cone.cos_half - 1e-12) << i;
    }
  }
  EXPECT_GT(narrow, runs / 3);
}

ViewCone cone_around(const Vec3& axis, double half_angle) {
  ViewCone cone;
  cone.axis = axis.normalized();
  cone.cos_half = std::cos(half_angle);
  cone.sin_half = std::sin(half_angle);
  cone.everything = false;
  return cone;
}

TEST(ViewCone, DisjointOnlyWhenTheAnglesSaySo) {
  // Axes 0.5 rad apart: cones of half-angles summing below 0.5 are disjoint, above not.
  const Vec3 x(1, 0, 0), y(std::cos(0.5), std::sin(0.5), 0);
  EXPECT_TRUE(view_cones_disjoint(cone_around(x, 0.2), cone_around(y, 0.29)));
  EXPECT_FALSE(view_cones_disjoint(cone_around(x, 0.2), cone_around(y, 0.31)));
  EXPECT_FALSE(view_cones_disjoint(cone_around(x, 0.25), cone_around(y, 0.25)));  // touching
  EXPECT_FALSE(view_cones_disjoint(cone_around(x, 0.1), ViewCone{}));             // everything
  // A bounding cone holds its members: disjoint from a third cone only if each member is.
  const ViewCone members[] = {cone_around(x, 0.05), cone_around(Vec3(1, 0.1, 0), 0.05)};
  const ViewCone group = bounding_view_cone(members, 2);
  ASSERT_FALSE(group.everything);
  for (const ViewCone& m : members) {
    // The member's farthest direction from the group axis is within the group's angle.
    const double to_axis = std::acos(std::min(1.0, m.axis.dot(group.axis)));
    EXPECT_LE(to_axis + std::acos(m.cos_half), std::acos(group.cos_half) + 1e-12);
  }
  const ViewCone far = cone_around(Vec3(0, 1, 0), 0.2);
  EXPECT_TRUE(view_cones_disjoint(group, far));
  EXPECT_FALSE(view_cones_disjoint(group, cone_around(Vec3(1, 0.2, 0), 0.05)));
}

}  // namespace
}  // namespace tailor
