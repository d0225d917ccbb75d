// The isolated set equals its definition, enumerated by brute force over every feature
// pair, on meshes with few and many orphans (regular grids, thin tubes, poles of high
// valence, non-manifold edges, bow-ties, fins, a doubled face, a two-sided flap, an
// octahedron, a lone triangle): the enumeration and the quick test that skips most edges of
// a regular mesh (dropping any one of its conditions fails this test).

#include "tailor/candidates/isolated_set.hpp"

#include <gtest/gtest.h>

#include <set>

#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

using Pairs = std::set<std::pair<Index, Index>>;

// VF pairs (v, g), v not in g and v on some face, whose every face around v shares a
// vertex with g; EE pairs e1 < e2 without a common vertex whose every pair of incident
// faces shares a vertex.
std::pair<Pairs, Pairs> by_definition(const TriangleMesh& mesh) {
  Pairs vf, ee;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.vertex_faces(v).empty()) continue;
    for (Index g = 0; g < mesh.num_faces(); ++g) {
      const auto face = mesh.faces().row(g);
      if (face[0] == v || face[1] == v || face[2] == v) continue;
      bool every_face_touches = true;
      for (Index f : mesh.vertex_faces(v)) every_face_touches &= mesh.faces_share_vertex(f, g);
      if (every_face_touches) vf.insert({v, g});
    }
  }
  for (Index e1 = 0; e1 < mesh.num_edges(); ++e1) {
    for (Index e2 = e1 + 1; e2 < mesh.num_edges(); ++e2) {
      if (mesh.edges_share_vertex(e1, e2)) continue;
      bool every_pair_touches = true;
      for (Index f1 : mesh.edge_faces(e1)) {
        for (Index f2 : mesh.edge_faces(e2)) every_pair_touches &= mesh.faces_share_vertex(f1, f2);
      }
      if (every_pair_touches) ee.insert({e1, e2});
    }
  }
  return {vf, ee};
}

TriangleMesh mesh_of(const MeshData& data) {
  return TriangleMesh(static_cast<Index>(data.vertices.rows()), data.faces);
}

TriangleMesh mesh_of(Index vertices, std::initializer_list<std::array<Index, 3>> faces) {
  FaceArray array(static_cast<Index>(faces.size()), 3);
  Index row = 0;
  for (const auto& face : faces) array.row(row++) << face[0], face[1], face[2];
  return TriangleMesh(vertices, array);
}

TEST(IsolatedSet, EqualsItsDefinitionByBruteForce) {
  const std::vector<std::pair<std::string, TriangleMesh>> meshes = [] {
    std::vector<std::pair<std::string, TriangleMesh>> m;
    m.emplace_back("grid", mesh_of(make_grid(6, 5, 1.0, 1.0)));
    m.emplace_back("tube of 3", mesh_of(make_tube(5, 3, 0.3, 1.0)));
    m.emplace_back("tube of 4", mesh_of(make_tube(4, 4, 0.3, 1.0)));
    m.emplace_back("tube of 6", mesh_of(make_tube(4, 6, 0.3, 1.0)));
    m.emplace_back("sphere", mesh_of(make_sphere(4, 5, 0.5)));
    m.emplace_back("small sphere", mesh_of(make_sphere(2, 3, 0.5)));
    // Three faces on one edge, a bow-tie through vertex 0, a lone triangle, and an
    // unreferenced vertex (9).
    m.emplace_back("non-manifold",
                   mesh_of(10, {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {0, 5, 6}, {7, 8, 2}, {2, 3, 4}}));
    m.emplace_back("lone triangle", mesh_of(3, {{0, 1, 2}}));
    // A grid with one face repeated (its edges have three faces, two of them the same).
    MeshData doubled = make_grid(5, 4, 1.0, 1.0);
    doubled.faces.conservativeResize(doubled.faces.rows() + 1, 3);
    doubled.faces.row(doubled.faces.rows() - 1) = doubled.faces.row(7);
    m.emplace_back("grid with a doubled face", mesh_of(doubled));
    // A two-sided flap (a triangle and its reverse) on an inner vertex of a grid: across
    // from that vertex an edge whose two faces both hold it.
    MeshData flap = make_grid(5, 5, 1.0, 1.0);
    const Index inner = 14, p = static_cast<Index>(flap.vertices.rows());  // (2, 2) of 6 × 6
    flap.vertices.conservativeResize(p + 2, 3);
    flap.vertices.row(p) << 0.5, 0.5, 1.0;
    flap.vertices.row(p + 1) << 0.6, 0.4, 1.0;
    flap.faces.conservativeResize(flap.faces.rows() + 2, 3);
    flap.faces.row(flap.faces.rows() - 2) << inner, p, p + 1;
    flap.faces.row(flap.faces.rows() - 1) << inner, p + 1, p;
    m.emplace_back("grid with a two-sided flap", mesh_of(flap));
    // Two fans glued along a path of three vertices on both sides (a pillow of valence-4
    // vertices): common neighbours beyond the apexes of an edge.
    m.emplace_back("octahedron", mesh_of(6, {{0, 2, 4},
                                             {2, 1, 4},
                                             {1, 3, 4},
                                             {3, 0, 4},
                                             {2, 0, 5},
                                             {1, 2, 5},
                                             {3, 1, 5},
                                             {0, 3, 5}}));
    // Fins: a third face on inner edges of a grid (the faces across an edge that do not
    // touch another edge's faces keep the two from being orphans).
    MeshData fins = make_grid(5, 5, 1.0, 1.0);
    const Index grid_faces = static_cast<Index>(fins.faces.rows());
    for (Index f = 3, k = 0; f < grid_faces; f += 7, ++k) {
      const Index top = static_cast<Index>(fins.vertices.rows());
      fins.vertices.conservativeResize(top + 1, 3);
      fins.vertices.row(top) << 0.1 * k, 0.5, 1.0;
      fins.faces.conservativeResize(fins.faces.rows() + 1, 3);
      fins.faces.row(fins.faces.rows() - 1) << fins.faces(f, k % 3), fins.faces(f, (k + 1) % 3),
          top;
    }
    m.emplace_back("grid with fins", mesh_of(fins));
    return m;
  }();
  std::size_t total_vf = 0, total_ee = 0;
  for (const auto& [name, mesh] : meshes) {
    const auto [vf, ee] = by_definition(mesh);
    const IsolatedSet set = IsolatedSet::build(mesh);
    Pairs built_vf, built_ee;
    for (const VertexFacePair& p : set.vertex_face) {
      EXPECT_TRUE(built_vf.insert({p.vertex, p.face}).second) << name << ": VF listed twice";
    }
    for (const EdgeEdgePair& p : set.edge_edge) {
      EXPECT_TRUE(built_ee.insert({p.edge_a, p.edge_b}).second) << name << ": EE listed twice";
    }
    EXPECT_EQ(built_vf, vf) << name;
    EXPECT_EQ(built_ee, ee) << name;
    total_vf += vf.size();
    total_ee += ee.size();
  }
  // The meshes do have orphans of both kinds.
  EXPECT_GT(total_vf, 20u);
  EXPECT_GT(total_ee, 20u);
}

}  // namespace
}  // namespace tailor
