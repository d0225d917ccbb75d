/// @file
/// The static intersection checker: hand-made meshes, BVH-accelerated vs brute force, CLI.

#include "support/run_cli.hpp"
#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "tailor/detection/intersection_check.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/triangle_intersection.hpp"

namespace tailor {
namespace {

using tailor::testing::sanitized;

/// An n×n-vertex grid in the plane z = 0 over [0, 1]², two triangles per cell.
struct Grid {
  FaceArray faces;
  Positions x;
};
Grid unit_square_grid(int n) {
  Grid g;
  g.x.resize(n * n, 3);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) g.x.row(j * n + i) << double(i) / (n - 1), double(j) / (n - 1), 0.0;
  }
  g.faces.resize(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const Index v = j * n + i;
      g.faces.row(f++) << v, v + 1, v + n + 1;
      g.faces.row(f++) << v, v + n + 1, v + n;
    }
  }
  return g;
}

/// All pairs, no BVH: the oracle.
IntersectionReport brute_force(const TriangleMesh& mesh, const Positions& x) {
  IntersectionReport r;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    for (Index g = f + 1; g < mesh.num_faces(); ++g) {
      const std::array<Index, 3> ff{mesh.faces()(f, 0), mesh.faces()(f, 1), mesh.faces()(f, 2)};
      const std::array<Index, 3> gg{mesh.faces()(g, 0), mesh.faces()(g, 1), mesh.faces()(g, 2)};
      const auto v = classify_face_pair(x, ff, gg);
      if (v == TrianglePairVerdict::intersecting) {
        ++(mesh.faces_share_vertex(f, g) ? r.adjacent_intersections : r.self_intersections);
        r.self_pairs.emplace_back(f, g);
      } else if (v == TrianglePairVerdict::degenerate_adjacent) {
        ++r.undecided_adjacent_pairs;
      }
    }
  }
  return r;
}

TEST(IntersectionCheck, FlatGridIsClean) {
  const Grid g = unit_square_grid(12);
  const TriangleMesh mesh(static_cast<Index>(g.x.rows()), g.faces);
  const auto r = check_intersections(mesh, g.x);
  EXPECT_TRUE(r.intersection_free());
  EXPECT_EQ(r.degenerate_faces, 0);
  EXPECT_EQ(r.undecided_adjacent_pairs, 0);
  EXPECT_GT(r.self_candidate_pairs, mesh.num_faces());  // neighbours' boxes touch
}

TEST(IntersectionCheck, WavyGridIsClean) {
  Grid g = unit_square_grid(20);
  for (Index v = 0; v < g.x.rows(); ++v)
    g.x(v, 2) = 0.1 * std::sin(9 * g.x(v, 0)) * std::cos(7 * g.x(v, 1));
  const TriangleMesh mesh(static_cast<Index>(g.x.rows()), g.faces);
  EXPECT_TRUE(check_intersections(mesh, g.x).intersection_free());
}

TEST(IntersectionCheck, VertexDraggedOverTheSheet) {
  // Fold the last column of a strip over the sheet, then push one vertex through it.
  Grid g = unit_square_grid(6);
  const TriangleMesh mesh(static_cast<Index>(g.x.rows()), g.faces);
  Positions x = g.x;
  // Drag a middle vertex flat over a distant part of the sheet: its faces now overlap
  // faces they share no vertex with (coplanar overlap).
  const Index mid = 2 * 6 + 2;
  x.row(mid) << 0.9, 0.9, 0.0;
  const auto r = check_intersections(mesh, x, nullptr, nullptr, 1000);
  EXPECT_FALSE(r.intersection_free());
  const auto b = brute_force(mesh, x);
  EXPECT_EQ(r.self_intersections, b.self_intersections);
  EXPECT_EQ(r.adjacent_intersections, b.adjacent_intersections);
  EXPECT_EQ(r.self_pairs, b.self_pairs);
}

