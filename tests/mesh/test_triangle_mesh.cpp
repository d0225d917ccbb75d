/// @file
/// TriangleMesh connectivity on hand-made meshes, checked against brute force.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {
namespace {

FaceArray make_faces(const std::vector<std::array<Index, 3>>& rows) {
  FaceArray faces(static_cast<Index>(rows.size()), 3);
  for (std::size_t f = 0; f < rows.size(); ++f) {
    for (int i = 0; i < 3; ++i) faces(static_cast<Index>(f), i) = rows[f][i];
  }
  return faces;
}

std::vector<Index> to_vector(std::span<const Index> s) {
  return {s.begin(), s.end()};
}

/// Checks every adjacency array of `mesh` against a brute-force computation.
void expect_matches_brute_force(const TriangleMesh& mesh) {
  const FaceArray& F = mesh.faces();
  const Index nf = mesh.num_faces(), nv = mesh.num_vertices();
  // Edges: unique (a<b), sorted by (b, a).
  std::vector<std::pair<Index, Index>> ba;
  for (Index f = 0; f < nf; ++f) {
    for (int i = 0; i < 3; ++i) {
      const Index a = F(f, i), b = F(f, (i + 1) % 3);
      ba.emplace_back(std::max(a, b), std::min(a, b));
    }
  }
  std::sort(ba.begin(), ba.end());
  ba.erase(std::unique(ba.begin(), ba.end()), ba.end());
  ASSERT_EQ(mesh.num_edges(), static_cast<Index>(ba.size()));
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    EXPECT_EQ(mesh.edges()(e, 0), ba[e].second) << "edge " << e;
    EXPECT_EQ(mesh.edges()(e, 1), ba[e].first) << "edge " << e;
    EXPECT_LT(mesh.edges()(e, 0), mesh.edges()(e, 1));
    EXPECT_EQ(mesh.find_edge(ba[e].first, ba[e].second), e);
    EXPECT_EQ(mesh.find_edge(ba[e].second, ba[e].first), e);
    // Faces with both endpoints, increasing.
    std::vector<Index> expected;
    for (Index f = 0; f < nf; ++f) {
      int hits = 0;
      for (int i = 0; i < 3; ++i) hits += (F(f, i) == ba[e].first || F(f, i) == ba[e].second);
      if (hits == 2) expected.push_back(f);
    }
    EXPECT_EQ(to_vector(mesh.edge_faces(e)), expected) << "edge " << e;
    EXPECT_EQ(mesh.is_boundary_edge(e), expected.size() == 1);
  }
  for (Index f = 0; f < nf; ++f) {
    const auto fe = mesh.face_edges(f);
    for (int i = 0; i < 3; ++i) {
      const Index a = F(f, i), b = F(f, (i + 1) % 3);
      EXPECT_EQ(mesh.edges()(fe[i], 0), std::min(a, b));
      EXPECT_EQ(mesh.edges()(fe[i], 1), std::max(a, b));
    }
  }
  for (Index v = 0; v < nv; ++v) {
    std::vector<Index> faces, edges;
    for (Index f = 0; f < nf; ++f) {
      if (F(f, 0) == v || F(f, 1) == v || F(f, 2) == v) faces.push_back(f);
    }
    for (Index e = 0; e < mesh.num_edges(); ++e) {
      if (mesh.edges()(e, 0) == v || mesh.edges()(e, 1) == v) edges.push_back(e);
    }
    EXPECT_EQ(to_vector(mesh.vertex_faces(v)), faces) << "vertex " << v;
    EXPECT_EQ(to_vector(mesh.vertex_edges(v)), edges) << "vertex " << v;
  }
  for (Index f = 0; f < nf; ++f) {
    for (Index g = 0; g < nf; ++g) {
      bool share = false;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) share = share || F(f, i) == F(g, j);
      }
      EXPECT_EQ(mesh.faces_share_vertex(f, g), share);
    }
  }
  // Components: faces sharing a vertex have the same id; count = number of distinct ids;
  // ids numbered by first appearance.
  ASSERT_EQ(mesh.face_components().size(), static_cast<std::size_t>(nf));
  Index next = 0;
  for (Index f = 0; f < nf; ++f) {
    const Index c = mesh.face_components()[f];
    EXPECT_LE(c, next);
    if (c == next) ++next;
  }
  EXPECT_EQ(mesh.num_components(), next);
  for (Index f = 0; f < nf; ++f) {
    for (Index g = 0; g < nf; ++g) {
      if (mesh.faces_share_vertex(f, g)) {
        EXPECT_EQ(mesh.face_components()[f], mesh.face_components()[g]);
      }
    }
  }
  // Boundary loops use each boundary edge exactly once.
  std::set<Index> boundary;
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    if (mesh.is_boundary_edge(e)) boundary.insert(e);
  }
  std::multiset<Index> walked;
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l) {
    const auto loop = mesh.boundary_loop(l);
    ASSERT_GE(loop.size(), 2u);
    for (std::size_t i = 0; i + 1 < loop.size(); ++i) {
      const Index e = mesh.find_edge(loop[i], loop[i + 1]);
      ASSERT_GE(e, 0);
      EXPECT_TRUE(boundary.count(e)) << "loop step is not a boundary edge";
      walked.insert(e);
    }
    const Index closing = mesh.find_edge(loop.back(), loop.front());
    if (loop.size() >= 3 && closing >= 0 && boundary.count(closing) && !walked.count(closing)) {
      walked.insert(closing);
    }
  }
  EXPECT_EQ(walked, std::multiset<Index>(boundary.begin(), boundary.end()));
}

