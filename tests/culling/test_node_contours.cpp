// The boundary loops of BVH nodes: each equals the loop found from its definition (the
// node's faces, edges met once, a single consistently oriented cycle), on patches, an
// annulus, a closed surface, a flipped face and a non-manifold fin; and children are built
// in parallel above a size, so the loop of every node must be the one a single thread
// finds.

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "support/sanitized.hpp"
#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/mesh/procedural_meshes.hpp"
#include "tailor/mesh/procedural_steps.hpp"

#include <map>
#include <numeric>

namespace tailor {
namespace {

// The loop of `node` by definition: its faces' half-edges; an edge with more than two faces
// in the mesh, or met twice in the same direction, leaves no loop; edges met once form
// the boundary, which must be one cycle through distinct vertices, listed from its
// smallest vertex.
std::vector<Index> loop_by_definition(const TriangleMesh& mesh, const MeshBvh& bvh, Index node) {
  std::map<Index, std::vector<std::pair<Index, Index>>> by_edge;  // edge -> (from, to)
  for (Index n = node; n < node + 2 * bvh.size(node) - 1; ++n) {
    if (!bvh.is_leaf(n)) continue;
    const Index f = bvh.leaf_face(n);
    for (int i = 0; i < 3; ++i) {
      const Index e = mesh.face_edges(f)[i];
      if (mesh.edge_faces(e).size() > 2) return {};
      by_edge[e].push_back({mesh.faces()(f, i), mesh.faces()(f, (i + 1) % 3)});
    }
  }
  std::map<Index, Index> next;
  for (const auto& [edge, halves] : by_edge) {
    if (halves.size() == 2) {
      if (halves[0].first != halves[1].second) return {};  // not consistently oriented
      continue;
    }
    if (!next.emplace(halves[0].first, halves[0].second).second) return {};  // vertex twice
  }
  if (next.size() < 3) return {};
  std::vector<Index> loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    const auto it = next.find(loop.back());
    if (it == next.end()) return {};
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  return loop.size() == next.size() ? loop : std::vector<Index>{};
}

constexpr Index kStripFaces = 120;

// A grid with some faces turned over (some inside their group, some on its border) and
// a strip of kStripFaces faces standing on one of its inner edges (a fin: that edge has three).
MeshData grid_with_flipped_faces_and_fin() {
  MeshData grid = make_grid(30, 20, 1.0, 0.7);
  for (Index f = 17; f < grid.faces.rows(); f += 61) std::swap(grid.faces(f, 1), grid.faces(f, 2));
  const Index a = grid.faces(900, 0), b = grid.faces(900, 1);
  const Index first = static_cast<Index>(grid.vertices.rows());
  grid.vertices.conservativeResize(first + kStripFaces, 3);
  for (Index k = 0; k < kStripFaces; ++k) {
    const Vec3 base = grid.vertices.row(k % 2 == 0 ? a : b);
    grid.vertices.row(first + k) = base + Vec3(0, 0, 0.05 * (k / 2 + 1));
  }
  const Index rows = static_cast<Index>(grid.faces.rows());
  grid.faces.conservativeResize(rows + kStripFaces, 3);
  // Quads (lower a', lower b', upper a', upper b') up the strip, two faces each.
  for (Index k = 0; k < kStripFaces / 2; ++k) {
    const Index lower_a = k == 0 ? a : first + 2 * (k - 1), lower_b = k == 0 ? b : lower_a + 1;
    const Index upper_a = first + 2 * k, upper_b = upper_a + 1;
    grid.faces.row(rows + 2 * k) << lower_a, lower_b, upper_b;
    grid.faces.row(rows + 2 * k + 1) << lower_a, upper_b, upper_a;
  }
  return grid;
}

TEST(NodeContours, EveryLoopIsTheOneItsDefinitionGives) {
  struct Case {
    std::string name;
    MeshData data;
    std::vector<Index> faces;  // the tree's faces (all when empty)
  };
  const MeshData fin = grid_with_flipped_faces_and_fin();
  std::vector<Index> strip(kStripFaces);
  std::iota(strip.begin(), strip.end(), static_cast<Index>(fin.faces.rows()) - kStripFaces);
  const std::vector<Case> cases = {
      {"pleated cloth",
       [] {
         const ProceduralStep step = make_pleated_cloth(5'000);
         return MeshData{step.x0, step.faces};
       }(),
       {}},
      {"tube", make_tube(40, 24, 0.3, 2.0), {}},
      {"sphere", make_sphere(20, 30, 0.5), {}},
      {"flipped faces and fin", fin, {}},
      // A tree over the fin alone: its foot has three faces in the mesh, one in the tree.
      {"the fin alone", fin, strip}};
  for (const auto& [name, data, faces] : cases) {
    const TriangleMesh mesh(static_cast<Index>(data.vertices.rows()), data.faces);
    const MeshBvh bvh(mesh, data.vertices, faces);
    const NodeContours contours(mesh, bvh);
    Index loops = 0, masked_without = 0;
    for (Index node = 0; node < bvh.num_nodes(); ++node) {
      if (!bvh.has_mask(node)) {
        EXPECT_TRUE(contours.loop(node).empty()) << name << ": node " << node;
        continue;
      }
      const auto loop = contours.loop(node);
      ASSERT_EQ(std::vector<Index>(loop.begin(), loop.end()), loop_by_definition(mesh, bvh, node))
          << name << ": node " << node;
      loops += !loop.empty();
      masked_without += loop.empty();
    }
    EXPECT_GT(loops, 0) << name;           // loops were compared,
    EXPECT_GT(masked_without, 0) << name;  // and nodes without one
  }
}

TEST(NodeContours, LoopsDoNotDependOnThreads) {
  const ProceduralStep step = make_pleated_cloth(testing::sanitized() ? 10'000 : 60'000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  const MeshBvh bvh(mesh, step.x0);
  const NodeContours parallel(mesh, bvh);
  NodeContours sequential;
  tbb::task_arena(1).execute([&] { sequential = NodeContours(mesh, bvh); });
  EXPECT_EQ(parallel.stored_vertices(), sequential.stored_vertices());
  Index single_loops = 0;
  for (Index node = 0; node < bvh.num_nodes(); ++node) {
    const auto a = parallel.loop(node), b = sequential.loop(node);
    ASSERT_EQ(std::vector<Index>(a.begin(), a.end()), std::vector<Index>(b.begin(), b.end()))
        << "node " << node;
    single_loops += !a.empty();
  }
  EXPECT_GT(single_loops, 1000);  // loops were compared
}

}  // namespace
}  // namespace tailor
