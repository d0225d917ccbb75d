/// @file
/// Rigid motion of an impact zone.

#include "tailor/sim/impact_zones.hpp"

#include <Eigen/SVD>

namespace tailor {
void move_zone_rigidly(std::span<const Index> members, const Positions& x0,
                       const Eigen::VectorXd& inverse_mass, const KinematicVertices& prescribed,
                       Positions& x1) {
  const auto& [pinned, follows, target] = prescribed;
  std::vector<Index> kinematic;
  for (Index v : members) {
    if (pinned[v] || follows[v]) kinematic.push_back(v);
  }
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 c0 = Vec3::Zero(), c1 = Vec3::Zero();
  if (!kinematic.empty()) {
    for (Index v : kinematic) {
      c0 += position(x0, v);
      c1 += target(v);
    }
    c0 /= static_cast<double>(kinematic.size());
    c1 /= static_cast<double>(kinematic.size());
    if (kinematic.size() >= 2) {
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (Index v : kinematic) cov += (target(v) - c1) * (position(x0, v) - c0).transpose();
      const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
      Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
      if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) d(2, 2) = -1;
      rotation = svd.matrixU() * d * svd.matrixV().transpose();
    }
    for (Index v : members) {
      if (pinned[v]) continue;
      const Vec3 moved = follows[v] ? target(v) : Vec3(c1 + rotation * (position(x0, v) - c0));
      x1.row(v) = moved.transpose();
    }
    return;
  }
  double mass = 0;
  Vec3 displacement = Vec3::Zero();
  for (Index v : members) {
    const double mv = 1.0 / inverse_mass[v];
    mass += mv;
    c0 += mv * position(x0, v);
    displacement += mv * (position(x1, v) - position(x0, v));
  }
  c0 /= mass;
  displacement /= mass;
  Vec3 angular = Vec3::Zero();  // angular momentum of the displacements
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (Index v : members) {
    const double mv = 1.0 / inverse_mass[v];
    const Vec3 r = position(x0, v) - c0;
    angular += mv * r.cross(position(x1, v) - position(x0, v) - displacement);
    inertia += mv * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  // Pseudo-inverse: a collinear zone has no inertia about its axis.
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(inertia, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d sv = svd.singularValues();
  const double cut = 1e-12 * sv(0);
  for (int k = 0; k < 3; ++k) sv(k) = sv(k) > cut ? 1.0 / sv(k) : 0.0;
  const Vec3 omega = svd.matrixV() * sv.asDiagonal() * svd.matrixU().transpose() * angular;
  const double angle = omega.norm();
  if (angle > 0) rotation = Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
  for (Index v : members)
    x1.row(v) = (c0 + displacement + rotation * (position(x0, v) - c0)).transpose();
}

}  // namespace tailor
