/// @file
/// The arm-sleeve simulation: short runs of every gesture at low resolution, and the
/// `tailor simulate` command's files (including Ctrl-C).

#include "sim/small_scene.hpp"
#include "support/run_cli.hpp"
#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tailor/scene/scene.hpp"
#include "tailor/sim/frame_writer.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor {
namespace {

namespace fs = std::filesystem;

using tailor::testing::run_cli_quietly;
using tailor::testing::sanitized;

/// A small, fast version of the default scene: the gesture played twice as fast, with
/// twice the substeps, so the arm moves as far per substep as in the default scene.
SceneConfig doubled_substep_scene(const std::string& gesture) {
  SceneConfig c = testing::small_fast_scene(gesture);
  c.substeps = 2 * SceneConfig{}.substeps;
  return c;
}

struct RunResult {
  SimulationTotals totals;
  double max_kinetic = 0;
  double max_edge_ratio = 0;
};

RunResult run(const SceneConfig& config, int frames) {
  SimulationOptions options;
  options.check_intersections = true;  // after every substep
  Simulation sim(config, options);
  RunResult r;
  const Positions& rest = sim.scene().sleeve().rest;
  const EdgeArray& edges = sim.cloth_mesh().edges();
  for (int f = 0; f < frames; ++f) {
    sim.step_frame();
    const Positions& x = sim.cloth_positions();
    EXPECT_TRUE(x.allFinite()) << "frame " << f;
    EXPECT_TRUE(sim.cloth_velocities().allFinite()) << "frame " << f;
    if (!x.allFinite()) break;
    r.max_kinetic = std::max(r.max_kinetic, sim.energy().kinetic);
    for (Eigen::Index e = 0; e < edges.rows(); ++e) {
      const double l = (x.row(edges(e, 0)) - x.row(edges(e, 1))).norm();
      const double l0 = (rest.row(edges(e, 0)) - rest.row(edges(e, 1))).norm();
      r.max_edge_ratio = std::max(r.max_edge_ratio, l / l0);
    }
    // The sleeve stays on the arm: within 0.8 m of the shoulder.
    EXPECT_LT(x.rowwise().norm().maxCoeff(), 0.8) << "frame " << f;
  }
  r.totals = sim.totals();
  return r;
}

void expect_sane(const RunResult& r, const SceneConfig& config) {
  // No intersection after any substep (the static check ran after every one).
  EXPECT_EQ(r.totals.intersections, 0);
  EXPECT_EQ(r.totals.checked_steps, r.totals.steps);
  EXPECT_EQ(r.totals.failed_solves, 0);
  // No fail-safe needed in normal use.
  EXPECT_EQ(r.totals.reverted_vertices, 0);
  EXPECT_EQ(r.totals.unresolved, 0);
  // Bounded energy: the sleeve (about 30 g) never moves on average faster than 3 m/s.
  const double mass = config.material.density * 0.5 * 0.45;
  EXPECT_LT(r.max_kinetic, 0.5 * mass * 3.0 * 3.0);
  // Woven cloth: no edge ever stretched past 10 % after any substep (the limiter's
  // limit is 2.5 %; the contact passes may add a little), measured by the simulation after
  // each substep and here again at each frame's end.
  EXPECT_LE(r.totals.max_strain, 0.10);
  EXPECT_LE(r.max_edge_ratio, 1.10);
}

TEST(Simulation, ElbowGestureMakesTheSleeveCollideWithItself) {
  const SceneConfig c = doubled_substep_scene("elbow");
  // Peak flexion at 0.1 + 1.0 / 2 s = frame 18.
  const RunResult r = run(c, sanitized() ? 18 : 24);
  expect_sane(r, c);
  EXPECT_GT(r.totals.self_collisions, 0);
}

TEST(Simulation, RaiseGesture) {
  const SceneConfig c = doubled_substep_scene("raise");
  const RunResult r = run(c, sanitized() ? 8 : 20);
  expect_sane(r, c);
}

TEST(Simulation, TwistGesture) {
  const SceneConfig c = doubled_substep_scene("twist");
  const RunResult r = run(c, sanitized() ? 8 : 20);
  expect_sane(r, c);
}

TEST(Simulation, PinnedRingFollowsTheArm) {
  SceneConfig c = doubled_substep_scene("raise");
  SimulationOptions options;
  options.contact = false;
  Simulation sim(c, options);
  for (int f = 0; f < 10; ++f) sim.step_frame();
  const Scene& scene = sim.scene();
  const ArmPose pose = scene.gesture().pose_at(sim.time());
  const auto ring = scene.sleeve().ring(0);
  Positions rest(static_cast<Eigen::Index>(ring.size()), 3);
  for (std::size_t i = 0; i < ring.size(); ++i)
    rest.row(static_cast<Eigen::Index>(i)) = scene.sleeve().rest.row(ring[i]);
  const Positions expected = scene.arm().skin_points(rest, pose);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    EXPECT_LT(
        (sim.cloth_positions().row(ring[i]) - expected.row(static_cast<Eigen::Index>(i))).norm(),
        1e-12);
  }
  EXPECT_GT(pose.shoulder_raise, 0.1);  // the arm did move
}

