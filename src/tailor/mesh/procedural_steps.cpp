#include "tailor/mesh/procedural_steps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {

namespace {

/// splitmix64: a tiny portable generator, so steps are identical with every standard
/// library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : m_state(seed) {}
  /// Uniform in [-1, 1).
  double symmetric() {
    std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1p-52 - 1.0;
  }

 private:
  std::uint64_t m_state;
};

/// Height of the sphere's flat top (a cut plane).
constexpr double kPlateau = 0.96;

/// The point at distance `radius` from the sphere's centre in the direction of (x, 1, z)
/// (a smooth map of the plane onto a cap around the sphere's top), lowered to `ceiling`
/// where it would rise above it.
Eigen::RowVector3d on_cap(double x, double z, double radius, double ceiling) {
  const Eigen::RowVector3d d(x, 1.0, z);
  Eigen::RowVector3d p = radius * d / d.norm();
  p.y() = std::min(p.y(), ceiling);
  return p;
}

}  // namespace

ProceduralStep make_folded_cloth_on_sphere(std::int64_t target_triangles, std::uint64_t seed) {
  if (target_triangles < 200) {
    throw std::invalid_argument("make_folded_cloth_on_sphere: at least 200 triangles");
  }
  constexpr int kFoldCells = 2;
  constexpr double kHalfWidth = 0.8;  // the cap spans [-0.8, 0.8]² before the map
  // 2 n (2 n + kFoldCells) triangles for n cells across.
  const int n = std::max(
      5, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target_triangles) / 4.0))));
  const int along = 2 * n + kFoldCells;
  const double h = 2 * kHalfWidth / n;  // edge length of the flat parts
  const double gap = 0.5 * h;           // distance between the two layers

  ProceduralStep step;
  MeshData grid = make_grid(along, n, 1.0, 1.0);
  step.faces = std::move(grid.faces);
  const Eigen::Index num_vertices = grid.vertices.rows();
  step.x0.resize(num_vertices, 3);
  step.x1.resize(num_vertices, 3);

  Random random(seed);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= along; ++i) {
      const Eigen::Index v = static_cast<Eigen::Index>(j) * (along + 1) + i;
      const double z = -kHalfWidth + j * h;
      // x along the cloth, radial distance, and how far into the top layer (0..1) the
      // vertex is (the fold blends the motion from bottom to top).
      double x = 0, radius = 1.0, top = 0;
      double jitter = 0.15 * h;
      if (i <= n) {
        x = -kHalfWidth + i * h;
      } else if (i < n + kFoldCells) {
        const double phi = std::numbers::pi * (i - n) / kFoldCells;
        x = kHalfWidth + 0.5 * gap * std::sin(phi);
        radius = 1.0 + 0.5 * gap * (1 - std::cos(phi));
        top = static_cast<double>(i - n) / kFoldCells;
        jitter = 0.02 * h;  // keep the tight fold free of self-intersection
      } else {
        x = kHalfWidth - (i - n - kFoldCells) * h;
        radius = 1.0 + gap;
        top = 1;
      }
      const double jx = jitter * random.symmetric(), jz = jitter * random.symmetric();
      // The layer's plateau: exactly kPlateau for the bottom layer, a gap above for the top.
      const double ceiling = kPlateau + (radius - 1.0);
      step.x0.row(v) = on_cap(x + jx, z + jz, radius, ceiling);

      // The top layer sinks by 0.55..1.45 gaps (through the bottom layer where the bump
      // exceeds one half) and drifts along the cloth; the bottom layer settles a little.
      const double bump = 0.5 + 0.5 * std::sin(3 * std::numbers::pi * x / kHalfWidth + 1.0) *
                                    std::cos(2 * std::numbers::pi * z / kHalfWidth);
      const double sink = top * gap * (0.55 + 0.9 * bump);
      const double settle = (1 - top) * 0.05 * gap * (1 + random.symmetric());
      const double drift = top * 0.2 * h;
      const double sx = 0.05 * h * random.symmetric(), sz = 0.05 * h * random.symmetric();
      // On the plateau the bottom layer slides exactly in its plane (coplanar all step).
      step.x1.row(v) =
          on_cap(x + jx + drift + sx, z + jz + sz, radius - sink - settle, ceiling - sink);
    }
  }
  return step;
}

