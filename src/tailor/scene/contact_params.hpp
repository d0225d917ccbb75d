#pragma once
/// @file
/// Contact settings: scene data that the simulation (sim/contact_solver) runs with.

namespace tailor {

/// Contact parameters (SI units: metres, seconds).
struct ContactParams {
  double thickness = 1e-3;  ///< repulsion distance between cloth and cloth / arm
  /// Coulomb friction coefficient, cloth on skin and on cloth: cotton on dry skin, the low
  /// end of the 0.2-0.6 that textile-skin measurements report (Derler & Gerhardt,
  /// "Tribology of skin", Tribology Letters 45, 2012).
  double friction = 0.25;
  int max_impulse_iterations = 20;  ///< CCD impulse passes before impact zones
  int max_zone_iterations = 100;    ///< impact-zone passes before the last resort
};

}  // namespace tailor
