#pragma once
/// @file
/// Helpers shared by the io tests: a per-test temporary folder and message checks.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/io/mesh_io.hpp"
#include "support/run_cli.hpp"
#include "support/scoped_memory_budget.hpp"

namespace tailor::test {

/// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "-" + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';
    }
    m_path = std::filesystem::temp_directory_path() /
             ("tailor-io-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(m_path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return m_path; }
  std::filesystem::path operator/(const std::string& name) const { return m_path / name; }

 private:
  std::filesystem::path m_path;
};

/// Writes `bytes` to `path` as is.
inline void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(out.good()) << path;
}

/// Reads the whole file.
inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Runs `action`, which must throw InputError, and returns its message ("" if it did not).
inline std::string input_error_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return "";
}

/// Expects `message` to contain every one of `parts`.
inline void expect_contains(const std::string& message,
                            std::initializer_list<std::string_view> parts) {
  for (std::string_view part : parts) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "message \"" << message << "\" lacks \"" << part << "\"";
  }
}

/// Makes `path` a sparse file of `size` zero bytes (no disk blocks, no memory).
inline void make_sparse_file(const std::filesystem::path& path, std::uintmax_t size,
                             std::string_view head = {}) {
  write_bytes(path, head);
  std::filesystem::resize_file(path, size);
}

/// The file names (without folders) of `paths`, in order.
inline std::vector<std::string> file_names(const std::vector<std::filesystem::path>& paths) {
  std::vector<std::string> names;
  for (const auto& p : paths) names.push_back(p.filename().string());
  return names;
}

/// Writes a mesh of one triangle to `path` (format from its extension).
inline void write_triangle(const std::filesystem::path& path) {
  Positions x(3, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  FaceArray f(1, 3);
  f << 0, 1, 2;
  write_mesh(path, x, f);
}

/// The mesh a read gives, or the message of the InputError it throws.
using MeshOutcome = std::variant<MeshData, std::string>;

/// Runs `read` (returning a MeshData) and keeps its mesh or its InputError's message.
template <typename Read>
MeshOutcome outcome_of(Read read) {
  try {
    return read();
  } catch (const InputError& e) {
    return std::string(e.what());
  }
}

/// Whether `a` and `b` have the same bits (tells -0 from 0, and compares NaNs).
inline bool bit_equal(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

/// Both outcomes are the same error message, or bit-identical meshes.
inline void expect_same(const MeshOutcome& a, const MeshOutcome& b, const std::string& what) {
  ASSERT_EQ(a.index(), b.index()) << what;
  if (const auto* message = std::get_if<std::string>(&a)) {
    EXPECT_EQ(*message, std::get<std::string>(b)) << what;
    return;
  }
  const MeshData& x = std::get<MeshData>(a);
  const MeshData& y = std::get<MeshData>(b);
  ASSERT_EQ(x.vertices.rows(), y.vertices.rows()) << what;
  for (Index i = 0; i < x.vertices.size(); ++i) {
    EXPECT_TRUE(bit_equal(x.vertices.data()[i], y.vertices.data()[i])) << what;
  }
  EXPECT_EQ(x.faces, y.faces) << what;
}

/// Exit code and combined output of one run of the built `tailor` CLI.
using CliResult = ::tailor::testing::CliRun;
using ::tailor::testing::quoted;
using ::tailor::testing::run_cli;

}  // namespace tailor::test
