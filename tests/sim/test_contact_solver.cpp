/// @file
/// The contact solver: after resolve() nothing collides over the substep (checked with the
/// brute-force CCD oracle and the exact static intersection test), pinned vertices stay.

#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "tailor/ccd/ccd.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/intersection_check.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/sim/contact_solver.hpp"

namespace tailor {
namespace {

using tailor::testing::sanitized;

/// A grid of nx × ny vertices; `place(i, j)` gives each vertex's position.
template <class Place>
void add_grid(int nx, int ny, Place place, Positions& x, std::vector<std::array<Index, 3>>& faces) {
  const Index base = static_cast<Index>(x.rows());
  x.conservativeResize(base + nx * ny, 3);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) x.row(base + j * nx + i) = place(i, j).transpose();
  }
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const Index v = base + j * nx + i;
      faces.push_back({v, v + 1, v + nx + 1});
      faces.push_back({v, v + nx + 1, v + nx});
    }
  }
}

FaceArray to_faces(const std::vector<std::array<Index, 3>>& faces) {
  FaceArray f(static_cast<Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i)
    f.row(static_cast<Index>(i)) << faces[i][0], faces[i][1], faces[i][2];
  return f;
}

/// Every cloth-obstacle VF (both ways) and EE contact over the step, by brute force.
std::int64_t obstacle_contacts(const TriangleMesh& cloth, const Positions& x0, const Positions& x1,
                               const TriangleMesh& obs, const Positions& y0, const Positions& y1,
                               const std::vector<char>& pinned) {
  std::int64_t n = 0;
  const auto r = [](const Positions& p, Index i) -> Vec3 { return p.row(i).transpose(); };
  for (Index v = 0; v < cloth.num_vertices(); ++v) {
    if (pinned[v]) continue;
    for (Index f = 0; f < obs.num_faces(); ++f) {
      const auto F = obs.faces().row(f);
      n += vertex_face_ccd({r(x0, v), r(y0, F(0)), r(y0, F(1)), r(y0, F(2)), r(x1, v), r(y1, F(0)),
                            r(y1, F(1)), r(y1, F(2))})
               .hit;
    }
  }
  for (Index f = 0; f < cloth.num_faces(); ++f) {
    const auto F = cloth.faces().row(f);
    if (pinned[F(0)] || pinned[F(1)] || pinned[F(2)]) continue;
    for (Index v = 0; v < obs.num_vertices(); ++v) {
      n += vertex_face_ccd({r(y0, v), r(x0, F(0)), r(x0, F(1)), r(x0, F(2)), r(y1, v), r(x1, F(0)),
                            r(x1, F(1)), r(x1, F(2))})
               .hit;
    }
  }
  for (Index e = 0; e < cloth.num_edges(); ++e) {
    const auto E = cloth.edges().row(e);
    if (pinned[E(0)] || pinned[E(1)]) continue;
    for (Index g = 0; g < obs.num_edges(); ++g) {
      const auto G = obs.edges().row(g);
      n += edge_edge_ccd({r(x0, E(0)), r(x0, E(1)), r(y0, G(0)), r(y0, G(1)), r(x1, E(0)),
                          r(x1, E(1)), r(y1, G(0)), r(y1, G(1))})
               .hit;
    }
  }
  return n;
}

void print(const ContactStats& s) {
  std::printf(
      "self %lld obstacle %lld repulsions %lld impulses %lld passes %lld zones %lld "
      "zone_passes %lld last_resort %d reverted %lld following %lld unresolved %lld "
      "detect %.2f ms response %.2f ms\n",
      (long long)s.self_collisions, (long long)s.obstacle_collisions, (long long)s.repulsions,
      (long long)s.impulses, (long long)s.impulse_iterations, (long long)s.impact_zones,
      (long long)s.zone_iterations, int(s.last_resort), (long long)s.reverted_vertices,
      (long long)s.arm_following_vertices, (long long)s.unresolved, s.detection_ms, s.response_ms);
}

ContactParams params_for_tests() {
  ContactParams p;
  p.thickness = 2e-3;
  p.friction = 0.3;
  p.max_impulse_iterations = 10;
  p.max_zone_iterations = 50;
  return p;
}

