/// @file
/// Input files are mapped (regular files) or read within the budget (anything else).

#include <gtest/gtest.h>

#include <string>

#include "io_test_support.hpp"
#include "tailor/io/input_file.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;

TEST(InputFile, GivesTheFileBytes) {
  TempDir dir;
  const std::string bytes("ply\n\0\x01\xff tail", 12);
  test::write_bytes(dir / "a.bin", bytes);
  const InputFile file(dir / "a.bin");
  EXPECT_EQ(file.bytes(), bytes);
  EXPECT_EQ(file.size(), bytes.size());
  EXPECT_EQ(file.path(), dir / "a.bin");
}

TEST(InputFile, EmptyFileIsEmpty) {
  TempDir dir;
  test::write_bytes(dir / "empty", "");
  const InputFile file(dir / "empty");
  EXPECT_TRUE(file.bytes().empty());
}

TEST(InputFile, ProcFilesWithoutASizeAreRead) {
  // stat() reports size 0 for /proc files; they must not look empty.
  const InputFile file("/proc/self/status");
  EXPECT_NE(file.bytes().find("Name:"), std::string::npos);
}

TEST(InputFile, MissingFileAndFolderAreNamed) {
  TempDir dir;
  expect_contains(input_error_message([&] { InputFile(dir / "absent.obj"); }),
                  {"absent.obj", "cannot open"});
  expect_contains(input_error_message([&] { InputFile{dir.path()}; }),
                  {"cannot open", "directory"});
}

TEST(InputFile, HugeSparseFileCostsNoMemoryToOpen) {
  TempDir dir;
  // 64 GiB: far beyond the budget and the machine, yet mapped without reading it.
  test::make_sparse_file(dir / "huge.bin", std::uintmax_t{64} << 30, "head");
  const InputFile file(dir / "huge.bin");
  EXPECT_EQ(file.size(), std::size_t{64} << 30);
  EXPECT_EQ(file.bytes().substr(0, 4), "head");
  EXPECT_EQ(file.bytes()[std::size_t{32} << 30], '\0');
}

TEST(InputFile, NonRegularFilesAreReadWithinTheBudget) {
  const test::ScopedMemoryBudget budget(1 << 20);
  // /dev/zero never ends: reading stops at the budget with a clear error.
  expect_contains(input_error_message([] { InputFile("/dev/zero"); }),
                  {"/dev/zero", "not a regular file", "memory budget"});
}

}  // namespace
}  // namespace tailor
