#pragma once
/// @file
/// The cloth's material: scene data that the simulation (sim/cloth_model) runs with.
///
/// Defaults: a plain-woven cotton shirting, from typical Kawabata (KES-FB) measurements of
/// cotton shirtings (Kawabata & Niwa, "Fabric performance in clothing and clothing
/// manufacture", J. Textile Inst. 80(1), 1989, the data behind KES-based cloth models such
/// as Breen, House & Wozny 1994 and Volino et al. 2009), converted to SI:
///  - weight W = 12 mg/cm² -> density 0.12 kg/m²;
///  - bending rigidity B = 0.08 gf·cm²/cm -> 0.08 × 9.807e-3 N × 1e-4 m² / 1e-2 m
///    = 7.8e-6 N·m;
///  - shear rigidity G = 0.8 gf/cm/degree -> 0.8 × 9.807e-3 N / 1e-2 m × (180/π)
///    = 45 N/m per radian of shear;
///  - tensile extensibility EMT = 5 % at 500 gf/cm (490 N/m) -> secant stretch stiffness
///    490 / 0.05 = 9.8e3 N/m per unit strain;
///  - strain limit 2.5 %: about where a shirting's load-extension curve turns steep (the
///    crimp is used up, half of EMT), far below its breaking strain; the strain limiter
///    (sim/strain_limiter) holds every edge to it, and the contact passes after it may add
///    a little.

namespace tailor {

/// Material of the cloth (SI units).
struct ClothMaterial {
  double density = 0.12;              ///< area density (kg/m²)
  double stretch_stiffness = 9.8e3;   ///< warp/weft stretch stiffness (N/m)
  double shear_stiffness = 45;        ///< in-plane shear stiffness (N/m)
  double bending_stiffness = 7.8e-6;  ///< bending stiffness (N·m)
  double stiffness_damping = 2e-3;    ///< Rayleigh damping proportional to stiffness (s)
  double air_damping = 0.2;           ///< Rayleigh damping proportional to mass (1/s)
  double strain_limit = 0.025;        ///< no edge stretches more than this (fraction)
};

}  // namespace tailor