TEST(ContactSolver, TwoPatchesDrivenThroughEachOther) {
  // Patch A lies at z = 0 (corners pinned); patch B starts 1 cm above it and is driven
  // 2 cm down in one step, straight through A.
  Positions x0(0, 3);
  std::vector<std::array<Index, 3>> faces;
  const int n = sanitized() ? 6 : 9;
  add_grid(
      n, n, [&](int i, int j) { return Vec3(i / (n - 1.0), j / (n - 1.0), 0.0); }, x0, faces);
  const Index b_first = static_cast<Index>(x0.rows());
  add_grid(
      n, n,
      [&](int i, int j) {
        return Vec3(0.1 + 0.8 * i / (n - 1.0), 0.05 + 0.8 * j / (n - 1.0), 0.01);
      },
      x0, faces);
  const TriangleMesh mesh(static_cast<Index>(x0.rows()), to_faces(faces));
  Eigen::VectorXd masses = Eigen::VectorXd::Constant(x0.rows(), 0.01);
  std::vector<char> pinned(static_cast<std::size_t>(x0.rows()), 0);
  for (Index v : {0, n - 1, n * (n - 1), n * n - 1}) {
    masses[v] = std::numeric_limits<double>::infinity();
    pinned[v] = 1;
  }
  Positions x1 = x0;
  for (Index v = b_first; v < x0.rows(); ++v) x1(v, 2) -= 0.02 + 0.001 * std::sin(3.0 * v);
  ASSERT_GT(brute_force_self_collisions(mesh, x0, x1).size(), 0u);

  ContactSolver solver(mesh, x0, masses, DetectionConfig::preset("paper"), params_for_tests());
  const Positions before = x1;
  const ContactStats stats = solver.resolve(x0, x1, KinematicObstacle{}, 1.0 / 100);
  print(stats);
  EXPECT_GT(stats.self_collisions, 0);
  EXPECT_EQ(stats.unresolved, 0);
  EXPECT_EQ(brute_force_self_collisions(mesh, x0, x1).size(), 0u);
  EXPECT_TRUE(check_intersections(mesh, x1).intersection_free());
  for (Index v = 0; v < x0.rows(); ++v) {
    if (pinned[v]) {
      EXPECT_EQ(x1.row(v), before.row(v)) << v;
    }
  }
  // Deterministic: the same call gives the same positions.
  ContactSolver again(mesh, x0, masses, DetectionConfig::preset("paper"), params_for_tests());
  Positions x1b = before;
  again.resolve(x0, x1b, KinematicObstacle{}, 1.0 / 100);
  EXPECT_EQ(x1b, x1);
}

TEST(ContactSolver, FoldedStripPressedFlat) {
  // A strip folded into a U (radius 1 cm); over several substeps the upper layer is pushed
  // down through the lower one, which is pinned along its far end.
  const double r = 0.01, len = 0.3;
  const int nu = sanitized() ? 24 : 40, nv = sanitized() ? 3 : 5;
  const double total = 2 * len + std::numbers::pi * r;
  const auto place = [&](int i, int j) {
    const double u = total * i / (nu - 1.0), y = 0.1 * j / (nv - 1.0);
    if (u <= len) return Vec3(u, y, 0.0);
    if (u <= len + std::numbers::pi * r) {
      const double a = (u - len) / r;
      return Vec3(len + r * std::sin(a), y, r - r * std::cos(a));
    }
    return Vec3(len - (u - len - std::numbers::pi * r), y, 2 * r);
  };
  Positions x(0, 3);
  std::vector<std::array<Index, 3>> faces;
  add_grid(nu, nv, place, x, faces);
  const TriangleMesh mesh(static_cast<Index>(x.rows()), to_faces(faces));
  ASSERT_TRUE(check_intersections(mesh, x).intersection_free());
  Eigen::VectorXd masses = Eigen::VectorXd::Constant(x.rows(), 0.001);
  std::vector<char> pinned(static_cast<std::size_t>(x.rows()), 0);
  for (int j = 0; j < nv; ++j) {
    masses[j * nu] = std::numeric_limits<double>::infinity();
    pinned[j * nu] = 1;
  }
  ContactSolver solver(mesh, x, masses, DetectionConfig::preset("paper"), params_for_tests());
  std::int64_t collisions = 0;
  const int steps = sanitized() ? 2 : 8;
  for (int step = 0; step < steps; ++step) {
    Positions x1 = x;
    for (int i = 0; i < nu; ++i) {
      const double u = total * i / (nu - 1.0);
      if (u <= len + 0.5 * std::numbers::pi * r) continue;
      for (int j = 0; j < nv; ++j) x1(j * nu + i, 2) -= 0.012 * (1 + 0.1 * j);  // tilted push
    }
    const Positions before = x1;
    const ContactStats stats = solver.resolve(x, x1, KinematicObstacle{}, 1.0 / 200);
    print(stats);
    collisions += stats.self_collisions;
    EXPECT_EQ(stats.unresolved, 0) << step;
    EXPECT_EQ(brute_force_self_collisions(mesh, x, x1).size(), 0u) << step;
    EXPECT_TRUE(check_intersections(mesh, x1).intersection_free()) << step;
    for (Index v = 0; v < x.rows(); ++v) {
      if (pinned[v]) {
        EXPECT_EQ(x1.row(v), before.row(v));
      }
    }
    x = x1;
  }
  EXPECT_GT(collisions, 0);  // the push did have to be stopped
}

