#pragma once
/// @file
/// Contact settings: scene data that the simulation (sim/contact_solver) runs with.

namespace tailor {

/// Contact parameters (SI units: metres, seconds).
struct ContactParams {
  double thickness = 1e-3;          ///< repulsion distance between cloth and cloth / arm
  double friction = 0.3;            ///< Coulomb friction coefficient
  int max_impulse_iterations = 20;  ///< CCD impulse passes before impact zones
  int max_zone_iterations = 100;    ///< impact-zone passes before the last resort
};

}  // namespace tailor
