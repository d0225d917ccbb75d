/// @file
/// Sleeve generation.

#include "tailor/scene/sleeve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tailor/geometry/error.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {

std::vector<Index> Sleeve::ring(Index r) const {
  std::vector<Index> ids(static_cast<std::size_t>(params.segments));
  for (Index j = 0; j < params.segments; ++j)
    ids[static_cast<std::size_t>(j)] = r * params.segments + j;
  return ids;
}

std::vector<std::vector<Index>> Sleeve::rings() const {
  std::vector<std::vector<Index>> out;
  out.reserve(static_cast<std::size_t>(params.rings));
  for (Index r = 0; r < params.rings; ++r) out.push_back(ring(r));
  return out;
}

Positions Sleeve::warp_directions() const {
  Positions d(mesh->num_faces(), 3);
  d.rowwise() = Eigen::RowVector3d(1, 0, 0);
  return d;
}

double sleeve_memory_estimate(const SleeveParams& params) {
  return static_cast<double>(params.rings) * params.segments * 16384.0;
}

Sleeve make_sleeve(const Arm& arm, const SleeveParams& params) {
  if (params.rings < 2 || params.segments < 3) {
    throw InputError(fmt::format("sleeve resolution too low: rings {} (≥ 2), segments {} (≥ 3)",
                                 params.rings, params.segments));
  }
  const double total = arm.params().upper_arm_length + arm.params().forearm_length;
  if (!(params.slack > 0) || !(params.length > 0) || !(params.start >= 0) ||
      !(params.start + params.length <= total)) {
    throw InputError(fmt::format(
        "sleeve must have positive slack and length and lie along the arm (start {} + length {} "
        "≤ {} m)",
        params.start, params.length, total));
  }
  const std::int64_t nv = static_cast<std::int64_t>(params.rings) * params.segments;
  if (nv > (std::int64_t{1} << 30)) throw InputError("sleeve resolution too high");
  check_memory_budget(sleeve_memory_estimate(params),
                      fmt::format("a sleeve of {} rings × {} segments ({} vertices)", params.rings,
                                  params.segments, nv));

  Sleeve s;
  s.params = params;
  const Index rings = params.rings, seg = params.segments;
  s.rest.resize(rings * seg, 3);
  std::vector<double> cosines(static_cast<std::size_t>(seg)), sines(static_cast<std::size_t>(seg));
  for (Index j = 0; j < seg; ++j) {
    const double phi = 2 * std::numbers::pi * j / seg;
    cosines[static_cast<std::size_t>(j)] = std::cos(phi);
    sines[static_cast<std::size_t>(j)] = std::sin(phi);
  }
  double best = 1e300;
  for (Index r = 0; r < rings; ++r) {
    const double x = params.start + params.length * r / (rings - 1);
    const double radius = arm.radius_at(x) + params.slack;
    for (Index j = 0; j < seg; ++j) {
      s.rest.row(r * seg + j) << x, radius * cosines[static_cast<std::size_t>(j)],
          radius * sines[static_cast<std::size_t>(j)];
    }
    const double d = std::abs(x - arm.params().upper_arm_length);
    if (d < best) {
      best = d;
      s.elbow_ring = r;
    }
  }

  // Observers at the elbow ring and every kObserverSpacing (in whole rings) toward the
  // ends, off the open end rings (an observer there would sit on its ghost fan).
  const double ring_spacing = params.length / (rings - 1);
  const auto step =
      std::max<Index>(1, static_cast<Index>(std::lround(Sleeve::kObserverSpacing / ring_spacing)));
  for (Index r = s.elbow_ring % step; r < rings; r += step) {
    if (r > 0 && r < rings - 1) s.observer_rings.push_back(r);
  }
  if (s.observer_rings.empty()) s.observer_rings.push_back(rings / 2);

  // Two triangles per quad, diagonals alternating so the tube has no helical bias;
  // (ring r, j), (r, j+1), (r+1, j) is outward (see Arm).
  FaceArray faces(2 * static_cast<Eigen::Index>(rings - 1) * seg, 3);
  Eigen::Index f = 0;
  for (Index r = 0; r + 1 < rings; ++r) {
    for (Index j = 0; j < seg; ++j) {
      const Index jn = (j + 1) % seg;
      const Index a = r * seg + j, an = r * seg + jn, b = (r + 1) * seg + j,
                  bn = (r + 1) * seg + jn;
      if ((r + j) % 2 == 0) {
        faces.row(f++) << a, an, b;
        faces.row(f++) << an, bn, b;
      } else {
        faces.row(f++) << a, an, bn;
        faces.row(f++) << a, bn, b;
      }
    }
  }
  s.mesh = std::make_shared<TriangleMesh>(rings * seg, std::move(faces));
  return s;
}

}  // namespace tailor
