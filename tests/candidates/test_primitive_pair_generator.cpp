// Feature assignment and pair generation: every VF and EE pair of a mesh is owed by
// exactly one candidate triangle pair or is in the isolated set, whatever the topology;
// without assignment every pair is still covered.

#include <gtest/gtest.h>

#include <map>

#include "tailor/candidates/isolated_set.hpp"
#include "tailor/candidates/primitive_pair_generator.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

struct Counted {
  std::map<std::pair<Index, Index>, int> vertex_face, edge_edge;
};

// Runs the generator with every geometric stage off on all triangle pairs (f < g; only
// vertex-disjoint ones under adjacency culling) plus the isolated set.
Counted generate_all(const TriangleMesh& mesh, bool assignment, bool adjacency) {
  std::vector<TrianglePair> ctps;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    for (Index g = f + 1; g < mesh.num_faces(); ++g) {
      if (!adjacency || !mesh.faces_share_vertex(f, g)) ctps.push_back({f, g});
    }
  }
  const Positions x = Positions::Zero(mesh.num_vertices(), 3);
  PrimitivePairGenerator generator(mesh);
  LowLevelOptions options;
  options.feature_assignment = assignment;
  options.adjacency_culling = adjacency;
  options.primitive_boxes = options.coplanarity_filter = options.projection_filter = false;
  generator.begin_step();
  generator.add_triangle_pairs(ctps, x, x, options);
  if (adjacency) generator.add_isolated(IsolatedSet::build(mesh), x, x, options);
  Counted counted;
  for (auto block : generator.vertex_face_blocks()) {
    for (const VertexFacePair& p : block) ++counted.vertex_face[{p.vertex, p.face}];
  }
  for (auto block : generator.edge_edge_blocks()) {
    for (const EdgeEdgePair& p : block) {
      EXPECT_LT(p.edge_a, p.edge_b);
      ++counted.edge_edge[{p.edge_a, p.edge_b}];
    }
  }
  const LowLevelCounts counts = generator.counts();
  EXPECT_EQ(counts.vf_generated, counts.vf_after_projection);  // nothing else filters
  return counted;
}

void expect_every_pair(const TriangleMesh& mesh, const Counted& counted, bool exactly_once,
                       const std::string& what) {
  std::int64_t vf = 0, ee = 0;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.vertex_faces(v).empty()) continue;
    for (Index g = 0; g < mesh.num_faces(); ++g) {
      const auto face = mesh.faces().row(g);
      if (face[0] == v || face[1] == v || face[2] == v) continue;
      const auto it = counted.vertex_face.find({v, g});
      const int n = it == counted.vertex_face.end() ? 0 : it->second;
      ASSERT_TRUE(exactly_once ? n == 1 : n >= 1)
          << what << ": VF (" << v << ", " << g << ") " << n;
      ++vf;
    }
  }
  for (Index e1 = 0; e1 < mesh.num_edges(); ++e1) {
    for (Index e2 = e1 + 1; e2 < mesh.num_edges(); ++e2) {
      if (mesh.edges_share_vertex(e1, e2)) continue;
      const auto it = counted.edge_edge.find({e1, e2});
      const int n = it == counted.edge_edge.end() ? 0 : it->second;
      ASSERT_TRUE(exactly_once ? n == 1 : n >= 1)
          << what << ": EE (" << e1 << ", " << e2 << ") " << n;
      ++ee;
    }
  }
  // Nothing else was generated.
  EXPECT_EQ(static_cast<std::int64_t>(counted.vertex_face.size()), vf) << what;
  EXPECT_EQ(static_cast<std::int64_t>(counted.edge_edge.size()), ee) << what;
}

TEST(PrimitivePairGenerator, EveryFeaturePairHasExactlyOneRepresentativeOrIsIsolated) {
  const std::vector<std::pair<std::string, MeshData>> meshes = {
      {"grid", make_grid(5, 4, 1.0, 1.0)},
      {"tube", make_tube(4, 6, 0.3, 1.0)},  // rings of 6: many orphans
      {"sphere", make_sphere(4, 5, 0.5)},   // closed, with poles of high valence
  };
  for (const auto& [name, data] : meshes) {
    const TriangleMesh mesh(static_cast<Index>(data.vertices.rows()), data.faces);
    expect_every_pair(mesh, generate_all(mesh, true, true), true, name + " adjacency");
    expect_every_pair(mesh, generate_all(mesh, true, false), true, name + " all pairs");
    expect_every_pair(mesh, generate_all(mesh, false, true), false, name + " no assignment");
  }
}

TEST(FeatureAssignment, OwnershipBitsMatchTheOwners) {
  const MeshData data = make_sphere(5, 7, 0.5);
  const TriangleMesh mesh(static_cast<Index>(data.vertices.rows()), data.faces);
  const FeatureAssignment assignment(mesh);
  Index vertices = 0, edges = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto face_edges = mesh.face_edges(f);
    for (int k = 0; k < 3; ++k) {
      const Index v = mesh.faces()(f, k);
      EXPECT_EQ(assignment.owns_corner(f, k), assignment.vertex_owner(v) == f);
      EXPECT_EQ(assignment.owns_edge(f, k), assignment.edge_owner(face_edges[k]) == f);
      if (assignment.owns_corner(f, k)) {
        const auto others = assignment.owner_other_corners(v);
        EXPECT_EQ(others[0], mesh.faces()(f, (k + 1) % 3));
        EXPECT_EQ(others[1], mesh.faces()(f, (k + 2) % 3));
      }
      if (assignment.owns_edge(f, k)) {
        EXPECT_EQ(assignment.owner_opposite_corner(face_edges[k]), mesh.faces()(f, (k + 2) % 3));
      }
    }
    vertices += assignment.vertices_assigned(f);
    edges += assignment.edges_assigned(f);
  }
  EXPECT_EQ(vertices, mesh.num_vertices());
  EXPECT_EQ(edges, mesh.num_edges());
}

}  // namespace
}  // namespace tailor
