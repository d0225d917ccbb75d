/// @file
/// `tailor bench`: its contract on bad input, and the shape of a tiny scale run (the timings
/// themselves are benchmarks, not tests).

#include <sstream>
#include <string>
#include <vector>

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliBench, Help) {
  expect_help("bench", {"paper", "scale"});
  expect_help("bench paper", {"--scene", "--frames", "--out"});
  expect_help("bench scale", {"--max-triangles", "--repetitions", "--min-seconds"});
}

TEST(CliBench, UnknownOptionAndBadValues) {
  expect_usage_error("bench paper --no-such-option", {"--no-such-option"});
  expect_usage_error("bench paper --frames 0", {"--frames"});
  expect_usage_error("bench scale --max-triangles 5", {"--max-triangles"});
  expect_usage_error("bench scale --repetitions 1000", {"--repetitions"});
  expect_usage_error("bench scale --min-seconds -1", {"--min-seconds"});
}

TEST(CliBench, ScaleWritesOneRowPerThreadCountWithPairedSpeedUps) {
  TempDir dir;
  const RunResult r = run_cli(
      "bench scale --scenes folded --min-triangles 2000 --max-triangles "
      "2000 --threads 1 2 --repetitions 2 --min-seconds 0 --out " +
      quoted(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream csv(read_bytes(dir / "out" / "scale.csv"));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_NE(header.find("threads,triangles,floor_ms"), std::string::npos) << header;
  EXPECT_NE(header.find("total_ms,speedup,"), std::string::npos) << header;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    rows.push_back(fields);
  }
  ASSERT_EQ(rows.size(), 2u) << r.output;
  const int speedup = 10;  // column of the header above: scene, threads, triangles, ...
  EXPECT_EQ(rows[0][1], "1");
  EXPECT_EQ(rows[1][1], "2");
  EXPECT_EQ(rows[0][2], rows[1][2]);  // the same mesh for both
  EXPECT_EQ(std::stod(rows[0][speedup]), 1.0);
  EXPECT_GT(std::stod(rows[1][speedup]), 0.0);
  // The same step on one and two threads finds the same collisions (a collision column > 0).
  EXPECT_EQ(rows[0][14], rows[1][14]);
  EXPECT_GT(std::stoll(rows[0][14]), 0);
}

TEST(CliBench, MissingSceneFileIsNamed) {
  TempDir dir;
  expect_usage_error("bench paper --scene " + quoted(dir / "absent.json"), {"absent.json"});
}

}  // namespace
}  // namespace tailor::test
