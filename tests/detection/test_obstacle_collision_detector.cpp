/// @file
/// The cloth vs moving obstacle detector reports exactly the collisions that brute force
/// (every vertex-face pair both ways and every edge-edge pair through the exact CCD)
/// reports, with exempt vertices skipped.

#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <random>

#include "tailor/ccd/ccd.hpp"
#include "tailor/detection/obstacle_collision_detector.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

/// An n × n grid in the x-z plane at height y, side `size`, jittered by `jitter`.
void grid(int n, double size, double y, double jitter, std::mt19937& rng, Positions& x,
          FaceArray& f) {
  std::uniform_real_distribution<double> u(-jitter, jitter);
  x.resize(n * n, 3);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      x.row(i * n + j) << size * j / (n - 1) + u(rng), y + u(rng), size * i / (n - 1) + u(rng);
  }
  f.resize(2 * (n - 1) * (n - 1), 3);
  int k = 0;
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + 1, c = a + n, d = c + 1;
      f.row(k++) << a, c, b;
      f.row(k++) << b, c, d;
    }
  }
}

Vec3 r(const Positions& p, Index i) {
  return p.row(i).transpose();
}

std::vector<ObstacleCollision> brute_force(const TriangleMesh& cloth, const Positions& x0,
                                           const Positions& x1, const TriangleMesh& obs,
                                           const Positions& y0, const Positions& y1,
                                           const std::vector<char>& exempt) {
  std::vector<ObstacleCollision> out;
  for (Index v = 0; v < cloth.num_vertices(); ++v) {
    if (exempt[v]) continue;
    for (Index f = 0; f < obs.num_faces(); ++f) {
      const auto F = obs.faces().row(f);
      const CcdResult c = vertex_face_ccd({r(x0, v), r(y0, F(0)), r(y0, F(1)), r(y0, F(2)),
                                           r(x1, v), r(y1, F(0)), r(y1, F(1)), r(y1, F(2))});
      if (c.hit) out.push_back({ObstacleCollision::vertex_face, v, f, c.toi});
    }
  }
  for (Index f = 0; f < cloth.num_faces(); ++f) {
    const auto F = cloth.faces().row(f);
    if (exempt[F(0)] || exempt[F(1)] || exempt[F(2)]) continue;
    for (Index v = 0; v < obs.num_vertices(); ++v) {
      const CcdResult c = vertex_face_ccd({r(y0, v), r(x0, F(0)), r(x0, F(1)), r(x0, F(2)),
                                           r(y1, v), r(x1, F(0)), r(x1, F(1)), r(x1, F(2))});
      if (c.hit) out.push_back({ObstacleCollision::face_vertex, f, v, c.toi});
    }
  }
  for (Index e = 0; e < cloth.num_edges(); ++e) {
    const auto E = cloth.edges().row(e);
    if (exempt[E(0)] || exempt[E(1)]) continue;
    for (Index g = 0; g < obs.num_edges(); ++g) {
      const auto G = obs.edges().row(g);
      const CcdResult c = edge_edge_ccd({r(x0, E(0)), r(x0, E(1)), r(y0, G(0)), r(y0, G(1)),
                                         r(x1, E(0)), r(x1, E(1)), r(y1, G(0)), r(y1, G(1))});
      if (c.hit) out.push_back({ObstacleCollision::edge_edge, e, g, c.toi});
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ObstacleCollisionDetector, MatchesBruteForceOnRandomSteps) {
  std::mt19937 rng(11);
  const int n = tailor::testing::sanitized() ? 5 : 8;
  const int steps = tailor::testing::sanitized() ? 4 : 12;
  std::int64_t total = 0;
  for (int step = 0; step < steps; ++step) {
    Positions x0, x1, y0, y1;
    FaceArray cf, of;
    // Cloth falling through a rising obstacle sheet: many collisions of every kind.
    grid(n, 0.1, 0.02, 0.004, rng, x0, cf);
    grid(n, 0.1, -0.02, 0.004, rng, x1, cf);
    grid(n - 1, 0.11, -0.015, 0.004, rng, y0, of);
    grid(n - 1, 0.11, 0.015, 0.004, rng, y1, of);
    const TriangleMesh cloth(n * n, cf), obstacle((n - 1) * (n - 1), of);
    std::vector<char> exempt(static_cast<std::size_t>(n * n), 0);
    exempt[static_cast<std::size_t>(step % (n * n))] = 1;
    ObstacleCollisionDetector detector(cloth, exempt);
    detector.set_obstacle(obstacle, y0, y1);
    const auto found = detector.detect(x0, x1);
    const auto expected = brute_force(cloth, x0, x1, obstacle, y0, y1, exempt);
    ASSERT_EQ(found.size(), expected.size()) << "step " << step;
    for (std::size_t i = 0; i < found.size(); ++i) {
      EXPECT_EQ(found[i], expected[i]) << "step " << step << " collision " << i;
      EXPECT_EQ(found[i].toi, expected[i].toi);
    }
    total += static_cast<std::int64_t>(found.size());
  }
  EXPECT_GT(total, 10 * steps);  // the steps did collide
}

TEST(ObstacleCollisionDetector, CleanStepAndBadInput) {
  std::mt19937 rng(3);
  Positions x0, y0;
  FaceArray cf, of;
  grid(4, 0.1, 0.05, 0.0, rng, x0, cf);
  grid(4, 0.1, 0.0, 0.0, rng, y0, of);
  const TriangleMesh cloth(16, cf), obstacle(16, of);
  ObstacleCollisionDetector detector(cloth);
  EXPECT_THROW(detector.detect(x0, x0), InputError);  // no obstacle yet
  detector.set_obstacle(obstacle, y0, y0);
  EXPECT_TRUE(detector.detect(x0, x0).empty());
  EXPECT_THROW(detector.detect(x0, Positions(3, 3)), InputError);
  EXPECT_THROW(detector.set_obstacle(obstacle, y0, Positions(2, 3)), InputError);
  EXPECT_THROW(ObstacleCollisionDetector(cloth, std::vector<char>(3, 0)), InputError);
  const ObstacleCollision c{ObstacleCollision::face_vertex, 0, 0, 1};
  EXPECT_EQ(detector.cloth_vertices(c).size(), 3u);
}

}  // namespace
}  // namespace tailor
