// The cloth-funnel step (227 -> 228) against its exact ground truth (mma_bool).

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

const std::string kDir = std::string(TAILOR_DATA_DIR) + "/cloth-funnel/";

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  return nlohmann::json::parse(in);
}

struct Truth {
  std::set<std::pair<Index, Index>> vertex_face;  // (vertex, face)
  std::set<std::pair<Index, Index>> edge_edge;    // (edge, edge), first < second
};

// Pairs marked true by mma_bool, with the data set's ids (vertices, then edges, then
// faces) mapped to ours (edges in the same order).
Truth load_truth(const TriangleMesh& mesh) {
  Truth truth;
  const Index num_v = mesh.num_vertices(), num_e = mesh.num_edges();
  const auto vf = read_json(kDir + "boxes/227vf.json");
  const auto vf_truth = read_json(kDir + "mma_bool/227vf_mma_bool.json");
  EXPECT_EQ(vf.size(), vf_truth.size());
  for (std::size_t i = 0; i < vf.size(); ++i) {
    if (vf_truth[i].get<bool>()) {
      truth.vertex_face.insert({vf[i][0].get<Index>(), vf[i][1].get<Index>() - num_v - num_e});
    }
  }
  const auto ee = read_json(kDir + "boxes/227ee.json");
  const auto ee_truth = read_json(kDir + "mma_bool/227ee_mma_bool.json");
  EXPECT_EQ(ee.size(), ee_truth.size());
  for (std::size_t i = 0; i < ee.size(); ++i) {
    if (ee_truth[i].get<bool>()) {
      const Index a = ee[i][0].get<Index>() - num_v, b = ee[i][1].get<Index>() - num_v;
      truth.edge_edge.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return truth;
}

Truth as_truth(const CollisionSet& collisions) {
  Truth found;
  for (const auto& c : collisions.vertex_face) found.vertex_face.insert({c.vertex, c.face});
  for (const auto& c : collisions.edge_edge) {
    found.edge_edge.insert({std::min(c.edge_a, c.edge_b), std::max(c.edge_a, c.edge_b)});
  }
  return found;
}

TEST(ClothFunnel, EveryPresetReportsExactlyTheTruePairs) {
  const MeshData t0 = read_mesh(kDir + "frames/227.ply");
  const MeshData t1 = read_mesh(kDir + "frames/228.ply");
  ASSERT_EQ(t0.vertices.rows(), 9450);
  const TriangleMesh mesh(static_cast<Index>(t0.vertices.rows()), t0.faces);
  const Truth truth = load_truth(mesh);
  EXPECT_EQ(truth.vertex_face.size(), 27u);
  EXPECT_EQ(truth.edge_edge.size(), 107u);

  const Truth brute = as_truth(brute_force_self_collisions(mesh, t0.vertices, t1.vertices));
  EXPECT_EQ(brute.vertex_face, truth.vertex_face);
  EXPECT_EQ(brute.edge_edge, truth.edge_edge);
  for (const std::string& method : DetectionConfig::preset_names()) {
    SelfCollisionDetector detector(mesh, t0.vertices, DetectionConfig::preset(method));
    const Truth found = as_truth(detector.detect(t0.vertices, t1.vertices).collisions);
    EXPECT_EQ(found.vertex_face, truth.vertex_face) << method;
    EXPECT_EQ(found.edge_edge, truth.edge_edge) << method;
  }
}

}  // namespace
}  // namespace tailor
