/// @file
/// libFuzzer target: a mesh decoded from the input is written (OBJ, or PLY in an encoding
/// and with types chosen by the input) and read back. The writer must refuse exactly what
/// cannot be written (non-finite coordinates, float32 overflow, ids too large for the
/// index type); whatever it writes must read back equal (coordinates rounded to float
/// for float32 files).

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include "fuzz_support.hpp"
#include "tailor/io/mesh_io.hpp"

namespace {

using namespace tailor;

std::filesystem::path g_folder;

constexpr PlyType kIntegerTypes[] = {PlyType::int8,   PlyType::uint8, PlyType::int16,
                                     PlyType::uint16, PlyType::int32, PlyType::uint32};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::set_up();
  g_folder = std::filesystem::temp_directory_path() /
             ("tailor-fuzz-round-trip-" + std::to_string(::getpid()));
  std::filesystem::create_directories(g_folder);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader input(data, size);
  // The file type and PLY options.
  const std::uint8_t kind = input.byte();
  const bool obj = kind % 2 == 0;
  PlyWriteOptions options;
  options.format = static_cast<PlyFormat>((kind / 2) % 3);
  options.coordinate_type = (kind / 6) % 2 ? PlyType::float32 : PlyType::float64;
  const std::uint8_t types = input.byte();
  options.count_type = kIntegerTypes[types % 6];
  options.index_type = kIntegerTypes[(types / 6) % 6];
  // The mesh: 3-200 vertices of any bit pattern, 1-64 faces of distinct vertices.
  const Index nv = 3 + input.byte() % 198;
  Positions x(nv, 3);
  for (Index v = 0; v < nv; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      const std::uint64_t bits = input.bits(8);
      double value;
      std::memcpy(&value, &bits, sizeof value);
      x(v, axis) = value;
    }
  }
  const Index nf = 1 + input.byte() % 64;
  FaceArray faces(nf, 3);
  for (Index f = 0; f < nf; ++f) {
    const Index a = input.byte() % nv;
    const Index b = (a + 1 + input.byte() % (nv - 1)) % nv;  // b != a
    Index c = input.byte() % nv;
    while (c == a || c == b) c = (c + 1) % nv;
    faces.row(f) << a, b, c;
  }

  // What the writer may refuse.
  const bool single = !obj && options.coordinate_type == PlyType::float32;
  bool writable = x.allFinite();
  for (Index v = 0; v < nv && writable && single; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(static_cast<float>(x(v, axis)))) writable = false;
    }
  }
  if (!obj && nv - 1 > ply_type_max(options.index_type)) writable = false;

  const std::filesystem::path path = g_folder / (obj ? "mesh.obj" : "mesh.ply");
  try {
    if (obj) {
      write_obj(path, x, faces);
    } else {
      write_ply(path, x, faces, options);
    }
  } catch (const InputError& error) {
    if (writable) fuzz::fail(std::string("writer refused a writable mesh: ") + error.what());
    return 0;
  }
  if (!writable) fuzz::fail("writer accepted a mesh it cannot write");

  MeshData back;
  try {
    back = read_mesh(path);
  } catch (const InputError& error) {
    fuzz::fail(std::string("a written mesh does not read back: ") + error.what());
  }
  if (back.faces != faces) fuzz::fail("faces changed in a round trip");
  if (back.vertices.rows() != nv) fuzz::fail("vertex count changed in a round trip");
  for (Index v = 0; v < nv; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      const double expected =
          single ? static_cast<double>(static_cast<float>(x(v, axis))) : x(v, axis);
      const double got = back.vertices(v, axis);
      if (std::memcmp(&expected, &got, sizeof got) != 0) {
        fuzz::fail("coordinate changed in a round trip: " + std::to_string(expected) + " -> " +
                   std::to_string(got));
      }
    }
  }
  return 0;
}
