#pragma once
/// @file
/// A procedural arm: a two-bone skeleton (shoulder, elbow, wrist), a closed surface
/// skinned to it by linear blend skinning, and its implicit volume (two round cones).
///
/// Frame (metres): the shoulder joint is at the origin, the arm points along +x in the
/// rest pose (a T-pose), +y is up (gravity is -y) and +z is the front. Elbow flexion
/// turns the forearm towards +z, a shoulder raise turns the arm towards +y.

#include <array>
#include <memory>

#include <Eigen/Geometry>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Dimensions and resolution of the arm.
struct ArmParams {
  double upper_arm_length = 0.30;  ///< shoulder to elbow (m)
  double forearm_length = 0.27;    ///< elbow to wrist (m)
  double shoulder_radius = 0.050;  ///< radius at the shoulder joint (m)
  double elbow_radius = 0.037;     ///< radius at the elbow (m)
  double wrist_radius = 0.027;     ///< radius at the wrist (m)
  double elbow_blend = 0.05;       ///< half-width of the skinning blend around the elbow (m)
  int rings = 40;                  ///< rings between shoulder and wrist (≥ 2)
  int segments = 24;               ///< vertices around each ring (≥ 3)
  int cap_rings = 5;               ///< rings of each rounded end, the pole included (≥ 1)
};

/// Joint angles (radians). All zero is the rest pose.
struct ArmPose {
  double shoulder_raise = 0;    ///< about +z: lifts the arm towards +y
  double shoulder_swing = 0;    ///< about -y: swings the arm towards +z
  double humeral_rotation = 0;  ///< about the upper arm's own axis
  double elbow_flexion = 0;     ///< about -y in the upper arm frame: forearm towards +z
  double forearm_twist = 0;     ///< about the forearm's own axis
};

/// The skeleton's two bone transforms (bone frame to world) for one pose.
struct ArmSkeleton {
  Eigen::Isometry3d upper_arm = Eigen::Isometry3d::Identity();  ///< origin at the shoulder
  Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();    ///< origin at the elbow
  /// Shoulder joint position.
  Vec3 shoulder() const { return upper_arm.translation(); }
  /// Elbow joint position.
  Vec3 elbow() const { return forearm.translation(); }
  /// Wrist position for a forearm of length `forearm_length`.
  Vec3 wrist(double forearm_length) const { return forearm * Vec3(forearm_length, 0, 0); }
};

/// Memory the simulation needs for an arm of these parameters, in bytes: the surface's
/// vertex count (2 poles and `rings + 1 + 2 (cap_rings - 1)` rings of `segments`) times
/// 4 KiB. Measured: about 0.35 KiB per arm vertex to build the scene and 2 KiB after one
/// simulated frame (`tailor simulate`, 40K arm vertices); the factor 2 is a margin.
double arm_memory_estimate(const ArmParams& params);

/// Closest-point query on the arm's implicit volume.
struct ArmDistance {
  double distance = 0;          ///< signed distance to the surface (negative inside)
  Vec3 normal = Vec3::UnitY();  ///< outward unit direction of steepest distance increase
  int bone = 0;                 ///< 0: upper arm, 1: forearm (the nearer of the two)
};

/// A procedurally generated, skinned arm. The surface is closed (no boundary loop) and
/// its vertices lie on the implicit volume's surface in the rest pose; skinned poses
/// stay inside the posed implicit volume up to about 1.3 mm (the blend mostly pulls
/// vertices inwards), so a cloth kept 1.5 contact thicknesses outside the
/// implicit volume is also outside the mesh.
class Arm {
 public:
  /// Builds the skeleton, the surface and the skinning weights. Throws InputError on
  /// non-positive sizes, a resolution below the minimum, or one whose
  /// arm_memory_estimate() exceeds the memory budget (io/memory_budget.hpp).
  explicit Arm(const ArmParams& params = {});

  /// The parameters the arm was built with.
  const ArmParams& params() const { return m_params; }
  /// The surface mesh (fixed connectivity).
  const TriangleMesh& mesh() const { return *m_mesh; }
  /// Surface positions in the rest pose.
  const Positions& rest_positions() const { return m_rest; }
  /// Forearm weight of each surface vertex (the upper arm's is 1 minus this).
  const Eigen::VectorXd& forearm_weights() const { return m_forearm_weight; }

  /// Bone transforms for `pose`.
  ArmSkeleton skeleton(const ArmPose& pose) const;
  /// Skinning matrices (posed bone frame times inverse rest bone frame), upper arm first.
  std::array<Eigen::Isometry3d, 2> skinning_transforms(const ArmPose& pose) const;
  /// Surface positions for `pose` (linear blend skinning).
  Positions skin(const ArmPose& pose) const;
  /// Skins arbitrary rest-pose points, e.g. cloth vertices attached to the arm.
  Positions skin_points(const Positions& rest_points, const ArmPose& pose) const;
  /// Forearm skinning weight of a rest-pose point (smooth step around the elbow).
  double forearm_weight(const Vec3& rest_point) const;

  /// Signed distance from `p` to the implicit arm of `skeleton` (union of two round cones).
  double signed_distance(const ArmSkeleton& skeleton, const Vec3& p) const;
  /// Signed distance, outward normal and nearer bone of `p`.
  ArmDistance distance(const ArmSkeleton& skeleton, const Vec3& p) const;
  /// Radius of the implicit arm's cross-section at rest-pose abscissa `x` (0 outside
  /// [0, upper + forearm length]).
  double radius_at(double x) const;

 private:
  ArmParams m_params;
  std::unique_ptr<TriangleMesh> m_mesh;
  Positions m_rest;
  Eigen::VectorXd m_forearm_weight;
};

/// Signed distance from `p` to the round cone (sphere-swept segment with linearly varying
/// radius) from `a` (radius `ra`) to `b` (radius `rb`); exact. When `normal` is given it
/// receives the outward unit gradient of the distance at `p` (left unchanged where that is
/// undefined: at an end sphere's centre or on the axis inside the cone).
double round_cone_distance(const Vec3& p, const Vec3& a, const Vec3& b, double ra, double rb,
                           Vec3* normal = nullptr);

}  // namespace tailor
