/// @file
/// `tailor view --detect FILE.json T0 T1`: one detected step shown as frames 0 and 1.

#include <gtest/gtest.h>

#include "tailor/detection/brute_force.hpp"
#include "tailor/mesh/triangle_mesh.hpp"
#include "view/view_test_support.hpp"

namespace tailor {
namespace {

using testing::quoted;
using testing::run_cli;

// Two squares, one passing through the other during the step: real collisions.
struct Step {
  Positions x0, x1;
  FaceArray faces;
};
Step crossing_squares() {
  Step s;
  s.x0.resize(8, 3);
  s.x1.resize(8, 3);
  s.x0 << test::square(0.0), test::square(0.5).rowwise() + Eigen::RowVector3d(0.25, 0.25, 0.0);
  s.x1 << test::square(0.0), test::square(-0.5).rowwise() + Eigen::RowVector3d(0.25, 0.25, 0.0);
  s.faces.resize(4, 3);
  s.faces << test::square_faces(), test::square_faces().array() + 4;
  return s;
}

void write_step(const test::TempDir& dir, const Step& s) {
  write_obj(dir / "t0.obj", s.x0, s.faces);
  write_obj(dir / "t1.obj", s.x1, s.faces);
}

std::string detect_arguments(const test::TempDir& dir, const std::string& json = "detect.json") {
  return "view --detect " + quoted(dir / json) + " " + quoted(dir / "t0.obj") + " " +
         quoted(dir / "t1.obj");
}

TEST(ViewDetection, ShowsTheCollisionsOfTailorDetectAndItsCandidates) {
  test::TempDir dir;
  const Step step = crossing_squares();
  write_step(dir, step);
  const auto detect = run_cli("detect " + quoted(dir / "t0.obj") + " " + quoted(dir / "t1.obj") +
                              " --json " + quoted(dir / "detect.json"));
  ASSERT_EQ(detect.exit_code, 0) << detect.output;
  TAILOR_RUN_VIEW_OR_SKIP(r, detect_arguments(dir));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  test::expect_contains(r.output, {"wrote 2 frames", "open file://"});

  const nlohmann::json scene = test::data_script_json(dir / "view/data/scene.js");
  EXPECT_EQ(scene["kind"], "detection");
  EXPECT_EQ(scene["frames"], 2);
  EXPECT_TRUE(scene["arm"].is_null());
  EXPECT_EQ(scene["has_contacts"], (nlohmann::json{false, true}));
  EXPECT_TRUE(scene["stats"]["series"].contains("detection.candidate_triangle_pairs"));

  // The collisions shown are those brute force finds (tailor detect reports exactly those).
  const TriangleMesh mesh(8, step.faces);
  const CollisionSet truth = brute_force_self_collisions(mesh, step.x0, step.x1);
  ASSERT_FALSE(truth.vertex_face.empty());
  const nlohmann::json frame = test::data_script_json(dir / "view/data/frame_0001.js");
  const auto& contacts = frame["contacts"];
  const std::vector<std::uint32_t> vf = test::decode_uint32(contacts["vertex_face"]);
  const std::vector<float> vf_toi = test::decode_float32(contacts["vertex_face_toi"]);
  ASSERT_EQ(vf.size(), 3 * truth.vertex_face.size());
  ASSERT_EQ(vf_toi.size(), truth.vertex_face.size());
  for (std::size_t i = 0; i < truth.vertex_face.size(); ++i) {
    EXPECT_EQ(vf[3 * i], static_cast<std::uint32_t>(truth.vertex_face[i].vertex));
    EXPECT_EQ(vf[3 * i + 1], static_cast<std::uint32_t>(truth.vertex_face[i].face));
    EXPECT_EQ(vf[3 * i + 2], 0u);  // one substep
    EXPECT_EQ(vf_toi[i], static_cast<float>(truth.vertex_face[i].toi));
  }
  const std::vector<std::uint32_t> ee = test::decode_uint32(contacts["edge_edge"]);
  ASSERT_EQ(ee.size(), 5 * truth.edge_edge.size());
  for (std::size_t i = 0; i < truth.edge_edge.size(); ++i) {
    const auto& c = truth.edge_edge[i];
    EXPECT_EQ(std::vector<std::uint32_t>(ee.begin() + 5 * i, ee.begin() + 5 * i + 5),
              (std::vector<std::uint32_t>{
                  static_cast<std::uint32_t>(c.a0), static_cast<std::uint32_t>(c.a1),
                  static_cast<std::uint32_t>(c.b0), static_cast<std::uint32_t>(c.b1), 0u}));
  }
  EXPECT_EQ(contacts["substeps"], 1);
  // Every face touched by a collision is in some candidate pair (culling drops none).
  const std::vector<std::uint32_t> candidates = test::decode_uint32(contacts["candidates"]);
  for (const auto& c : truth.vertex_face) {
    EXPECT_NE(std::find(candidates.begin(), candidates.end(), static_cast<std::uint32_t>(c.face)),
              candidates.end())
        << "face " << c.face;
  }
  EXPECT_TRUE(std::is_sorted(candidates.begin(), candidates.end()));

  TAILOR_RUN_VIEW_OR_SKIP(
      none, detect_arguments(dir) + " --no-candidates --out " + quoted(dir / "plain"));
  ASSERT_EQ(none.exit_code, 0) << none.output;
  const nlohmann::json plain = test::data_script_json(dir / "plain/data/frame_0001.js");
  EXPECT_TRUE(test::decode_uint32(plain["contacts"]["candidates"]).empty());
}

TEST(ViewDetection, BadInput) {
  test::TempDir dir;
  const Step step = crossing_squares();
  write_step(dir, step);
  const std::string good = "{\"collisions\": {\"vertex_face\": [], \"edge_edge\": []}}";
  struct Case {
    std::string json;
    std::vector<std::string_view> expected;
  };
  const std::vector<Case> cases = {
      {"{\"collisions\": ", {"detect.json", "not valid JSON"}},
      {"{\"stats\": {}}", {"detect.json", "missing field", "collisions"}},
      {"{\"collisions\": {\"vertex_face\": [[8, 0, 0.5]], \"edge_edge\": []}}",
       {"detect.json", "vertex_face[0][0]", "out of range"}},
      {"{\"collisions\": {\"vertex_face\": [[0, 4, 0.5]], \"edge_edge\": []}}",
       {"detect.json", "vertex_face[0][1]", "out of range"}},
      {"{\"collisions\": {\"vertex_face\": [], \"edge_edge\": [[0, 1, 2, 3, \"x\"]]}}",
       {"detect.json", "edge_edge[0][4]", "expected a number"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.json);
    test::write_bytes(dir / "detect.json", c.json);
    const auto r = run_cli(detect_arguments(dir));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (std::string_view part : c.expected) test::expect_contains(r.output, {part});
  }

  test::write_bytes(dir / "detect.json", good);
  Positions fewer = step.x1.topRows(7);
  FaceArray faces(1, 3);
  faces << 0, 1, 2;
  write_obj(dir / "t1.obj", fewer, faces);
  const auto topology = run_cli(detect_arguments(dir));
  EXPECT_EQ(topology.exit_code, 2) << topology.output;
  test::expect_contains(topology.output, {"t1.obj"});

  const auto one_mesh =
      run_cli("view --detect " + quoted(dir / "detect.json") + " " + quoted(dir / "t0.obj"));
  EXPECT_EQ(one_mesh.exit_code, 2) << one_mesh.output;
  test::expect_contains(one_mesh.output, {"T0 and T1"});
  const auto absent = run_cli(detect_arguments(dir, "absent.json"));
  EXPECT_EQ(absent.exit_code, 2) << absent.output;
  test::expect_contains(absent.output, {"absent.json", "cannot open"});
}

}  // namespace
}  // namespace tailor
