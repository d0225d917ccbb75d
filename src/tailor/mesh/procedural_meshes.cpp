#include "tailor/mesh/procedural_meshes.hpp"

#include <cmath>
#include <numbers>

namespace tailor {

MeshData make_grid(int cells_x, int cells_y, double size_x, double size_y) {
  MeshData mesh;
  const int nx = cells_x + 1, ny = cells_y + 1;
  mesh.vertices.resize(static_cast<Eigen::Index>(nx) * ny, 3);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      mesh.vertices.row(j * nx + i) << size_x * i / cells_x, size_y * j / cells_y, 0.0;
    }
  }
  mesh.faces.resize(2 * static_cast<Eigen::Index>(cells_x) * cells_y, 3);
  Eigen::Index f = 0;
  for (int j = 0; j < cells_y; ++j) {
    for (int i = 0; i < cells_x; ++i) {
      const Index v = j * nx + i;
      mesh.faces.row(f++) << v, v + 1, v + nx + 1;
      mesh.faces.row(f++) << v, v + nx + 1, v + nx;
    }
  }
  return mesh;
}

MeshData make_tube(int rings, int segments, double radius, double length) {
  MeshData mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(rings) * segments, 3);
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const double angle = 2 * std::numbers::pi * s / segments;
      mesh.vertices.row(r * segments + s) << radius * std::cos(angle), radius * std::sin(angle),
          length * r / (rings - 1);
    }
  }
  mesh.faces.resize(2 * static_cast<Eigen::Index>(rings - 1) * segments, 3);
  Eigen::Index f = 0;
  for (int r = 0; r + 1 < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const Index a = r * segments + s, b = r * segments + (s + 1) % segments;
      const Index c = a + segments, d = b + segments;
      mesh.faces.row(f++) << a, b, d;
      mesh.faces.row(f++) << a, d, c;
    }
  }
  return mesh;
}

MeshData make_sphere(int stacks, int slices, double radius) {
  MeshData mesh;
  const Eigen::Index rings = stacks - 1;  // latitude rings between the poles
  mesh.vertices.resize(rings * slices + 2, 3);
  for (int r = 0; r < rings; ++r) {
    const double polar = std::numbers::pi * (r + 1) / stacks;
    for (int s = 0; s < slices; ++s) {
      const double azimuth = 2 * std::numbers::pi * s / slices;
      mesh.vertices.row(r * slices + s) << radius * std::sin(polar) * std::cos(azimuth),
          radius * std::sin(polar) * std::sin(azimuth), radius * std::cos(polar);
    }
  }
  const Index north = static_cast<Index>(rings * slices), south = north + 1;
  mesh.vertices.row(north) << 0, 0, radius;
  mesh.vertices.row(south) << 0, 0, -radius;
  mesh.faces.resize(2 * slices + 2 * (rings - 1) * slices, 3);
  Eigen::Index f = 0;
  for (int s = 0; s < slices; ++s) {
    const Index next = (s + 1) % slices;
    mesh.faces.row(f++) << north, s, next;
    const Index last = static_cast<Index>((rings - 1) * slices);
    mesh.faces.row(f++) << south, last + next, last + s;
  }
  for (int r = 0; r + 1 < rings; ++r) {
    for (int s = 0; s < slices; ++s) {
      const Index a = r * slices + s, b = r * slices + (s + 1) % slices;
      const Index c = a + slices, d = b + slices;
      mesh.faces.row(f++) << a, c, d;
      mesh.faces.row(f++) << a, d, b;
    }
  }
  return mesh;
}

Positions crumpling_cloth(const Positions& rest, double t) {
  // Folds: a few travelling waves of growing amplitude across the cloth, plus a
  // contraction towards the centre that pushes the folds into each other.
  Positions x = rest;
  const Eigen::RowVector3d center = 0.5 * (rest.colwise().minCoeff() + rest.colwise().maxCoeff());
  const double size = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).maxCoeff();
  const double k = 2 * std::numbers::pi / size;
  for (Eigen::Index i = 0; i < rest.rows(); ++i) {
    const double u = rest(i, 0) - center.x(), v = rest(i, 1) - center.y();
    const double shrink = 1 - 0.35 * t;
    const double fold =
        0.12 * size * t *
        (std::sin(3 * k * u + 2 * t) * std::cos(2 * k * v - t) +
         0.6 * std::sin(5 * k * (u + v) + 3 * t) + 0.4 * std::cos(7 * k * (u - 0.5 * v) - 2 * t));
    x(i, 0) = center.x() + shrink * u + 0.05 * size * t * std::sin(4 * k * v);
    x(i, 1) = center.y() + shrink * v + 0.05 * size * t * std::sin(4 * k * u);
    x(i, 2) = fold;
  }
  return x;
}

}  // namespace tailor
