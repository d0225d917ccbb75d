/// @file
/// Damaged files (every truncation, random byte changes) either load or throw InputError:
/// never a crash, another exception, or a mesh with bad indices.

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "io_test_support.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

MeshData small_mesh() {
  MeshData m;
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1;
  m.faces.resize(4, 3);
  m.faces << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4;
  return m;
}

/// Reads `path`; passes if it loads a consistent mesh or throws InputError naming it.
void expect_loads_or_input_error(const std::filesystem::path& path) {
  try {
    const MeshData m = read_mesh(path);
    const Index nv = static_cast<Index>(m.vertices.rows());
    for (Index f = 0; f < m.faces.rows(); ++f) {
      for (int i = 0; i < 3; ++i) {
        ASSERT_GE(m.faces(f, i), 0);
        ASSERT_LT(m.faces(f, i), nv);
      }
    }
    ASSERT_TRUE(m.vertices.allFinite());
  } catch (const InputError& e) {
    ASSERT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos) << e.what();
  }
}

TEST(CorruptedInput, EveryTruncationAndRandomDamage) {
  test::TempDir dir;
  const MeshData m = small_mesh();
  std::vector<std::filesystem::path> sources;
  write_obj(dir / "src.obj", m.vertices, m.faces);
  sources.push_back(dir / "src.obj");
  const std::pair<const char*, PlyWriteOptions> plys[] = {
      {"src_a.ply", {PlyFormat::ascii, PlyType::float64, PlyType::uint8, PlyType::int32}},
      {"src_le.ply",
       {PlyFormat::binary_little_endian, PlyType::float64, PlyType::uint8, PlyType::int32}},
      {"src_be.ply",
       {PlyFormat::binary_big_endian, PlyType::float32, PlyType::int32, PlyType::uint32}}};
  for (const auto& [name, options] : plys) {
    write_ply(dir / name, m.vertices, m.faces, options);
    sources.push_back(dir / name);
  }
  const int damaged_copies = std::getenv("TAILOR_SANITIZED") ? 40 : 100;
  std::mt19937 rng(99);
  for (const auto& source : sources) {
    SCOPED_TRACE(source.filename().string());
    const std::string bytes = test::read_bytes(source);
    const auto target = dir / ("damaged" + source.extension().string());
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      test::write_bytes(target, bytes.substr(0, n));
      expect_loads_or_input_error(target);
    }
    const char noise[] = {'\0', '\n', ' ', '-', '9', 'x', '/', '\xff', '#', '.'};
    for (int copy = 0; copy < damaged_copies; ++copy) {
      std::string damaged = bytes;
      const int changes = 1 + static_cast<int>(rng() % 4);
      for (int c = 0; c < changes; ++c) {
        const std::size_t at = rng() % damaged.size();
        damaged[at] = (rng() % 2) ? noise[rng() % sizeof(noise)] : static_cast<char>(rng());
      }
      test::write_bytes(target, damaged);
      expect_loads_or_input_error(target);
    }
  }
}

}  // namespace
}  // namespace tailor
