#pragma once
/// @file
/// Cloth dynamics: implicit Euler (Baraff & Witkin 1998), one linearised Newton step per
/// call, with Baraff-Witkin stretch and shear conditions, dihedral-angle bending
/// (Bridson et al. 2003; Grinspun et al. 2003 weights), gravity, mass- and
/// stiffness-proportional damping, lumped masses from rest areas and pinned vertices.
///
/// Every stiffness matrix is positive semidefinite by construction (Gauss-Newton terms, the
/// coupling of a hinge's two opposite vertices lumped onto their diagonals,
/// plus the clamped positive part of the stretch term), so the linear system
/// `(1 + h α) M + (h β + h²) K` is symmetric positive definite on the free vertices.

#include <memory>
#include <span>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"
#include "tailor/scene/cloth_material.hpp"
#include "tailor/sim/cloth_linear_solver.hpp"

namespace tailor {

/// Energies of a state (J).
struct ClothEnergy {
  ///@{
  /// Kinetic, gravitational potential, membrane (in-plane) and bending energy (J).
  double kinetic = 0, gravity = 0, membrane = 0, bending = 0;
  ///@}
  /// Sum of all four.
  double total() const { return kinetic + gravity + membrane + bending; }
};

/// A one-step contact constraint, as a stiff spring (penalty, handled implicitly) that
/// holds `vertex` on the plane through `point` with unit `normal`, so the solve knows the
/// vertex cannot move into the obstacle (Baraff & Witkin 1998 constrain such vertices
/// too; a spring keeps the system a plain SPD solve).
///
/// Coulomb friction acts inside the same implicit solve, with the normal force and the
/// slip speed lagged by one step (as IPC lags them, Li et al. 2020 §5): the tangential
/// force is `-μ λ T (v1 - w) / max(s, kStickSpeed)` with `T` the tangent projector, `w`
/// the obstacle's velocity, `λ` = `normal_force` and `s` = `slip_speed`. At a fixed point
/// (s the actual slip) its magnitude is exactly μλ while sliding faster than
/// kStickSpeed and below μλ while sticking: Coulomb's law, with sticking resolved to a
/// creep of at most kStickSpeed.
struct ContactPlane {
  /// Slip speed (m/s) below which a contact counts as sticking.
  static constexpr double kStickSpeed = 1e-3;
  /// The cloth vertex held.
  Index vertex = -1;
  /// Unit normal of the plane, pointing out of the obstacle.
  Vec3 normal = Vec3::UnitY();
  /// A point of the plane (m).
  Vec3 point = Vec3::Zero();
  double stiffness = 0;          ///< N/m
  double friction = 0;           ///< Coulomb coefficient μ
  double normal_force = 0;       ///< lagged normal force λ (N)
  double slip_speed = 0;         ///< lagged tangential slip speed (m/s)
  Vec3 velocity = Vec3::Zero();  ///< obstacle velocity at the contact (m/s)

  /// The spring's push (N, ≥ 0) on a vertex at `x`: the contact's normal force there.
  double force_at(const Vec3& x) const {
    const double s = normal.dot(x - point);
    return s < 0 ? -stiffness * s : 0.0;
  }
  /// Tangential speed of a vertex moving at `v` relative to the obstacle.
  double tangential_speed(const Vec3& v) const {
    const Vec3 r = v - velocity;
    return (r - r.dot(normal) * normal).norm();
  }
};

/// What one implicit step did.
struct ClothStepInfo {
  bool direct = true;      ///< sparse Cholesky (true) or conjugate gradient (false)
  int iterations = 0;      ///< CG iterations (0 for Cholesky)
  double residual = 0;     ///< relative residual of the linear solve
  bool ok = true;          ///< false if the solve failed (then the step keeps v0)
  double assemble_ms = 0;  ///< forces and system assembly
  double solve_ms = 0;     ///< factorisation and solve (or CG)
};

/// What drives one ClothModel::step besides the cloth's start state.
struct ClothStepDrive {
  double h = 0;                 ///< step length (s)
  Vec3 gravity = Vec3::Zero();  ///< acceleration (m/s²)
  /// Row i: where pinned vertex `pinned()[i]` ends (null when nothing is pinned).
  const Positions* pinned_targets = nullptr;
  /// Contact springs (free vertices only) for this step only.
  std::span<const ContactPlane> contacts;
};

/// Implicit cloth model on a fixed mesh.
class ClothModel {
 public:
  /// `rest` gives rest lengths, angles and areas. `warp` (one row per face, optional)
  /// is the warp direction of each face; without it, each face's first edge.
  /// Throws InputError on a non-positive density or negative stiffness, or a
  /// degenerate rest triangle.
  ClothModel(const TriangleMesh& mesh, const Positions& rest, const ClothMaterial& material,
             const Positions* warp = nullptr);
  ~ClothModel();
  /// Moves the model; the moved-from one may only be destroyed or assigned to.
  ClothModel(ClothModel&&) noexcept;
  /// Move assignment (as the move constructor).
  ClothModel& operator=(ClothModel&&) noexcept;

  /// The material the model was built with.
  const ClothMaterial& material() const;
  /// Lumped vertex masses (kg): a third of each incident face's rest area times density.
  const Eigen::VectorXd& masses() const;
  /// Vertices whose positions are prescribed (sorted, unique on return).
  void set_pinned(std::vector<Index> vertices);
  /// The pinned vertices, sorted.
  const std::vector<Index>& pinned() const;
  /// Chooses the linear solver and, for block-Jacobi CG, the relative residual to reach.
  void set_solver(ClothSolver solver, double cg_tolerance = 1e-6);

  /// One linearised implicit Euler step of length `drive.h` from (x0, v0): writes the
  /// candidate end positions `x1` and velocities `v1` (see ClothStepDrive).
  ClothStepInfo step(const Positions& x0, const Positions& v0, const ClothStepDrive& drive,
                     Positions& x1, Positions& v1);

  /// Membrane plus bending energy of positions `x` (J).
  double elastic_energy(const Positions& x) const;
  /// Elastic forces (minus the gradient of elastic_energy) at `x`.
  Positions elastic_forces(const Positions& x) const;
  /// Every energy of a state.
  ClothEnergy energy(const Positions& x, const Positions& v, const Vec3& gravity) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

/// Signed dihedral angle at the hinge `a`-`b` between triangles (a, b, c) and (b, a, d)
/// (zero when flat) and its gradient with respect to (a, b, c, d).
double dihedral_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                      Eigen::Matrix<double, 12, 1>* gradient = nullptr);

}  // namespace tailor
