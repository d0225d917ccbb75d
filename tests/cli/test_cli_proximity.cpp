/// @file
/// `tailor proximity`: the pairs of a reference frame equal the library's, written as JSON;
/// bad options and files exit with code 2.

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "tailor/detection/proximity_pairs.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor::test {
namespace {

TEST(CliProximity, Help) {
  expect_help("proximity", {"MESH", "--thickness", "--thickness-share", "--json"});
}

TEST(CliProximity, ReferenceFrameMatchesTheLibrary) {
  TempDir dir;
  const std::filesystem::path frame = data_file("cloth-funnel/frames/227.ply");
  const auto json = dir / "pairs.json";
  const RunResult r = run_cli("proximity " + quoted(frame) + " --thickness-share 2e-3 --json " +
                              quoted(json) + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, {"thickness", "vertex-face", "edge-edge"});
  const nlohmann::json out = nlohmann::json::parse(std::ifstream(json));
  const MeshData data = read_mesh(frame.string());
  const TriangleMesh mesh(static_cast<Index>(data.vertices.rows()), data.faces);
  const ProximityPairs pairs = proximity_pairs(mesh, data.vertices, out["thickness"].get<double>());
  ASSERT_EQ(out["vertex_face"].size(), pairs.vertex_face.size());
  ASSERT_EQ(out["edge_edge"].size(), pairs.edge_edge.size());
  EXPECT_GT(pairs.vertex_face.size() + pairs.edge_edge.size(), 0u);
  for (std::size_t i = 0; i < pairs.vertex_face.size(); ++i) {
    EXPECT_EQ(out["vertex_face"][i][0].get<Index>(), pairs.vertex_face[i].vertex);
    EXPECT_EQ(out["vertex_face"][i][1].get<Index>(), pairs.vertex_face[i].face);
  }
}

TEST(CliProximity, BadInputExitsWithCode2) {
  TempDir dir;
  const std::string frame = quoted(data_file("cloth-funnel/frames/227.ply"));
  expect_usage_error("proximity " + frame, {"--thickness"});
  expect_usage_error("proximity " + frame + " --thickness -1", {"--thickness"});
  expect_usage_error("proximity " + frame + " --thickness 1 --thickness-share 1", {"--thickness"});
  const auto cut = truncated_copy(dir, "thick-cloth/t0.ply", "cut.ply");
  expect_usage_error("proximity " + quoted(cut) + " --thickness 0.1", {"cut.ply"});
}

}  // namespace
}  // namespace tailor::test
