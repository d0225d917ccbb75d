#pragma once
/// @file
/// Inelastic contact impulses with Coulomb friction in displacement form (Bridson, Fedkiw &
/// Anderson 2002, §7): a contact pairs up to four points (cloth vertices or obstacle
/// points) with weights, positive on one side and negative on the other, so the weighted
/// sum is the relative position of the two sides; an impulse along the contact normal is
/// spread over the cloth points by weight and inverse mass.

#include <array>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// One point of a contact: a cloth vertex (`cloth` ≥ 0) or an obstacle point, with its
/// positions at the start and end of the step and its weight in the relative position.
struct ContactPoint {
  /// Cloth vertex id, or -1 for an obstacle point (which never moves).
  Index cloth = -1;
  ///@{
  /// Positions at the start and end of the step.
  Vec3 p0 = Vec3::Zero(), p1 = Vec3::Zero();
  ///@}
  /// Weight in the relative position Σ w·p: positive on one side, negative on the other,
  /// summing to 0 (vertex 1 against the face's barycentric weights, negated; for edges
  /// 1 - s, s against -(1 - u), -u).
  double w = 0;
};

/// A contact between two features: up to four points.
struct Contact {
  /// The points; only the first `n` are used.
  std::array<ContactPoint, 4> points;
  /// Number of points used (at most 4).
  int n = 0;
  Vec3 normal = Vec3::Zero();  ///< from the negative side towards the positive side
  double gap0 = 0;             ///< gap along the normal at t = 0
};

/// Weights and normal of a vertex-face contact (point 0 the vertex, 1..3 the triangle)
/// from the closest points at time `t` of the step.
void set_vertex_face_weights(Contact& c, double t);
/// Weights and normal of an edge-edge contact (points 0, 1 and 2, 3) at time `t`.
void set_edge_edge_weights(Contact& c, double t);
/// Normalises the normal and orients it so the gap at t = 0 is positive (against the
/// approach when it is zero); false when no direction can be found.
bool orient_contact(Contact& c);

/// Applies contact impulses to end positions.
class ContactResponse {
 public:
  /// `inverse_mass` per cloth vertex (0: pinned, never moved); Coulomb `friction`.
  ContactResponse(Eigen::VectorXd inverse_mass, double friction);

  /// A contact point on cloth vertex `v` (positions from x0 and the current x1).
  ContactPoint cloth_point(Index v, const Positions& x0, const Positions& x1) const {
    return {v, x0.row(v).transpose(), x1.row(v).transpose(), 0};
  }
  /// Adds `dn` to the contact's relative normal displacement, spread over its cloth points
  /// by weight and inverse mass, and takes off up to friction·dn of the relative
  /// tangential displacement. False when no cloth point can move.
  bool push_apart(const Contact& c, double dn, Positions& x1) const;
  /// The CCD impulse: makes the linearised gap at the end at least `target_gap`
  /// (inelastic when the pair already ends that far apart). False when nothing can move.
  bool apply(const Contact& c, double target_gap, Positions& x1) const;

  /// Inverse mass per cloth vertex (1/kg; 0: the vertex never moves, e.g. pinned).
  const Eigen::VectorXd& inverse_mass() const { return m_inverse_mass; }

 private:
  /// Relative displacement of the two sides over the step with the current x1, and the
  /// effective inverse mass Σ w² / m of the cloth points.
  Vec3 relative_displacement(const Contact& c, const Positions& x1, double& denominator) const;

  Eigen::VectorXd m_inverse_mass;
  double m_friction = 0;
};

}  // namespace tailor
