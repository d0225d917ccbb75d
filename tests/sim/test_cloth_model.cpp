/// @file
/// Cloth model: derivatives against finite differences, a hanging cloth, stability.

#include "support/sanitized.hpp"
#include "sim/flat_sheet.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>

#include "tailor/geometry/error.hpp"
#include "tailor/sim/cloth_model.hpp"

namespace tailor {
namespace {

using tailor::testing::sanitized;

TEST(DihedralAngle, GradientMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    std::array<Vec3, 4> p;
    p[0] = Vec3(0, 0, 0) + 0.2 * Vec3(u(rng), u(rng), u(rng));
    p[1] = Vec3(1, 0, 0) + 0.2 * Vec3(u(rng), u(rng), u(rng));
    p[2] = Vec3(0.5, 1, 0) + 0.3 * Vec3(u(rng), u(rng), u(rng));
    p[3] = Vec3(0.5, -1, 0) + 0.3 * Vec3(u(rng), u(rng), u(rng));
    Eigen::Matrix<double, 12, 1> g;
    dihedral_angle(p[0], p[1], p[2], p[3], &g);
    const double h = 1e-6;
    for (int k = 0; k < 12; ++k) {
      auto q = p, r = p;
      q[k / 3][k % 3] += h;
      r[k / 3][k % 3] -= h;
      const double fd =
          (dihedral_angle(q[0], q[1], q[2], q[3]) - dihedral_angle(r[0], r[1], r[2], r[3])) /
          (2 * h);
      EXPECT_NEAR(g[k], fd, 1e-5 * (1 + std::abs(fd))) << "trial " << trial << " component " << k;
    }
  }
}

TEST(DihedralAngle, FlatIsZeroAndFoldSignsDiffer) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 1, 0), d(0.5, -1, 0);
  EXPECT_NEAR(dihedral_angle(a, b, c, d), 0.0, 1e-15);
  const double up = dihedral_angle(a, b, c, Vec3(0.5, -1, 0.5));
  const double down = dihedral_angle(a, b, c, Vec3(0.5, -1, -0.5));
  EXPECT_GT(std::abs(up), 0.1);
  EXPECT_NEAR(up, -down, 1e-12);
}

TEST(ClothModel, ForcesAreMinusEnergyGradient) {
  testing::Sheet s = testing::make_sheet(4, 0.3);
  ClothMaterial m;
  m.bending_stiffness = 1e-3;  // large enough to matter in the check
  const ClothModel model(*s.mesh, s.rest, m);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  Positions x = s.rest;
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    x.row(i) += 0.02 * Eigen::RowVector3d(u(rng), u(rng), u(rng));
  const Positions f = model.elastic_forces(x);
  const double h = 1e-7;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (int c = 0; c < 3; ++c) {
      Positions xp = x, xm = x;
      xp(i, c) += h;
      xm(i, c) -= h;
      const double fd = -(model.elastic_energy(xp) - model.elastic_energy(xm)) / (2 * h);
      EXPECT_NEAR(f(i, c), fd, 1e-4 * (1 + std::abs(fd))) << "vertex " << i << " axis " << c;
    }
  }
}

TEST(ClothModel, RestShapeHasNoEnergyAndMassesSumToDensityTimesArea) {
  testing::Sheet s = testing::make_sheet(5, 0.4);
  ClothMaterial m;
  const ClothModel model(*s.mesh, s.rest, m);
  EXPECT_NEAR(model.elastic_energy(s.rest), 0.0, 1e-14);
  EXPECT_NEAR(model.masses().sum(), m.density * 0.4 * 0.4, 1e-12);
  EXPECT_NEAR(model.elastic_forces(s.rest).cwiseAbs().maxCoeff(), 0.0, 1e-10);
}

TEST(ClothModel, RejectsBadMaterial) {
  testing::Sheet s = testing::make_sheet(3, 0.1);
  ClothMaterial m;
  m.density = 0;
  EXPECT_THROW(ClothModel(*s.mesh, s.rest, m), InputError);
  m = ClothMaterial{};
  m.stretch_stiffness = -1;
  EXPECT_THROW(ClothModel(*s.mesh, s.rest, m), InputError);
}

