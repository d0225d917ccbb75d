#pragma once
/// @file
/// Helpers of the `tailor view` tests: small simulation-output folders and readers of the
/// data scripts the viewer writes (base64 Float32/Uint32 arrays inside JSON).

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/io_test_support.hpp"
#include "support/run_cli.hpp"
#include "tailor/geometry/types.hpp"
#include "tailor/io/obj_io.hpp"

namespace tailor::test {

/// A unit square of two triangles lifted to height `z` (4 vertices).
inline Positions square(double z) {
  Positions x(4, 3);
  x << 0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z;
  return x;
}
inline FaceArray square_faces() {
  FaceArray f(2, 3);
  f << 0, 1, 2, 0, 2, 3;
  return f;
}

/// Writes cloth_NNNN.obj (the square falling) and arm_NNNN.obj (a fixed triangle) for
/// frames 0..frames-1 into `dir`, as `tailor simulate` names them.
inline void write_simulation_frames(const std::filesystem::path& dir, int frames) {
  Positions arm(3, 3);
  arm << 0, 0, -1, 1, 0, -1, 0, 1, -1;
  FaceArray arm_faces(1, 3);
  arm_faces << 0, 1, 2;
  for (int k = 0; k < frames; ++k) {
    char name[32];
    std::snprintf(name, sizeof(name), "cloth_%04d.obj", k);
    write_obj(dir / name, square(0.5 - 0.125 * k), square_faces());
    std::snprintf(name, sizeof(name), "arm_%04d.obj", k);
    write_obj(dir / name, arm, arm_faces);
  }
}

/// Decodes standard base64 (with padding).
inline std::string base64_decode(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  EXPECT_EQ(text.size() % 4, 0u) << "base64 length";
  std::string bytes;
  for (std::size_t i = 0; i + 4 <= text.size(); i += 4) {
    std::uint32_t word = 0;
    int padding = 0;
    for (std::size_t j = 0; j < 4; ++j) {
      const int v = text[i + j] == '=' ? (++padding, 0) : value(text[i + j]);
      EXPECT_GE(v, 0) << "bad base64 character";
      word = word << 6 | static_cast<std::uint32_t>(v);
    }
    bytes.push_back(static_cast<char>(word >> 16));
    if (padding < 2) bytes.push_back(static_cast<char>(word >> 8));
    if (padding < 1) bytes.push_back(static_cast<char>(word));
  }
  return bytes;
}

/// Little-endian Float32 values of a base64 string.
inline std::vector<float> decode_float32(const std::string& text) {
  const std::string bytes = base64_decode(text);
  EXPECT_EQ(bytes.size() % 4, 0u);
  std::vector<float> values(bytes.size() / 4);
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint32_t word = 0;
    for (int b = 3; b >= 0; --b) {
      word = word << 8 | static_cast<unsigned char>(bytes[4 * i + static_cast<std::size_t>(b)]);
    }
    std::memcpy(&values[i], &word, 4);
  }
  return values;
}

/// Little-endian Uint32 values of a base64 string.
inline std::vector<std::uint32_t> decode_uint32(const std::string& text) {
  const std::string bytes = base64_decode(text);
  EXPECT_EQ(bytes.size() % 4, 0u);
  std::vector<std::uint32_t> values(bytes.size() / 4);
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (int b = 3; b >= 0; --b) {
      values[i] =
          values[i] << 8 | static_cast<unsigned char>(bytes[4 * i + static_cast<std::size_t>(b)]);
    }
  }
  return values;
}

/// The JSON argument of a data script `tailorViewData.NAME(..., {...});`.
inline nlohmann::json data_script_json(const std::filesystem::path& path) {
  const std::string text = read_bytes(path);
  const std::size_t open = text.find('{');
  const std::size_t close = text.rfind('}');
  EXPECT_NE(open, std::string::npos) << path;
  EXPECT_NE(close, std::string::npos) << path;
  if (open == std::string::npos || close == std::string::npos) return {};
  return nlohmann::json::parse(text.substr(open, close - open + 1));
}

/// Runs `tailor view ARGUMENTS`; skips the test when this build has no page assets.
#define TAILOR_RUN_VIEW_OR_SKIP(result, arguments)                                \
  const ::tailor::testing::CliRun result = ::tailor::testing::run_cli(arguments); \
  if (result.output.find("built without the viewer page") != std::string::npos) { \
    GTEST_SKIP() << "this build has no viewer page (web/node_modules missing)";   \
  }

}  // namespace tailor::test
