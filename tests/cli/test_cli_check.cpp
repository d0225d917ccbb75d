/// @file
/// `tailor check`: exit codes, JSON lines, natural order, the simulator's folder layout, bad
/// input, and Ctrl-C (a real SIGINT to the running command).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_run.hpp"
#include "io/io_test_support.hpp"
#include "support/sanitized.hpp"
#include "support/sequence_files.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/procedural_meshes.hpp"
#include "tailor/mesh/procedural_sequences.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::quoted;
using test::run_cli;
using test::TempDir;
using testing::write_sequence;

FallingFoldOptions fold(int frames, int piercing_frame = -1) {
  FallingFoldOptions o;
  o.cells_along = 32;
  o.cells_across = 3;
  o.frames = frames;
  o.piercing_frame = piercing_frame;
  o.jitter = 1e-3;  // keeps the exact CCD on its fast path
  return o;
}

/// The records of a JSON lines file; fails the test on a line that does not parse.
std::vector<nlohmann::json> read_records(const std::filesystem::path& path) {
  std::vector<nlohmann::json> records;
  std::istringstream lines(test::read_bytes(path));
  std::string line;
  while (std::getline(lines, line)) {
    try {
      records.push_back(nlohmann::json::parse(line));
    } catch (const nlohmann::json::exception& e) {
      ADD_FAILURE() << path << ": line " << records.size() + 1 << " is not JSON: " << e.what();
    }
  }
  return records;
}

