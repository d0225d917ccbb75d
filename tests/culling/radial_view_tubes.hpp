#pragma once
// Bending, folding tubes with observers along their axis: the test scenes of radial-view
// culling (the sleeve of the paper without the simulation).

#include <cmath>
#include <random>
#include <vector>

#include "support/random_steps.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor::testing {

/// A tube of `rings` × `segments` vertices along z (make_tube), its step and its observer
/// section loops.
struct TubeStep {
  MeshData mesh;  // vertices = x0
  Positions x1;
  std::vector<std::vector<Index>> loops;
};

constexpr int kTubeRings = 24, kTubeSegments = 16;
constexpr double kTubeRadius = 0.3, kTubeLength = 2.0;

inline std::vector<Index> tube_ring(int r, int segments = kTubeSegments) {
  std::vector<Index> loop;
  for (int s = 0; s < segments; ++s) loop.push_back(r * segments + s);
  return loop;
}

/// Observers every five rings, off the open ends.
inline std::vector<std::vector<Index>> tube_observer_loops() {
  std::vector<std::vector<Index>> loops;
  for (int r = 2; r < kTubeRings - 1; r += 5) loops.push_back(tube_ring(r));
  return loops;
}

/// Bends a tube along z into an arc of `angle` radians and radius `bend_radius`.
inline Positions bend(const Positions& straight, double angle, double bend_radius, double length) {
  Positions x = straight;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double theta = angle * straight(i, 2) / length;
    const Vec3 radial(std::cos(theta), 0, std::sin(theta));
    const Vec3 p = Vec3(bend_radius, 0, 0) - bend_radius * radial + straight(i, 0) * radial +
                   straight(i, 1) * Vec3::UnitY();
    x.row(i) = p.transpose();
  }
  return x;
}

/// How a tube is folded: wrinkles pushed along the axis (folds overlap once
/// `axial` * 2π / `wavelength` passes 1), lobes around it, then a bend.
struct FoldShape {
  double axial = 0, wavelength = 0.3, phase = 0;  // accordion around the middle
  double radial = 0;                              // ripple of the radius
  int lobes = 3;
  double lobe_depth = 0;
  double bend_angle = 0, bend_radius = 1.0;
};

inline Positions fold(const Positions& straight, const FoldShape& s) {
  Positions x = straight;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double z = straight(i, 2);
    const double phi = std::atan2(straight(i, 1), straight(i, 0));
    const double centred = (z - 0.5 * kTubeLength) / (0.25 * kTubeLength);
    const double window = std::exp(-centred * centred);
    const double wave = 2 * M_PI * z / s.wavelength + s.phase;
    const double scale =
        1 + s.radial * window * std::sin(wave) + s.lobe_depth * window * std::cos(s.lobes * phi);
    x(i, 0) = straight(i, 0) * scale;
    x(i, 1) = straight(i, 1) * scale;
    x(i, 2) = z + s.axial * window * std::sin(wave);
  }
  return s.bend_angle == 0 ? x : bend(x, s.bend_angle, s.bend_radius, kTubeLength);
}

/// A random step of a tube folding further (or unfolding): from a shape at t = 0 to a
/// deeper or shallower one at t = 1, sometimes through itself.
inline TubeStep random_folding_tube(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TubeStep step{make_tube(kTubeRings, kTubeSegments, kTubeRadius, kTubeLength), {}, {}};
  const Positions straight = step.mesh.vertices;
  FoldShape a;
  a.axial = 0.06 * unit(rng);
  a.wavelength = 0.25 + 0.2 * unit(rng);
  a.phase = 2 * M_PI * unit(rng);
  a.radial = 0.25 * unit(rng);
  a.lobes = 2 + static_cast<int>(3 * unit(rng));
  a.lobe_depth = 0.3 * unit(rng);
  a.bend_angle = 2.5 * unit(rng);
  a.bend_radius = kTubeRadius * (0.6 + 3 * unit(rng));
  FoldShape b = a;
  const double change = 0.5 + 1.5 * unit(rng);  // deeper (> 1) or shallower folds
  b.axial *= change;
  b.radial *= change;
  b.lobe_depth *= change;
  b.bend_angle = a.bend_angle * (0.8 + 0.5 * unit(rng));
  b.phase += 0.3 * (unit(rng) - 0.5);
  step.mesh.vertices = fold(straight, a);
  step.x1 = fold(straight, b);
  jitter(step.mesh.vertices, rng, 0.002);
  jitter(step.x1, rng, 0.002);
  step.loops = tube_observer_loops();
  return step;
}

}  // namespace tailor::testing
