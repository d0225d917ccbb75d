/// @file
/// libFuzzer target: the self-collision detector against brute force. The input builds a
/// small mesh (3-12 vertices, 1-16 triangles), its two frames and, optionally, radial-view
/// section loops; every preset must report exactly the brute-force collisions.
///
/// Coordinates come in two flavours, picked by the input: small lattice values (k / 4,
/// |k| < 128), where exact degeneracies (coplanar motion, touching at t = 0 or 1, shared
/// lines) are common, and general doubles of moderate exponent.

#include <cmath>
#include <cstring>
#include <string>
#include <optional>
#include <tuple>
#include <vector>

#include "fuzz_support.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"

namespace {

using namespace tailor;

double coordinate(fuzz::ByteReader& input, bool lattice) {
  if (lattice) return static_cast<std::int8_t>(input.byte()) / 4.0;
  const auto mantissa = static_cast<std::int16_t>(input.bits(2));
  const int exponent = static_cast<int>(input.byte() % 32) - 24;  // 2^-24 .. 2^7 steps
  return std::ldexp(static_cast<double>(mantissa), exponent);
}

std::string describe(const CollisionSet& set) {
  std::string text;
  for (const auto& c : set.vertex_face)
    text += "VF(" + std::to_string(c.vertex) + "," + std::to_string(c.face) + ") ";
  for (const auto& c : set.edge_edge) {
    text += "EE(" + std::to_string(c.a0) + "-" + std::to_string(c.a1) + "," + std::to_string(c.b0) +
            "-" + std::to_string(c.b1) + ") ";
  }
  return text;
}

/// Same pairs (the times of impact may differ between paths; the pairs may not).
bool same_pairs(const CollisionSet& a, const CollisionSet& b) {
  if (a.vertex_face.size() != b.vertex_face.size() || a.edge_edge.size() != b.edge_edge.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.vertex_face.size(); ++i) {
    if (a.vertex_face[i].vertex != b.vertex_face[i].vertex ||
        a.vertex_face[i].face != b.vertex_face[i].face) {
      return false;
    }
  }
  for (std::size_t i = 0; i < a.edge_edge.size(); ++i) {
    const auto& x = a.edge_edge[i];
    const auto& y = b.edge_edge[i];
    if (std::tie(x.a0, x.a1, x.b0, x.b1) != std::tie(y.a0, y.a1, y.b0, y.b1)) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::set_up();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader input(data, size);
  const std::uint8_t mode = input.byte();
  const bool lattice = (mode & 1) == 0;
  const bool still = (mode & 2) != 0;  // x1 = x0 + a small lattice move instead of free
  const int num_loops = (mode >> 2) % 3;
  const Index nv = 3 + input.byte() % 10;
  const Index nf = 1 + input.byte() % 16;
  FaceArray faces(nf, 3);
  for (Index f = 0; f < nf; ++f) {
    const Index a = input.byte() % nv;
    const Index b = (a + 1 + input.byte() % (nv - 1)) % nv;
    Index c = input.byte() % nv;
    while (c == a || c == b) c = (c + 1) % nv;
    faces.row(f) << a, b, c;
  }
  Positions x0(nv, 3), x1(nv, 3);
  for (Index v = 0; v < nv; ++v) {
    for (int axis = 0; axis < 3; ++axis) x0(v, axis) = coordinate(input, lattice);
  }
  for (Index v = 0; v < nv; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      x1(v, axis) = still ? x0(v, axis) + static_cast<std::int8_t>(input.byte()) / 64.0
                          : coordinate(input, lattice);
    }
  }
  std::vector<std::vector<Index>> loops;
  for (int l = 0; l < num_loops; ++l) {
    std::vector<Index>& loop = loops.emplace_back();
    const int length = 1 + input.byte() % 4;
    for (int i = 0; i < length; ++i) loop.push_back(input.byte() % nv);
  }

  std::optional<TriangleMesh> mesh;
  try {
    mesh.emplace(nv, faces);
  } catch (const InputError&) {
    return 0;  // duplicate faces and the like: the mesh refuses them, no detection
  }
  const CollisionSet truth = brute_force_self_collisions(*mesh, x0, x1);
  for (const std::string& name : DetectionConfig::preset_names()) {
    DetectionConfig config = DetectionConfig::preset(name);
    config.threads = 1;
    try {
      SelfCollisionDetector detector(*mesh, x0, config, loops);
      const CollisionSet found = detector.detect(x0, x1).collisions;
      if (!same_pairs(found, truth)) {
        fuzz::fail("preset " + name + (loops.empty() ? "" : " with section loops") + " found " +
                   describe(found) + "but brute force " + describe(truth));
      }
    } catch (const InputError& error) {
      fuzz::fail("preset " + name + " refused a valid step: " + error.what());
    }
  }
  return 0;
}
