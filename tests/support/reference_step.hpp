#pragma once
// The two real cloth steps of ../shared/data with exact ground truth (cloth-funnel,
// cloth-ball): their frames, topology and the colliding pairs that mma_bool marks true.

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tailor/detection/collision.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor::testing {

/// Colliding pairs as id sets: (vertex, face) and (edge, edge) with first < second.
struct PairSets {
  std::set<std::pair<Index, Index>> vertex_face;
  std::set<std::pair<Index, Index>> edge_edge;
};

/// The pairs of a detector's or brute force's collisions.
inline PairSets pair_sets(const CollisionSet& collisions) {
  PairSets found;
  for (const auto& c : collisions.vertex_face) found.vertex_face.insert({c.vertex, c.face});
  for (const auto& c : collisions.edge_edge) {
    found.edge_edge.insert({std::min(c.edge_a, c.edge_b), std::max(c.edge_a, c.edge_b)});
  }
  return found;
}

/// One step of a data set folder: frames/T0, frames/T1, boxes/<prefix>{vf,ee}.json and
/// mma_bool/<prefix>{vf,ee}_mma_bool.json (../shared/data/README.md).
struct ReferenceStep {
  MeshData t0, t1;
  std::unique_ptr<TriangleMesh> mesh;
  PairSets truth;
};

inline nlohmann::json read_reference_json(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  return nlohmann::json::parse(in);
}

/// Reads the step; the data set's ids (vertices, then edges, then faces) become ours (the
/// edges are in the same order).
inline ReferenceStep load_reference_step(const std::string& folder, const std::string& frame_t0,
                                         const std::string& frame_t1, const std::string& prefix) {
  const std::string dir = std::string(TAILOR_DATA_DIR) + "/" + folder + "/";
  ReferenceStep step;
  step.t0 = read_mesh(dir + "frames/" + frame_t0);
  step.t1 = read_mesh(dir + "frames/" + frame_t1);
  step.mesh =
      std::make_unique<TriangleMesh>(static_cast<Index>(step.t0.vertices.rows()), step.t0.faces);
  const Index num_v = step.mesh->num_vertices(), num_e = step.mesh->num_edges();
  const auto vf = read_reference_json(dir + "boxes/" + prefix + "vf.json");
  const auto vf_truth = read_reference_json(dir + "mma_bool/" + prefix + "vf_mma_bool.json");
  EXPECT_EQ(vf.size(), vf_truth.size());
  for (std::size_t i = 0; i < vf.size(); ++i) {
    if (vf_truth[i].get<bool>()) {
      step.truth.vertex_face.insert({vf[i][0].get<Index>(), vf[i][1].get<Index>() - num_v - num_e});
    }
  }
  const auto ee = read_reference_json(dir + "boxes/" + prefix + "ee.json");
  const auto ee_truth = read_reference_json(dir + "mma_bool/" + prefix + "ee_mma_bool.json");
  EXPECT_EQ(ee.size(), ee_truth.size());
  for (std::size_t i = 0; i < ee.size(); ++i) {
    if (ee_truth[i].get<bool>()) {
      const Index a = ee[i][0].get<Index>() - num_v, b = ee[i][1].get<Index>() - num_v;
      step.truth.edge_edge.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return step;
}

}  // namespace tailor::testing
