#pragma once
/// @file
/// The shared query sets the CCD benchmarks read (../shared/data: cloth-funnel with its
/// mma_bool truth, the erleben scenes and the unit tests of ccd-queries with their truth
/// column).

#include <string>
#include <vector>

#include "tailor/ccd/query_io.hpp"

namespace tailor {

/// Queries of one set with their ground truth (touching at h = 0).
struct QuerySet {
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
  std::vector<bool> vf_truth, ee_truth;
  std::size_t size() const { return vf.size() + ee.size(); }
};

/// The shared data folder (../shared/data).
inline const std::string kData = TAILOR_DATA_DIR;
/// The erleben scenes of ccd-queries.
inline const char* kErleben[] = {
    "cube-cliff-edges", "cube-internal-edges", "sliding-spike", "sliding-wedge", "spike-crack",
    "spike-hole",       "spike-wedge",         "spikes",        "wedge-crack",   "wedges"};

/// Appends the queries of one CSV (and their truth: the CSV's column, or `truth_json`).
inline void append(QuerySet& s, const std::string& path, const std::string& truth_json = "") {
  CcdQueryFile f = read_ccd_queries(path);
  std::vector<bool> truth = truth_json.empty() ? f.truth : read_ccd_truth_json(truth_json);
  if (f.kind == CcdQueryKind::vertex_face) {
    s.vf.insert(s.vf.end(), f.vertex_face.begin(), f.vertex_face.end());
    s.vf_truth.insert(s.vf_truth.end(), truth.begin(), truth.end());
  } else {
    s.ee.insert(s.ee.end(), f.edge_edge.begin(), f.edge_edge.end());
    s.ee_truth.insert(s.ee_truth.end(), truth.begin(), truth.end());
  }
}

/// cloth-funnel 227 (truth: mma_bool).
inline QuerySet funnel() {
  QuerySet r;
  const std::string d = kData + "/cloth-funnel";
  append(r, d + "/queries/227vf.csv", d + "/mma_bool/227vf_mma_bool.json");
  append(r, d + "/queries/227ee.csv", d + "/mma_bool/227ee_mma_bool.json");
  return r;
}

/// The erleben scenes, vertex-face and edge-edge.
inline QuerySet erleben() {
  QuerySet r;
  for (const char* name : kErleben) {
    const std::string d = kData + "/ccd-queries/erleben-" + name;
    append(r, d + "/vertex-face/data_0_0.csv");
    append(r, d + "/edge-edge/data_0_0.csv");
  }
  return r;
}

/// The unit tests of ccd-queries.
inline QuerySet unit_tests() {
  QuerySet r;
  const std::string d = kData + "/ccd-queries/unit-tests";
  for (const char* f : {"vertex-face/data_0_0.csv", "vertex-face/data_0_1.csv",
                        "edge-edge/data_0_0.csv", "edge-edge/data_0_1.csv"}) {
    append(r, d + "/" + f);
  }
  return r;
}

}  // namespace tailor
