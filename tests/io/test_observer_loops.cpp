/// @file
/// Observer files: strict integer ids in range, every error naming the file and entry.

#include <gtest/gtest.h>

#include <string>

#include "io_test_support.hpp"
#include "tailor/io/observer_loops.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;

/// The InputError message for observers file `text` on a mesh of 10 vertices.
std::string observers_error(const TempDir& dir, const std::string& text) {
  test::write_bytes(dir / "observers.json", text);
  return input_error_message([&] { read_observer_loops(dir / "observers.json", 10); });
}

TEST(ObserverLoops, ReadsLoops) {
  TempDir dir;
  test::write_bytes(dir / "obs.json", R"({"loops": [[0, 1, 2], [9, 8]]})");
  const auto loops = read_observer_loops(dir / "obs.json", 10);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(loops[0], (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(loops[1], (std::vector<Index>{9, 8}));
}

TEST(ObserverLoops, FractionalIdIsRefused) {
  // Used to be accepted and truncated to vertex 2.
  TempDir dir;
  expect_contains(observers_error(dir, R"({"loops": [[0, 2.5, 1]]})"),
                  {"observers.json", "loops[0][1]", "2.5"});
}

TEST(ObserverLoops, HugeIdIsRefused) {
  // 1e30 used to become -2147483648 (undefined behaviour in the conversion).
  TempDir dir;
  expect_contains(observers_error(dir, R"({"loops": [[0, 1e30, 1]]})"),
                  {"observers.json", "loops[0][1]", "1e+30"});
  expect_contains(observers_error(dir, R"({"loops": [[0, 1], [4294967296]]})"),
                  {"observers.json", "loops[1][0]", "4294967296"});
}

TEST(ObserverLoops, OutOfRangeAndNegativeIdsAreRefused) {
  TempDir dir;
  expect_contains(observers_error(dir, R"({"loops": [[10]]})"),
                  {"observers.json", "loops[0][0]", "[0, 10)", "got 10"});
  expect_contains(observers_error(dir, R"({"loops": [[-1]]})"),
                  {"observers.json", "loops[0][0]", "got -1"});
}

TEST(ObserverLoops, ShapeErrorsNameTheFile) {
  TempDir dir;
  expect_contains(observers_error(dir, R"([[0, 1]])"), {"observers.json", "expected an object"});
  expect_contains(observers_error(dir, R"({})"), {"observers.json", "missing field 'loops'"});
  expect_contains(observers_error(dir, R"({"loops": []})"), {"observers.json", "non-empty"});
  expect_contains(observers_error(dir, R"({"loops": [[]]})"), {"observers.json", "loops[0]"});
  expect_contains(observers_error(dir, R"({"loops": [3]})"), {"observers.json", "loops[0]"});
  expect_contains(observers_error(dir, R"({"loops": [[1]], "extra": 1})"),
                  {"observers.json", "unknown field 'extra'"});
  expect_contains(observers_error(dir, R"({"loops": [[1]],})"),
                  {"observers.json", "malformed JSON"});
  expect_contains(observers_error(dir, R"({"loops": [["1"]]})"),
                  {"observers.json", "loops[0][0]", "\"1\""});
}

}  // namespace
}  // namespace tailor
