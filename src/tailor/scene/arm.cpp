/// @file
/// Procedural arm: surface by ray casting onto the implicit volume, smooth LBS weights.

#include "tailor/scene/arm.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {
namespace {

double sign_of(double v) {
  return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
}

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// Distance along the ray `origin + t * dir` (origin inside) to the surface where
/// `sdf` changes sign, by bisection (the volume is star-shaped about the origins used).
template <typename Sdf>
double ray_to_surface(const Sdf& sdf, const Vec3& origin, const Vec3& dir, double t_max) {
  double lo = 0, hi = t_max;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (sdf(origin + mid * dir) < 0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

void check_positive(double value, const char* name) {
  if (!(value > 0) || !std::isfinite(value)) {
    throw InputError(fmt::format("arm: {} must be a positive number, got {}", name, value));
  }
}

// The parameters' ranges, and the memory the arm's mesh would take.
void validate_arm_params(const ArmParams& params) {
  check_positive(params.upper_arm_length, "upper_arm_length");
  check_positive(params.forearm_length, "forearm_length");
  check_positive(params.shoulder_radius, "shoulder_radius");
  check_positive(params.elbow_radius, "elbow_radius");
  check_positive(params.wrist_radius, "wrist_radius");
  check_positive(params.elbow_blend, "elbow_blend");
  if (params.rings < 2 || params.segments < 3 || params.cap_rings < 1) {
    throw InputError(
        fmt::format("arm: resolution too low (rings {} ≥ 2, segments {} ≥ 3, "
                    "cap_rings {} ≥ 1 needed)",
                    params.rings, params.segments, params.cap_rings));
  }
  // Round cones need |ra - rb| < length.
  if (std::abs(params.shoulder_radius - params.elbow_radius) >= params.upper_arm_length ||
      std::abs(params.elbow_radius - params.wrist_radius) >= params.forearm_length) {
    throw InputError("arm: radii differ by more than a bone length");
  }
  // Vertex ids are 32-bit: whatever the budget, stay far from the range's end.
  if (arm_memory_estimate(params) / 4096.0 > static_cast<double>(std::int64_t{1} << 28)) {
    throw InputError(
        fmt::format("arm: resolution too high ({} rings, {} cap rings, {} segments: "
                    "more than 2^28 vertices)",
                    params.rings, params.cap_rings, params.segments));
  }
  check_memory_budget(arm_memory_estimate(params),
                      fmt::format("an arm of {} rings, {} cap rings and {} segments", params.rings,
                                  params.cap_rings, params.segments));
}

// The surface points of the arm in its rest pose, ring by ring from the shoulder pole to
// the wrist pole (a pole is a ring of one vertex): (first vertex, count) per ring.
struct ArmRings {
  std::vector<Vec3> points;
  std::vector<std::pair<Index, Index>> rings;
};

ArmRings cast_arm_rings(const Arm& arm, const ArmParams& params) {
  const double max_r = std::max({params.shoulder_radius, params.elbow_radius, params.wrist_radius});

  const ArmSkeleton rest = arm.skeleton(ArmPose{});
  const auto sdf = [&](const Vec3& p) { return arm.signed_distance(rest, p); };
  const int seg = params.segments;
  const double total = params.upper_arm_length + params.forearm_length;
  const Vec3 shoulder = rest.shoulder();
  const Vec3 wrist = rest.wrist(params.forearm_length);
  const double t_max = 4 * max_r;

  ArmRings out;
  std::vector<Vec3>& points = out.points;
  std::vector<std::pair<Index, Index>>& rings = out.rings;
  const auto add_ring = [&](const Vec3& origin, double axial, double radial_scale) {
    // Directions (axial, radial_scale * cos, radial_scale * sin), cast from `origin`.
    rings.emplace_back(static_cast<Index>(points.size()), seg);
    for (int j = 0; j < seg; ++j) {
      const double phi = 2 * std::numbers::pi * j / seg;
      const Vec3 dir =
          Vec3(axial, radial_scale * std::cos(phi), radial_scale * std::sin(phi)).normalized();
      points.push_back(origin + ray_to_surface(sdf, origin, dir, t_max) * dir);
    }
  };
  const auto add_pole = [&](const Vec3& origin, const Vec3& dir) {
    rings.emplace_back(static_cast<Index>(points.size()), 1);
    points.push_back(origin + ray_to_surface(sdf, origin, dir, t_max) * dir);
  };
  const int caps = params.cap_rings;
  add_pole(shoulder, -Vec3::UnitX());
  for (int k = 1; k < caps; ++k) {
    const double alpha = 0.5 * std::numbers::pi * (caps - k) / caps;
    add_ring(shoulder, -std::sin(alpha), std::cos(alpha));
  }
  for (int k = 0; k <= params.rings; ++k) {
    add_ring(shoulder + Vec3(total * k / params.rings, 0, 0), 0.0, 1.0);
  }
  for (int k = caps - 1; k >= 1; --k) {
    const double alpha = 0.5 * std::numbers::pi * (caps - k) / caps;
    add_ring(wrist, std::sin(alpha), std::cos(alpha));
  }
  add_pole(wrist, Vec3::UnitX());
  return out;
}

// Faces between consecutive rings, oriented outwards.
FaceArray ring_faces(const std::vector<std::pair<Index, Index>>& rings, int seg) {
  std::vector<Eigen::Matrix<Index, 1, 3>> faces;
  for (std::size_t r = 0; r + 1 < rings.size(); ++r) {
    const auto [a0, na] = rings[r];
    const auto [b0, nb] = rings[r + 1];
    for (int j = 0; j < seg; ++j) {
      const int jn = (j + 1) % seg;
      const Index a = a0 + (na == 1 ? 0 : j), an = a0 + (na == 1 ? 0 : jn);
      const Index b = b0 + (nb == 1 ? 0 : j), bn = b0 + (nb == 1 ? 0 : jn);
      if (na != 1) faces.emplace_back(a, an, b);
      if (nb != 1) faces.emplace_back(an, bn, b);
    }
  }
  FaceArray face_array(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    face_array.row(static_cast<Eigen::Index>(f)) = faces[f];
  return face_array;
}

}  // namespace

double round_cone_distance(const Vec3& p, const Vec3& a, const Vec3& b, double ra, double rb,
                           Vec3* normal) {
  // Exact distance to a sphere-swept segment with linearly varying radius (I. Quilez);
  // the outward normal is the gradient of the branch taken: from the centre of the end
  // sphere, or along the cone's slanted side (the perpendicular direction from the axis
  // tilted by the slope, whose cosine is sqrt(a2 / l2) and sine rr / l).
  const Vec3 ba = b - a;
  const double l2 = ba.squaredNorm();
  const double rr = ra - rb;
  const double a2 = l2 - rr * rr;
  const double il2 = 1.0 / l2;
  const Vec3 pa = p - a;
  const double y = pa.dot(ba);
  const double z = y - l2;
  const Vec3 across = pa * l2 - ba * y;  // l2 times the component of pa across the axis
  const double x2 = across.squaredNorm();
  const double y2 = y * y * l2;
  const double z2 = z * z * l2;
  const double k = sign_of(rr) * rr * rr * x2;
  const auto unit_or_keep = [&](const Vec3& v) {
    const double n = v.norm();
    if (normal != nullptr && n > 0) *normal = v / n;
  };
  if (sign_of(z) * a2 * z2 > k) {
    unit_or_keep(p - b);
    return std::sqrt(x2 + z2) * il2 - rb;
  }
  if (sign_of(y) * a2 * y2 < k) {
    unit_or_keep(p - a);
    return std::sqrt(x2 + y2) * il2 - ra;
  }
  if (normal != nullptr) {
    const double x = std::sqrt(x2);
    if (x > 0)
      *normal = std::sqrt(a2 * il2) * (across / x) + (rr / std::sqrt(l2)) * (ba / std::sqrt(l2));
  }
  return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - ra;
}

double arm_memory_estimate(const ArmParams& params) {
  const double rings = static_cast<double>(params.rings) + 1 + 2.0 * (params.cap_rings - 1);
  return (2 + rings * params.segments) * 4096.0;
}

Arm::Arm(const ArmParams& params) : m_params(params) {
  validate_arm_params(params);
  const ArmRings surface = cast_arm_rings(*this, params);
  const std::vector<Vec3>& points = surface.points;
  m_rest.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    m_rest.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  m_mesh = std::make_unique<TriangleMesh>(static_cast<Index>(points.size()),
                                          ring_faces(surface.rings, params.segments));
  m_forearm_weight.resize(m_rest.rows());
  for (Eigen::Index i = 0; i < m_rest.rows(); ++i) {
    m_forearm_weight[i] = forearm_weight(m_rest.row(i).transpose());
  }
}

ArmSkeleton Arm::skeleton(const ArmPose& pose) const {
  using Eigen::AngleAxisd;
  ArmSkeleton s;
  s.upper_arm = Eigen::Isometry3d::Identity();
  s.upper_arm.rotate(AngleAxisd(pose.shoulder_raise, Vec3::UnitZ()));
  s.upper_arm.rotate(AngleAxisd(-pose.shoulder_swing, Vec3::UnitY()));
  s.upper_arm.rotate(AngleAxisd(pose.humeral_rotation, Vec3::UnitX()));
  s.forearm = s.upper_arm;
  s.forearm.translate(Vec3(m_params.upper_arm_length, 0, 0));
  s.forearm.rotate(AngleAxisd(-pose.elbow_flexion, Vec3::UnitY()));
  s.forearm.rotate(AngleAxisd(pose.forearm_twist, Vec3::UnitX()));
  return s;
}

std::array<Eigen::Isometry3d, 2> Arm::skinning_transforms(const ArmPose& pose) const {
  const ArmSkeleton posed = skeleton(pose);
  const ArmSkeleton rest = skeleton(ArmPose{});
  return {posed.upper_arm * rest.upper_arm.inverse(), posed.forearm * rest.forearm.inverse()};
}

double Arm::forearm_weight(const Vec3& rest_point) const {
  const double b = m_params.elbow_blend;
  return smoothstep((rest_point.x() - (m_params.upper_arm_length - b)) / (2 * b));
}

Positions Arm::skin(const ArmPose& pose) const {
  const auto m = skinning_transforms(pose);
  Positions out(m_rest.rows(), 3);
  for (Eigen::Index i = 0; i < m_rest.rows(); ++i) {
    const Vec3 p = m_rest.row(i).transpose();
    const double w = m_forearm_weight[i];
    out.row(i) = ((1 - w) * (m[0] * p) + w * (m[1] * p)).transpose();
  }
  return out;
}

Positions Arm::skin_points(const Positions& rest_points, const ArmPose& pose) const {
  const auto m = skinning_transforms(pose);
  Positions out(rest_points.rows(), 3);
  for (Eigen::Index i = 0; i < rest_points.rows(); ++i) {
    const Vec3 p = rest_points.row(i).transpose();
    const double w = forearm_weight(p);
    out.row(i) = ((1 - w) * (m[0] * p) + w * (m[1] * p)).transpose();
  }
  return out;
}

double Arm::signed_distance(const ArmSkeleton& s, const Vec3& p) const {
  const Vec3 wrist = s.wrist(m_params.forearm_length);
  return std::min(
      round_cone_distance(p, s.shoulder(), s.elbow(), m_params.shoulder_radius,
                          m_params.elbow_radius),
      round_cone_distance(p, s.elbow(), wrist, m_params.elbow_radius, m_params.wrist_radius));
}

ArmDistance Arm::distance(const ArmSkeleton& s, const Vec3& p) const {
  const Vec3 wrist = s.wrist(m_params.forearm_length);
  const Vec3 a = s.shoulder(), e = s.elbow();
  Vec3 nu = Vec3::UnitY(), nf = Vec3::UnitY();
  const double du =
      round_cone_distance(p, a, e, m_params.shoulder_radius, m_params.elbow_radius, &nu);
  const double df =
      round_cone_distance(p, e, wrist, m_params.elbow_radius, m_params.wrist_radius, &nf);
  ArmDistance out;
  out.bone = df < du ? 1 : 0;
  out.distance = std::min(du, df);
  out.normal = out.bone == 0 ? nu : nf;  // the nearer cone's gradient (analytic)
  return out;
}

double Arm::radius_at(double x) const {
  const double total = m_params.upper_arm_length + m_params.forearm_length;
  if (x < 0 || x > total) return 0;
  const ArmSkeleton rest = skeleton(ArmPose{});
  const auto sdf = [&](const Vec3& p) { return signed_distance(rest, p); };
  const double max_r =
      std::max({m_params.shoulder_radius, m_params.elbow_radius, m_params.wrist_radius});
  return ray_to_surface(sdf, Vec3(x, 0, 0), Vec3::UnitY(), 4 * max_r);
}

}  // namespace tailor
