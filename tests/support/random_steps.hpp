#pragma once
// Random and adversarial time steps of procedural meshes, shared by the detection tests.

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "tailor/mesh/mesh_data.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor::testing {

/// One step of a mesh: topology plus positions at t=0 and t=1.
struct Step {
  std::string name;
  MeshData mesh;  // vertices = x0
  Positions x1;
};

/// Rounds every coordinate to a multiple of 2^-bits times `scale`: exact touches,
/// coplanarities and parallel edges become common.
inline void snap(Positions& x, int bits, double scale) {
  const double unit = std::ldexp(scale, -bits);
  x = (x / unit).array().round().matrix() * unit;
}

inline void jitter(Positions& x, std::mt19937& rng, double amount) {
  std::uniform_real_distribution<double> uniform(-amount, amount);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (int k = 0; k < 3; ++k) x(i, k) += uniform(rng);
  }
}

/// A grid folded like a book closing: the two halves pass through each other when
/// `angle1` goes beyond pi.
inline Positions fold_grid(const Positions& flat, double fold_x, double angle) {
  Positions x = flat;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double d = flat(i, 0) - fold_x;
    if (d > 0) {
      x(i, 0) = fold_x + d * std::cos(angle);
      x(i, 2) = d * std::sin(angle);
    }
  }
  return x;
}

/// Steps of a flat grid, a crumpled grid, an open tube and a closed sphere, with large
/// and tiny motions, near contacts and exact touches. `scale` sets the mesh resolution.
inline std::vector<Step> make_random_steps(unsigned seed, int resolution) {
  std::mt19937 rng(seed);
  std::vector<Step> steps;
  const int n = resolution;

  {  // Flat grid folding through itself (book closing past 180 degrees).
    Step step{"grid_fold", make_grid(n, n / 2, 1.0, 0.5), {}};
    const Positions flat = step.mesh.vertices;
    step.mesh.vertices = fold_grid(flat, 0.5, 0.97 * M_PI);
    step.x1 = fold_grid(flat, 0.5, 1.03 * M_PI);
    jitter(step.mesh.vertices, rng, 0.2 / n);
    jitter(step.x1, rng, 0.2 / n);
    steps.push_back(std::move(step));
  }
  {  // Crumpled grid, large step.
    Step step{"grid_crumple_large", make_grid(n, n, 1.0, 1.0), {}};
    const Positions rest = step.mesh.vertices;
    step.mesh.vertices = crumpling_cloth(rest, 0.7);
    step.x1 = crumpling_cloth(rest, 1.0);
    jitter(step.x1, rng, 0.5 / n);
    steps.push_back(std::move(step));
  }
  {  // Crumpled grid, tiny step.
    Step step{"grid_crumple_tiny", make_grid(n, n, 1.0, 1.0), {}};
    const Positions rest = step.mesh.vertices;
    step.mesh.vertices = crumpling_cloth(rest, 0.9);
    step.x1 = step.mesh.vertices;
    jitter(step.x1, rng, 1e-4 / n);
    steps.push_back(std::move(step));
  }
  {  // Flat grid snapped to a coarse dyadic lattice and moving in its plane and out of
     // it: many exactly coplanar, touching and parallel configurations.
    Step step{"grid_snapped", make_grid(n / 2, n / 2, 1.0, 1.0), {}};
    step.x1 = step.mesh.vertices;
    jitter(step.mesh.vertices, rng, 1.5 / n);
    jitter(step.x1, rng, 1.5 / n);
    for (Eigen::Index i = 0; i < step.x1.rows(); ++i) {
      if (i % 3 == 0) step.mesh.vertices(i, 2) = 0, step.x1(i, 2) = 0;
    }
    snap(step.mesh.vertices, 5, 1.0);
    snap(step.x1, 5, 1.0);
    steps.push_back(std::move(step));
  }
  {  // Open tube squashed flat and through itself.
    Step step{"tube_squash", make_tube(n / 2, n / 2, 0.3, 1.0), {}};
    Positions x1 = step.mesh.vertices;
    step.mesh.vertices.col(1) *= 0.08;
    x1.col(1) *= -0.05;
    step.x1 = x1;
    jitter(step.mesh.vertices, rng, 0.1 / n);
    jitter(step.x1, rng, 0.1 / n);
    steps.push_back(std::move(step));
  }
  {  // Closed sphere squashed until its poles pass each other, snapped.
    Step step{"sphere_squash_snapped", make_sphere(n / 3, n / 2, 0.5), {}};
    Positions x1 = step.mesh.vertices;
    step.mesh.vertices.col(2) *= 0.1;
    x1.col(2) *= -0.1;
    step.x1 = x1;
    snap(step.mesh.vertices, 8, 1.0);
    snap(step.x1, 8, 1.0);
    steps.push_back(std::move(step));
  }
  {  // Sphere under random large motion of every vertex.
    Step step{"sphere_random", make_sphere(n / 3, n / 2, 0.5), {}};
    step.x1 = step.mesh.vertices;
    jitter(step.x1, rng, 0.1);
    steps.push_back(std::move(step));
  }
  return steps;
}

}  // namespace tailor::testing
