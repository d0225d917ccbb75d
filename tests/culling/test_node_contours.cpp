// The boundary loops of BVH nodes: children are built in parallel above a size, so the
// loop of every node must be the one a single thread finds.

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "support/sanitized.hpp"
#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

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
