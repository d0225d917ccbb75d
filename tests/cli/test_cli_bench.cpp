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
  expect_usage_error("bench memory --scene nope", {"--scene"});
  expect_usage_error("bench memory --triangles 5", {"--triangles"});
}

TEST(CliBench, MemoryOfOneRowIsAFigurePerTriangle) {
  // What `bench scale` runs in a child process for each row: bytes per triangle, alone.
  const RunResult r = run_cli("bench memory --scene folded --triangles 2000 --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double bytes = std::stod(r.output);
  // At least the BVH's node records (64 B per triangle), and far from a leak's size.
  EXPECT_GT(bytes, 64.0) << r.output;
  EXPECT_LT(bytes, 10'000.0) << r.output;
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
  // A folded cloth's root is never certified: every step refits the boxes.
  EXPECT_EQ(rows[0][column("boxes_refitted")], "1");
  EXPECT_GT(std::stod(rows[0][column("bytes_per_triangle")]), 64.0);
}

TEST(CliBench, MissingSceneFileIsNamed) {
  TempDir dir;
  expect_usage_error("bench paper --scene " + quoted(dir / "absent.json"), {"absent.json"});
}

}  // namespace
}  // namespace tailor::test
