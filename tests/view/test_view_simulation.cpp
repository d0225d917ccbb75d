/// @file
/// `tailor view DIR` on simulation outputs: the data it writes decodes to the input, and
/// bad folders or files give exit code 2 with the file named.

#include <gtest/gtest.h>

#include "view/view_test_support.hpp"

namespace tailor {
namespace {

using testing::quoted;
using testing::run_cli;

// Contacts of frame `frame` in the shared format (docs/viewer.md).
std::string contacts_json(int frame, const std::string& candidates) {
  return "{\"frame\": " + std::to_string(frame) + ", \"candidate_triangles\": " + candidates +
         ", \"vertex_face\": [[3, 0, 1, 0.25]], \"edge_edge\": [[0, 1, 2, 3, 0, 0.5]], "
         "\"observers\": [[0.5, 0.5, 2.0]], \"substeps\": 2}";
}

// A three-frame run with every optional file: steps.jsonl (two substeps per frame),
// contacts of frames 1 and 2 (one and two candidate faces: base64 with padding), clusters.
void write_full_run(const std::filesystem::path& dir) {
  test::write_simulation_frames(dir, 3);
  test::write_bytes(dir / "steps.jsonl",
                    "{\"frame\": 1, \"substep\": 0, \"time\": 0.1, \"self_collisions\": 2, "
                    "\"detection\": {\"vf_tested\": 5}, \"ms\": {\"step\": 1.5}}\n"
                    "{\"frame\": 1, \"substep\": 1, \"time\": 0.2, \"self_collisions\": 1, "
                    "\"detection\": {\"vf_tested\": 7}, \"ms\": {\"step\": 2.0}}\n"
                    "{\"frame\": 2, \"substep\": 0, \"time\": 0.3, \"self_collisions\": 0, "
                    "\"detection\": {\"vf_tested\": 1}, \"ms\": {\"step\": 1.0}}\n");
  test::write_bytes(dir / "contacts_0001.json", contacts_json(1, "[1]"));
  test::write_bytes(dir / "contacts_0002.json", contacts_json(2, "[0, 1]"));
  test::write_bytes(dir / "clusters.json", "{\"cluster_of_face\": [0, 3]}");
}

TEST(ViewSimulation, WritesPageAndDataThatDecodeToTheInput) {
  test::TempDir dir;
  write_full_run(dir.path());
  TAILOR_RUN_VIEW_OR_SKIP(r, "view " + quoted(dir.path()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto view = dir / "view";
  test::expect_contains(r.output, {"wrote 3 frames", "open file://", "index.html"});
  for (const char* name : {"index.html", "viewer.js", "data/scene.js", "data/frame_0000.js",
                           "data/frame_0001.js", "data/frame_0002.js"}) {
    EXPECT_TRUE(std::filesystem::exists(view / name)) << name;
  }
  test::expect_contains(test::read_bytes(view / "index.html"), {"<script src=\"viewer.js\">"});
  test::expect_contains(test::read_bytes(view / "viewer.js"), {"tailorViewData", "Three.js"});

  const nlohmann::json scene = test::data_script_json(view / "data/scene.js");
  EXPECT_EQ(scene["kind"], "simulation");
  EXPECT_EQ(scene["frames"], 3);
  EXPECT_EQ(scene["cloth"]["vertices"], 4);
  EXPECT_EQ(test::decode_uint32(scene["cloth"]["indices"]),
            (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(test::decode_uint32(scene["arm"]["indices"]), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(test::decode_uint32(scene["clusters"]), (std::vector<std::uint32_t>{0, 3}));
  EXPECT_EQ(scene["has_contacts"], (nlohmann::json{false, true, true}));
  // steps.jsonl summed per frame; frame 0 has no step.
  const auto& series = scene["stats"]["series"];
  EXPECT_EQ(series["detection.vf_tested"], (nlohmann::json{nullptr, 12.0, 1.0}));
  EXPECT_EQ(series["ms.step"], (nlohmann::json{nullptr, 3.5, 1.0}));
  EXPECT_EQ(series["self_collisions"], (nlohmann::json{nullptr, 3.0, 0.0}));
  EXPECT_FALSE(series.contains("substep"));
  EXPECT_FALSE(series.contains("time"));

  for (int k = 0; k < 3; ++k) {
    const nlohmann::json frame =
        test::data_script_json(view / ("data/frame_000" + std::to_string(k) + ".js"));
    const std::vector<float> cloth = test::decode_float32(frame["cloth"]);
    const Positions expected = test::square(0.5 - 0.125 * k);
    ASSERT_EQ(cloth.size(), 12u);
    for (Eigen::Index i = 0; i < 12; ++i) {
      EXPECT_EQ(cloth[static_cast<std::size_t>(i)], static_cast<float>(expected(i / 3, i % 3)));
    }
    EXPECT_EQ(test::decode_float32(frame["arm"]).size(), 9u);
    EXPECT_EQ(frame.contains("contacts"), k > 0);
  }
  const nlohmann::json frame2 = test::data_script_json(view / "data/frame_0002.js");
  const auto& contacts = frame2["contacts"];
  EXPECT_EQ(test::decode_uint32(contacts["candidates"]), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(contacts["vertex_face_count"], 1);
  EXPECT_EQ(test::decode_uint32(contacts["vertex_face"]), (std::vector<std::uint32_t>{3, 0, 1}));
  EXPECT_EQ(test::decode_float32(contacts["vertex_face_toi"]), (std::vector<float>{0.25f}));
  EXPECT_EQ(contacts["edge_edge_count"], 1);
  EXPECT_EQ(test::decode_uint32(contacts["edge_edge"]),
            (std::vector<std::uint32_t>{0, 1, 2, 3, 0}));
  EXPECT_EQ(test::decode_float32(contacts["edge_edge_toi"]), (std::vector<float>{0.5f}));
  EXPECT_EQ(contacts["observers"], (nlohmann::json{{0.5, 0.5, 2.0}}));
  EXPECT_EQ(contacts["substeps"], 2);
  const nlohmann::json frame1 = test::data_script_json(view / "data/frame_0001.js");
  EXPECT_EQ(test::decode_uint32(frame1["contacts"]["candidates"]), (std::vector<std::uint32_t>{1}));
}

TEST(ViewSimulation, MinimalRunAndOutFolder) {
  test::TempDir dir;
  test::write_simulation_frames(dir.path(), 1);
  std::filesystem::remove(dir / "arm_0000.obj");
  TAILOR_RUN_VIEW_OR_SKIP(r, "view " + quoted(dir.path()) + " --out " + quoted(dir / "elsewhere"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json scene = test::data_script_json(dir / "elsewhere/data/scene.js");
  EXPECT_EQ(scene["frames"], 1);
  EXPECT_TRUE(scene["arm"].is_null());
  EXPECT_TRUE(scene["clusters"].is_null());
  EXPECT_TRUE(scene["stats"].is_null());
  EXPECT_FALSE(std::filesystem::exists(dir / "view"));
}

TEST(ViewSimulation, NotASimulationFolder) {
  test::TempDir dir;
  test::write_bytes(dir / "notes.txt", "hello");
  const auto empty = run_cli("view " + quoted(dir.path()));
  EXPECT_EQ(empty.exit_code, 2) << empty.output;
  test::expect_contains(empty.output,
                        {dir.path().string(), "not a `tailor simulate` output", "cloth_0000.obj"});
  const auto file = run_cli("view " + quoted(dir / "notes.txt"));
  EXPECT_EQ(file.exit_code, 2) << file.output;
  test::expect_contains(file.output, {"notes.txt", "not a folder"});
  const auto missing = run_cli("view " + quoted(dir / "absent"));
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  test::expect_contains(missing.output, {"absent", "not a folder"});
}

TEST(ViewSimulation, FramesWithDifferentVertexCounts) {
  test::TempDir dir;
  test::write_simulation_frames(dir.path(), 3);
  Positions five(5, 3);
  five << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 2, 0;
  FaceArray faces(2, 3);
  faces << 0, 1, 2, 0, 2, 4;
  write_obj(dir / "cloth_0002.obj", five, faces);
  const auto r = run_cli("view " + quoted(dir.path()));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  test::expect_contains(r.output, {"cloth_0002.obj", "5"});
  EXPECT_FALSE(std::filesystem::exists(dir / "view/index.html"));
}

TEST(ViewSimulation, ArmMissingForAFrame) {
  test::TempDir dir;
  test::write_simulation_frames(dir.path(), 3);
  std::filesystem::remove(dir / "arm_0001.obj");
  const auto r = run_cli("view " + quoted(dir.path()));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  test::expect_contains(r.output, {"arm_0001.obj", "missing"});
}

TEST(ViewSimulation, MalformedOrTruncatedFrame) {
  test::TempDir dir;
  test::write_simulation_frames(dir.path(), 2);
  const std::string bytes = test::read_bytes(dir / "cloth_0001.obj");
  test::write_bytes(dir / "cloth_0001.obj", bytes.substr(0, bytes.size() - 9));
  const auto r = run_cli("view " + quoted(dir.path()));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  test::expect_contains(r.output, {"cloth_0001.obj"});
}

struct BadContacts {
  std::string file, content;
  std::vector<std::string_view> expected;
};

TEST(ViewSimulation, BadContactFilesNameTheFileAndEntry) {
  const std::vector<BadContacts> cases = {
      {"contacts_0001.json", "{\"frame\": 1, \"candidate_triangles\": [", {"not valid JSON"}},
      {"contacts_0001.json", contacts_json(1, "[2]"), {"candidate_triangles[0]", "out of range"}},
      {"contacts_0001.json", contacts_json(1, "[1, 0]"), {"candidate_triangles[1]", "sorted"}},
      {"contacts_0001.json", contacts_json(2, "[1]"), {"frame", "does not match"}},
      {"contacts_0001.json",
       "{\"frame\": 1, \"candidate_triangles\": [], \"vertex_face\": [[3, 0, 2, 0.5]], "
       "\"edge_edge\": [], \"observers\": [], \"substeps\": 2}",
       {"vertex_face[0][2]", "out of range"}},
      {"contacts_0001.json",
       "{\"frame\": 1, \"candidate_triangles\": [], \"vertex_face\": [[3, 0, 0, 1.5]], "
       "\"edge_edge\": [], \"observers\": [], \"substeps\": 2}",
       {"vertex_face[0][3]", "out of range"}},
      {"contacts_0001.json",
       "{\"frame\": 1, \"candidate_triangles\": [], \"vertex_face\": [], "
       "\"edge_edge\": [[1, 0, 2, 3, 0, 0.5]], \"observers\": [], \"substeps\": 2}",
       {"edge_edge[0]", "a0 < a1"}},
      {"contacts_0001.json",
       "{\"frame\": 1, \"candidate_triangles\": [], \"vertex_face\": [], "
       "\"edge_edge\": [], \"observers\": [[1, 2]], \"substeps\": 2}",
       {"observers[0]", "expected 3 elements"}},
      {"contacts_0001.json", "{\"frame\": 1}", {"missing field", "substeps"}},
      {"clusters.json", "{\"cluster_of_face\": [0]}", {"cluster_of_face", "expected 2 elements"}},
      {"clusters.json", "[0, 1]", {"expected a JSON object"}},
      {"steps.jsonl", "{\"frame\": 1}\nnot json\n", {"steps.jsonl:2", "not valid JSON"}},
      {"steps.jsonl", "{\"frame\": 7}\n", {"steps.jsonl:1", "frame 7"}},
  };
  for (const BadContacts& c : cases) {
    SCOPED_TRACE(c.content);
    test::TempDir dir;
    test::write_simulation_frames(dir.path(), 2);
    test::write_bytes(dir / c.file, c.content);
    const auto r = run_cli("view " + quoted(dir.path()));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    test::expect_contains(r.output, {c.file});
    for (std::string_view part : c.expected) test::expect_contains(r.output, {part});
  }
}

TEST(ViewSimulation, BadArguments) {
  test::TempDir dir;
  test::write_simulation_frames(dir.path(), 1);
  for (const std::string& arguments :
       {std::string("view"), "view " + quoted(dir.path()) + " " + quoted(dir.path()),
        "view --no-such-option " + quoted(dir.path())}) {
    const auto r = run_cli(arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.output;
  }
}

}  // namespace
}  // namespace tailor
