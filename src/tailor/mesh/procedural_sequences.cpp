/// @file
/// The falling fold: an extruded profile curve, so its intersections are known exactly.

#include "tailor/mesh/procedural_sequences.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>

#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

constexpr double kFoldX = 0.5;         // where the fold starts; the bottom layer is [0, 0.5]
constexpr double kStartRadius = 0.15;  // π · 0.15 < 0.5: the arc fits in the folded half

/// The profile point at arc length `s` of a strip folded with radius `r`.
Eigen::Vector2d fold_profile(double s, double r) {
  const double arc = std::numbers::pi * r;
  if (s <= kFoldX) return {s, 0.0};
  if (s <= kFoldX + arc) {
    const double angle = (s - kFoldX) / r;  // 0 at the bottom, π at the top
    return {kFoldX + r * std::sin(angle), r - r * std::cos(angle)};
  }
  return {kFoldX - (s - kFoldX - arc), 2 * r};
}

/// 1 on the plateau |d| <= width / 2, easing (cos²) to 0 at |d| = width.
double plateau_bump(double d, double width) {
  const double a = std::abs(d);
  if (a <= width / 2) return 1.0;
  if (a >= width) return 0.0;
  const double c = std::cos(std::numbers::pi * (a - width / 2) / width);
  return c * c;
}

/// A deterministic value in [-1, 1) for `key` (the splitmix64 finaliser).
double hashed_unit(std::uint64_t key) {
  key += 0x9e3779b97f4a7c15ULL;
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
  key ^= key >> 31;
  return static_cast<double>(key >> 11) * 0x1.0p-52 - 1.0;
}

}  // namespace

ProceduralSequence make_falling_fold(const FallingFoldOptions& options) {
  if (options.cells_along < 8 || options.cells_across < 1 || options.frames < 2 ||
      options.piercing_frame < -1 || options.piercing_frame >= options.frames ||
      !(options.jitter >= 0 && options.jitter <= 0.01)) {
    throw std::invalid_argument("make_falling_fold: options out of range");
  }
  const double h = 1.0 / options.cells_along;
  const MeshData flat =
      make_grid(options.cells_along, options.cells_across, 1.0, h * options.cells_across);
  ProceduralSequence sequence;
  sequence.faces = flat.faces;
  const double end_radius = 0.75 * h;
  for (int k = 0; k < options.frames; ++k) {
    const double t = static_cast<double>(k) / (options.frames - 1);
    const double r = kStartRadius + (end_radius - kStartRadius) * t;
    const double free_length = (1.0 - kFoldX) - std::numbers::pi * r;
    const bool pierce = k == options.piercing_frame;
    if (pierce && free_length < 8 * h) {
      throw std::invalid_argument("make_falling_fold: the free layer of piercing frame " +
                                  std::to_string(k) + " is shorter than 8 cells");
    }
    const double dent_centre = kFoldX - free_length / 2;
    const double dent_width = free_length / 3;
    Positions x = flat.vertices;
    for (Eigen::Index v = 0; v < x.rows(); ++v) {
      const double s = flat.vertices(v, 0);
      Eigen::Vector2d p = fold_profile(s, r);
      if (pierce && s > kFoldX + std::numbers::pi * r) {
        p.y() -= (2 * r + 4 * h) * plateau_bump(p.x() - dent_centre, dent_width);
      }
      x(v, 0) = p.x();
      x(v, 2) = p.y();
      if (options.jitter > 0) {
        const std::uint64_t key =
            3 * (static_cast<std::uint64_t>(k) * static_cast<std::uint64_t>(x.rows()) +
                 static_cast<std::uint64_t>(v));
        for (int c = 0; c < 3; ++c) x(v, c) += options.jitter * h * hashed_unit(key + c);
      }
    }
    sequence.frames.push_back(std::move(x));
    sequence.intersecting.push_back(pierce);
  }
  return sequence;
}

}  // namespace tailor
