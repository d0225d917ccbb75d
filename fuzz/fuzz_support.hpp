#pragma once
/// @file
/// What every fuzz target checks: a reader either returns a well-formed result or throws
/// InputError with a short message naming the source; anything else (another exception,
/// a crash, a sanitizer report) is a finding.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include "tailor/geometry/error.hpp"
#include "tailor/io/memory_budget.hpp"
#include "tailor/mesh/mesh_data.hpp"

namespace tailor::fuzz {

/// Memory budget of the fuzz targets: far below libFuzzer's 2 GB RSS limit, so that an
/// input the budget lets through can never look like a leak or an out-of-memory.
inline constexpr std::uint64_t kFuzzMemoryBudget = std::uint64_t{64} << 20;

/// Longest acceptable error message (a path, a location, a problem, a ~40-byte quote).
inline constexpr std::size_t kMaxMessageBytes = 400;

/// Stops the fuzzer with a description of the broken property.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz property violated: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

/// Once per process (call from LLVMFuzzerInitialize): the memory budget, one worker
/// thread (TBB's workers would make every input start and stop threads, and make
/// coverage depend on scheduling), and only errors logged (the readers' warnings about
/// polygons or unused vertices would flood the output).
inline void set_up() {
  set_memory_budget(kFuzzMemoryBudget);
  static tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  spdlog::set_level(spdlog::level::err);
}

/// The input as text.
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// An InputError message must name `source` and stay short.
inline void check_message(const InputError& error, std::string_view source) {
  const std::string_view message = error.what();
  if (message.find(source) == std::string_view::npos) {
    fail("message does not name " + std::string(source) + ": " +
         std::string(message.substr(0, 600)));
  }
  if (message.size() > kMaxMessageBytes) {
    fail("message of " + std::to_string(message.size()) +
         " bytes: " + std::string(message.substr(0, 600)));
  }
}

/// A mesh a reader returns: finite coordinates, at least one face, face ids in range,
/// three distinct vertices per face.
inline void check_mesh(const MeshData& mesh) {
  const auto nv = mesh.vertices.rows();
  if (!mesh.vertices.allFinite()) fail("non-finite coordinate accepted");
  if (mesh.faces.rows() == 0) fail("mesh without faces accepted");
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    for (int i = 0; i < 3; ++i) {
      if (mesh.faces(f, i) < 0 || mesh.faces(f, i) >= nv) fail("face index out of range");
    }
    if (mesh.faces(f, 0) == mesh.faces(f, 1) || mesh.faces(f, 1) == mesh.faces(f, 2) ||
        mesh.faces(f, 0) == mesh.faces(f, 2)) {
      fail("face with a repeated vertex accepted");
    }
  }
}

/// Reads little-endian values off the front of the input; zeros once it is used up.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

  /// The next byte (0 at the end).
  std::uint8_t byte() { return m_pos < m_size ? m_data[m_pos++] : 0; }
  /// The next `n` bytes as an unsigned integer (n ≤ 8).
  std::uint64_t bits(int n) {
    std::uint64_t value = 0;
    for (int i = 0; i < n; ++i) value |= static_cast<std::uint64_t>(byte()) << (8 * i);
    return value;
  }
  /// True once every byte was read.
  bool done() const { return m_pos >= m_size; }
  /// The bytes not read yet.
  std::string_view rest() const {
    return {reinterpret_cast<const char*>(m_data) + m_pos, m_size - std::min(m_pos, m_size)};
  }

 private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_pos = 0;
};

}  // namespace tailor::fuzz
