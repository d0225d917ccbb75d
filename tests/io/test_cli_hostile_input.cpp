/// @file
/// The CLI on the hostile and careless inputs of issue 17: each one a clear error naming
/// the file or option, exit code 2, no crash.

#include <gtest/gtest.h>

#include <string>

#include "io_test_support.hpp"

namespace tailor {
namespace {

using test::CliResult;
using test::expect_contains;
using test::quoted;
using test::run_cli;
using test::TempDir;

/// Expects exit code 2 and every part in the output.
void expect_usage_error(const CliResult& r, std::initializer_list<std::string_view> parts) {
  EXPECT_EQ(r.exit_code, 2) << r.output.substr(0, 2000);
  expect_contains(r.output, parts);
}

TEST(CliHostileInput, ThreadsAboveTheBoundAreRefused) {
  // `detect --threads 100000` used to segfault in the task arena's shutdown, and
  // `simulate --threads 100000` to start 30,000 threads.
  TempDir dir;
  test::write_triangle(dir / "a.obj");  // a one-triangle step (t0 = t1)
  const std::string mesh = quoted(dir / "a.obj");
  expect_usage_error(run_cli("detect " + mesh + " " + mesh + " --threads 100000"),
                     {"--threads", "hardware threads"});
  expect_usage_error(run_cli("simulate --frames 0 --threads 100000 --out " + quoted(dir / "o")),
                     {"--threads", "hardware threads"});
  expect_usage_error(run_cli("detect " + mesh + " " + mesh + " --threads -1"), {"--threads"});
  const CliResult ok = run_cli("detect " + mesh + " " + mesh + " --threads 2");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST(CliHostileInput, DeeplyNestedSceneIsAnError) {
  // 100,000 levels used to overflow the stack (exit by SIGSEGV).
  TempDir dir;
  test::write_bytes(dir / "deep.json",
                    "{\"arm\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}");
  const CliResult r = run_cli("simulate --frames 0 --scene " + quoted(dir / "deep.json") +
                              " --out " + quoted(dir / "o"));
  expect_usage_error(r, {"deep.json", "nested deeper than 64 levels"});
  EXPECT_LT(r.output.size(), 300u);
}

TEST(CliHostileInput, NumberOverflowInSceneNamesTheFile) {
  // Used to escape as nlohmann::json::out_of_range (exit 1, no file named).
  TempDir dir;
  test::write_bytes(dir / "big.json", R"({"gravity": [0, 1e400, 0]})");
  expect_usage_error(run_cli("simulate --frames 0 --scene " + quoted(dir / "big.json") + " --out " +
                             quoted(dir / "o")),
                     {"big.json", "1e400"});
}

TEST(CliHostileInput, HugeSleeveIsRefusedUnlessTheBudgetAllowsIt) {
  // 16384 × 16384 used to pass the 2^28 cap and take over 4 GB in seconds.
  TempDir dir;
  test::write_bytes(dir / "huge.json", R"({"sleeve": {"rings": 16384, "segments": 16384}})");
  expect_usage_error(run_cli("simulate --frames 0 --scene " + quoted(dir / "huge.json") +
                             " --out " + quoted(dir / "o")),
                     {"huge.json", "16384 × 16384", "memory budget", "--max-memory"});
  expect_usage_error(
      run_cli("simulate --frames 0 --rings 16384 --segments 16384 --out " + quoted(dir / "o")),
      {"sleeve of 16384 rings × 16384 segments", "memory budget"});
  // The arm had no cap at all.
  test::write_bytes(dir / "arm.json", R"({"arm": {"rings": 100000, "segments": 100000}})");
  expect_usage_error(run_cli("simulate --frames 0 --scene " + quoted(dir / "arm.json") + " --out " +
                             quoted(dir / "o")),
                     {"arm.json", "memory budget"});
  // The budget is an option: a small one refuses the default scene, which fits in 4 GiB.
  expect_usage_error(run_cli("--max-memory 0.01 simulate --frames 0 --out " + quoted(dir / "o")),
                     {"memory budget of 10.2 MiB"});
  expect_usage_error(run_cli("simulate --frames 0 --max-memory 0.01 --out " + quoted(dir / "o")),
                     {"memory budget of 10.2 MiB"});
  const CliResult ok = run_cli("simulate --frames 0 --out " + quoted(dir / "o"));
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST(CliHostileInput, MeshWithoutFacesIsAnError) {
  TempDir dir;
  test::write_bytes(dir / "empty.obj", "");
  expect_usage_error(run_cli("info " + quoted(dir / "empty.obj")), {"empty.obj", "no faces"});
  test::write_bytes(dir / "points.obj", "v 0 0 0\n");
  expect_usage_error(run_cli("info " + quoted(dir / "points.obj")), {"points.obj", "no faces"});
}

TEST(CliHostileInput, ObserverIdsMustBeIntegersInRange) {
  TempDir dir;
  test::write_triangle(dir / "a.obj");  // a one-triangle step (t0 = t1)
  const std::string mesh = quoted(dir / "a.obj");
  test::write_bytes(dir / "half.json", R"({"loops": [[0, 2.5, 1]]})");
  expect_usage_error(
      run_cli("detect " + mesh + " " + mesh + " --observers " + quoted(dir / "half.json")),
      {"half.json", "loops[0][1]", "2.5"});
  test::write_bytes(dir / "huge.json", R"({"loops": [[0, 1e30, 1]]})");
  expect_usage_error(
      run_cli("detect " + mesh + " " + mesh + " --observers " + quoted(dir / "huge.json")),
      {"huge.json", "loops[0][1]"});
}

TEST(CliHostileInput, OutputFoldersAreCheckedFirst) {
  // bench used to run the whole benchmark, then fail with exit code 1; generate failed
  // with exit code 1 (an escaping std::filesystem::filesystem_error).
  TempDir dir;
  test::write_bytes(dir / "existing", "a file, not a folder");
  expect_usage_error(run_cli("generate --triangles 200 --out " + quoted(dir / "existing")),
                     {"existing", "output folder"});
  for (const char* run :
       {"scale --min-triangles 1000 --max-triangles 1000 --repetitions 1", "paper --frames 1"}) {
    const CliResult r = run_cli(std::string("bench ") + run + " --out " + quoted(dir / "existing"));
    expect_usage_error(r, {"existing", "output folder"});
    EXPECT_EQ(r.output.find("| scene"), std::string::npos) << "the benchmark ran: " << r.output;
    EXPECT_EQ(r.output.find("## Fig. 1"), std::string::npos) << "the benchmark ran: " << r.output;
  }
}

TEST(CliHostileInput, NegativeMaxPairsIsRefused) {
  TempDir dir;
  test::write_triangle(dir / "a.obj");  // a one-triangle step (t0 = t1)
  expect_usage_error(run_cli("check-intersections " + quoted(dir / "a.obj") + " --max-pairs -1"),
                     {"--max-pairs"});
}

TEST(CliHostileInput, EmptyQueryFileNamesTheFile) {
  TempDir dir;
  std::filesystem::create_directories(dir / "vertex-face");
  test::write_bytes(dir / "vertex-face" / "empty.csv", "");
  expect_usage_error(run_cli("ccd-check " + quoted(dir / "vertex-face" / "empty.csv")),
                     {"empty.csv", "no queries"});
}

TEST(CliHostileInput, GigabytesOfZerosAsQueriesFailFast) {
  TempDir dir;
  std::filesystem::create_directories(dir / "edge-edge");
  test::make_sparse_file(dir / "edge-edge" / "zeros.csv", std::uintmax_t{2} << 30);
  const CliResult r = run_cli("ccd-check " + quoted(dir / "edge-edge" / "zeros.csv"));
  expect_usage_error(r, {"zeros.csv:1:", "longer than"});
  EXPECT_LT(r.output.size(), 300u);
}

}  // namespace
}  // namespace tailor