/// Positions of a cyclic sequence up to rotation.
std::vector<Index> rotate_to_min(std::vector<Index> loop) {
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

TEST(TriangleMesh, OneTriangle) {
  const TriangleMesh mesh(3, make_faces({{0, 1, 2}}));
  expect_matches_brute_force(mesh);
  ASSERT_EQ(mesh.num_edges(), 3);
  // Sorted by b then a: (0,1), (0,2), (1,2).
  EXPECT_EQ(mesh.edges()(0, 0), 0);
  EXPECT_EQ(mesh.edges()(0, 1), 1);
  EXPECT_EQ(mesh.edges()(1, 0), 0);
  EXPECT_EQ(mesh.edges()(1, 1), 2);
  EXPECT_EQ(mesh.edges()(2, 0), 1);
  EXPECT_EQ(mesh.edges()(2, 1), 2);
  EXPECT_EQ(mesh.face_edges(0), (std::array<Index, 3>{0, 2, 1}));
  EXPECT_EQ(mesh.num_boundary_loops(), 1);
  EXPECT_EQ(to_vector(mesh.boundary_loop(0)), (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(mesh.num_components(), 1);
  EXPECT_TRUE(mesh.validation().is_manifold());
  EXPECT_TRUE(mesh.validation().unreferenced_vertices.empty());
  EXPECT_EQ(mesh.find_edge(0, 0), -1);
  EXPECT_EQ(mesh.find_edge(0, 7), -1);
  EXPECT_EQ(mesh.find_edge(-1, 2), -1);
}

TEST(TriangleMesh, QuadStrip) {
  // 3---4---5
  // | / | / |
  // 0---1---2
  const TriangleMesh mesh(6, make_faces({{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}}));
  expect_matches_brute_force(mesh);
  EXPECT_EQ(mesh.num_edges(), 9);
  Index boundary = 0;
  for (Index e = 0; e < mesh.num_edges(); ++e) boundary += mesh.is_boundary_edge(e);
  EXPECT_EQ(boundary, 6);
  ASSERT_EQ(mesh.num_boundary_loops(), 1);
  // Walked along the faces' orientation, from the first boundary edge (0, 1).
  EXPECT_EQ(to_vector(mesh.boundary_loop(0)), (std::vector<Index>{0, 1, 2, 5, 4, 3}));
  EXPECT_EQ(to_vector(mesh.edge_faces(mesh.find_edge(1, 4))), (std::vector<Index>{0, 3}));
  EXPECT_EQ(to_vector(mesh.vertex_faces(1)), (std::vector<Index>{0, 2, 3}));
  EXPECT_EQ(to_vector(mesh.vertex_faces(4)), (std::vector<Index>{0, 1, 3}));
  EXPECT_TRUE(mesh.faces_share_vertex(0, 2));   // share vertex 1
  EXPECT_FALSE(mesh.faces_share_vertex(1, 2));  // {0,4,3} vs {1,2,5}
  EXPECT_TRUE(mesh.faces_share_vertex(3, 3));
  EXPECT_EQ(mesh.num_components(), 1);
}

TEST(TriangleMesh, ClosedTetrahedron) {
  const TriangleMesh mesh(4, make_faces({{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
  expect_matches_brute_force(mesh);
  EXPECT_EQ(mesh.num_edges(), 6);
  EXPECT_EQ(mesh.num_boundary_loops(), 0);
  for (Index e = 0; e < mesh.num_edges(); ++e) EXPECT_EQ(mesh.edge_faces(e).size(), 2u);
  EXPECT_EQ(mesh.num_vertices() - mesh.num_edges() + mesh.num_faces(), 2);
  EXPECT_TRUE(mesh.validation().is_manifold());
  EXPECT_EQ(mesh.num_components(), 1);
}

TEST(TriangleMesh, OpenTubeHasTwoBoundaryLoops) {
  const Index n = 5, rings = 4;
  std::vector<std::array<Index, 3>> rows;
  for (Index r = 0; r + 1 < rings; ++r) {
    for (Index i = 0; i < n; ++i) {
      const Index a = r * n + i, b = r * n + (i + 1) % n, c = a + n, d = b + n;
      rows.push_back({a, b, d});
      rows.push_back({a, d, c});
    }
  }
  const TriangleMesh mesh(n * rings, make_faces(rows));
  expect_matches_brute_force(mesh);
  ASSERT_EQ(mesh.num_boundary_loops(), 2);
  std::set<std::vector<Index>> loops;
  for (Index l = 0; l < 2; ++l) loops.insert(rotate_to_min(to_vector(mesh.boundary_loop(l))));
  // The bottom ring is walked along the faces (0 -> 1 -> ...), the top ring the other way.
  EXPECT_TRUE(loops.count({0, 1, 2, 3, 4}));
  EXPECT_TRUE(loops.count({15, 19, 18, 17, 16}));
  EXPECT_EQ(mesh.num_components(), 1);
  EXPECT_TRUE(mesh.validation().is_manifold());
  // Euler characteristic of an annulus is 0.
  EXPECT_EQ(mesh.num_vertices() - mesh.num_edges() + mesh.num_faces(), 0);
}

TEST(TriangleMesh, NonManifoldFanOfThreeTrianglesOnOneEdge) {
  const TriangleMesh mesh(5, make_faces({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));
  expect_matches_brute_force(mesh);
  const Index shared = mesh.find_edge(0, 1);
  ASSERT_GE(shared, 0);
  EXPECT_EQ(to_vector(mesh.edge_faces(shared)), (std::vector<Index>{0, 1, 2}));
  EXPECT_FALSE(mesh.validation().is_manifold());
  EXPECT_EQ(mesh.validation().non_manifold_edges, (std::vector<Index>{shared}));
  EXPECT_FALSE(mesh.is_boundary_edge(shared));
  EXPECT_GE(mesh.num_boundary_loops(), 1);
  EXPECT_EQ(mesh.num_components(), 1);
}

TEST(TriangleMesh, PinchedBoundaryAndMoebiusStripTerminate) {
  // Two triangles touching at vertex 0 only (a bow tie).
  const TriangleMesh bowtie(5, make_faces({{0, 1, 2}, {0, 3, 4}}));
  expect_matches_brute_force(bowtie);
  EXPECT_EQ(bowtie.num_boundary_loops(), 2);
  EXPECT_EQ(bowtie.num_components(), 1);
  // A Moebius strip: no consistent orientation, one boundary loop through all vertices.
  // Top vertices 0..n-1, bottom n..2n-1; the last quad closes with a half twist.
  const Index n = 6;
  std::vector<std::array<Index, 3>> rows;
  for (Index i = 0; i + 1 < n; ++i) {
    rows.push_back({i, i + 1, n + i + 1});
    rows.push_back({i, n + i + 1, n + i});
  }
  rows.push_back({n - 1, n, 0});
  rows.push_back({n - 1, 0, 2 * n - 1});
  const TriangleMesh moebius(2 * n, make_faces(rows));
  expect_matches_brute_force(moebius);
  EXPECT_EQ(moebius.num_boundary_loops(), 1);
  EXPECT_EQ(moebius.boundary_loop(0).size(), static_cast<std::size_t>(2 * n));
}

TEST(TriangleMesh, ComponentsAndUnreferencedVertices) {
  // Triangle A, triangle B (disjoint), bow tie C+D; vertex 9 unused.
  const TriangleMesh mesh(12, make_faces({{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {6, 10, 11}}));
  expect_matches_brute_force(mesh);
  EXPECT_EQ(mesh.num_components(), 3);
  EXPECT_EQ(mesh.face_components(), (std::vector<Index>{0, 1, 2, 2}));
  EXPECT_EQ(mesh.validation().unreferenced_vertices, (std::vector<Index>{9}));
  EXPECT_TRUE(mesh.vertex_faces(9).empty());
  EXPECT_TRUE(mesh.vertex_edges(9).empty());
}

TEST(TriangleMesh, EmptyMesh) {
  const TriangleMesh mesh(0, FaceArray(0, 3));
  EXPECT_EQ(mesh.num_edges(), 0);
  EXPECT_EQ(mesh.num_boundary_loops(), 0);
  EXPECT_EQ(mesh.num_components(), 0);
}

TEST(TriangleMesh, OutOfRangeIndexThrowsNamingTheFace) {
  try {
    TriangleMesh(3, make_faces({{0, 1, 2}, {0, 2, 3}}));
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("face 1"), std::string::npos) << message;
    EXPECT_NE(message.find("out of range"), std::string::npos) << message;
  }
  EXPECT_THROW(TriangleMesh(3, make_faces({{0, -1, 2}})), InputError);
}

TEST(TriangleMesh, RepeatedVertexThrowsNamingTheFace) {
  try {
    TriangleMesh(4, make_faces({{0, 1, 2}, {3, 1, 3}}));
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("face 1"), std::string::npos) << message;
    EXPECT_NE(message.find("repeats"), std::string::npos) << message;
  }
}

TEST(TriangleMesh, RandomSoupsMatchBruteForce) {
  const bool sanitized = std::getenv("TAILOR_SANITIZED") != nullptr;
  std::mt19937 rng(1234);
  for (int trial = 0; trial < (sanitized ? 10 : 40); ++trial) {
    const Index nv = 3 + static_cast<Index>(rng() % 12);
    const Index nf = 1 + static_cast<Index>(rng() % 25);
    std::vector<std::array<Index, 3>> rows;
    std::uniform_int_distribution<Index> pick(0, nv - 1);
    while (static_cast<Index>(rows.size()) < nf) {
      const std::array<Index, 3> f{pick(rng), pick(rng), pick(rng)};
      if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) rows.push_back(f);
    }
    const TriangleMesh mesh(nv, make_faces(rows));
    SCOPED_TRACE(trial);
    expect_matches_brute_force(mesh);
  }
}

TEST(TriangleMesh, LargeGridCounts) {
  // A (k x k)-quad grid: V = (k+1)^2, F = 2k^2, E = 3k^2 + 2k, 4k boundary edges.
  const Index k = std::getenv("TAILOR_SANITIZED") ? 60 : 300;
  std::vector<std::array<Index, 3>> rows;
  for (Index j = 0; j < k; ++j) {
    for (Index i = 0; i < k; ++i) {
      const Index a = j * (k + 1) + i, b = a + 1, c = a + k + 1, d = c + 1;
      rows.push_back({a, b, d});
      rows.push_back({a, d, c});
    }
  }
  const TriangleMesh mesh((k + 1) * (k + 1), make_faces(rows));
  EXPECT_EQ(mesh.num_edges(), 3 * k * k + 2 * k);
  ASSERT_EQ(mesh.num_boundary_loops(), 1);
  EXPECT_EQ(mesh.boundary_loop(0).size(), static_cast<std::size_t>(4 * k));
  EXPECT_EQ(mesh.num_components(), 1);
  for (Index e = 1; e < mesh.num_edges(); ++e) {
    const auto prev = std::make_pair(mesh.edges()(e - 1, 1), mesh.edges()(e - 1, 0));
    const auto cur = std::make_pair(mesh.edges()(e, 1), mesh.edges()(e, 0));
    ASSERT_LT(prev, cur);
  }
}

}  // namespace
}  // namespace tailor
