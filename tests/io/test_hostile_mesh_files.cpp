/// @file
/// Mesh files built to hurt: gigabytes of garbage, endless tokens and lines, absurd
/// counts. Each must fail fast with a short message naming the file, without reading the
/// file into memory or allocating what the header claims.

#include <gtest/gtest.h>

#include <string>

#include "../support/sanitized.hpp"
#include "io_test_support.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;

constexpr std::uintmax_t kTwoGiB = std::uintmax_t{2} << 30;
/// A message that quotes its input must stay one short line.
constexpr std::size_t kShortMessage = 300;

std::string mesh_error(const std::filesystem::path& path) {
  const std::string message = input_error_message([&] { read_mesh(path); });
  EXPECT_LT(message.size(), kShortMessage) << message.substr(0, 2 * kShortMessage);
  return message;
}

const char* kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
const char* kBinaryHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n";

TEST(HostileMeshFiles, TwoGigabytesOfNulBytesAsObj) {
  // Used to take 44 s and 8.4 GB (the whole file became one quoted "line").
  TempDir dir;
  test::make_sparse_file(dir / "zeros.obj", kTwoGiB);
  expect_contains(mesh_error(dir / "zeros.obj"),
                  {"zeros.obj", "line 1", "unknown statement", "\\x00\\x00", "not an OBJ file"});
}

TEST(HostileMeshFiles, ValidPlyHeaderThenTwoGigabytesOfGarbage) {
  // Used to be read whole before anything was checked.
  TempDir dir;
  test::make_sparse_file(dir / "ascii.ply", kTwoGiB, kAsciiHeader);
  expect_contains(mesh_error(dir / "ascii.ply"), {"ascii.ply", "line 10", "longer than 1024"});
  test::make_sparse_file(dir / "binary.ply", kTwoGiB, kBinaryHeader);
  expect_contains(mesh_error(dir / "binary.ply"), {"binary.ply", "face 0 has 0 vertices"});
}

TEST(HostileMeshFiles, DeclaredCountsBeyondTheBudgetAreRefusedBeforeAllocating) {
  TempDir dir;
  // 170M float vertices fit in the 2 GiB body but need 8 GB as doubles (twice).
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 170000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  test::make_sparse_file(dir / "counts.ply", kTwoGiB, header);
  expect_contains(mesh_error(dir / "counts.ply"),
                  {"counts.ply", "170000000 vertices", "memory budget", "--max-memory"});
}

TEST(HostileMeshFiles, ObjArraysBeyondTheBudgetAreRefused) {
  TempDir dir;
  std::string text;
  for (int i = 0; i < 10'000; ++i) text += "v 0 0 0\n";
  text += "f 1 2 3\n";
  test::write_bytes(dir / "many.obj", text);
  const test::ScopedMemoryBudget budget(64 << 10);
  expect_contains(mesh_error(dir / "many.obj"), {"many.obj", "memory budget"});
}

TEST(HostileMeshFiles, LongTokensAreQuotedShort) {
  TempDir dir;
  test::write_bytes(dir / "token.obj", "v 0 0 " + std::string(1 << 20, '7') + "x\n");
  expect_contains(mesh_error(dir / "token.obj"), {"token.obj", "garbage token", "bytes)"});
  test::write_bytes(dir / "keyword.obj", std::string(1 << 20, 'k') + "\n");
  expect_contains(mesh_error(dir / "keyword.obj"), {"keyword.obj", "unknown statement"});
  test::write_bytes(dir / "format.ply", "ply\nformat " + std::string(50'000, 'f') + " 1.0\n");
  expect_contains(mesh_error(dir / "format.ply"), {"format.ply", "unknown format"});
}

TEST(HostileMeshFiles, EndlessLinesAreRefused) {
  TempDir dir;
  test::make_sparse_file(dir / "line.obj", std::uintmax_t{128} << 20, "f 1 2 3");
  expect_contains(mesh_error(dir / "line.obj"), {"line.obj", "line 1", "longer than 64.0 MiB"});
  test::write_bytes(dir / "header.ply", "ply\ncomment " + std::string(100'000, 'c') + "\n");
  expect_contains(mesh_error(dir / "header.ply"), {"header.ply", "line 2", "longer than 64.0 KiB"});
  test::make_sparse_file(dir / "binary.ply", std::uintmax_t{1} << 20,
                         "\x7f"
                         "ELF");
  expect_contains(mesh_error(dir / "binary.ply"), {"binary.ply", "not a PLY file"});
}

TEST(HostileMeshFiles, HugeHeadersAreRefused) {
  TempDir dir;
  std::string elements = "ply\nformat ascii 1.0\n";
  for (int i = 0; i < 300; ++i) elements += "element e" + std::to_string(i) + " 0\n";
  test::write_bytes(dir / "elements.ply", elements);
  expect_contains(mesh_error(dir / "elements.ply"), {"elements.ply", "more than 256 elements"});
  std::string properties = "ply\nformat ascii 1.0\nelement vertex 0\n";
  for (int i = 0; i < 300; ++i) properties += "property float p" + std::to_string(i) + "\n";
  test::write_bytes(dir / "properties.ply", properties);
  expect_contains(mesh_error(dir / "properties.ply"),
                  {"properties.ply", "more than 256 properties"});
}

TEST(HostileMeshFiles, CliStaysWithinFourGigabytesOfAddressSpace) {
  // The CLI run on 2 GiB of garbage under `ulimit -v 4 GiB`: reading the file whole (the
  // old way) cannot fit, mapping it does. Address-space limits break the sanitizers.
  if (tailor::testing::sanitized()) GTEST_SKIP() << "ulimit -v and ASan do not mix";
  TempDir dir;
  test::make_sparse_file(dir / "zeros.obj", kTwoGiB);
  test::make_sparse_file(dir / "garbage.ply", kTwoGiB, kAsciiHeader);
  for (const char* name : {"zeros.obj", "garbage.ply"}) {
    const test::CliResult r =
        test::run_cli("info " + test::quoted(dir / name), "ulimit -v 4194304;");
    EXPECT_EQ(r.exit_code, 2) << r.output.substr(0, 500);
    expect_contains(r.output, {name});
    EXPECT_LT(r.output.size(), kShortMessage) << r.output.substr(0, 500);
  }
}

}  // namespace
}  // namespace tailor
