#pragma once
/// @file
/// The cloth's material: scene data that the simulation (sim/cloth_model) runs with.

namespace tailor {

/// Material of the cloth (SI units).
struct ClothMaterial {
  double density = 0.15;            ///< area density (kg/m²)
  double stretch_stiffness = 500;   ///< warp/weft stretch stiffness (N/m)
  double shear_stiffness = 50;      ///< in-plane shear stiffness (N/m)
  double bending_stiffness = 1e-5;  ///< bending stiffness (N·m)
  double stiffness_damping = 2e-3;  ///< Rayleigh damping proportional to stiffness (s)
  double air_damping = 0.2;         ///< Rayleigh damping proportional to mass (1/s)
};

}  // namespace tailor