TEST(Simulation, SummaryHasTheRequiredFields) {
  Simulation sim(doubled_substep_scene("elbow"));
  sim.step_frame();
  const nlohmann::json s = simulation_summary(sim, false);
  for (const char* key :
       {"frames", "steps", "self_collisions", "intersections", "interrupted", "ms_per_step"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  for (const char* key : {"forces_solve", "detection", "response", "total"}) {
    EXPECT_TRUE(s["ms_per_step"].contains(key)) << key;
  }
  EXPECT_EQ(s["frames"], 1);
  EXPECT_EQ(s["steps"], 2 * SceneConfig{}.substeps);
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

TEST(SimulateCommand, WritesFramesStepsAndSummary) {
  const fs::path out = fs::temp_directory_path() / "tailor_test_simulate";
  fs::remove_all(out);
  const int frames = 3;
  SceneConfig small;
  small.sleeve.rings = 9;
  small.sleeve.segments = 12;
  const std::size_t observers = Scene(small).observer_loops().size();
  ASSERT_GE(observers, 1u);
  ASSERT_EQ(
      run_cli_quietly({"simulate", "--frames", std::to_string(frames), "--rings", "9", "--segments",
                       "12", "--out", out.string(), "--check-intersections", "--threads", "1"}),
      0);
  for (int f = 0; f <= frames; ++f) {
    EXPECT_TRUE(fs::exists(out / frame_file_name("cloth", f))) << f;
    EXPECT_TRUE(fs::exists(out / frame_file_name("arm", f))) << f;
  }
  EXPECT_FALSE(fs::exists(out / frame_file_name("cloth", frames + 1)));
  std::ifstream steps(out / "steps.jsonl");
  std::string line;
  int lines = 0;
  while (std::getline(steps, line)) {
    const auto j = nlohmann::json::parse(line);
    EXPECT_TRUE(j.contains("detection"));
    EXPECT_TRUE(j.contains("self_collisions"));
    EXPECT_TRUE(j.contains("impulses"));
    EXPECT_TRUE(j.contains("impact_zones"));
    EXPECT_TRUE(j["ms"].contains("step"));
    EXPECT_EQ(j["intersections"]["self"], 0);
    ++lines;
  }
  const int substeps = SceneConfig{}.substeps;
  EXPECT_EQ(lines, frames * substeps);
  const auto s = read_json(out / "summary.json");
  EXPECT_EQ(s["frames"], frames);
  EXPECT_EQ(s["steps"], frames * substeps);
  EXPECT_EQ(s["intersections"], 0);
  EXPECT_EQ(s["interrupted"], false);
  EXPECT_EQ(s["cloth"]["vertices"], 108);
  // The per-frame contact files (the shared contract with the viewer and the renderer).
  EXPECT_FALSE(fs::exists(out / frame_file_name("contacts", 0, ".json")));
  for (int f = 1; f <= frames; ++f) {
    const auto c = read_json(out / frame_file_name("contacts", f, ".json"));
    EXPECT_EQ(c["frame"], f);
    EXPECT_EQ(c["substeps"], substeps);
    ASSERT_TRUE(c["candidate_triangles"].is_array());
    const auto& faces = c["candidate_triangles"];
    for (std::size_t i = 0; i < faces.size(); ++i) {
      EXPECT_GE(faces[i].get<int>(), 0);
      EXPECT_LT(faces[i].get<int>(), 2 * 8 * 12);  // 9 rings × 12 segments: 192 faces
      if (i > 0) {
        EXPECT_LT(faces[i - 1].get<int>(), faces[i].get<int>());  // sorted, unique
      }
    }
    for (const auto& vf : c["vertex_face"]) EXPECT_EQ(vf.size(), 4u);
    for (const auto& ee : c["edge_edge"]) {
      ASSERT_EQ(ee.size(), 6u);
      EXPECT_LT(ee[0].get<int>(), ee[1].get<int>());
      EXPECT_LT(ee[2].get<int>(), ee[3].get<int>());
    }
    // The paper preset has radial view: one observer per section loop of the sleeve.
    EXPECT_EQ(c["observers"].size(), observers);
  }
  const auto clusters = read_json(out / "clusters.json");
  EXPECT_EQ(clusters["cluster_of_face"].size(), 192u);
  // The contact sheet is always written.
  EXPECT_TRUE(fs::exists(out / "contact_sheet.png"));
}

TEST(SimulateCommand, NoContactsWritesNoContactFilesAndRenderWritesFramePictures) {
  const fs::path out = fs::temp_directory_path() / "tailor_test_simulate_nocontacts";
  fs::remove_all(out);
  ASSERT_EQ(run_cli_quietly({"simulate", "--frames", "2", "--rings", "9", "--segments", "12",
                             "--out", out.string(), "--no-contacts", "--render", "--threads", "1"}),
            0);
  EXPECT_FALSE(fs::exists(out / frame_file_name("contacts", 1, ".json")));
  EXPECT_FALSE(fs::exists(out / "clusters.json"));
  for (int f = 0; f <= 2; ++f) EXPECT_TRUE(fs::exists(out / frame_file_name("render", f, ".png")));
}

TEST(SimulateCommand, StaticCheckOnlyWhenAsked) {
  const fs::path out = fs::temp_directory_path() / "tailor_test_simulate_checks";
  const auto checked_steps = [&](std::vector<std::string> extra) {
    fs::remove_all(out);
    std::vector<std::string> args{"simulate",   "--frames",      "2",         "--rings",
                                  "9",          "--segments",    "12",        "--out",
                                  out.string(), "--no-contacts", "--threads", "1"};
    args.insert(args.end(), extra.begin(), extra.end());
    EXPECT_EQ(run_cli_quietly(args), 0);
    return read_json(out / "summary.json")["checked_steps"].get<int>();
  };
  EXPECT_EQ(checked_steps({}), 0);
  EXPECT_EQ(checked_steps({"--check-frames"}), 2);
  EXPECT_EQ(checked_steps({"--check-intersections"}), 2 * SceneConfig{}.substeps);
}

TEST(SimulateCommand, RejectsBadInputWithExitCode2) {
  EXPECT_EQ(run_cli_quietly({"simulate", "--method", "fastest", "--frames", "1"}), 2);
  EXPECT_EQ(run_cli_quietly({"simulate", "--gesture", "wave", "--frames", "1"}), 2);
  EXPECT_EQ(run_cli_quietly({"simulate", "--scene", "/nonexistent/scene.json"}), 2);
  // Too coarse for its faces to clear the arm (see Simulation): rejected, not run.
  EXPECT_EQ(run_cli_quietly({"simulate", "--frames", "1", "--rings", "4", "--segments", "6"}), 2);
}

TEST(SimulateCommand, CtrlCStopsAfterTheFrameWithAValidSummary) {
  const fs::path out = fs::temp_directory_path() / "tailor_test_simulate_sigint";
  fs::remove_all(out);
  const int status = run_cli_quietly({"simulate", "--frames", "100000", "--rings", "13",
                                      "--segments", "20", "--out", out.string(), "--threads", "1"},
                                     sanitized() ? 4.0 : 1.5);
  EXPECT_EQ(status, 130);
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  const auto s = read_json(out / "summary.json");
  EXPECT_EQ(s["interrupted"], true);
  const int frames = s["frames"];
  EXPECT_GT(frames, 0);
  EXPECT_LT(frames, 100000);
  EXPECT_TRUE(fs::exists(out / frame_file_name("cloth", frames)));
  EXPECT_FALSE(fs::exists(out / frame_file_name("cloth", frames + 1)));
  // Every line of steps.jsonl is complete.
  std::ifstream steps(out / "steps.jsonl");
  std::string line;
  int lines = 0;
  while (std::getline(steps, line)) {
    EXPECT_TRUE(nlohmann::json::accept(line)) << line;
    ++lines;
  }
  EXPECT_EQ(lines, frames * SceneConfig{}.substeps);
}

}  // namespace
}  // namespace tailor