TEST(IntersectionCheck, FoldedFlatFlapIsAdjacentIntersection) {
  // Two triangles sharing an edge, folded flat onto each other: no vertex-disjoint pair
  // intersects, only the adjacent test sees it.
  Positions x(4, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.5, 0;
  FaceArray f(2, 3);
  f << 0, 1, 2, 1, 0, 3;
  const TriangleMesh mesh(4, f);
  auto r = check_intersections(mesh, x);
  EXPECT_EQ(r.adjacent_intersections, 1);
  EXPECT_EQ(r.self_intersections, 0);
  x(3, 2) = 1e-9;  // lifted: clean
  r = check_intersections(mesh, x);
  EXPECT_TRUE(r.intersection_free());
  x(3, 1) = -0.5;  // unfolded
  x(3, 2) = 0;
  EXPECT_TRUE(check_intersections(mesh, x).intersection_free());
}

TEST(IntersectionCheck, ObstacleCrossingAndTouching) {
  const Grid g = unit_square_grid(8);
  const TriangleMesh cloth(static_cast<Index>(g.x.rows()), g.faces);
  // A tetrahedron whose apex goes through the sheet, then one that only touches it.
  Positions y(4, 3);
  y << 0.3, 0.3, -0.5, 0.7, 0.3, -0.5, 0.5, 0.7, -0.5, 0.5, 0.45, 0.25;
  FaceArray tf(4, 3);
  tf << 0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3;
  const TriangleMesh tet(4, tf);
  auto r = check_intersections(cloth, g.x, &tet, &y);
  EXPECT_GT(r.obstacle_intersections, 0);
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_FALSE(r.obstacle_pairs.empty());
  EXPECT_TRUE(std::is_sorted(r.obstacle_pairs.begin(), r.obstacle_pairs.end()));
  y(3, 2) = 0.0;  // the apex exactly on the sheet: touching counts
  r = check_intersections(cloth, g.x, &tet, &y);
  EXPECT_GT(r.obstacle_intersections, 0);
  // Exempting the vertices around the touching point hides exactly those faces.
  std::vector<Index> exempt;
  for (Index v = 0; v < cloth.num_vertices(); ++v) {
    if (std::abs(g.x(v, 0) - 0.5) < 0.2 && std::abs(g.x(v, 1) - 0.45) < 0.2) exempt.push_back(v);
  }
  EXPECT_TRUE(check_intersections(cloth, g.x, &tet, &y, 10, exempt).intersection_free());
  y(3, 2) = -1e-12;  // below the sheet: clean
  r = check_intersections(cloth, g.x, &tet, &y);
  EXPECT_TRUE(r.intersection_free());
}

TEST(IntersectionCheck, BadInputThrows) {
  const Grid g = unit_square_grid(3);
  const TriangleMesh mesh(static_cast<Index>(g.x.rows()), g.faces);
  const Positions wrong = g.x.topRows(4);
  EXPECT_THROW(check_intersections(mesh, wrong), InputError);
}

TEST(IntersectionCheck, MatchesBruteForceOnRandomMeshes) {
  std::mt19937 rng(3);
  const int rounds = sanitized() ? 4 : 25;
  std::int64_t found = 0;
  for (int round = 0; round < rounds; ++round) {
    // A crumpled grid: random displacements large enough to make many intersections,
    // coordinates on a coarse dyadic grid so that coplanar and touching cases are common.
    Grid g = unit_square_grid(7 + round % 4);
    std::uniform_int_distribution<int> d(-4, 4);
    const double amp = (round % 3 == 0) ? 0.0 : 1.0 / 32.0 * (round % 3);
    for (Index v = 0; v < g.x.rows(); ++v) {
      g.x(v, 0) += amp * d(rng);
      g.x(v, 1) += amp * d(rng);
      g.x(v, 2) += 2 * amp * d(rng);
    }
    const TriangleMesh mesh(static_cast<Index>(g.x.rows()), g.faces);
    const auto r = check_intersections(mesh, g.x, nullptr, nullptr, 1u << 30);
    const auto b = brute_force(mesh, g.x);
    EXPECT_EQ(r.self_intersections, b.self_intersections) << round;
    EXPECT_EQ(r.adjacent_intersections, b.adjacent_intersections) << round;
    EXPECT_EQ(r.undecided_adjacent_pairs, b.undecided_adjacent_pairs) << round;
    EXPECT_EQ(r.self_pairs, b.self_pairs) << round;
    found += r.total();
    // Deterministic: a second run gives the same list.
    EXPECT_EQ(check_intersections(mesh, g.x, nullptr, nullptr, 1u << 30).self_pairs, r.self_pairs);
  }
  EXPECT_GT(found, 0);  // the crumpled meshes do intersect
}

#ifdef TAILOR_CLI_PATH
void write_obj_file(const std::filesystem::path& p, const Positions& x, const FaceArray& f) {
  std::ofstream out(p);
  out.precision(17);
  for (Index v = 0; v < x.rows(); ++v)
    out << "v " << x(v, 0) << ' ' << x(v, 1) << ' ' << x(v, 2) << '\n';
  for (Index i = 0; i < f.rows(); ++i)
    out << "f " << f(i, 0) + 1 << ' ' << f(i, 1) + 1 << ' ' << f(i, 2) + 1 << '\n';
}

/// Exit code of `tailor check-intersections FILES...`.
int run_check_intersections_cli(const std::vector<std::filesystem::path>& files) {
  std::string arguments = "check-intersections";
  for (const auto& file : files) {
    arguments += ' ';
    arguments += testing::quoted(file);
  }
  return testing::run_cli(arguments).exit_code;
}

TEST(IntersectionCheckCli, ExitCodes) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tailor_check_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Grid g = unit_square_grid(5);
  write_obj_file(dir / "clean.obj", g.x, g.faces);
  g.x.row(12) << 0.9, 0.9, 0.0;
  write_obj_file(dir / "crossed.obj", g.x, g.faces);
  {
    std::ofstream bad(dir / "bad.obj");
    bad << "v 0 0 0\nf 1 2 3\n";
  }
  EXPECT_EQ(run_check_intersections_cli({dir / "clean.obj"}), 0);
  EXPECT_EQ(run_check_intersections_cli({dir / "crossed.obj"}), 1);
  EXPECT_EQ(run_check_intersections_cli({dir / "clean.obj", dir / "crossed.obj"}), 1);
  EXPECT_EQ(run_check_intersections_cli({dir / "bad.obj"}), 2);
  EXPECT_EQ(run_check_intersections_cli({dir / "missing.obj"}), 2);
  std::filesystem::remove_all(dir);
}
#endif

}  // namespace
}  // namespace tailor
