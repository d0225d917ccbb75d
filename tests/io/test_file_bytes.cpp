/// @file
/// Whole-file reads within the memory budget; output folders checked before any work.

#include <gtest/gtest.h>

#include <string>

#include "io_test_support.hpp"
#include "tailor/io/file_bytes.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;

TEST(FileBytes, ReadsWithinTheBudgetOnly) {
  TempDir dir;
  test::write_bytes(dir / "small.bin", std::string(1000, 'a'));
  EXPECT_EQ(read_file_bytes(dir / "small.bin"), std::string(1000, 'a'));
  const test::ScopedMemoryBudget budget(999);
  expect_contains(input_error_message([&] { read_file_bytes(dir / "small.bin"); }),
                  {"small.bin", "memory budget"});
}

TEST(FileBytes, PrepareOutputFolderCreatesOrRefuses) {
  TempDir dir;
  prepare_output_folder(dir / "a" / "b");
  EXPECT_TRUE(std::filesystem::is_directory(dir / "a" / "b"));
  prepare_output_folder(dir / "a" / "b");  // existing folders are fine
  test::write_bytes(dir / "file", "x");
  expect_contains(input_error_message([&] { prepare_output_folder(dir / "file"); }),
                  {"file", "output folder"});
  expect_contains(input_error_message([&] { prepare_output_folder(dir / "file" / "sub"); }),
                  {"file/sub", "output folder"});
}

}  // namespace
}  // namespace tailor