TEST(CmdCheck, CleanSequenceExitsZero) {
  TempDir dir;
  write_sequence(dir.path(), make_falling_fold(fold(6)), "fold_{}.ply");
  const auto r =
      run_cli("check " + quoted(dir.path()) + " --json-lines " + quoted(dir / "s.jsonl"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, {"check summary", "6 read", "fold_0.ply", "fold_5.ply", "steps",
                             "frames with intersections", "ms per step"});
  const auto records = read_records(dir / "s.jsonl");
  ASSERT_EQ(records.size(), 5u);
  for (std::size_t k = 0; k < records.size(); ++k) {
    EXPECT_EQ(records[k]["step"], k);
    EXPECT_EQ(records[k]["start"]["frame"], k);
    EXPECT_EQ(records[k]["end"]["frame"], k + 1);
    EXPECT_EQ(records[k]["end"]["intersection_free"], true);
    EXPECT_TRUE(records[k]["vf_collisions"].is_number_integer());
    EXPECT_TRUE(records[k]["ee_collisions"].is_number_integer());
    EXPECT_TRUE(records[k].contains("earliest_toi"));
    EXPECT_TRUE(records[k]["stats"].contains("candidate_triangle_pairs"));
  }
}

TEST(CmdCheck, IntersectingFrameExitsOneAndIsNamed) {
  TempDir dir;
  const int piercing = 7;
  write_sequence(dir.path(), make_falling_fold(fold(10, piercing)), "fold_{:04d}.obj");
  const auto r =
      run_cli("check " + quoted(dir.path()) + " --json-lines " + quoted(dir / "s.jsonl"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  expect_contains(r.output, {"frames with intersections", "1 (first: frame 7, fold_0007.obj)",
                             "intersecting frame 7 (fold_0007.obj)", "steps with contacts"});
  const auto records = read_records(dir / "s.jsonl");
  ASSERT_EQ(records.size(), 9u);
  for (const auto& record : records) {
    const bool into = record["end"]["frame"] == piercing;
    const bool out_of = record["start"]["frame"] == piercing;
    EXPECT_EQ(record["end"]["intersection_free"], !into) << record.dump();
    EXPECT_EQ(record["start"]["intersection_free"], !out_of) << record.dump();
    if (into) {
      EXPECT_GT(record["end"]["self_intersections"].get<int>(), 0);
    }
    if (into || out_of) {
      EXPECT_GT(record["vf_collisions"].get<int>() + record["ee_collisions"].get<int>(), 0);
      EXPECT_TRUE(record["earliest_toi"].is_number());
    }
  }
  // Steps only: the frame is not checked, so nothing fails.
  const auto steps_only = run_cli("check " + quoted(dir.path()) + " --no-frame-check");
  EXPECT_EQ(steps_only.exit_code, 0) << steps_only.output;
  expect_contains(steps_only.output, {"not checked"});
}

TEST(CmdCheck, NaturalOrderFromAFolderAGlobOrTheShell) {
  TempDir dir;
  write_sequence(dir.path(), make_falling_fold(fold(12)), "frame_{}.obj");
  const std::string unquoted_glob = dir.path().string() + "/frame_*.obj";  // no spaces in TempDir
  for (const std::string& frames :
       {quoted(dir.path()), quoted(dir / "frame_*.obj"), unquoted_glob}) {
    const auto r = run_cli("check " + frames + " --json-lines " + quoted(dir / "s.jsonl"));
    EXPECT_EQ(r.exit_code, 0) << frames << "\n" << r.output;
    const auto records = read_records(dir / "s.jsonl");
    ASSERT_EQ(records.size(), 11u) << frames;
    for (std::size_t k = 0; k < records.size(); ++k) {
      EXPECT_EQ(std::filesystem::path(records[k]["start"]["file"]).filename(),
                fmt::format("frame_{}.obj", k))
          << frames;
    }
  }
}

TEST(CmdCheck, RangeOfFrames) {
  TempDir dir;
  write_sequence(dir.path(), make_falling_fold(fold(10, 8)), "f_{}.ply");
  const auto r = run_cli("check " + quoted(dir.path()) + " --from 2 --to 6 --json-lines " +
                         quoted(dir / "s.jsonl"));
  EXPECT_EQ(r.exit_code, 0) << r.output;  // frame 8 is outside the range
  const auto records = read_records(dir / "s.jsonl");
  ASSERT_EQ(records.size(), 4u);
  EXPECT_EQ(records.front()["step"], 2);
  EXPECT_EQ(records.back()["end"]["frame"], 6);
  const auto bad = run_cli("check " + quoted(dir.path()) + " --from 6 --to 2");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  expect_contains(bad.output, {"frames 6 to 2 are not within the sequence", "f_0.ply"});
}

TEST(CmdCheck, MismatchedTopologyStopsNamingTheFrame) {
  TempDir dir;
  ProceduralSequence s = make_falling_fold(fold(6));
  const auto paths = write_sequence(dir.path(), s, "fold_{}.ply");
  MeshData extra;
  extra.vertices.resize(s.frames[3].rows() + 1, 3);
  extra.vertices << s.frames[3], Eigen::RowVector3d(5, 5, 5);
  write_mesh(paths[3], extra.vertices, s.faces);
  const auto r =
      run_cli("check " + quoted(dir.path()) + " --json-lines " + quoted(dir / "s.jsonl"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  expect_contains(r.output,
                  {"error:", "fold_3.ply", "vertices", "fold_0.ply", "stopped at a bad frame"});
  EXPECT_EQ(read_records(dir / "s.jsonl").size(), 2u);  // steps 0 and 1 were complete
}

/// Writes a simulator-like folder: cloth_NNNN.obj beside arm_NNNN.obj (a floor under the
/// cloth; at `raised_frame` it cuts through the fold).
void write_simulator_layout(const TempDir& dir, int frames, int raised_frame) {
  write_sequence(dir.path(), make_falling_fold(fold(frames)), "cloth_{:04d}.obj");
  MeshData floor = make_grid(2, 2, 1.4, 0.4);
  floor.vertices.col(0).array() -= 0.2;
  floor.vertices.col(1).array() -= 0.1;
  for (int k = 0; k < frames; ++k) {
    floor.vertices.col(2).setConstant(k == raised_frame ? 0.01 : -0.01);
    write_mesh(dir / fmt::format("arm_{:04d}.obj", k), floor.vertices, floor.faces);
  }
  test::write_bytes(dir / "steps.jsonl", "{}\n");
}

TEST(CmdCheck, SimulatorFolderChecksTheClothAgainstTheArm) {
  TempDir dir;
  write_simulator_layout(dir, 5, 3);
  const auto r =
      run_cli("check " + quoted(dir.path()) + " --json-lines " + quoted(dir / "s.jsonl"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  expect_contains(
      r.output, {"cloth_*.obj", "arm_*.obj", "beside", "5 read", "first: frame 3, cloth_0003.obj"});
  const auto records = read_records(dir / "s.jsonl");
  ASSERT_EQ(records.size(), 4u);
  EXPECT_GT(records[2]["end"]["obstacle_intersections"].get<int>(), 0);
  EXPECT_EQ(records[2]["end"]["self_intersections"], 0);
  EXPECT_EQ(records[1]["end"]["obstacle_intersections"], 0);

  // A pattern picks the cloth alone; a named obstacle replaces the arm.
  const auto cloth_only = run_cli("check " + quoted(dir / "cloth_*.obj"));
  EXPECT_EQ(cloth_only.exit_code, 0) << cloth_only.output;
  expect_contains(cloth_only.output, {"obstacle", "none"});
  const auto named =
      run_cli("check " + quoted(dir.path()) + " --obstacle " + quoted(dir / "arm_0000.obj"));
  EXPECT_EQ(named.exit_code, 0) << named.output;
  expect_contains(named.output, {"arm_0000.obj (1 frame)"});
}

TEST(CmdCheck, BadInputExitsTwo) {
  TempDir dir;
  write_sequence(dir.path(), make_falling_fold(fold(3)), "a_{}.obj");
  write_sequence(dir.path(), make_falling_fold(fold(2)), "b_{}.obj");
  const auto mixed = run_cli("check " + quoted(dir.path()));
  EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
  expect_contains(mixed.output, {"mixes 2 frame sequences", "a_*.obj (3 files)",
                                 "b_*.obj (2 files)", "name one with a pattern"});
  const auto count =
      run_cli("check " + quoted(dir / "a_*.obj") + " --obstacle " + quoted(dir / "b_*.obj"));
  EXPECT_EQ(count.exit_code, 2) << count.output;
  expect_contains(count.output, {"obstacle has 2 frames", "sequence has 3"});
  const auto missing = run_cli("check " + quoted(dir / "none_*.obj"));
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  expect_contains(missing.output, {"none_*.obj"});
  const auto observers_file = dir / "observers.json";
  test::write_bytes(observers_file, "{\"loops\": [[0, 1, 2]], \"extra\": 1}");
  const auto observers =
      run_cli("check " + quoted(dir / "a_*.obj") + " --observers " + quoted(observers_file));
  EXPECT_EQ(observers.exit_code, 2) << observers.output;
  expect_contains(observers.output, {"observers.json", "unknown field"});
  const auto unwritable = run_cli("check " + quoted(dir / "a_*.obj") + " --json-lines " +
                                  quoted(dir / "no-such-folder" / "s.jsonl"));
  EXPECT_EQ(unwritable.exit_code, 2) << unwritable.output;
  expect_contains(unwritable.output, {"s.jsonl", "cannot write"});
  EXPECT_EQ(run_cli("check " + quoted(dir / "a_*.obj") + " --no-such-option").exit_code, 2);
  EXPECT_EQ(run_cli("check").exit_code, 2);
  EXPECT_EQ(run_cli("check " + quoted(dir / "a_*.obj") + " --read-ahead -1").exit_code, 2);
  const auto help = run_cli("check --help");
  EXPECT_EQ(help.exit_code, 0);
  expect_contains(help.output, {"--obstacle", "--json-lines", "--from", "--to", "--observers",
                                "--method", "--read-ahead"});
}

TEST(CmdCheck, CtrlCKeepsEveryRecordWritten) {
  TempDir dir;
  // Long enough that the run is far from done when the signal arrives (~1 s in release).
  FallingFoldOptions o;
  o.cells_along = 96;
  o.cells_across = 16;
  o.frames = testing::sanitized() ? 150 : 300;
  o.jitter = 1e-3;
  write_sequence(dir.path(), make_falling_fold(o), "fold_{}.ply");
  const auto jsonl = dir / "s.jsonl";
  const pid_t pid = test::spawn_cli(
      {"check", dir.path().string(), "--json-lines", jsonl.string(), "--threads", "1"},
      dir / "log.txt");
  ASSERT_GT(pid, 0);
  // Wait for three complete records, then press Ctrl-C.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  bool exited_early = false;
  int status = 0;
  while (true) {
    const std::string text = test::read_bytes(jsonl);
    if (std::count(text.begin(), text.end(), '\n') >= 3) break;
    if (waitpid(pid, &status, WNOHANG) == pid) {
      exited_early = true;
      break;
    }
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "no records after 120 s";
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_FALSE(exited_early) << test::read_bytes(dir / "log.txt");
  ASSERT_EQ(kill(pid, SIGINT), 0);
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  const std::string log = test::read_bytes(dir / "log.txt");
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << "\n" << log;
  EXPECT_EQ(WEXITSTATUS(status), 130) << log;
  expect_contains(log, {"check summary", "(interrupted)", "interrupted after step"});

  const std::string text = test::read_bytes(jsonl);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "the last record is incomplete";
  const auto records = read_records(jsonl);
  EXPECT_GE(records.size(), 3u);
  EXPECT_LT(records.size(), static_cast<std::size_t>(o.frames - 1)) << "did not stop early";
  for (std::size_t k = 0; k < records.size(); ++k) EXPECT_EQ(records[k]["step"], k);
}

}  // namespace
}  // namespace tailor
