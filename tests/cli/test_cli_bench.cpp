/// @file
/// `tailor bench`: its contract on bad input, and the shape of a tiny scale run (the timings
/// themselves are benchmarks, not tests).

#include <algorithm>
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
  const auto fields = [](const std::string& text) {
    std::vector<std::string> cells;
    std::istringstream stream(text);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    return cells;
  };
  const std::vector<std::string> names = fields(header);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    EXPECT_NE(it, names.end()) << name << " in " << header;
    return static_cast<std::size_t>(it - names.begin());
  };
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows.push_back(fields(line));
  ASSERT_EQ(rows.size(), 2u) << r.output;
  const std::size_t threads = column("threads"), triangles = column("triangles"),
                    speedup = column("speedup"), collisions = column("collisions");
  ASSERT_EQ(names.size(), rows[0].size());
  ASSERT_EQ(names.size(), rows[1].size());
  EXPECT_EQ(rows[0][threads], "1");
  EXPECT_EQ(rows[1][threads], "2");
  EXPECT_EQ(rows[0][triangles], rows[1][triangles]);  // the same mesh for both
  EXPECT_EQ(std::stod(rows[0][speedup]), 1.0);
  EXPECT_GT(std::stod(rows[1][speedup]), 0.0);
  // The same step on one and two threads finds the same collisions, and some.
  EXPECT_EQ(rows[0][collisions], rows[1][collisions]);
  EXPECT_GT(std::stoll(rows[0][collisions]), 0);
}

TEST(CliBench, MissingSceneFileIsNamed) {
  TempDir dir;
  expect_usage_error("bench paper --scene " + quoted(dir / "absent.json"), {"absent.json"});
}

}  // namespace
}  // namespace tailor::test
