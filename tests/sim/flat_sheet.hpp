#pragma once
/// @file
/// A flat square sheet for the cloth-model and friction tests.

#include <memory>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor::testing {

/// Rest positions and topology of a sheet.
struct Sheet {
  Positions rest;
  std::unique_ptr<TriangleMesh> mesh;
};

/// A square sheet of n × n vertices, side `size` metres, in the x-z plane at y = 0, its
/// faces wound so that their normals point along +y.
inline Sheet make_sheet(int n, double size) {
  Sheet s;
  s.rest.resize(n * n, 3);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      s.rest.row(i * n + j) << size * j / (n - 1), 0.0, size * i / (n - 1);
  }
  FaceArray f(2 * (n - 1) * (n - 1), 3);
  int k = 0;
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + 1, c = a + n, d = c + 1;
      f.row(k++) << a, c, b;
      f.row(k++) << b, c, d;
    }
  }
  s.mesh = std::make_unique<TriangleMesh>(n * n, f);
  return s;
}

}  // namespace tailor::testing