/// A cloth patch falls under gravity onto a box that rises into it; the box is the
/// kinematic obstacle. The iteration limits force later stages.
void cloth_on_rising_box(int impulse_passes, int zone_passes, bool expect_rest, int steps) {
  Positions box(8, 3);
  const double lo = -0.1, hi = 0.1;
  for (int k = 0; k < 8; ++k)
    box.row(k) << ((k & 1) ? hi : lo), ((k & 2) ? hi : lo), ((k & 4) ? 0.0 : -0.2);
  FaceArray bf(12, 3);  // outward orientation
  bf << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1,
      3, 5, 3, 7, 5;
  const TriangleMesh box_mesh(8, bf);

  Positions x(0, 3);
  std::vector<std::array<Index, 3>> faces;
  const int n = 12;
  add_grid(
      n, n,
      [&](int i, int j) {
        return Vec3(-0.15 + 0.3 * i / (n - 1.0) + 0.003, -0.15 + 0.3 * j / (n - 1.0) + 0.002, 0.01);
      },
      x, faces);
  const TriangleMesh cloth(static_cast<Index>(x.rows()), to_faces(faces));
  const Eigen::VectorXd masses = Eigen::VectorXd::Constant(x.rows(), 0.001);
  const std::vector<char> pinned(static_cast<std::size_t>(x.rows()), 0);
  ContactParams p = params_for_tests();
  p.max_impulse_iterations = impulse_passes;
  p.max_zone_iterations = zone_passes;
  ContactSolver solver(cloth, x, masses, DetectionConfig::preset("paper"), p);

  const double dt = 1.0 / 100;
  Positions v = Positions::Zero(x.rows(), 3);
  const Vec3 gravity(0, 0, -9.81);
  std::int64_t obstacle_hits = 0, repulsions = 0;
  Positions y = box;
  for (int step = 0; step < steps; ++step) {
    Positions y1 = y;
    y1.col(2).array() += 0.01;  // the box rises 1 cm per step
    Positions x1 = x + dt * v;
    x1.rowwise() += (dt * dt * gravity).transpose();
    KinematicObstacle obstacle{&box_mesh, y, y1};
    const ContactStats stats = solver.resolve(x, x1, obstacle, dt);
    print(stats);
    obstacle_hits += stats.obstacle_collisions;
    repulsions += stats.repulsions;
    EXPECT_EQ(stats.unresolved, 0) << step;
    EXPECT_EQ(obstacle_contacts(cloth, x, x1, box_mesh, y, y1, pinned), 0) << step;
    EXPECT_EQ(brute_force_self_collisions(cloth, x, x1).size(), 0u) << step;
    EXPECT_TRUE(check_intersections(cloth, x1, &box_mesh, &y1).intersection_free()) << step;
    // No cloth vertex inside the box.
    for (Index i = 0; i < x1.rows(); ++i) {
      const bool inside = x1(i, 0) > lo && x1(i, 0) < hi && x1(i, 1) > lo && x1(i, 1) < hi &&
                          x1(i, 2) < y1(4, 2) && x1(i, 2) > y1(0, 2);
      EXPECT_FALSE(inside) << "step " << step << " vertex " << i;
    }
    v = (x1 - x) / dt;
    x = x1;
    y = y1;
  }
  EXPECT_GT(obstacle_hits + repulsions, 0);  // the box did reach the cloth
  // The cloth rests on the box top (within a few thicknesses) where it covers it.
  const Index centre = (n / 2) * n + n / 2;
  EXPECT_GE(x(centre, 2), y(4, 2));
  if (expect_rest) {
    EXPECT_LT(x(centre, 2), y(4, 2) + 0.02);
  }
}

