/// Reference queries with exact ground truth: zero false negatives and false positives,
/// the same answers after scaling by 2^20 and 2^-20, batch == single, and the CLI.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include "ccd_test_support.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/ccd/query_io.hpp"

namespace tailor {
namespace {

struct FileWithTruth {
  CcdQueryFile file;
  std::vector<bool> truth;
};

std::vector<FileWithTruth> all_reference_files() {
  std::vector<FileWithTruth> out;
  for (const auto& path : test::reference_query_files()) {
    CcdQueryFile f = read_ccd_queries(path);
    std::vector<bool> truth = f.truth;
    out.push_back({std::move(f), std::move(truth)});
  }
  const std::string funnel = test::data_dir() + "/cloth-funnel";
  for (const char* kind : {"vf", "ee"}) {
    CcdQueryFile f = read_ccd_queries(funnel + "/queries/227" + kind + ".csv");
    std::vector<bool> truth =
        read_ccd_truth_json(funnel + "/mma_bool/227" + std::string(kind) + "_mma_bool.json");
    out.push_back({std::move(f), std::move(truth)});
  }
  return out;
}

const std::vector<FileWithTruth>& reference() {
  static const std::vector<FileWithTruth> files = all_reference_files();
  return files;
}

CcdResult run(const CcdQueryFile& f, std::size_t i, int scale = 0) {
  if (f.kind == CcdQueryKind::vertex_face) {
    return vertex_face_ccd(scale ? test::scaled(f.vertex_face[i], scale) : f.vertex_face[i]);
  }
  return edge_edge_ccd(scale ? test::scaled(f.edge_edge[i], scale) : f.edge_edge[i]);
}

TEST(CcdReferenceData, FilesAndCountsAsDocumented) {
  ASSERT_EQ(test::reference_query_files().size(), 24u);
  std::size_t queries = 0, colliding = 0;
  for (const auto& r : reference()) {
    if (r.file.path.find("ccd-queries") == std::string::npos) continue;
    queries += r.file.size();
    for (bool t : r.truth) colliding += t;
  }
  EXPECT_EQ(queries, 5029u);
  EXPECT_EQ(colliding, 329u);
}

TEST(CcdReferenceData, NoFalseNegativesNoFalsePositives) {
  std::size_t total = 0, hits = 0;
  for (const auto& r : reference()) {
    ASSERT_EQ(r.truth.size(), r.file.size()) << r.file.path;
    for (std::size_t i = 0; i < r.file.size(); ++i) {
      const CcdResult res = run(r.file, i);
      EXPECT_EQ(res.hit, r.truth[i]) << r.file.path << " query " << i;
      EXPECT_GE(res.toi, 0.0);
      EXPECT_LE(res.toi, 1.0);
      if (!res.hit) {
        EXPECT_EQ(res.toi, 1.0);
      }
      ++total;
      hits += res.hit;
    }
  }
  EXPECT_EQ(total, 5029u + 92u + 263u);
  EXPECT_EQ(hits, 329u + 27u + 107u);
}

TEST(CcdReferenceData, EveryTierAndTheOracleAgreeWithTruth) {
  std::size_t paths[kCcdPathCount] = {};
  for (const auto& r : reference()) {
    for (std::size_t i = 0; i < r.file.size(); ++i) {
      const bool vf = r.file.kind == CcdQueryKind::vertex_face;
      const CcdResult oracle =
          vf ? test::oracle(r.file.vertex_face[i]) : test::oracle(r.file.edge_edge[i]);
      EXPECT_EQ(oracle.hit, r.truth[i]) << r.file.path << " query " << i;
      const CcdResult exact =
          vf ? test::exact_tier(r.file.vertex_face[i]) : test::exact_tier(r.file.edge_edge[i]);
      const CcdResult gmp = vf ? test::exact_tier_gmp(r.file.vertex_face[i])
                               : test::exact_tier_gmp(r.file.edge_edge[i]);
      EXPECT_TRUE(exact.path == CcdPath::exact || exact.path == CcdPath::gmp);
      ++paths[static_cast<int>(exact.path)];
      EXPECT_TRUE(test::agrees(exact, oracle)) << r.file.path << " query " << i;
      EXPECT_TRUE(test::agrees(gmp, oracle)) << r.file.path << " query " << i;
      const auto dbl =
          vf ? test::double_tier(r.file.vertex_face[i]) : test::double_tier(r.file.edge_edge[i]);
      if (dbl) {
        EXPECT_TRUE(test::agrees(*dbl, oracle)) << r.file.path << " query " << i;
      }
    }
  }
  // The fixed-size integers hold all but the widest queries (coordinates ~1e-18 beside
  // ~1: 110-bit spreads, whose pseudo-remainders outgrow 2048 bits).
  EXPECT_GT(paths[static_cast<int>(CcdPath::exact)], 50 * paths[static_cast<int>(CcdPath::gmp)]);
}

TEST(CcdReferenceData, ScaleInvariance) {
  for (const auto& r : reference()) {
    for (std::size_t i = 0; i < r.file.size(); ++i) {
      const CcdResult base = run(r.file, i);
      // 2^±20 keeps the double tier in range; 2^±600 leaves it to the exact tier.
      for (int e : {20, -20, 600, -600}) {
        const bool exact_scaling =
            r.file.kind == CcdQueryKind::vertex_face
                ? test::same(test::scaled(test::scaled(r.file.vertex_face[i], e), -e),
                             r.file.vertex_face[i])
                : test::same(test::scaled(test::scaled(r.file.edge_edge[i], e), -e),
                             r.file.edge_edge[i]);
        ASSERT_TRUE(exact_scaling) << r.file.path << " query " << i << " scale 2^" << e;
        const CcdResult s = run(r.file, i, e);
        EXPECT_EQ(s.hit, base.hit) << r.file.path << " query " << i << " scale 2^" << e;
        EXPECT_NEAR(s.toi, base.toi, 2e-6) << r.file.path << " query " << i;
      }
    }
  }
}

TEST(CcdReferenceData, BatchEqualsSingle) {
  for (const auto& r : reference()) {
    std::vector<CcdResult> batch(r.file.size());
    if (r.file.kind == CcdQueryKind::vertex_face) {
      vertex_face_ccd(r.file.vertex_face, batch);
    } else {
      edge_edge_ccd(r.file.edge_edge, batch);
    }
    for (std::size_t i = 0; i < r.file.size(); ++i) {
      const CcdResult single = run(r.file, i);
      EXPECT_EQ(batch[i].hit, single.hit);
      EXPECT_EQ(batch[i].toi, single.toi);
      EXPECT_EQ(batch[i].path, single.path);
    }
  }
  std::vector<CcdResult> wrong(1);
  EXPECT_THROW(vertex_face_ccd(std::span<const VertexFaceQuery>{}, wrong), std::invalid_argument);
}

std::string run_cli(const std::string& args, int* exit_code) {
  const std::string cmd = std::string(TAILOR_CLI_PATH) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (pipe && fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int status = pipe ? pclose(pipe) : -1;
  *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

TEST(CcdCheckCli, ClothFunnelWithTruth) {
  const std::string f = test::data_dir() + "/cloth-funnel";
  int code = -1;
  const std::string out =
      run_cli("ccd-check " + f + "/queries/227vf.csv " + f + "/queries/227ee.csv --truth " + f +
                  "/mma_bool/227vf_mma_bool.json --truth " + f + "/mma_bool/227ee_mma_bool.json",
              &code);
  EXPECT_EQ(code, 0) << out;
  const auto last = out.substr(out.rfind("queries="));
  EXPECT_EQ(last, "queries=355 fn=0 fp=0\n") << out;
}

TEST(CcdCheckCli, UnitTestsFolder) {
  const std::string d = test::data_dir() + "/ccd-queries/unit-tests";
  int code = -1;
  const std::string out = run_cli(
      "ccd-check " + d + "/vertex-face/data_0_0.csv " + d + "/edge-edge/data_0_0.csv", &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("queries=179 fn=0 fp=0\n"), std::string::npos) << out;
}

TEST(CcdCheckCli, MissingTruthIsUsageError) {
  int code = -1;
  const std::string out =
      run_cli("ccd-check " + test::data_dir() + "/cloth-funnel/queries/227vf.csv", &code);
  EXPECT_EQ(code, 2) << out;
}

}  // namespace
}  // namespace tailor
