/// @file
/// Projection of cloth vertices out of the implicit arm.

#include "tailor/sim/arm_collision.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

namespace tailor {
namespace {

/// A vertex this close to the margin (relative) counts as outside: a vertex just
/// projected lands on the margin only up to rounding, and projecting it again every time
/// would keep the strain limiter's alternating projections from ever finishing.
constexpr double kMarginRounding = 1e-9;

/// Vertices per parallel task of the projection: the strain limiter projects after every
/// sweep, so a task must outweigh its scheduling (the default sleeve, 693 vertices, stays
/// one task; the 10× sleeve, 6,864, makes seven).
constexpr Eigen::Index kProjectionGrain = 1024;

std::array<Eigen::Isometry3d, 2> bone_motion(const ArmSkeleton& s0, const ArmSkeleton& s1) {
  return {s1.upper_arm * s0.upper_arm.inverse(), s1.forearm * s0.forearm.inverse()};
}

}  // namespace

void ArmClearanceCache::reset(Index vertices) {
  m_where.assign(static_cast<std::size_t>(vertices), Vec3::Zero());
  m_clearance.assign(static_cast<std::size_t>(vertices), 0.0);
}

double face_clearance_margin(double min_arm_radius, double longest_rest_edge, double max_strain,
                             double clearance) {
  const double r = min_arm_radius;
  const double rho = (1 + max_strain) * longest_rest_edge / std::sqrt(3.0);
  return std::max(clearance, std::sqrt((r + clearance) * (r + clearance) + rho * rho) - r);
}

std::vector<ContactPlane> arm_contact_planes(const ArmMotion& arm_motion,
                                             const ClothAtSubstepStart& cloth, double h,
                                             const ArmContactSettings& settings,
                                             const ArmContactMemory& memory) {
  const Arm& arm = arm_motion.arm;
  const ArmSkeleton &skeleton0 = arm_motion.skeleton0, &skeleton1 = arm_motion.skeleton1;
  const Positions &x0 = cloth.x0, &v0 = cloth.v0;
  const std::vector<char>& fixed = memory.fixed;
  std::vector<char>& released = memory.released;
  std::vector<ContactPlane> planes;
  const auto motion = bone_motion(skeleton0, skeleton1);
  for (Eigen::Index i = 0; i < x0.rows(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!fixed.empty() && fixed[k] != 0) continue;
    const Vec3 p = x0.row(i).transpose();
    // The plain distance first: most vertices are away from the arm and need no normal.
    if (arm.signed_distance(skeleton0, p) > settings.margin + settings.activation) {
      released[k] = 0;  // away from the arm: the next touch is a new contact
      continue;
    }
    if (released[k] != 0) continue;
    const ArmDistance d0 = arm.distance(skeleton0, p);
    const Vec3 carried = motion[static_cast<std::size_t>(d0.bone)] * p;
    const ArmDistance d1 = arm.distance(skeleton1, carried);
    ContactPlane c;
    c.vertex = static_cast<Index>(i);
    c.normal = d1.normal;
    c.point = carried + (settings.margin - d1.distance) * d1.normal;
    c.stiffness = settings.stiffness_ratio * cloth.masses[i] / (h * h);
    c.friction = settings.friction;
    c.normal_force = memory.normal_forces[k];
    c.velocity = (carried - p) / h;
    c.slip_speed = c.tangential_speed(v0.row(i).transpose());
    planes.push_back(c);
  }
  return planes;
}

std::int64_t finish_arm_contacts(const std::vector<ContactPlane>& planes, const Positions& x1,
                                 std::vector<char>& released, std::vector<double>& normal_forces) {
  std::int64_t pushing = 0;
  std::fill(normal_forces.begin(), normal_forces.end(), 0.0);
  for (const ContactPlane& c : planes) {
    const auto i = static_cast<std::size_t>(c.vertex);
    const Vec3 p = x1.row(c.vertex).transpose();
    if (c.normal.dot(p - c.point) > 0) {
      released[i] = 1;
      continue;
    }
    ++pushing;
    normal_forces[i] = c.force_at(p);
  }
  return pushing;
}

ArmCollisionStats project_out_of_arm(const ArmMotion& arm_motion, const Positions& x0,
                                     Positions& x1, const ArmProjection& projection) {
  const Arm& arm = arm_motion.arm;
  const ArmSkeleton &skeleton0 = arm_motion.skeleton0, &skeleton1 = arm_motion.skeleton1;
  const double margin = projection.margin, friction = projection.friction;
  static const std::vector<char> kNoneFixed;
  const std::vector<char>& fixed = projection.fixed != nullptr ? *projection.fixed : kNoneFixed;
  std::vector<Index>* const projected_ids = projection.projected_ids;
  ArmClearanceCache* const cache = projection.cache;
  const auto motion = bone_motion(skeleton0, skeleton1);
  // Moves vertex i out of the arm; true when it moved. Touches row i of x1 and entry i of
  // the cache only, so vertices are independent.
  const auto project = [&](Eigen::Index i, double& max_depth) {
    if (!fixed.empty() && fixed[static_cast<std::size_t>(i)] != 0) return false;
    Vec3 p = x1.row(i).transpose();
    if (cache != nullptr && cache->known_unmoved(static_cast<Index>(i), p)) return false;
    const double clearance = arm.signed_distance(skeleton1, p) - margin;  // cheap test first
    if (clearance >= 0) {
      if (cache != nullptr) cache->store(static_cast<Index>(i), p, clearance);
      return false;
    }
    bool moved = false, settled = false;
    // A few passes: in the elbow crease, leaving one cone can enter the other.
    for (int pass = 0; pass < 4; ++pass) {
      const ArmDistance d = arm.distance(skeleton1, p);
      if (d.distance >= margin * (1 - kMarginRounding)) {
        // The same p would be decided the same way again (its signed distance is below
        // the margin, its distance not): it stays.
        settled = true;
        break;
      }
      const double depth = margin - d.distance;
      max_depth = std::max(max_depth, depth);
      p += depth * d.normal;
      if (pass == 0 && friction > 0) {
        // Tangential slip relative to the moving arm, reduced by at most μ·depth.
        const Vec3 carried = motion[static_cast<std::size_t>(d.bone)] * Vec3(x0.row(i).transpose());
        Vec3 slip = p - carried;
        slip -= slip.dot(d.normal) * d.normal;
        const double s = slip.norm();
        if (s > 0) p -= std::min(1.0, friction * depth / s) * slip;
      }
      moved = true;
    }
    if (cache != nullptr) {
      if (settled) {
        cache->settle(static_cast<Index>(i), p);
      } else {
        cache->store(static_cast<Index>(i), p, 0.0);
      }
    }
    if (moved) x1.row(i) = p.transpose();
    return moved;
  };

  // Blocks of vertices in parallel; the counts and the deepest penetration are reduced
  // exactly (integer sum, maximum), so the result does not depend on the thread count.
  std::vector<char> moved(projected_ids != nullptr ? static_cast<std::size_t>(x1.rows()) : 0, 0);
  const ArmCollisionStats stats = tbb::parallel_reduce(
      tbb::blocked_range<Eigen::Index>(0, x1.rows(), kProjectionGrain), ArmCollisionStats{},
      [&](const tbb::blocked_range<Eigen::Index>& range, ArmCollisionStats s) {
        for (Eigen::Index i = range.begin(); i != range.end(); ++i) {
          if (!project(i, s.max_depth)) continue;
          ++s.projected;
          if (!moved.empty()) moved[static_cast<std::size_t>(i)] = 1;
        }
        return s;
      },
      [](ArmCollisionStats a, const ArmCollisionStats& b) {
        a.projected += b.projected;
        a.max_depth = std::max(a.max_depth, b.max_depth);
        return a;
      });
  if (projected_ids != nullptr) {
    projected_ids->clear();
    for (std::size_t i = 0; i < moved.size(); ++i) {
      if (moved[i] != 0) projected_ids->push_back(static_cast<Index>(i));
    }
  }
  return stats;
}

}  // namespace tailor