ProceduralStep make_pleated_cloth(std::int64_t target_triangles, int layers, std::uint64_t seed) {
  if (target_triangles < 200 || layers < 2) {
    throw std::invalid_argument("make_pleated_cloth: at least 200 triangles and 2 layers");
  }
  constexpr int kFoldCells = 2;
  constexpr double kHalfWidth = 0.8;  // each layer spans [-0.8, 0.8]²
  // 2 n (layers n + (layers - 1) kFoldCells) triangles for n cells across.
  const int n = std::max(5, static_cast<int>(std::lround(std::sqrt(
                                static_cast<double>(target_triangles) / (2.0 * layers)))));
  const int per_layer = n + kFoldCells;  // cells along the strip per layer and its fold
  const int along = layers * n + (layers - 1) * kFoldCells;
  const double h = 2 * kHalfWidth / n;  // edge length of the flat parts
  const double gap = 0.4 * h;           // distance between consecutive layers

  ProceduralStep step;
  MeshData grid = make_grid(along, n, 1.0, 1.0);
  step.faces = std::move(grid.faces);
  step.x0.resize(grid.vertices.rows(), 3);
  step.x1.resize(grid.vertices.rows(), 3);
  Random random(seed);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= along; ++i) {
      const Eigen::Index v = static_cast<Eigen::Index>(j) * (along + 1) + i;
      const double z = -kHalfWidth + j * h;
      // Layer l runs along +x when l is even, -x when odd; a half-circle fold of diameter
      // `gap` joins it to the next. `level` is the height in layers (fractional in folds).
      const int l = std::min(i / per_layer, layers - 1);
      const int cell = i - l * per_layer;
      const double direction = l % 2 == 0 ? 1.0 : -1.0;
      double x = 0, level = l, jitter = 0.15 * h;
      if (cell <= n) {
        x = direction * (-kHalfWidth + cell * h);
      } else {
        const double phi = std::numbers::pi * (cell - n) / kFoldCells;
        x = direction * (kHalfWidth + 0.5 * gap * std::sin(phi));
        level = l + 0.5 * (1 - std::cos(phi));
        jitter = 0.02 * h;  // keep the tight fold free of self-intersection
      }
      const double jx = jitter * random.symmetric(), jz = jitter * random.symmetric();
      step.x0.row(v) << x + jx, level * gap, z + jz;
      // Each layer heaves by up to 1.6 gaps in a smooth wave of its own phase, so every
      // layer passes through its neighbours over part of its area, and slides a little
      // (alternating directions: the edges of consecutive layers cross).
      const double phase = 1.7 * level;
      const double heave = 2.5 * gap * std::sin(2.5 * std::numbers::pi * x / kHalfWidth + phase) *
                           std::cos(1.5 * std::numbers::pi * z / kHalfWidth + 0.6 * phase);
      const double slide = (l % 2 == 0 ? 4.0 : -4.0) * h;
      const double sx = 0.05 * h * random.symmetric(), sz = 0.05 * h * random.symmetric();
      step.x1.row(v) << x + jx + slide + sx, level * gap + heave, z + jz + sz;
    }
  }
  return step;
}

ProceduralStep make_crumpling_cloth_step(std::int64_t target_triangles) {
  if (target_triangles < 8)
    throw std::invalid_argument("make_crumpling_cloth_step: at least 8 triangles");
  const int cells = std::max(
      2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target_triangles) / 2.0))));
  MeshData grid = make_grid(cells, cells, 1.0, 1.0);
  ProceduralStep step;
  step.x0 = crumpling_cloth(grid.vertices, 0.5);
  step.x1 = crumpling_cloth(grid.vertices, 0.51);
  step.faces = std::move(grid.faces);
  return step;
}

}  // namespace tailor