TEST(ContactSolver, ClothFallingOntoARisingBox) {
  cloth_on_rising_box(10, 50, true, sanitized() ? 4 : 20);
}

TEST(ContactSolver, ClothOnRisingBoxZonesAndLastResort) {
  const int steps = sanitized() ? 3 : 8;
  cloth_on_rising_box(1, 50, false, steps);  // impact zones with arm-following kinematic vertices
  cloth_on_rising_box(1, 0, false, steps);   // last resort: vertices follow the box
}

/// A wavy sheet given large random end positions: many collisions at once, with the
/// impulse, zone and last-resort stages forced one by one by their iteration limits.
void chaotic_step(int seed, int impulse_passes, int zone_passes, bool pin_some) {
  std::mt19937 rng(static_cast<unsigned>(seed));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Positions x0(0, 3);
  std::vector<std::array<Index, 3>> faces;
  const int n = 8;
  add_grid(
      n, n,
      [&](int i, int j) {
        return Vec3(i / (n - 1.0), j / (n - 1.0),
                    0.05 * std::sin(5.0 * i / n + seed) * std::cos(4.0 * j / n));
      },
      x0, faces);
  const TriangleMesh mesh(static_cast<Index>(x0.rows()), to_faces(faces));
  Eigen::VectorXd masses = Eigen::VectorXd::Constant(x0.rows(), 0.002);
  std::vector<char> pinned(static_cast<std::size_t>(x0.rows()), 0);
  if (pin_some) {
    for (Index v = 0; v < x0.rows(); v += 9) {
      masses[v] = std::numeric_limits<double>::infinity();
      pinned[v] = 1;
    }
  }
  Positions x1 = x0;
  for (Index v = 0; v < x0.rows(); ++v) {
    if (!pinned[v]) x1.row(v) += 0.25 * Vec3(u(rng), u(rng), u(rng)).transpose();
  }
  ContactParams p = params_for_tests();
  p.max_impulse_iterations = impulse_passes;
  p.max_zone_iterations = zone_passes;
  ContactSolver solver(mesh, x0, masses, DetectionConfig::preset("paper"), p);
  const Positions before = x1;
  const ContactStats stats = solver.resolve(x0, x1, KinematicObstacle{}, 0.01);
  print(stats);
  EXPECT_GT(stats.self_collisions, 0);
  EXPECT_EQ(stats.unresolved, 0);
  EXPECT_EQ(brute_force_self_collisions(mesh, x0, x1).size(), 0u);
  EXPECT_TRUE(check_intersections(mesh, x1).intersection_free());
  for (Index v = 0; v < x0.rows(); ++v) {
    if (pinned[v]) {
      EXPECT_EQ(x1.row(v), before.row(v));
    }
  }
  if (zone_passes == 0 && impulse_passes <= 1) {
    EXPECT_TRUE(stats.last_resort);
  }
}

TEST(ContactSolver, ChaoticMotionAllStages) {
  const int seeds = sanitized() ? 1 : 3;
  for (int seed = 0; seed < seeds; ++seed) {
    chaotic_step(seed, 20, 100, seed % 2 == 1);  // the defaults
    chaotic_step(seed, 1, 100, seed % 2 == 0);   // straight to the impact zones
    chaotic_step(seed, 1, 0, seed % 2 == 1);     // straight to the last resort
  }
}

TEST(ContactSolver, RejectsBadInput) {
  Positions x(0, 3);
  std::vector<std::array<Index, 3>> faces;
  add_grid(
      3, 3, [](int i, int j) { return Vec3(i, j, 0); }, x, faces);
  const TriangleMesh mesh(static_cast<Index>(x.rows()), to_faces(faces));
  const auto make_bad = [&] {
    ContactSolver bad(mesh, x, Eigen::VectorXd::Ones(4), DetectionConfig{}, ContactParams{});
  };
  EXPECT_THROW(make_bad(), InputError);
  ContactSolver solver(mesh, x, Eigen::VectorXd::Ones(x.rows()), DetectionConfig{},
                       ContactParams{});
  Positions wrong = x.topRows(3);
  EXPECT_THROW(solver.resolve(x, wrong, KinematicObstacle{}, 0.01), InputError);
}

}  // namespace
}  // namespace tailor