/// A sheet pinned along one edge, hanging under gravity at 30 fps with `substeps`.
void run_hanging_sheet(ClothSolver solver, int substeps, int frames, bool weft_down = false,
                       double energy_slack = 1e-9) {
  testing::Sheet s = testing::make_sheet(12, 0.5);
  // Warp across (x) or along (z) the direction the sheet will hang in.
  Positions warp(s.mesh->num_faces(), 3);
  warp.rowwise() = weft_down ? Eigen::RowVector3d(1, 0, 0) : Eigen::RowVector3d(0, 0, 1);
  ClothModel model(*s.mesh, s.rest, ClothMaterial{}, &warp);
  model.set_solver(solver, 1e-8);
  std::vector<Index> pinned;
  for (Index j = 0; j < 12; ++j) pinned.push_back(j);  // the row at z = 0
  model.set_pinned(pinned);
  Positions targets(12, 3);
  for (Index j = 0; j < 12; ++j) targets.row(j) = s.rest.row(j);
  const Vec3 g(0, -9.81, 0);
  Positions x = s.rest, v = Positions::Zero(x.rows(), 3), x1, v1;
  const double h = 1.0 / 30.0 / substeps;
  const double e0 = model.energy(x, v, g).total();
  double max_energy = e0;
  for (int step = 0; step < frames * substeps; ++step) {
    const ClothStepInfo info = model.step(x, v, {h, g, &targets, {}}, x1, v1);
    ASSERT_TRUE(info.ok) << "step " << step;
    ASSERT_TRUE(x1.allFinite() && v1.allFinite()) << "step " << step;
    x = x1;
    v = v1;
    max_energy = std::max(max_energy, model.energy(x, v, g).total());
    for (Index j = 0; j < 12; ++j) ASSERT_EQ(x.row(j), s.rest.row(j));
  }
  // Damped and driven only by gravity: the energy never rises above the start (with
  // `energy_slack` for the linearisation error of very long steps).
  EXPECT_LE(max_energy, e0 + energy_slack);
  // It hangs: the free edge fell close to the sheet's length below the pins, no further
  // than the cloth can stretch.
  const double lowest = x.col(1).minCoeff();
  EXPECT_LT(lowest, -0.4);
  EXPECT_GT(lowest, -0.55);
  // Nearly inextensible: no edge longer than 5% beyond rest.
  const auto& edges = s.mesh->edges();
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    const double l = (x.row(edges(e, 0)) - x.row(edges(e, 1))).norm();
    const double l0 = (s.rest.row(edges(e, 0)) - s.rest.row(edges(e, 1))).norm();
    EXPECT_LT(l, 1.05 * l0) << "edge " << e;
  }
  // Still swinging but damped: below the energy the fall released (~0.09 J), well below
  // after three seconds.
  EXPECT_LT(model.energy(x, v, g).kinetic, frames >= 90 ? 0.01 : 0.05);
}

TEST(ClothModel, HangingSheetDirectSolver) {
  run_hanging_sheet(ClothSolver::direct, 5, sanitized() ? 30 : 90);
}

TEST(ClothModel, HangingSheetWeftDown) {
  run_hanging_sheet(ClothSolver::direct, 5, sanitized() ? 30 : 90, true);
}

TEST(ClothModel, HangingSheetSupernodalSolver) {
  run_hanging_sheet(ClothSolver::supernodal, 5, sanitized() ? 30 : 90);
}

TEST(ClothModel, HangingSheetConjugateGradient) {
  run_hanging_sheet(ClothSolver::iterative, 5, sanitized() ? 30 : 90);
}

TEST(ClothModel, StableAtThirtyFramesPerSecondWithFewSubsteps) {
  // Two substeps per frame stay finite and bounded (implicit Euler, PSD stiffness). The
  // fall releases ~0.09 J; the linearised step of the stiff cotton membrane may add a
  // little at 1/60 s.
  run_hanging_sheet(ClothSolver::direct, 2, sanitized() ? 30 : 90, false, 0.02);
}

TEST(ClothModel, HangsAtOneStepPerFrame) {
  // One step per frame (the default scene's): the sheet still hangs, nearly inextensible
  // and damped. The energy is not bounded by the start here: one linearised step of 1/30 s
  // over-shoots the stiff membrane's fall and gained up to 0.13 J (the sleeve's strain
  // limiter takes that back), so only the other checks apply.
  run_hanging_sheet(ClothSolver::direct, 1, sanitized() ? 30 : 90, false,
                    std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace tailor
